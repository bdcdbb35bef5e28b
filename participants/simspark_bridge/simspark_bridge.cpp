#include "participants/simspark_bridge/simspark_bridge.h"

#include <poll.h>
#include <spdlog/spdlog.h>
#include <sys/socket.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <condition_variable>
#include <mutex>
#include <stdexcept>
#include <vector>

#include "codecs/simspark/framing.h"
#include "codecs/simspark/session.h"
#include "participants/common/process.h"
#include "participants/common/tcp.h"
#include "participants/simspark_bridge/world_link.h"

namespace turf {

namespace {

using Clock = std::chrono::steady_clock;
constexpr auto kCycle = std::chrono::milliseconds(20);
constexpr double kCycleSeconds = 0.02;
constexpr int kSendBuffer = 128 * 1024;  // kernel buffer per client (bounds what a stalled client holds)
constexpr size_t kMaxReadPerPoll = 1 << 18;

constexpr auto kConnectionLogInterval = std::chrono::seconds(1);  // per kind of connection line

struct Client {
  std::unique_ptr<TcpPeer> peer;
  simspark::FrameDecoder decoder;
  bool monitor = false;
  int agent = -1;                                                // session id (agents only)
  simspark::TrainerRole role = simspark::TrainerRole::kTrainer;  // monitors only: from an operator's address?
};

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
        connections_("SimSpark client", kConnectionLogInterval, LogLine::kEvent) {
    std::string error;
    auto agents = TcpListener::Listen(options_.listen, options_.agent_port, &error);
    if (!agents) throw std::runtime_error("agent port: " + error);
    auto monitors = TcpListener::Listen(options_.listen, options_.monitor_port, &error);
    if (!monitors) throw std::runtime_error("monitor port: " + error);
    agent_listener_ = std::move(*agents);
    monitor_listener_ = std::move(*monitors);
  }

  uint16_t agent_port() const { return agent_listener_.LocalPort(); }
  uint16_t monitor_port() const { return monitor_listener_.LocalPort(); }

  bool Run(const std::function<bool()>& stop) {
    if (!Attach(stop)) return stop();
    spdlog::info("agents: TCP {}:{}; monitors and trainers: TCP {}:{}; {} mode", options_.listen, agent_port(),
                 options_.listen, monitor_port(), options_.sync_mode ? "sync" : "real-time");
    spdlog::info("operators (may end, restart or rewrite the match from the monitor port): {}", operators_.Describe());
    auto next_cycle = Clock::now();
    auto waiting_since = Clock::now();
    auto next_status = Clock::now() + std::chrono::seconds(10);
    const int64_t end_cycles = options_.duration > 0 ? std::llround(options_.duration / kCycleSeconds) : -1;
    while (!stop() && !session_->quit_requested()) {
      // Sync mode without agents: the world waits (a run is the agents' stream alone).
      const bool idle = options_.sync_mode && session_->agents_with_robot() == 0;
      const bool paced = !options_.sync_mode;
      const auto now = Clock::now();
      const auto wait = paced ? std::max(next_cycle - now, Clock::duration::zero()) : Clock::duration(kCycle);
      PollSockets(std::chrono::duration_cast<std::chrono::milliseconds>(wait));
      for (int agent : session_->TakeKicked()) DropAgent(agent, "killed by the trainer");
      const auto after = Clock::now();
      if (after >= next_status) {
        ReportStatus();
        next_status = after + std::chrono::seconds(10);
      }
      const bool due = paced ? after >= next_cycle : !idle && session_->ReadyToStep();
      if (!due) {
        if (!paced && !idle && options_.sync_timeout.count() > 0 && after - waiting_since > options_.sync_timeout) {
          for (int agent : session_->Waiting()) DropAgent(agent, "sent no (syn) within the sync timeout");
          waiting_since = after;
        }
        continue;
      }
      split_.waiting += Clock::now() - waiting_since;
      if (!RunCycle(stop)) return false;
      next_cycle = std::max(next_cycle + kCycle, Clock::now());  // late: no catching up
      waiting_since = Clock::now();
      if (end_cycles >= 0 && static_cast<int64_t>(session_->cycle()) >= end_cycles) break;
    }
    if (session_->quit_requested()) spdlog::info("a trainer sent (killsim): stopping");
    ReportStatus();
    return true;
  }

