// What every modelled stream (camera, radio, joint, IMU, touch) achieved over
// the last window of simulation time: the kernels' statistics output, which
// turf-sim publishes on its stats topic.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/stream_stats.h"

namespace turf {

inline constexpr int64_t kStatsWindowNs = 1'000'000'000;

struct StreamReport {
  int64_t time_ns = 0;
  double window_s = kStatsWindowNs * 1e-9;
  std::vector<std::pair<std::string, StreamWindow>> streams;
};

}  // namespace turf
