#include "participants/rcssservermj_bridge/rcssservermj_bridge.h"

#include <poll.h>
#include <spdlog/spdlog.h>
#include <sys/socket.h>

#include <algorithm>
#include <cmath>
#include <condition_variable>
#include <mutex>
#include <stdexcept>
#include <vector>

#include "codecs/rcssservermj/session.h"
#include "codecs/simspark/framing.h"
#include "participants/common/address_allowlist.h"
#include "participants/common/process.h"
#include "participants/common/tcp.h"
#include "participants/rcssservermj_bridge/legged_link.h"

namespace turf {

namespace {

using Clock = std::chrono::steady_clock;
constexpr auto kCycle = std::chrono::milliseconds(20);
constexpr int kSendBuffer = 128 * 1024;
constexpr size_t kMaxReadPerPoll = 1 << 18;
constexpr auto kConnectionLogInterval = std::chrono::seconds(1);

struct Client {
  std::unique_ptr<TcpPeer> peer;
  simspark::FrameDecoder decoder;  // RCSSServerMJ frames exactly as SimSpark does
  bool monitor = false;
  int agent = -1;
};

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
        rejects_("RCSSServerMJ input"),
        connections_("RCSSServerMJ client", kConnectionLogInterval, LogLine::kEvent) {
    if (options_.sequential || !options_.realtime) options_.sync_mode = true;
    rcssservermj::SessionOptions check;
    check.rules = options_.rules;
    check.field = options_.field;
    rcssservermj::Session probe(check, {});  // throws std::invalid_argument for a bad rule book or field
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
    spdlog::info("RCSSServerMJ agents: TCP {}:{}; monitor commands: TCP {}:{}; {}{}{}", options_.listen, agent_port(),
                 options_.listen, monitor_port(), options_.realtime ? "real time" : "as fast as possible",
                 options_.sync_mode ? ", sync mode" : "", options_.sequential ? ", sequential loop" : "");
    spdlog::info("monitor-port clients allowed from: {}", monitor_allow_.Describe());
    auto next_cycle = Clock::now();
    auto waiting_since = Clock::now();
    auto next_status = Clock::now() + std::chrono::seconds(10);
    const int64_t end_cycles =
        options_.duration > 0 ? std::llround(options_.duration / rcssservermj::kCycleSeconds) : -1;
    while (!stop() && !session_->quit_requested()) {
      const bool idle = options_.sync_mode && session_->active_agents() == 0 && !session_->HasPendingInit();
      const auto now = Clock::now();
      Clock::duration wait = kCycle;
      if (options_.realtime) wait = std::max(next_cycle - now, Clock::duration::zero());
      if (options_.sync_mode && !idle && session_->ReadyToStep() && !options_.realtime) wait = Clock::duration::zero();
      PollSockets(std::chrono::duration_cast<std::chrono::milliseconds>(wait));
      for (int agent : session_->TakeKicked()) DropAgent(agent, "closed by the server");
      ReportIssues();
      const auto after = Clock::now();
      if (after >= next_status) {
        ReportStatus();
        next_status = after + std::chrono::seconds(10);
      }
      const bool time_ok = !options_.realtime || after >= next_cycle;
      const bool agents_ok = !options_.sync_mode || (!idle && session_->ReadyToStep());
      if (!(time_ok && agents_ok)) {
        if (options_.sync_mode && !idle && after - waiting_since > options_.agent_timeout) {
          for (int agent : session_->Waiting()) DropAgent(agent, "sent no message within the agent timeout");
          waiting_since = after;
        }
        continue;
      }
      if (!RunCycle(stop)) return false;
      next_cycle = std::max(next_cycle + kCycle, Clock::now());  // late: no catching up
      waiting_since = Clock::now();
      if (end_cycles >= 0 && static_cast<int64_t>(session_->cycle()) >= end_cycles) break;
    }
    if (session_->quit_requested()) spdlog::info("a monitor sent (killsim): stopping");
    ReportStatus();
    return true;
  }

  RcssServerMjStats Stats() const {
    std::lock_guard<std::mutex> lock(stats_mutex_);
    return stats_;
  }

  RcssServerMjStats WaitForStats(const std::function<bool(const RcssServerMjStats&)>& done,
                                 std::chrono::milliseconds timeout) const {
    std::unique_lock<std::mutex> lock(stats_mutex_);
    stats_changed_.wait_for(lock, timeout, [&] { return done(stats_); });
    return stats_;
  }

