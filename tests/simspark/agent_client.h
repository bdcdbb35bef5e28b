// A scripted SimSpark agent's connection for tests and benchmarks: blocking
// TCP with timeouts and the 4-byte big-endian length framing.
#pragma once

#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>

#include "tests/support/tcp_connect.h"

namespace turf::test {

class AgentClient : public LoopbackClient {
 public:
  AgentClient() = default;
  AgentClient(AgentClient&& o) noexcept : LoopbackClient(std::move(o)), in_(std::move(o.in_)) {}

  // To 127.0.0.1:port, from `source` when given (tests/support/tcp_connect.h).
  bool Connect(uint16_t port, const char* source = nullptr) { return OpenSocket(port, source); }
  void Close() { CloseSocket(); }
  bool Send(const std::string& payload) { return SendRaw(Framed(payload)); }
  // The next message, or nullopt on timeout or a closed connection.
  std::optional<std::string> Receive(std::chrono::milliseconds timeout = std::chrono::milliseconds(5000)) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (true) {
      if (auto m = Next()) return m;
      const auto left =
          std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
      if (left.count() <= 0) return std::nullopt;
      pollfd p{fd_, POLLIN, 0};
      if (poll(&p, 1, static_cast<int>(left.count())) <= 0) continue;
      if (!ReadSome()) return Next();
    }
  }
  // Reads what is there without waiting; false once the peer closed.
  bool ReadSome() {
    char buffer[65536];
    const ssize_t n = recv(fd_, buffer, sizeof(buffer), MSG_DONTWAIT);
    if (n > 0) in_.append(buffer, static_cast<size_t>(n));
    return n > 0 || (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR));
  }
  // A complete buffered message, if any.
  std::optional<std::string> Next() {
    if (in_.size() < 4) return std::nullopt;
    uint32_t n = 0;
    std::memcpy(&n, in_.data(), 4);
    n = ntohl(n);
    if (in_.size() < 4 + n) return std::nullopt;
    std::string m = in_.substr(4, n);
    in_.erase(0, 4 + n);
    return m;
  }

 private:
  std::string in_;
};

}  // namespace turf::test
