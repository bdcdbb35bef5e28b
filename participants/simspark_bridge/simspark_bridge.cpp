#include "participants/simspark_bridge/simspark_bridge.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "codecs/simspark/framing.h"
#include "codecs/simspark/session.h"
#include "participants/common/cycle_loop.h"
#include "participants/common/front_end_server.h"
#include "participants/common/process.h"
#include "participants/common/watched_stats.h"
#include "participants/simspark_bridge/world_link.h"

namespace turf {

namespace {

using Clock = std::chrono::steady_clock;
constexpr double kCycleSeconds = 0.02;

// A monitor's FrontEndClient::role: from an operator's address?
simspark::TrainerRole RoleOf(const FrontEndClient& c) { return static_cast<simspark::TrainerRole>(c.role); }

const char* RoleName(simspark::TrainerRole role) {
  return role == simspark::TrainerRole::kOperator ? "operator" : "not an operator";
}

}  // namespace

namespace {

// On `bus`, or (null) on a DDS participant of the link's own.
WorldLink MakeLink(const SimSparkBridgeOptions& o, dds::Bus* bus) {
  if (bus != nullptr) return WorldLink(*bus);
  return WorldLink(DdsOptions(o, "turf-simspark-bridge"));
}

}  // namespace

class SimSparkBridge::Impl {
 public:
  Impl(SimSparkBridgeOptions options, dds::Bus* bus)
      : options_(std::move(options)),
        link_(MakeLink(options_, bus)),
        operators_(options_.operator_allow),
        rejects_("SimSpark input"),
        server_({options_.listen,
                 options_.agent_port,
                 options_.monitor_port,
                 options_.max_clients,
                 options_.max_unsent,
                 {},
                 true},
                "SimSpark client", &rejects_, MakeHooks()) {}

  uint16_t agent_port() const { return server_.agent_port(); }
  uint16_t monitor_port() const { return server_.monitor_port(); }

  bool Run(const std::function<bool()>& stop) {
    if (!Attach(stop)) return stop();
    spdlog::info("agents: TCP {}:{}; monitors and trainers: TCP {}:{}; {} mode", options_.listen, agent_port(),
                 options_.listen, monitor_port(), options_.sync_mode ? "sync" : "real-time");
    spdlog::info("operators (may end, restart or rewrite the match from the monitor port): {}", operators_.Describe());
    CycleLoopOptions loop;
    loop.paced = !options_.sync_mode;
    loop.sync = options_.sync_mode;
    loop.agent_timeout = options_.sync_timeout;
    loop.end_cycles = options_.duration > 0 ? std::llround(options_.duration / kCycleSeconds) : -1;
    CycleLoopHooks hooks;
    hooks.poll = [&](std::chrono::milliseconds timeout) {
      PollSockets(timeout);
      for (int agent : session_->TakeKicked()) DropAgent(agent, "killed by the trainer");
    };
    // Sync mode without agents: the world waits (a run is the agents' stream alone).
    hooks.idle = [&] { return session_->agents_with_robot() == 0; };
    hooks.ready = [&] { return session_->ReadyToStep(); };
    hooks.drop_waiting = [&] {
      for (int agent : session_->Waiting()) DropAgent(agent, "sent no (syn) within the sync timeout");
    };
    hooks.cycle = [&] { return RunCycle(stop); };
    hooks.cycles = [&] { return session_->cycle(); };
    hooks.quit = [&] { return session_->quit_requested(); };
    hooks.status = [&] { ReportStatus(); };
    hooks.waited = [&](Clock::duration d) { split_.waiting += d; };
    if (!RunCycleLoop(loop, hooks, stop)) return false;
    if (session_->quit_requested()) spdlog::info("a trainer sent (killsim): stopping");
    ReportStatus();
    return true;
  }

  const WatchedStats<SimSparkBridgeStats>& stats() const { return stats_; }

