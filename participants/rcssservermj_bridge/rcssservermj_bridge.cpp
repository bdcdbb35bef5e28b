#include "participants/rcssservermj_bridge/rcssservermj_bridge.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <vector>

#include "codecs/rcssservermj/session.h"
#include "codecs/simspark/framing.h"
#include "participants/common/address_allowlist.h"
#include "participants/common/cycle_loop.h"
#include "participants/common/front_end_server.h"
#include "participants/common/process.h"
#include "participants/common/watched_stats.h"
#include "participants/common/worker_thread.h"
#include "participants/rcssservermj_bridge/legged_link.h"

namespace turf {

namespace {

// RCSSServerMJ frames exactly as SimSpark does (FrontEndServer's framing).
FrontEndServer::Options ServerOptions(const RcssServerMjOptions& o) {
  return {o.listen, o.agent_port, o.monitor_port, o.max_clients, o.max_unsent, {}, true};
}

MjLeggedLink MakeLink(const RcssServerMjOptions& o, dds::Bus* bus) {
  if (bus != nullptr) return MjLeggedLink(*bus);
  return MjLeggedLink(DdsOptions(o, "turf-rcssservermj-bridge"));
}

}  // namespace

class RcssServerMjBridge::Impl {
 public:
  Impl(RcssServerMjOptions options, dds::Bus* bus)
      : options_(std::move(options)),
        link_(MakeLink(options_, bus)),
        monitor_allow_(options_.monitor_allow),
        rejects_("RCSSServerMJ input") {
    if (options_.sequential || !options_.realtime) options_.sync_mode = true;
    rcssservermj::SessionOptions check;
    check.rules = options_.rules;
    check.field = options_.field;
    rcssservermj::Session probe(check, {});  // throws std::invalid_argument for a bad rule book or field
    server_ = std::make_unique<FrontEndServer>(ServerOptions(options_), "RCSSServerMJ client", &rejects_, MakeHooks());
  }

  uint16_t agent_port() const { return server_->agent_port(); }
  uint16_t monitor_port() const { return server_->monitor_port(); }

  bool Run(const std::function<bool()>& stop) {
    if (!Attach(stop)) return stop();
    spdlog::info("RCSSServerMJ agents: TCP {}:{}; monitor commands: TCP {}:{}; {}{}{}", options_.listen, agent_port(),
                 options_.listen, monitor_port(), options_.realtime ? "real time" : "as fast as possible",
                 options_.sync_mode ? ", sync mode" : "", options_.sequential ? ", sequential loop" : "");
    spdlog::info("monitor-port clients allowed from: {}", monitor_allow_.Describe());
    CycleLoopOptions loop;
    loop.paced = options_.realtime;
    loop.sync = options_.sync_mode;
    loop.agent_timeout = options_.agent_timeout;
    loop.end_cycles = options_.duration > 0 ? std::llround(options_.duration / rcssservermj::kCycleSeconds) : -1;
    CycleLoopHooks hooks;
    hooks.poll = [&](std::chrono::milliseconds timeout) {
      PollSockets(timeout);
      for (int agent : session_->TakeKicked()) DropAgent(agent, "closed by the server");
      ReportIssues();
    };
    hooks.idle = [&] { return session_->active_agents() == 0 && !session_->HasPendingInit(); };
    hooks.ready = [&] { return session_->ReadyToStep(); };
    hooks.drop_waiting = [&] {
      for (int agent : session_->Waiting()) DropAgent(agent, "sent no message within the agent timeout");
    };
    hooks.cycle = [&] { return RunCycle(stop); };
    hooks.cycles = [&] { return session_->cycle(); };
    hooks.quit = [&] { return session_->quit_requested(); };
    hooks.status = [&] { ReportStatus(); };
    if (!RunCycleLoop(loop, hooks, stop)) return false;
    if (session_->quit_requested()) spdlog::info("a monitor sent (killsim): stopping");
    ReportStatus();
    return true;
  }

