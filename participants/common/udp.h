// A UDP socket for the bridge participants (RAII, IPv4): bind, receive with a
// timeout (reporting truncation), send, and the multicast options SSL needs.
// Errors come back as strings for the caller to log; nothing throws.
#pragma once

#include <netinet/in.h>

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "participants/common/socket_fd.h"

namespace turf {

struct UdpEndpoint {
  sockaddr_in addr{};
  std::string ToString() const;
  uint32_t ip() const { return ntohl(addr.sin_addr.s_addr); }
  uint16_t port() const { return ntohs(addr.sin_port); }
};

// "a.b.c.d" and a port; nullopt if the address is not dotted IPv4.
std::optional<UdpEndpoint> MakeEndpoint(const std::string& ip, uint16_t port);

struct Datagram {
  std::vector<uint8_t> bytes;
  UdpEndpoint from;
  bool truncated = false;  // larger than the receive limit; bytes hold the start
  size_t size = 0;         // the datagram's real size
};

class UdpSocket {
 public:
  UdpSocket() = default;

  // A socket bound to ip:port (port 0: any free port). reuse: SO_REUSEADDR,
  // so several listeners can share a multicast port.
  static std::optional<UdpSocket> Bind(const std::string& ip, uint16_t port, bool reuse, std::string* error);

  bool JoinMulticast(const std::string& group, const std::string& interface_ip, std::string* error);
  bool SetMulticastInterface(const std::string& interface_ip, std::string* error);
  bool SetMulticastTtl(int ttl, std::string* error);
  bool SetMulticastLoop(bool on, std::string* error);

  // Waits up to `timeout` for one datagram; nullopt on timeout or error.
  std::optional<Datagram> Receive(size_t max_bytes, std::chrono::milliseconds timeout);
  bool SendTo(const std::vector<uint8_t>& bytes, const UdpEndpoint& to, std::string* error);
  uint16_t LocalPort() const { return BoundPort(fd_.get()); }
  bool valid() const { return fd_.valid(); }

 private:
  explicit UdpSocket(int fd) : fd_(fd) {}
  SocketFd fd_;
};

}  // namespace turf
