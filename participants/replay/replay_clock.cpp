#include "participants/replay/replay_clock.h"

#include <algorithm>

namespace turf {

std::chrono::steady_clock::time_point ReplayClock::Due(uint64_t log_time_ns) {
  if (!have_origin_) {
    have_origin_ = true;
    origin_ns_ = log_time_ns;
  }
  if (speed_ <= 0 || log_time_ns <= origin_ns_) return start_;
  // A file's log times are untrusted: a gap of centuries waits kMaxReplayWaitNs, still far inside the clock's range.
  const double wall_ns = std::min(static_cast<double>(log_time_ns - origin_ns_) / speed_, kMaxReplayWaitNs);
  return start_ + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                      std::chrono::duration<double, std::nano>(wall_ns));
}

void ReplayClock::Rebase(uint64_t log_time_ns, double speed, std::chrono::steady_clock::time_point now) {
  speed_ = speed;
  start_ = now;
  have_origin_ = true;
  origin_ns_ = log_time_ns;
  if (paused_) paused_at_ = now;
}

void ReplayClock::Pause(std::chrono::steady_clock::time_point now) {
  if (paused_) return;
  paused_ = true;
  paused_at_ = now;
}

void ReplayClock::Resume(std::chrono::steady_clock::time_point now) {
  if (!paused_) return;
  paused_ = false;
  if (now > paused_at_) start_ += now - paused_at_;
}

}  // namespace turf
