// Which clock the SSL-Vision times are in, and the rules every sent time
// obeys. Pure: the caller passes the wall clock in.
//
//   kUnix (default, what real SSL-Vision sends): t_sent is the Unix time at
//     sending, passed in by the caller; t_capture = t_sent minus the frame's
//     simulated latency (sent_time_ns - capture_time_ns).
//   kSim: seconds of simulation time since the scene started (or last reset).
//
// Guarantees: every time is > 0 and t_sent >= t_capture. A frame that would
// break them (capture at or before sim time 0, sent before captured, a wall
// clock that is not a positive number) is refused with a named error.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "bridges/ssl_vision/detection.h"
#include "bridges/ssl_vision/errors.h"

namespace turf::vision {

enum class ClockMode : uint8_t { kUnix, kSim };

const char* ClockModeName(ClockMode mode);                         // "unix", "sim"
std::optional<ClockMode> ParseClockMode(const std::string& name);  // inverse of ClockModeName

class WireClock {
 public:
  explicit WireClock(ClockMode mode = ClockMode::kUnix) : mode_(mode) {}
  ClockMode mode() const { return mode_; }

  // A camera frame's t_capture and t_sent. `unix_now` (seconds since the Unix
  // epoch, at sending) is used in kUnix mode only.
  VisionError ForFrame(int64_t capture_time_ns, int64_t sent_time_ns, double unix_now, FrameTimes* out) const;

  // A tracked frame's timestamp: `unix_now` or the world state's sim time.
  VisionError ForState(int64_t sim_time_ns, double unix_now, double* out) const;

 private:
  ClockMode mode_;
};

}  // namespace turf::vision
