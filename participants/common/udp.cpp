#include "participants/common/udp.h"

#include <arpa/inet.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace turf {

namespace {
bool ParseIp(const std::string& ip, in_addr* out) { return inet_pton(AF_INET, ip.c_str(), out) == 1; }
}  // namespace

std::string UdpEndpoint::ToString() const {
  char buf[INET_ADDRSTRLEN] = "";
  inet_ntop(AF_INET, &addr.sin_addr, buf, sizeof(buf));
  return std::string(buf) + ":" + std::to_string(port());
}

std::optional<UdpEndpoint> MakeEndpoint(const std::string& ip, uint16_t port) {
  UdpEndpoint e;
  e.addr.sin_family = AF_INET;
  e.addr.sin_port = htons(port);
  if (!ParseIp(ip, &e.addr.sin_addr)) return std::nullopt;
  return e;
}

std::optional<UdpSocket> UdpSocket::Bind(const std::string& ip, uint16_t port, bool reuse, std::string* error) {
  const auto endpoint = MakeEndpoint(ip, port);
  if (!endpoint) {
    *error = "not an IPv4 address: " + ip;
    return std::nullopt;
  }
  const int fd = socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  if (fd < 0) {
    *error = ErrnoText("socket");
    return std::nullopt;
  }
  UdpSocket s(fd);
  const int one = 1;
  if (reuse && setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof(one)) != 0) {
    *error = ErrnoText("SO_REUSEADDR");
    return std::nullopt;
  }
  if (bind(fd, reinterpret_cast<const sockaddr*>(&endpoint->addr), sizeof(endpoint->addr)) != 0) {
    *error = ErrnoText("bind " + endpoint->ToString());
    return std::nullopt;
  }
  return s;
}

bool UdpSocket::JoinMulticast(const std::string& group, const std::string& interface_ip, std::string* error) {
  ip_mreq req{};
  if (!ParseIp(group, &req.imr_multiaddr) || !ParseIp(interface_ip, &req.imr_interface)) {
    *error = "bad multicast group or interface address";
    return false;
  }
  if (setsockopt(fd_.get(), IPPROTO_IP, IP_ADD_MEMBERSHIP, &req, sizeof(req)) != 0) {
    *error = ErrnoText("IP_ADD_MEMBERSHIP");
    return false;
  }
  return true;
}

bool UdpSocket::SetMulticastInterface(const std::string& interface_ip, std::string* error) {
  in_addr addr{};
  if (!ParseIp(interface_ip, &addr)) {
    *error = "bad interface address " + interface_ip;
    return false;
  }
  if (setsockopt(fd_.get(), IPPROTO_IP, IP_MULTICAST_IF, &addr, sizeof(addr)) != 0) {
    *error = ErrnoText("IP_MULTICAST_IF");
    return false;
  }
  return true;
}

bool UdpSocket::SetMulticastTtl(int ttl, std::string* error) {
  const unsigned char value = static_cast<unsigned char>(ttl);
  if (setsockopt(fd_.get(), IPPROTO_IP, IP_MULTICAST_TTL, &value, sizeof(value)) != 0) {
    *error = ErrnoText("IP_MULTICAST_TTL");
    return false;
  }
  return true;
}

bool UdpSocket::SetMulticastLoop(bool on, std::string* error) {
  const unsigned char value = on ? 1 : 0;
  if (setsockopt(fd_.get(), IPPROTO_IP, IP_MULTICAST_LOOP, &value, sizeof(value)) != 0) {
    *error = ErrnoText("IP_MULTICAST_LOOP");
    return false;
  }
  return true;
}

std::optional<Datagram> UdpSocket::Receive(size_t max_bytes, std::chrono::milliseconds timeout) {
  pollfd p{fd_.get(), POLLIN, 0};
  if (poll(&p, 1, static_cast<int>(timeout.count())) <= 0 || (p.revents & POLLIN) == 0) return std::nullopt;
  // Received into a buffer kept per thread, then copied at its size: a fresh zeroed max_bytes buffer per datagram
  // (64 KiB for most callers) cost more than the rest of a loopback round trip (memset and page faults).
  thread_local std::vector<uint8_t> buffer;
  if (buffer.size() < max_bytes) buffer.resize(max_bytes);
  Datagram d;
  socklen_t len = sizeof(d.from.addr);
  // MSG_TRUNC makes recvfrom return the datagram's real length.
  const ssize_t n =
      recvfrom(fd_.get(), buffer.data(), max_bytes, MSG_TRUNC, reinterpret_cast<sockaddr*>(&d.from.addr), &len);
  if (n < 0) return std::nullopt;
  d.size = static_cast<size_t>(n);
  d.truncated = d.size > max_bytes;
  d.bytes.assign(buffer.begin(), buffer.begin() + static_cast<ptrdiff_t>(std::min(d.size, max_bytes)));
  return d;
}

bool UdpSocket::SendTo(const std::vector<uint8_t>& bytes, const UdpEndpoint& to, std::string* error) {
  const ssize_t n =
      sendto(fd_.get(), bytes.data(), bytes.size(), 0, reinterpret_cast<const sockaddr*>(&to.addr), sizeof(to.addr));
  if (n != static_cast<ssize_t>(bytes.size())) {
    *error = ErrnoText("sendto " + to.ToString());
    return false;
  }
  return true;
}

}  // namespace turf