  const WatchedStats<RcssServerMjStats>& stats() const { return stats_; }

 private:
  bool Attach(const std::function<bool()>& stop) {
    if (session_) {
      for (auto& [fd, c] : server_->clients())
        if (!c.monitor) server_->MarkDrop(fd, "turf-sim stopped answering; reconnect when it is back");
      server_->FlushDrops();
    }
    spdlog::info("waiting for turf-sim's legged scene on {} ({})", link_.DescribeBus(),
                 link_.TopicName(dds::Topic::kLeggedScene));
    std::string error;
    auto scene = link_.Attach(options_.attach_timeout, stop, &error);
    if (!scene) {
      if (!stop()) spdlog::error("{}", error);
      return false;
    }
    steps_ = static_cast<uint32_t>(std::max<long>(1, std::lround(rcssservermj::kCycleSeconds / link_.step_s())));
    int t1 = 0, k1 = 0;
    for (const rcssservermj::SceneRobot& r : scene->robots) {
      t1 += r.model == "T1";
      k1 += r.model == "K1";
    }
    spdlog::info("scene '{}': {} T1 and {} K1 robots for agents, {} physics steps of {} ms per 20 ms cycle; rules {}",
                 scene->name, t1, k1, steps_, link_.step_s() * 1e3, options_.rules);
    if (std::abs(steps_ * link_.step_s() - rcssservermj::kCycleSeconds) > 1e-9)
      spdlog::warn("the scene's physics step does not divide 20 ms: a cycle is {} ms", steps_ * link_.step_s() * 1e3);
    spdlog::info("publishing {} (steps, moves, PD joint commands); subscribing {}, {}",
                 link_.TopicName(dds::Topic::kControl), link_.TopicName(dds::Topic::kRobotsState),
                 link_.TopicName(dds::Topic::kControlReply));
    rcssservermj::SessionOptions o;
    o.sync_mode = options_.sync_mode;
    o.sequential = options_.sequential;
    o.rules = options_.rules;
    o.field = options_.field;
    o.seed = options_.seed;
    session_ = std::make_unique<rcssservermj::Session>(o, scene->robots);
    return true;
  }

  // The reference's order: the actions, then the perceptions of the state before this step go out while the world
  // steps (the world on the stepper thread, so the agents think meanwhile), then the referee; the sequential loop's
  // perceptions of the state after it.
  bool RunCycle(const std::function<bool()>& stop) {
    std::string error;
    std::vector<std::string> warnings;
    const rcssservermj::WorldRequests requests = session_->TakeRequests();
    for (int agent : session_->TakeKicked()) DropAgent(agent, "closed by the server");
    std::optional<rcssservermj::MjWorldSnapshot> world;
    stepper_.Start([&] { world = link_.Cycle(requests, steps_, options_.step_timeout, stop, &error, &warnings); });
    try {
      SendPerceptions();
    } catch (...) {
      stepper_.Wait();  // the job uses this frame's locals
      throw;
    }
    stepper_.Wait();
    for (const std::string& w : warnings) spdlog::warn("turf-sim refused {}", w);
    if (!world) {
      if (stop()) return true;
      spdlog::error("{}; attaching again", error);
      return Attach(stop) || stop();
    }
    const double sim_time = world->time;
    session_->Advance(std::move(*world));
    SendPerceptions();
    ReportIssues();
    stats_.Update([&](RcssServerMjStats& s) {
      s.cycles = session_->cycle();
      s.sim_time = sim_time;
      s.agents = session_->agents();
      s.active_agents = session_->active_agents();
    });
    return true;
  }

  void SendPerceptions() {
    for (const auto& [agent, perception] : session_->TakePerceptions())
      server_->SendToAgent(agent, simspark::Frame(rcssservermj::FormatPerception(perception)));
    server_->FlushDrops();
  }

