// Why the SSL-Vision codec refused an input: errors are values with names,
// never exceptions. A caller counts them per kind (RejectLog) and drops the
// sample; nothing half-encoded is ever sent.
#pragma once

#include <cstdint>

#include "core/errors.h"

namespace turf::vision {

// turf's one taxonomy (core/errors.h). The codec answers kNotFinite, kOutOfRange,
// kNonPositiveSize, kBadRobotId, kUnknownTeam, kTooMany, kTimeNotPositive,
// kTimeOrder, kNoEpoch (run clock: no run epoch from turf-sim yet) and kBadEpoch.
// Stable snake_case name, for logs and per-kind counters ("not_finite", ...).
using VisionError = turf::Error;
inline const char* VisionErrorName(VisionError error) { return turf::ErrorName(error); }

}  // namespace turf::vision
