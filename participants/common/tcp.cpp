#include "participants/common/tcp.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace turf {

namespace {

bool SetNonBlocking(int fd) {
  const int flags = fcntl(fd, F_GETFL, 0);
  return flags >= 0 && fcntl(fd, F_SETFL, flags | O_NONBLOCK) == 0;
}

}  // namespace

TcpPeer::TcpPeer(int fd, std::string address, size_t max_pending)
    : fd_(fd), address_(std::move(address)), max_pending_(max_pending) {}

bool TcpPeer::Read(std::string* out, size_t max, std::string* error) {
  char buffer[16384];
  size_t total = 0;
  while (total < max) {
    const ssize_t n = recv(fd_.get(), buffer, sizeof(buffer), 0);
    if (n > 0) {
      out->append(buffer, static_cast<size_t>(n));
      total += static_cast<size_t>(n);
      continue;
    }
    if (n == 0) {
      *error = "closed by the peer";
      return false;
    }
    if (errno == EINTR) continue;
    if (errno == EAGAIN || errno == EWOULDBLOCK) return true;
    *error = ErrnoText("recv");
    return false;
  }
  return true;
}

bool TcpPeer::Write(const std::string& bytes, std::string* error) {
  if (pending() + bytes.size() > max_pending_) {
    *error = "the peer stopped reading (" + std::to_string(pending()) + " bytes unsent)";
    return false;
  }
  if (sent_ > 0 && sent_ == out_.size()) {
    out_.clear();
    sent_ = 0;
  }
  out_ += bytes;
  return Flush(error);
}

bool TcpPeer::Flush(std::string* error) {
  while (sent_ < out_.size()) {
    const ssize_t n = send(fd_.get(), out_.data() + sent_, out_.size() - sent_, MSG_NOSIGNAL);
    if (n > 0) {
      sent_ += static_cast<size_t>(n);
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) break;
    *error = ErrnoText("send");
    return false;
  }
  if (sent_ == out_.size()) {
    out_.clear();
    sent_ = 0;
  } else if (sent_ > (1u << 20)) {
    out_.erase(0, sent_);
    sent_ = 0;
  }
  return true;
}

std::optional<TcpListener> TcpListener::Listen(const std::string& ip, uint16_t port, std::string* error) {
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_port = htons(port);
  if (inet_pton(AF_INET, ip.c_str(), &addr.sin_addr) != 1) {
    *error = "not an IPv4 address: " + ip;
    return std::nullopt;
  }
  const int fd = socket(AF_INET, SOCK_STREAM, 0);
  if (fd < 0) {
    *error = ErrnoText("socket");
    return std::nullopt;
  }
  TcpListener listener(fd);
  const int one = 1;
  setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof(one));
  if (bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof(addr)) != 0) {
    *error = ErrnoText("bind " + ip + ":" + std::to_string(port));
    return std::nullopt;
  }
  if (listen(fd, 64) != 0 || !SetNonBlocking(fd)) {
    *error = ErrnoText("listen");
    return std::nullopt;
  }
  return listener;
}

int TcpListener::Accept(std::string* address) {
  sockaddr_in addr{};
  socklen_t len = sizeof(addr);
  const int fd = accept(fd_.get(), reinterpret_cast<sockaddr*>(&addr), &len);
  if (fd < 0) return -1;
  if (!SetNonBlocking(fd)) {
    close(fd);
    return -1;
  }
  const int one = 1;
  setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof(one));
  char ip[INET_ADDRSTRLEN] = {0};
  inet_ntop(AF_INET, &addr.sin_addr, ip, sizeof(ip));
  *address = std::string(ip) + ":" + std::to_string(ntohs(addr.sin_port));
  return fd;
}

}  // namespace turf