  void ReportIssues() {
    for (const rcssservermj::SessionIssue& issue : session_->TakeIssues())
      rejects_.Reject(issue.kind, issue.agent < 0 ? "monitor: " + issue.detail
                                                  : fmt::format("agent {}: {}", issue.agent, issue.detail));
    stats_.Update([&](RcssServerMjStats& s) {
      if (s.refused == rejects_.Total()) return;
      s.refused = rejects_.Total();
      s.refused_by_kind = rejects_.counts();
    });
  }

  void PollSockets(std::chrono::milliseconds timeout) { server_->Poll(timeout); }

  FrontEndServer::Hooks MakeHooks() {
    FrontEndServer::Hooks h;
    h.admit = [this](FrontEndClient& c, const std::string& address, std::string*) {
      if (c.monitor && !monitor_allow_.Allows(address)) {
        rejects_.Reject("monitor_not_allowed", fmt::format("{} refused: not in the monitor allowlist ({})", address,
                                                           monitor_allow_.Describe()));
        return false;  // the peer's destructor closes it
      }
      if (!c.monitor) c.agent = session_->Connect();
      server_->connections().Reject(c.monitor ? "monitor_connected" : "agent_connected",
                                    c.monitor ? address : fmt::format("agent {} from {}", c.agent, address));
      stats_.Update([&](RcssServerMjStats& s) { s.agents = session_->agents(); });
      return true;
    };
    h.message = [this](FrontEndClient& c, const std::string& payload) {
      if (c.monitor) {
        session_->Monitor(payload);
      } else {
        session_->Receive(c.agent, payload);
      }
    };
    h.left = [this](const FrontEndClient& c) {
      if (!c.monitor) session_->Disconnect(c.agent);
      stats_.Update([&](RcssServerMjStats& s) {
        ++s.dropped_clients;
        s.agents = session_->agents();
        s.active_agents = session_->active_agents();
      });
    };
    return h;
  }

  void DropAgent(int agent, const std::string& why) { server_->DropAgent(agent, why); }

  void ReportStatus() {
    if (!session_) return;
    const rcssservermj::Referee& r = session_->referee();
    spdlog::info("cycle {} agents {} ({} active) play mode {} play time {:.2f} score {}:{} refused {}",
                 session_->cycle(), session_->agents(), session_->active_agents(),
                 rcssservermj::PlayModeName(r.play_mode()), r.play_time(), r.score(rcssservermj::Side::kLeft),
                 r.score(rcssservermj::Side::kRight), rejects_.Total());
  }

  RcssServerMjOptions options_;
  MjLeggedLink link_;
  AddressAllowlist monitor_allow_;
  std::unique_ptr<rcssservermj::Session> session_;
  uint32_t steps_ = 4;
  RejectLog rejects_;
  std::unique_ptr<FrontEndServer> server_;
  WatchedStats<RcssServerMjStats> stats_;
  WorkerThread stepper_;  // steps the world while the perceptions go out; last: stopped before the rest goes
};

RcssServerMjBridge::RcssServerMjBridge(RcssServerMjOptions options)
    : impl_(std::make_unique<Impl>(std::move(options), nullptr)) {}
RcssServerMjBridge::RcssServerMjBridge(RcssServerMjOptions options, dds::Bus& bus)
    : impl_(std::make_unique<Impl>(std::move(options), &bus)) {}
RcssServerMjBridge::~RcssServerMjBridge() = default;
uint16_t RcssServerMjBridge::agent_port() const { return impl_->agent_port(); }
uint16_t RcssServerMjBridge::monitor_port() const { return impl_->monitor_port(); }
bool RcssServerMjBridge::Run(const std::function<bool()>& stop) { return impl_->Run(stop); }
RcssServerMjStats RcssServerMjBridge::Stats() const { return impl_->stats().Get(); }
RcssServerMjStats RcssServerMjBridge::WaitForStats(const std::function<bool(const RcssServerMjStats&)>& done,
                                                   std::chrono::milliseconds timeout) const {
  return impl_->stats().WaitFor(done, timeout);
}

}  // namespace turf
