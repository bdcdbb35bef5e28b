#include "participants/common/address_allowlist.h"

#include <arpa/inet.h>

#include <charconv>
#include <stdexcept>

namespace turf {

namespace {

// An IPv4 or IPv6 address alone (no port, no prefix).
std::optional<AddressRange> ParseAddress(std::string_view text) {
  const std::string s(text);
  AddressRange r;
  if (inet_pton(AF_INET, s.c_str(), r.bytes.data()) == 1) {
    r.prefix = 32;
    return r;
  }
  if (inet_pton(AF_INET6, s.c_str(), r.bytes.data()) == 1) {
    r.v6 = true;
    r.prefix = 128;
    return r;
  }
  return std::nullopt;
}

// The ip of "ip:port", "[ip]:port" or "ip".
std::string_view HostOf(std::string_view address) {
  if (!address.empty() && address.front() == '[') {
    const size_t close = address.find(']');
    return close == std::string_view::npos ? std::string_view() : address.substr(1, close - 1);
  }
  // One ':' is a port separator; more make a bare IPv6 address.
  const size_t colon = address.find(':');
  if (colon != std::string_view::npos && address.find(':', colon + 1) == std::string_view::npos)
    return address.substr(0, colon);
  return address;
}

bool Contains(const AddressRange& range, const AddressRange& address) {
  if (range.v6 != address.v6) return false;
  const int full_bytes = range.prefix / 8;
  for (int i = 0; i < full_bytes; ++i)
    if (range.bytes[i] != address.bytes[i]) return false;
  const int rest = range.prefix % 8;
  if (rest == 0) return true;
  const auto mask = static_cast<uint8_t>(0xFF << (8 - rest));
  return (range.bytes[full_bytes] & mask) == (address.bytes[full_bytes] & mask);
}

}  // namespace

std::optional<AddressRange> ParseAddressRange(std::string_view text, std::string* error) {
  const size_t slash = text.find('/');
  std::optional<AddressRange> range = ParseAddress(text.substr(0, slash));
  if (!range) {
    *error = "'" + std::string(text) + "' is not an IPv4 or IPv6 address[/prefix]";
    return std::nullopt;
  }
  if (slash == std::string_view::npos) return range;
  const std::string_view digits = text.substr(slash + 1);
  const int max = range->v6 ? 128 : 32;
  int prefix = -1;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), prefix);
  if (digits.empty() || ec != std::errc() || end != digits.data() + digits.size() || prefix < 0 || prefix > max) {
    *error = "'" + std::string(text) + "': the prefix must be 0.." + std::to_string(max);
    return std::nullopt;
  }
  range->prefix = prefix;
  return range;
}

AddressAllowlist::AddressAllowlist(const std::vector<std::string>& entries) : entries_(entries) {
  for (const std::string& entry : entries) {
    std::string error;
    const std::optional<AddressRange> range = ParseAddressRange(entry, &error);
    if (!range) throw std::invalid_argument("allowlist: " + error);
    ranges_.push_back(*range);
  }
}

bool AddressAllowlist::Allows(std::string_view address) const {
  const std::optional<AddressRange> peer = ParseAddress(HostOf(address));
  if (!peer) return false;
  for (const AddressRange& range : ranges_)
    if (Contains(range, *peer)) return true;
  return false;
}

bool AddressAllowlist::AllowsIpv4(uint32_t ip) const {
  AddressRange peer;
  peer.prefix = 32;
  for (int i = 0; i < 4; ++i) peer.bytes[i] = static_cast<uint8_t>(ip >> (24 - 8 * i));
  for (const AddressRange& range : ranges_)
    if (Contains(range, peer)) return true;
  return false;
}

std::string AddressAllowlist::Describe() const {
  std::string out;
  for (const std::string& entry : entries_) out += (out.empty() ? "" : ", ") + entry;
  return out.empty() ? "nobody" : out;
}

}  // namespace turf
