// What the TCP and UDP sockets share: an owned file descriptor (closed once,
// by its last owner; a move hands it on), errno as text, the bound port.
#pragma once

#include <cstdint>
#include <string>
#include <utility>

namespace turf {

class SocketFd {
 public:
  SocketFd() = default;
  explicit SocketFd(int fd) : fd_(fd) {}
  ~SocketFd() { Close(); }
  SocketFd(SocketFd&& other) noexcept : fd_(std::exchange(other.fd_, -1)) {}
  SocketFd& operator=(SocketFd&& other) noexcept {
    if (this != &other) {
      Close();
      fd_ = std::exchange(other.fd_, -1);
    }
    return *this;
  }
  SocketFd(const SocketFd&) = delete;
  SocketFd& operator=(const SocketFd&) = delete;

  int get() const { return fd_; }
  bool valid() const { return fd_ >= 0; }

 private:
  void Close();
  int fd_ = -1;
};

// "what: <strerror(errno)>".
std::string ErrnoText(const std::string& what);
// The local port `fd` is bound to; 0 if it cannot be read.
uint16_t BoundPort(int fd);

}  // namespace turf
