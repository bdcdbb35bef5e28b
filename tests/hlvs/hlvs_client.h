// A scripted HLVS team program for tests: TCP to 127.0.0.1 (optionally from another loopback address), the 8-byte
// greeting, framed ActuatorRequests out and SensorMeasurements in, parsed with turf's own hlvs.proto (the facts'
// field numbers), as the league's sample client does. Every read waits with a deadline.
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
#include <optional>
#include <string>

#include "codecs/proto/hlvs.pb.h"

#include "tests/support/tcp_connect.h"

namespace turf::test {

class HlvsClient : public LoopbackClient {
 public:
  using Clock = std::chrono::steady_clock;

  // To 127.0.0.1:port, from `source` when given (tests/support/tcp_connect.h).
  bool Connect(uint16_t port, const char* source = nullptr) {
    Close();
    return OpenSocket(port, source);
  }
  void Close() {
    CloseSocket();
    in_.clear();
    closed_ = false;
  }

  // The 8 greeting bytes ("Welcome\0" / "Refused\0"), or what came before the deadline or the close.
  std::string Greeting(std::chrono::milliseconds timeout = std::chrono::seconds(20)) {
    const auto deadline = Clock::now() + timeout;
    while (in_.size() < 8 && Fill(deadline)) {
    }
    const std::string g = in_.substr(0, 8);
    in_.erase(0, g.size());
    return g;
  }

  bool Send(const hlvs::pb::ActuatorRequests& r) { return SendRaw(Framed(r.SerializeAsString())); }

  // The next SensorMeasurements; nullopt on timeout, a close, or bytes that do not parse (then bad() is true).
  std::optional<hlvs::pb::SensorMeasurements> Receive(std::chrono::milliseconds timeout = std::chrono::seconds(20)) {
    const auto deadline = Clock::now() + timeout;
    while (true) {
      if (in_.size() >= 4) {
        const auto* b = reinterpret_cast<const unsigned char*>(in_.data());
        const size_t n = (size_t{b[0]} << 24) | (size_t{b[1]} << 16) | (size_t{b[2]} << 8) | b[3];
        if (n == 0 || n > 1920 * 1080 * 3 + 1000) {  // the sample client's "out of sync"
          bad_ = true;
          return std::nullopt;
        }
        if (in_.size() >= 4 + n) {
          hlvs::pb::SensorMeasurements m;
          bad_ = !m.ParseFromArray(in_.data() + 4, static_cast<int>(n));
          in_.erase(0, 4 + n);
          if (bad_) return std::nullopt;
          return m;
        }
      }
      if (!Fill(deadline)) return std::nullopt;
    }
  }
  // True once the server closed the connection (after reading what it sent).
  bool WaitClosed(std::chrono::milliseconds timeout = std::chrono::seconds(20)) {
    const auto deadline = Clock::now() + timeout;
    while (!closed_ && Fill(deadline)) in_.clear();
    return closed_;
  }
  bool bad() const { return bad_; }

 private:
  // Reads more; false on the deadline or a close.
  bool Fill(Clock::time_point deadline) {
    while (true) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
      if (fd_ < 0 || closed_ || left.count() <= 0) return false;
      pollfd p{fd_, POLLIN, 0};
      if (poll(&p, 1, static_cast<int>(left.count())) <= 0) continue;
      char buffer[65536];
      const ssize_t n = recv(fd_, buffer, sizeof(buffer), MSG_DONTWAIT);
      if (n > 0) {
        in_.append(buffer, static_cast<size_t>(n));
        return true;
      }
      if (n == 0 || (errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)) {
        closed_ = true;
        return false;
      }
    }
  }

  std::string in_;
  bool closed_ = false;
  bool bad_ = false;
};

}  // namespace turf::test
