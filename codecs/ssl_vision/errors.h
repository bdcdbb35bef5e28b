// Why the SSL-Vision codec refused an input: errors are values with names,
// never exceptions. A caller counts them per kind (RejectLog) and drops the
// sample; nothing half-encoded is ever sent.
#pragma once

#include <cstdint>

namespace turf::vision {

enum class VisionError : uint8_t {
  kOk = 0,
  kNotFinite,        // a NaN or infinite number
  kOutOfRange,       // a finite number outside what the wire or the world allows
  kNonPositiveSize,  // a field, ball, robot or camera size that is zero or negative
  kBadRobotId,       // robot id above 15
  kUnknownTeam,      // a team enum value that is neither blue nor yellow
  kTooMany,          // more balls, robots or cameras than one datagram should carry
  kTimeNotPositive,  // a wire time would be zero or negative
  kTimeOrder,        // sent before it was captured
  kNoEpoch,          // run clock: no run epoch from turf-sim yet (or not yet the one after a reset)
  kBadEpoch,         // run clock: a run epoch that is not a plausible Unix time
};

// Stable snake_case name, for logs and per-kind counters ("not_finite", ...).
const char* VisionErrorName(VisionError error);

}  // namespace turf::vision