  SimSparkBridgeStats Stats() const {
    std::lock_guard<std::mutex> lock(stats_mutex_);
    return stats_;
  }

  SimSparkBridgeStats WaitForStats(const std::function<bool(const SimSparkBridgeStats&)>& done,
                                   std::chrono::milliseconds timeout) const {
    std::unique_lock<std::mutex> lock(stats_mutex_);
    stats_changed_.wait_for(lock, timeout, [&] { return done(stats_); });
    return stats_;
  }

 private:
  bool Attach(const std::function<bool()>& stop) {
    if (session_) {
      // turf-sim went away (or restarted): its world starts over, so do the
      // agents, as with a restarted rcssserver3d.
      for (auto& [fd, c] : clients_)
        if (!c.monitor) MarkDrop(fd, "turf-sim stopped answering; reconnect when it is back");
      FlushDrops();
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
    for (auto& [agent, message] : session_->TakeOutputs()) SendToAgent(agent, simspark::Frame(message));
    const std::string monitor = session_->TakeMonitorOutput();
    if (!monitor.empty()) {
      const std::string framed = simspark::Frame(monitor);
      for (auto& [fd, c] : clients_)
        if (c.monitor) Send(fd, framed);
    }
    FlushDrops();
    split_.bridge += Clock::now() - stepped;
    ReportIssues();
    std::lock_guard<std::mutex> lock(stats_mutex_);
    stats_.cycles = session_->cycle();
    stats_.sim_time = sim_time;
    stats_.agents = session_->agents();
    stats_changed_.notify_all();
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
    std::lock_guard<std::mutex> lock(stats_mutex_);
    if (stats_.refused == rejects_.Total()) return;
    stats_.refused = rejects_.Total();
    stats_.refused_by_kind = rejects_.counts();
    stats_changed_.notify_all();
  }

  void PollSockets(std::chrono::milliseconds timeout) {
    std::vector<pollfd> fds;
    fds.push_back({agent_listener_.fd(), POLLIN, 0});
    fds.push_back({monitor_listener_.fd(), POLLIN, 0});
    for (const auto& [fd, c] : clients_)
      fds.push_back({fd, static_cast<short>(POLLIN | (c.peer->pending() > 0 ? POLLOUT : 0)), 0});
    const int n = poll(fds.data(), fds.size(), static_cast<int>(std::max<int64_t>(0, timeout.count())));
    if (n <= 0) return;
    if (fds[0].revents & POLLIN) AcceptAll(&agent_listener_, false);
    if (fds[1].revents & POLLIN) AcceptAll(&monitor_listener_, true);
    for (size_t i = 2; i < fds.size(); ++i) {
      if (fds[i].revents == 0) continue;
      auto it = clients_.find(fds[i].fd);
      if (it == clients_.end()) continue;
      std::string error;
      if ((fds[i].revents & POLLOUT) && !it->second.peer->Flush(&error)) {
        MarkDrop(fds[i].fd, error);
        continue;
      }
      if (fds[i].revents & (POLLIN | POLLHUP | POLLERR)) ReadClient(fds[i].fd);
    }
    FlushDrops();
    ReportIssues();
  }

  void AcceptAll(TcpListener* listener, bool monitor) {
    std::string address;
    for (int fd = listener->Accept(&address); fd >= 0; fd = listener->Accept(&address)) {
      setsockopt(fd, SOL_SOCKET, SO_SNDBUF, &kSendBuffer, sizeof(kSendBuffer));
      auto peer = std::make_unique<TcpPeer>(fd, address, options_.max_unsent);
      if (clients_.size() >= options_.max_clients) {
        rejects_.Reject("too_many_clients", fmt::format("{} refused: {} clients connected", address, clients_.size()));
        continue;  // the peer's destructor closes it
      }
      Client c{std::move(peer), simspark::FrameDecoder(), monitor, -1};
      if (monitor) {
        if (operators_.Allows(address)) c.role = simspark::TrainerRole::kOperator;
        connections_.Reject("monitor_connected", fmt::format("{} ({})", address, RoleName(c.role)));
        const std::string greeting = simspark::Frame(session_->MonitorGreeting());
        clients_.emplace(fd, std::move(c));
        Send(fd, greeting);
      } else {
        c.agent = session_->Connect();
        connections_.Reject("agent_connected", fmt::format("agent {} from {}", c.agent, address));
        clients_.emplace(fd, std::move(c));
        std::lock_guard<std::mutex> lock(stats_mutex_);
        stats_.agents = session_->agents();
        stats_changed_.notify_all();
      }
    }
  }

  void ReadClient(int fd) {
    Client& c = clients_.at(fd);
    std::string bytes;
    std::string error;
    const bool open = c.peer->Read(&bytes, kMaxReadPerPoll, &error);
    c.decoder.Feed(bytes.data(), bytes.size());
    while (auto payload = c.decoder.Next()) {
      if (c.monitor) {
        session_->Trainer(*payload, c.role);
      } else {
        session_->Receive(c.agent, *payload);
      }
    }
    if (c.decoder.error() != simspark::FrameError::kOk) {
      rejects_.Reject("frame_too_large",
                      fmt::format("{}: a length prefix above {} bytes", c.peer->address(), simspark::kMaxAgentPayload));
      MarkDrop(fd, "sent an oversized frame");
    } else if (!open) {
      MarkDrop(fd, error);
    }
  }

  void Send(int fd, const std::string& framed) {
    auto it = clients_.find(fd);
    if (it == clients_.end()) return;
    std::string error;
    if (!it->second.peer->Write(framed, &error)) MarkDrop(fd, error);
  }

  void SendToAgent(int agent, const std::string& framed) {
    for (auto& [fd, c] : clients_) {
      if (c.agent == agent) {
        Send(fd, framed);
        return;
      }
    }
  }

  void DropAgent(int agent, const std::string& why) {
    for (auto& [fd, c] : clients_)
      if (c.agent == agent) MarkDrop(fd, why);
    FlushDrops();
  }

  void MarkDrop(int fd, const std::string& why) { drops_.emplace_back(fd, why); }

  void FlushDrops() {
    for (const auto& [fd, why] : drops_) {
      auto it = clients_.find(fd);
      if (it == clients_.end()) continue;
      if (it->second.monitor) {
        connections_.Reject("monitor_left", fmt::format("{}: {}", it->second.peer->address(), why));
      } else {
        connections_.Reject("agent_left",
                            fmt::format("agent {} ({}): {}", it->second.agent, it->second.peer->address(), why));
        session_->Disconnect(it->second.agent);
      }
      clients_.erase(it);
      std::lock_guard<std::mutex> lock(stats_mutex_);
      ++stats_.dropped_clients;
      stats_.agents = session_->agents();
      stats_changed_.notify_all();
    }
    drops_.clear();
  }

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
  TcpListener agent_listener_;
  TcpListener monitor_listener_;
  AddressAllowlist operators_;
  std::unique_ptr<simspark::Session> session_;
  std::map<int, Client> clients_;
  std::vector<std::pair<int, std::string>> drops_;
  uint32_t steps_ = 4;
  struct {
    Clock::duration world{}, bridge{}, waiting{};
    uint64_t cycles = 0;
  } split_;
  RejectLog rejects_;
  RejectLog connections_;  // clients connecting and leaving (LogLine::kEvent)
  mutable std::mutex stats_mutex_;
  mutable std::condition_variable stats_changed_;
  SimSparkBridgeStats stats_;
};

SimSparkBridge::SimSparkBridge(SimSparkBridgeOptions options)
    : impl_(std::make_unique<Impl>(std::move(options), nullptr)) {}
SimSparkBridge::SimSparkBridge(SimSparkBridgeOptions options, dds::Bus& bus)
    : impl_(std::make_unique<Impl>(std::move(options), &bus)) {}
SimSparkBridge::~SimSparkBridge() = default;
uint16_t SimSparkBridge::agent_port() const { return impl_->agent_port(); }
uint16_t SimSparkBridge::monitor_port() const { return impl_->monitor_port(); }
bool SimSparkBridge::Run(const std::function<bool()>& stop) { return impl_->Run(stop); }
SimSparkBridgeStats SimSparkBridge::Stats() const { return impl_->Stats(); }
SimSparkBridgeStats SimSparkBridge::WaitForStats(const std::function<bool(const SimSparkBridgeStats&)>& done,
                                                 std::chrono::milliseconds timeout) const {
  return impl_->WaitForStats(done, timeout);
}

}  // namespace turf
