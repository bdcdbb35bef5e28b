// Non-blocking TCP for participants that serve many clients from one poll
// loop (IPv4, RAII). A TcpPeer buffers what it could not send yet up to a
// limit: a client that stops reading is reported (WriteOverflow) instead of
// blocking the server. Errors come back as strings; nothing throws.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "core/pinned.h"
#include "participants/common/socket_fd.h"

namespace turf {

class TcpPeer : Pinned {
 public:
  TcpPeer(int fd, std::string address, size_t max_pending);

  int fd() const { return fd_.get(); }
  const std::string& address() const { return address_; }
  // Reads what is available (up to `max` bytes) into `out` (appended).
  // false: the peer closed or failed (error says why).
  bool Read(std::string* out, size_t max, std::string* error);
  // Queues bytes and sends as much as the socket takes. false: the peer
  // failed, or more than max_pending bytes wait (it stopped reading).
  bool Write(const std::string& bytes, std::string* error);
  bool Flush(std::string* error);  // sends queued bytes
  size_t pending() const { return out_.size() - sent_; }

 private:
  SocketFd fd_;
  std::string address_;
  size_t max_pending_;
  std::string out_;
  size_t sent_ = 0;
};

class TcpListener {
 public:
  TcpListener() = default;

  // Listening on ip:port (port 0: any free port), non-blocking.
  static std::optional<TcpListener> Listen(const std::string& ip, uint16_t port, std::string* error);
  // A new connection's fd (non-blocking, TCP_NODELAY) and address, or -1 when none waits.
  int Accept(std::string* address);
  int fd() const { return fd_.get(); }
  uint16_t LocalPort() const { return BoundPort(fd_.get()); }

 private:
  explicit TcpListener(int fd) : fd_(fd) {}
  SocketFd fd_;
};

}  // namespace turf
