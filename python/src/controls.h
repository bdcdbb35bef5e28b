// The control operations both Python kernels share, validated by the same
// functions turf-sim uses for its control topic: a STEP's count
// (kernel/time_control.h, as in lockstep), a realism change
// (loader/realism_change.h).
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/sensor_realism.h"

namespace turf::py {

// Throws SimError (out_of_range) unless 1 <= n <= kMaxStepRequest.
void CheckStepCount(int64_t n);

// The realism `current` becomes with a preset (a name in configs/realism/;
// empty: none) and named values ("camera.link.latency", core/realism_fields.h),
// all or nothing. Throws SimError: unknown_key for a name no parameter has,
// else ApplyRealismChange's error (unknown_preset, not_finite, out_of_range,
// unknown_enum, invalid_realism).
SensorRealism ChangedRealism(const SensorRealism& current, const std::string& preset,
                             const std::vector<std::pair<std::string, double>>& values);

}  // namespace turf::py
