// Real-time pacing and the measured real-time factor. Lives outside the core:
// it only decides how long the loop sleeps, never how far the world steps.
#pragma once

#include <chrono>
#include <cstdint>

#include "kernel/time_control.h"

namespace turf {

class Pacer {
 public:
  using Clock = std::chrono::steady_clock;
  // Falling further behind than this re-anchors instead of racing to catch up.
  static constexpr std::chrono::milliseconds kMaxLag{100};

  // Anchors simulation time `sim_ns` to the wall time `now`.
  void Anchor(Clock::time_point now, int64_t sim_ns) {
    wall0_ = now;
    sim0_ = sim_ns;
  }
  // When the loop may take the step that reaches `sim_ns` at `speed`.
  Clock::time_point Deadline(int64_t sim_ns, double speed) const {
    const double wall_s = static_cast<double>(sim_ns - sim0_) * 1e-9 / speed;
    return wall0_ + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(wall_s));
  }
  // Re-anchors if `now` is past `deadline` by more than kMaxLag; true if so.
  bool CatchUp(Clock::time_point now, Clock::time_point deadline, int64_t sim_ns) {
    if (now - deadline <= kMaxLag) return false;
    Anchor(now, sim_ns);
    ++lag_resets_;
    return true;
  }
  uint64_t lag_resets() const { return lag_resets_; }

  // Simulated seconds per wall second over windows of about a second.
  void Measure(Clock::time_point now, int64_t sim_ns) {
    const double wall = std::chrono::duration<double>(now - window_wall_).count();
    if (window_wall_ == Clock::time_point{}) {
      window_wall_ = now;
      window_sim_ = sim_ns;
    } else if (wall >= 1.0) {
      rtf_ = static_cast<double>(sim_ns - window_sim_) * 1e-9 / wall;
      window_wall_ = now;
      window_sim_ = sim_ns;
    }
  }
  double real_time_factor() const { return rtf_; }

 private:
  Clock::time_point wall0_{};
  int64_t sim0_ = 0;
  uint64_t lag_resets_ = 0;
  Clock::time_point window_wall_{};
  int64_t window_sim_ = 0;
  double rtf_ = 0.0;
};

}  // namespace turf