 private:
  bool Attach(const std::function<bool()>& stop) {
    if (session_) {
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

  bool RunCycle(const std::function<bool()>& stop) {
    std::string error;
    std::vector<std::string> warnings;
    const rcssservermj::WorldRequests requests = session_->TakeRequests();
    for (int agent : session_->TakeKicked()) DropAgent(agent, "closed by the server");
    auto world = link_.Cycle(requests, steps_, options_.step_timeout, stop, &error, &warnings);
    for (const std::string& w : warnings) spdlog::warn("turf-sim refused {}", w);
    if (!world) {
      if (stop()) return true;
      spdlog::error("{}; attaching again", error);
      return Attach(stop) || stop();
    }
    const double sim_time = world->time;
    session_->Advance(std::move(*world));
    for (auto& [agent, message] : session_->TakeOutputs()) SendToAgent(agent, simspark::Frame(message));
    FlushDrops();
    ReportIssues();
    std::lock_guard<std::mutex> lock(stats_mutex_);
    stats_.cycles = session_->cycle();
    stats_.sim_time = sim_time;
    stats_.agents = session_->agents();
    stats_.active_agents = session_->active_agents();
    stats_changed_.notify_all();
    return true;
  }

  void ReportIssues() {
    for (const rcssservermj::SessionIssue& issue : session_->TakeIssues())
      rejects_.Reject(issue.kind, issue.agent < 0 ? "monitor: " + issue.detail
                                                  : fmt::format("agent {}: {}", issue.agent, issue.detail));
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
  }

  void AcceptAll(TcpListener* listener, bool monitor) {
    std::string address;
    for (int fd = listener->Accept(&address); fd >= 0; fd = listener->Accept(&address)) {
      setsockopt(fd, SOL_SOCKET, SO_SNDBUF, &kSendBuffer, sizeof(kSendBuffer));
      auto peer = std::make_unique<TcpPeer>(fd, address, options_.max_unsent);
      if (clients_.size() >= options_.max_clients) {
        rejects_.Reject("too_many_clients", fmt::format("{} refused: {} clients connected", address, clients_.size()));
        continue;
      }
      if (monitor && !monitor_allow_.Allows(address)) {
        rejects_.Reject("monitor_not_allowed", fmt::format("{} refused: not in the monitor allowlist ({})", address,
                                                           monitor_allow_.Describe()));
        continue;  // the peer's destructor closes it
      }
      Client c{std::move(peer), simspark::FrameDecoder(), monitor, -1};
      if (!monitor) c.agent = session_->Connect();
      connections_.Reject(monitor ? "monitor_connected" : "agent_connected",
                          monitor ? address : fmt::format("agent {} from {}", c.agent, address));
      clients_.emplace(fd, std::move(c));
      std::lock_guard<std::mutex> lock(stats_mutex_);
      stats_.agents = session_->agents();
      stats_changed_.notify_all();
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
        session_->Monitor(*payload);
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
      stats_.active_agents = session_->active_agents();
      stats_changed_.notify_all();
    }
    drops_.clear();
  }

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
  TcpListener agent_listener_;
  TcpListener monitor_listener_;
  AddressAllowlist monitor_allow_;
  std::unique_ptr<rcssservermj::Session> session_;
  std::map<int, Client> clients_;
  std::vector<std::pair<int, std::string>> drops_;
  uint32_t steps_ = 4;
  RejectLog rejects_;
  RejectLog connections_;
  mutable std::mutex stats_mutex_;
  mutable std::condition_variable stats_changed_;
  RcssServerMjStats stats_;
};

RcssServerMjBridge::RcssServerMjBridge(RcssServerMjOptions options)
    : impl_(std::make_unique<Impl>(std::move(options), nullptr)) {}
RcssServerMjBridge::RcssServerMjBridge(RcssServerMjOptions options, dds::Bus& bus)
    : impl_(std::make_unique<Impl>(std::move(options), &bus)) {}
RcssServerMjBridge::~RcssServerMjBridge() = default;
uint16_t RcssServerMjBridge::agent_port() const { return impl_->agent_port(); }
uint16_t RcssServerMjBridge::monitor_port() const { return impl_->monitor_port(); }
bool RcssServerMjBridge::Run(const std::function<bool()>& stop) { return impl_->Run(stop); }
RcssServerMjStats RcssServerMjBridge::Stats() const { return impl_->Stats(); }
RcssServerMjStats RcssServerMjBridge::WaitForStats(const std::function<bool(const RcssServerMjStats&)>& done,
                                                   std::chrono::milliseconds timeout) const {
  return impl_->WaitForStats(done, timeout);
}

}  // namespace turf
