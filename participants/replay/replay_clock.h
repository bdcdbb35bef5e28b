// When a replayed message is due: the recording's receive times (log_time) replayed at a speed, from a start on
// the local monotonic clock. Pure: the caller reads its clock and sleeps.
#pragma once

#include <chrono>
#include <cstdint>

namespace turf {

// The latest a message is due after the origin, in wall-clock ns (about 116 days).
inline constexpr double kMaxReplayWaitNs = 1e16;

class ReplayClock {
 public:
  // `speed`: a multiple of real time (> 0); 0: as fast as possible (every message is due at once).
  ReplayClock(double speed, std::chrono::steady_clock::time_point start) : speed_(speed), start_(start) {}
  // The log time that is due at the start; without it, the first message given to Due() fixes it.
  void SetOrigin(uint64_t log_time_ns) {
    have_origin_ = true;
    origin_ns_ = log_time_ns;
  }
  // From `now` on, the message logged at `log_time_ns` is due at once and later ones at `speed` (a seek or a new
  // speed); a pause stays in force, counted from `now`.
  void Rebase(uint64_t log_time_ns, double speed, std::chrono::steady_clock::time_point now);
  double speed() const { return speed_; }
  // The moment the message logged at `log_time_ns` is due (at once for one before the origin).
  std::chrono::steady_clock::time_point Due(uint64_t log_time_ns);
  // Pause at `now`; Resume at a later `now` moves every later message on by the time paused (a second Pause or a
  // Resume while running changes nothing).
  void Pause(std::chrono::steady_clock::time_point now);
  void Resume(std::chrono::steady_clock::time_point now);
  bool paused() const { return paused_; }

 private:
  double speed_;
  std::chrono::steady_clock::time_point start_;
  bool have_origin_ = false;
  uint64_t origin_ns_ = 0;
  bool paused_ = false;
  std::chrono::steady_clock::time_point paused_at_;
};

}  // namespace turf