 private:
  bool Attach(const std::function<bool()>& stop) {
    if (session_) {
      // turf-sim went away (or restarted): its world starts over, so do the
      // agents, as with a restarted rcssserver3d.
      for (auto& [fd, c] : server_.clients())
        if (!c.monitor) server_.MarkDrop(fd, "turf-sim stopped answering; reconnect when it is back");
      server_.FlushDrops();
    }
    spdlog::info("waiting for turf-sim's legged scene on {} ({})", link_.DescribeBus(),
                 link_.TopicName(dds::Topic::kLeggedScene));
    std::string error;
    auto scene = link_.Attach(options_.attach_timeout, stop, &error);
    if (!scene) {
      if (!stop()) spdlog::error("{}", error);
      return false;
    }
    steps_ = static_cast<uint32_t>(std::max<long>(1, std::lround(kCycleSeconds / link_.step_s())));
    spdlog::info("scene '{}': {} robots for agents, {} physics steps of {} ms per 20 ms cycle; turf-sim in lockstep",
                 scene->name, scene->robots.size(), steps_, link_.step_s() * 1e3);
    spdlog::info("publishing {} (steps, moves, joint velocities); subscribing robots/*, {}, {}",
                 link_.TopicName(dds::Topic::kControl), link_.TopicName(dds::Topic::kWorldState),
                 link_.TopicName(dds::Topic::kControlReply));
    simspark::SessionOptions o;
    o.seed = options_.seed;
    o.sync_mode = options_.sync_mode;
    session_ = std::make_unique<simspark::Session>(o, scene->robots, scene->park);
    return true;
  }

  bool RunCycle(const std::function<bool()>& stop) {
    std::string error;
    std::vector<std::string> warnings;
    const auto start = Clock::now();
    const simspark::WorldRequests requests = session_->TakeRequests();
    auto world = link_.Cycle(requests, steps_, options_.step_timeout, stop, &error, &warnings);
    const auto stepped = Clock::now();
    split_.world += stepped - start;
    ++split_.cycles;
    for (const std::string& w : warnings) spdlog::warn("turf-sim refused {}", w);
    if (!world) {
      if (stop()) return true;
      spdlog::error("{}; attaching again", error);
      return Attach(stop) || stop();
    }
    const double sim_time = world->time;
    session_->Advance(std::move(*world));
    for (auto& [agent, message] : session_->TakeOutputs()) server_.SendToAgent(agent, simspark::Frame(message));
    const std::string monitor = session_->TakeMonitorOutput();
    if (!monitor.empty()) {
      const std::string framed = simspark::Frame(monitor);
      for (auto& [fd, c] : server_.clients())
        if (c.monitor) server_.Send(fd, framed);
    }
    server_.FlushDrops();
    split_.bridge += Clock::now() - stepped;
    ReportIssues();
    stats_.Update([&](SimSparkBridgeStats& s) {
      s.cycles = session_->cycle();
      s.sim_time = sim_time;
      s.agents = session_->agents();
    });
    return true;
  }

  // The session's refusals into the log, and every refusal into the stats,
  // after each cycle and each poll: a trainer's refused command counts even
  // while no cycle runs (sync mode without agents).
  void ReportIssues() {
    for (const simspark::SessionIssue& issue : session_->TakeIssues()) {
      rejects_.Reject(issue.kind, issue.agent < 0 ? "trainer: " + issue.detail
                                                  : fmt::format("agent {}: {}", issue.agent, issue.detail));
    }
    stats_.Update([&](SimSparkBridgeStats& s) {
      if (s.refused == rejects_.Total()) return;
      s.refused = rejects_.Total();
      s.refused_by_kind = rejects_.counts();
    });
  }

  void PollSockets(std::chrono::milliseconds timeout) {
    if (server_.Poll(timeout)) ReportIssues();
  }

