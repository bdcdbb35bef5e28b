// Source-address allowlists (IPv4 or IPv6 ranges), one home for every bridge: the SimSpark monitor port's
// operators (who may end, restart or rewrite a match), and the SSL bridges' per-team and operator lists
// (source_gate.h). Pure: no sockets.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace turf {

// One range: "ADDR" (that address alone) or "ADDR/PREFIX" (PREFIX 0..32 for IPv4, 0..128 for IPv6).
struct AddressRange {
  bool v6 = false;
  std::array<uint8_t, 16> bytes{};  // network order; IPv4 in the first 4
  int prefix = 0;                   // leading bits that must match
};

// nullopt, with `error` saying why, for anything else (a host name, a bad prefix). Bits past the prefix are
// ignored: "10.1.2.3/8" is 10.0.0.0/8.
std::optional<AddressRange> ParseAddressRange(std::string_view text, std::string* error);

class AddressAllowlist {
 public:
  // Throws std::invalid_argument naming the first entry that does not parse.
  explicit AddressAllowlist(const std::vector<std::string>& entries);
  // `address`: a peer as turf's TCP reports it, "ip:port" ("[ip]:port" for IPv6), or a bare ip. An address that
  // does not parse is not allowed.
  bool Allows(std::string_view address) const;
  // An IPv4 address in host byte order (UdpEndpoint::ip()), without text on the way: the UDP bridges ask this per
  // datagram.
  bool AllowsIpv4(uint32_t ip) const;
  std::string Describe() const;  // the entries, comma-separated

 private:
  std::vector<AddressRange> ranges_;
  std::vector<std::string> entries_;
};

}  // namespace turf
