#include "bridges/ssl_vision/timestamps.h"

#include <cmath>

namespace turf::vision {

namespace {

VisionError CheckWallClock(double unix_now) {
  if (!std::isfinite(unix_now)) return VisionError::kNotFinite;
  return unix_now > 0.0 ? VisionError::kOk : VisionError::kTimeNotPositive;
}

}  // namespace

const char* ClockModeName(ClockMode mode) { return mode == ClockMode::kSim ? "sim" : "unix"; }

std::optional<ClockMode> ParseClockMode(const std::string& name) {
  if (name == "unix") return ClockMode::kUnix;
  if (name == "sim") return ClockMode::kSim;
  return std::nullopt;
}

VisionError WireClock::ForFrame(int64_t capture_time_ns, int64_t sent_time_ns, double unix_now, FrameTimes* out) const {
  if (capture_time_ns <= 0) return VisionError::kTimeNotPositive;
  if (sent_time_ns < capture_time_ns) return VisionError::kTimeOrder;
  FrameTimes t{};
  if (mode_ == ClockMode::kSim) {
    t.t_capture = static_cast<double>(capture_time_ns) * 1e-9;
    t.t_sent = static_cast<double>(sent_time_ns) * 1e-9;
  } else {
    const VisionError e = CheckWallClock(unix_now);
    if (e != VisionError::kOk) return e;
    // Subtract the latency in integers first: no cancellation for small delays.
    const double latency = static_cast<double>(sent_time_ns - capture_time_ns) * 1e-9;
    t.t_sent = unix_now;
    t.t_capture = unix_now - latency;
  }
  if (!(t.t_capture > 0.0)) return VisionError::kTimeNotPositive;
  if (t.t_sent < t.t_capture) return VisionError::kTimeOrder;  // rounding can never do this, but promise it
  *out = t;
  return VisionError::kOk;
}

VisionError WireClock::ForState(int64_t sim_time_ns, double unix_now, double* out) const {
  if (mode_ == ClockMode::kUnix) {
    const VisionError e = CheckWallClock(unix_now);
    if (e != VisionError::kOk) return e;
    *out = unix_now;
    return VisionError::kOk;
  }
  if (sim_time_ns <= 0) return VisionError::kTimeNotPositive;
  *out = static_cast<double>(sim_time_ns) * 1e-9;
  return VisionError::kOk;
}

}  // namespace turf::vision
