#include "python/src/controls.h"

#include <limits>

#include "core/realism_fields.h"
#include "kernel/time_control.h"
#include "loader/realism_change.h"
#include "python/src/sim_error.h"

namespace turf::py {

void CheckStepCount(int64_t n) {
  const TimeControl lockstep(TimeMode::kLockstep, 1.0, false);
  const bool fits = n > 0 && n <= std::numeric_limits<uint32_t>::max();
  Check(lockstep.CheckSteps(fits ? static_cast<uint32_t>(n) : 0), "step count " + std::to_string(n));
}

SensorRealism ChangedRealism(const SensorRealism& current, const std::string& preset,
                             const std::vector<std::pair<std::string, double>>& values) {
  RealismChange change;
  change.preset = preset;
  for (const auto& [name, value] : values) {
    const std::optional<RealismField> field = RealismFieldNamed(name);
    if (!field) Check(Error::kUnknownKey, "realism parameter '" + name + "'");
    change.values.push_back({static_cast<uint32_t>(*field), value});
  }
  const RealismChangeResult r = ApplyRealismChange(current, change);
  Check(r.error, "realism change (" + r.reason + ")");
  return r.realism;
}

}  // namespace turf::py
