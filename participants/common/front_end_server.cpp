#include "participants/common/front_end_server.h"

#include <poll.h>
#include <spdlog/spdlog.h>
#include <sys/socket.h>

#include <algorithm>
#include <set>
#include <stdexcept>

namespace turf {

namespace {

constexpr int kSendBuffer = 128 * 1024;  // kernel buffer per client (bounds what a stalled client holds)
constexpr size_t kMaxReadPerPoll = 1 << 18;
constexpr auto kConnectionLogInterval = std::chrono::seconds(1);  // per kind of connection line

}  // namespace

FrontEndServer::FrontEndServer(const Options& options, const std::string& connection_log, RejectLog* rejects,
                               Hooks hooks)
    : options_(options),
      rejects_(rejects),
      hooks_(std::move(hooks)),
      connections_(connection_log, kConnectionLogInterval, LogLine::kEvent) {
  std::vector<uint16_t> agents{options_.agent_port};
  agents.insert(agents.end(), options_.more_agent_ports.begin(), options_.more_agent_ports.end());
  std::string error;
  for (uint16_t port : agents) {
    auto listener = TcpListener::Listen(options_.listen, port, &error);
    if (!listener) throw std::runtime_error("agent port: " + error);
    listeners_.push_back({std::move(*listener), false});
  }
  if (!options_.monitor) return;
  auto monitors = TcpListener::Listen(options_.listen, options_.monitor_port, &error);
  if (!monitors) throw std::runtime_error("monitor port: " + error);
  listeners_.push_back({std::move(*monitors), true});
}

uint16_t FrontEndServer::monitor_port() const {
  return listeners_.back().monitor ? listeners_.back().socket.LocalPort() : 0;
}

std::vector<uint16_t> FrontEndServer::agent_ports() const {
  std::vector<uint16_t> ports;
  for (const Listener& l : listeners_)
    if (!l.monitor) ports.push_back(l.socket.LocalPort());
  return ports;
}

bool FrontEndServer::Poll(std::chrono::milliseconds timeout) {
  std::vector<pollfd> fds;
  for (const Listener& l : listeners_) fds.push_back({l.socket.fd(), POLLIN, 0});
  for (const auto& [fd, c] : clients_)
    fds.push_back({fd, static_cast<short>(POLLIN | (c.peer->pending() > 0 ? POLLOUT : 0)), 0});
  const int n = poll(fds.data(), fds.size(), static_cast<int>(std::max<int64_t>(0, timeout.count())));
  if (n <= 0) return false;
  for (size_t i = 0; i < listeners_.size(); ++i)
    if (fds[i].revents & POLLIN) AcceptAll(&listeners_[i]);
  for (size_t i = listeners_.size(); i < fds.size(); ++i) {
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
  return true;
}

void FrontEndServer::AcceptAll(Listener* listener) {
  std::string address;
  const bool monitor = listener->monitor;
  for (int fd = listener->socket.Accept(&address); fd >= 0; fd = listener->socket.Accept(&address)) {
    setsockopt(fd, SOL_SOCKET, SO_SNDBUF, &kSendBuffer, sizeof(kSendBuffer));
    auto peer = std::make_unique<TcpPeer>(fd, address, options_.max_unsent);
    if (LiveClients() >= options_.max_clients) {
      rejects_->Reject("too_many_clients", fmt::format("{} refused: {} clients connected", address, LiveClients()));
      continue;  // the peer's destructor closes it
    }
    FrontEndClient c{std::move(peer), simspark::FrameDecoder(), monitor, -1, 0, listener->socket.LocalPort()};
    std::string greeting;
    if (!hooks_.admit(c, address, &greeting)) continue;
    clients_.emplace(fd, std::move(c));
    if (!greeting.empty()) Send(fd, greeting);
  }
}

size_t FrontEndServer::LiveClients() const {
  std::set<int> leaving;
  for (const auto& [fd, why] : drops_)
    if (clients_.count(fd) != 0) leaving.insert(fd);
  return clients_.size() - leaving.size();
}

void FrontEndServer::ReadClient(int fd) {
  FrontEndClient& c = clients_.at(fd);
  std::string bytes;
  std::string error;
  const bool open = c.peer->Read(&bytes, kMaxReadPerPoll, &error);
  c.decoder.Feed(bytes.data(), bytes.size());
  while (auto payload = c.decoder.Next()) hooks_.message(c, *payload);
  if (c.decoder.error() != simspark::FrameError::kOk) {
    rejects_->Reject("frame_too_large",
                     fmt::format("{}: a length prefix above {} bytes", c.peer->address(), simspark::kMaxAgentPayload));
    MarkDrop(fd, "sent an oversized frame");
  } else if (!open) {
    MarkDrop(fd, error);
  }
}

void FrontEndServer::Send(int fd, const std::string& framed) {
  auto it = clients_.find(fd);
  if (it == clients_.end()) return;
  std::string error;
  if (!it->second.peer->Write(framed, &error)) MarkDrop(fd, error);
}

void FrontEndServer::SendToAgent(int agent, const std::string& framed) {
  for (auto& [fd, c] : clients_) {
    if (c.agent == agent) {
      Send(fd, framed);
      return;
    }
  }
}

void FrontEndServer::DropAgent(int agent, const std::string& why) {
  for (auto& [fd, c] : clients_)
    if (c.agent == agent) MarkDrop(fd, why);
  FlushDrops();
}

void FrontEndServer::FlushDrops() {
  for (const auto& [fd, why] : drops_) {
    auto it = clients_.find(fd);
    if (it == clients_.end()) continue;
    const FrontEndClient& c = it->second;
    if (c.monitor) {
      connections_.Reject("monitor_left", fmt::format("{}: {}", c.peer->address(), why));
    } else {
      connections_.Reject("agent_left", fmt::format("agent {} ({}): {}", c.agent, c.peer->address(), why));
    }
    hooks_.left(c);
    clients_.erase(it);
  }
  drops_.clear();
}

}  // namespace turf