  FrontEndServer::Hooks MakeHooks() {
    FrontEndServer::Hooks h;
    h.admit = [this](FrontEndClient& c, const std::string& address, std::string* greeting) {
      if (c.monitor) {
        if (operators_.Allows(address)) c.role = static_cast<int>(simspark::TrainerRole::kOperator);
        server_.connections().Reject("monitor_connected", fmt::format("{} ({})", address, RoleName(RoleOf(c))));
        *greeting = simspark::Frame(session_->MonitorGreeting());
        return true;
      }
      c.agent = session_->Connect();
      server_.connections().Reject("agent_connected", fmt::format("agent {} from {}", c.agent, address));
      stats_.Update([&](SimSparkBridgeStats& s) { s.agents = session_->agents(); });
      return true;
    };
    h.message = [this](FrontEndClient& c, const std::string& payload) {
      if (c.monitor) {
        session_->Trainer(payload, RoleOf(c));
      } else {
        session_->Receive(c.agent, payload);
      }
    };
    h.left = [this](const FrontEndClient& c) {
      if (!c.monitor) session_->Disconnect(c.agent);
      stats_.Update([&](SimSparkBridgeStats& s) {
        ++s.dropped_clients;
        s.agents = session_->agents();
      });
    };
    return h;
  }

  void DropAgent(int agent, const std::string& why) { server_.DropAgent(agent, why); }

  void ReportStatus() {
    if (!session_) return;
    if (split_.cycles > 0) {
      // Where a cycle's wall time went: turf-sim stepping and publishing (with
      // the DDS hops), the bridge's perceptions, and waiting (agents' answers in
      // sync mode, the 20 ms pacing in real time).
      auto ms = [&](Clock::duration d) { return std::chrono::duration<double, std::milli>(d).count() / split_.cycles; };
      spdlog::info("per cycle: world {:.2f} ms, bridge {:.2f} ms, waiting {:.2f} ms ({} cycles)", ms(split_.world),
                   ms(split_.bridge), ms(split_.waiting), split_.cycles);
      split_ = {};
    }
    const simspark::Game& g = session_->game();
    spdlog::info("cycle {} agents {} ({} with robots) play mode {} game time {:.2f} score {}:{} refused {}",
                 session_->cycle(), session_->agents(), session_->agents_with_robot(),
                 simspark::PlayModeName(g.play_mode()), g.game_time(), g.score(simspark::Side::kLeft),
                 g.score(simspark::Side::kRight), rejects_.Total());
  }

  SimSparkBridgeOptions options_;
  WorldLink link_;
  AddressAllowlist operators_;
  std::unique_ptr<simspark::Session> session_;
  uint32_t steps_ = 4;
  struct {
    Clock::duration world{}, bridge{}, waiting{};
    uint64_t cycles = 0;
  } split_;
  RejectLog rejects_;
  FrontEndServer server_;
  WatchedStats<SimSparkBridgeStats> stats_;
};

SimSparkBridge::SimSparkBridge(SimSparkBridgeOptions options)
    : impl_(std::make_unique<Impl>(std::move(options), nullptr)) {}
SimSparkBridge::SimSparkBridge(SimSparkBridgeOptions options, dds::Bus& bus)
    : impl_(std::make_unique<Impl>(std::move(options), &bus)) {}
SimSparkBridge::~SimSparkBridge() = default;
uint16_t SimSparkBridge::agent_port() const { return impl_->agent_port(); }
uint16_t SimSparkBridge::monitor_port() const { return impl_->monitor_port(); }
bool SimSparkBridge::Run(const std::function<bool()>& stop) { return impl_->Run(stop); }
SimSparkBridgeStats SimSparkBridge::Stats() const { return impl_->stats().Get(); }
SimSparkBridgeStats SimSparkBridge::WaitForStats(const std::function<bool(const SimSparkBridgeStats&)>& done,
                                                 std::chrono::milliseconds timeout) const {
  return impl_->stats().WaitFor(done, timeout);
}

}  // namespace turf
