// Who may send to the SSL bridges' UDP ports: per-team and operator source allowlists (--blue-allow,
// --yellow-allow, --operator-allow on turf-grsim-bridge, turf-simproto-bridge and turf-sim --simproto). A list with
// no entries (its flag not given) lets anyone in, as before the lists existed. SourceGate::Admit is the one place a
// bridge refuses a datagram for its source: counted there and in the bridge's RejectLog, and logged at the
// RejectLog's limited rate with the address and the list's name.
#pragma once

#include <atomic>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "participants/common/address_allowlist.h"
#include "participants/common/process.h"
#include "participants/common/udp.h"

namespace turf {

// The lists as given on the command line: "ADDR" or "ADDR/PREFIX" each (IPv4: the UDP ports are IPv4); empty: anyone.
struct SourceAllowlists {
  std::vector<std::string> blue;
  std::vector<std::string> yellow;
  std::vector<std::string> operators;  // teleports, replacement, simulator control, sync steps
};

class SourceGate {
 public:
  // `name` says whose list it is in log lines ("blue", "yellow", "operator"). Throws std::invalid_argument naming
  // the first entry that does not parse.
  SourceGate(std::string name, const std::vector<std::string>& entries);
  SourceGate(const SourceGate&) = delete;
  SourceGate& operator=(const SourceGate&) = delete;

  bool Allows(const UdpEndpoint& from) const { return !list_ || list_->AllowsIpv4(from.ip()); }
  // Allows(from); if not, counts it here and in `rejects` as `kind` ("blue.not_allowed"), with a rate-limited line
  // "refused ... (<kind>): from <address>: not on the <name> allowlist (<entries>)". Thread-safe.
  bool Admit(const UdpEndpoint& from, RejectLog& rejects, const std::string& kind);
  // The same, counted as "<name>.not_allowed".
  bool Admit(const UdpEndpoint& from, RejectLog& rejects) { return Admit(from, rejects, kind_); }
  uint64_t refused() const { return refused_.load(); }
  const std::string& name() const { return name_; }
  std::string Describe() const;  // "anyone", or the entries

 private:
  const std::string name_;
  const std::string kind_;
  std::optional<AddressAllowlist> list_;  // none: anyone
  std::atomic<uint64_t> refused_{0};
};

// A bridge's three gates.
struct SourceGates {
  explicit SourceGates(const SourceAllowlists& lists)
      : blue("blue", lists.blue), yellow("yellow", lists.yellow), operators("operator", lists.operators) {}
  SourceGate& team(int team) { return team == 0 ? blue : yellow; }  // idl::Team: 0 blue, 1 yellow
  uint64_t refused() const { return blue.refused() + yellow.refused() + operators.refused(); }
  // One start-up line: who may send what (`operator_use` says what the operator list guards).
  void ReportStartup(const std::string& operator_use) const;

  SourceGate blue;
  SourceGate yellow;
  SourceGate operators;
};

}  // namespace turf
