#include "codecs/ssl_vision/timestamps.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace turf::vision {

namespace {

VisionError CheckWallClock(double unix_now) {
  if (!std::isfinite(unix_now)) return VisionError::kNotFinite;
  return unix_now > 0.0 ? VisionError::kOk : VisionError::kTimeNotPositive;
}

// Whole seconds and the rest converted apart: a Unix time in ns does not fit a
// double's 53 bits, its parts do.
double Seconds(int64_t ns) {
  return static_cast<double>(ns / 1'000'000'000) + static_cast<double>(ns % 1'000'000'000) * 1e-9;
}

}  // namespace

// Indexed by ClockMode.
constexpr const char* kClockModeNames[] = {"run", "unix", "sim"};
constexpr size_t kClockModes = sizeof(kClockModeNames) / sizeof(kClockModeNames[0]);
static_assert(kClockModes == static_cast<size_t>(ClockMode::kSim) + 1, "one name per ClockMode");

const char* ClockModeName(ClockMode mode) {
  const auto i = static_cast<size_t>(mode);
  return i < kClockModes ? kClockModeNames[i] : "?";
}

std::optional<ClockMode> ParseClockMode(const std::string& name) {
  for (size_t i = 0; i < kClockModes; ++i)
    if (name == kClockModeNames[i]) return static_cast<ClockMode>(i);
  return std::nullopt;
}

VisionError CheckRunEpoch(int64_t run_epoch_unix_ns) {
  return run_epoch_unix_ns >= kMinRunEpochNs && run_epoch_unix_ns <= kMaxRunEpochNs ? VisionError::kOk
                                                                                    : VisionError::kBadEpoch;
}

VisionError WireClock::AddRunEpoch(int64_t run_epoch_unix_ns) {
  const VisionError e = CheckRunEpoch(run_epoch_unix_ns);
  if (e != VisionError::kOk) return e;
  if (!epochs_.empty() && epochs_.back() == run_epoch_unix_ns) return VisionError::kOk;  // the same timeline
  epochs_.push_back(run_epoch_unix_ns);
  if (epochs_.size() > kKeptEpochs) {
    epochs_.pop_front();
    ++first_seq_;
  }
  return VisionError::kOk;
}

std::optional<int64_t> WireClock::run_epoch_ns() const {
  if (epochs_.empty()) return std::nullopt;
  return epochs_.back();
}

// A stream keeps its timeline's epoch while its times go forward. When they go
// back (a reset, or a restarted turf-sim) it takes the first newer epoch whose
// timeline could hold the time: timeline k lasted epoch[k+1] - epoch[k] of sim
// time, so a time past that is from a later one (a stream that saw nothing of
// a short timeline skips it). No newer epoch yet: refused until one arrives.
VisionError WireClock::EpochFor(Stream* stream, bool known, int64_t time_ns, bool equal_is_new,
                                int64_t* epoch_ns) const {
  if (epochs_.empty()) return VisionError::kNoEpoch;
  const uint64_t newest = first_seq_ + epochs_.size() - 1;
  if (!known) {
    *stream = Stream{newest, time_ns, false};
  } else {
    const bool back = equal_is_new ? time_ns <= stream->last_ns : time_ns < stream->last_ns;
    stream->last_ns = time_ns;
    if (back || stream->waiting) {
      if (stream->epoch_seq >= newest) {
        stream->waiting = true;
        return VisionError::kNoEpoch;
      }
      uint64_t seq = std::max(stream->epoch_seq + 1, first_seq_);
      while (seq < newest && time_ns > epochs_[seq + 1 - first_seq_] - epochs_[seq - first_seq_]) ++seq;
      stream->epoch_seq = seq;
      stream->waiting = false;
    }
  }
  if (stream->epoch_seq < first_seq_) return VisionError::kNoEpoch;  // more resets ago than remembered
  *epoch_ns = epochs_[stream->epoch_seq - first_seq_];
  return VisionError::kOk;
}

VisionError WireClock::RunTimes(int64_t epoch_ns, int64_t capture_time_ns, int64_t sent_time_ns,
                                FrameTimes* out) const {
  if (sent_time_ns > std::numeric_limits<int64_t>::max() - epoch_ns) return VisionError::kOutOfRange;
  const FrameTimes t{Seconds(epoch_ns + capture_time_ns), Seconds(epoch_ns + sent_time_ns)};
  if (!(t.t_capture > 0.0)) return VisionError::kTimeNotPositive;
  if (t.t_sent < t.t_capture) return VisionError::kTimeOrder;
  *out = t;
  return VisionError::kOk;
}

VisionError WireClock::ForCamera(uint32_t camera_id, int64_t capture_time_ns, int64_t sent_time_ns, double unix_now,
                                 FrameTimes* out) {
  if (mode_ != ClockMode::kRun) return ForFrame(capture_time_ns, sent_time_ns, unix_now, out);
  // Frames refused for their own times never move a timeline.
  if (capture_time_ns <= 0) return VisionError::kTimeNotPositive;
  if (sent_time_ns < capture_time_ns) return VisionError::kTimeOrder;
  auto it = cameras_.find(camera_id);
  const bool known = it != cameras_.end();
  if (!known && cameras_.size() >= kMaxStreams) return VisionError::kTooMany;
  Stream fresh;
  int64_t epoch_ns = 0;
  const VisionError e = EpochFor(known ? &it->second : &fresh, known, capture_time_ns, true, &epoch_ns);
  if (e != VisionError::kOk) return e;
  if (!known) cameras_.emplace(camera_id, fresh);
  return RunTimes(epoch_ns, capture_time_ns, sent_time_ns, out);
}

VisionError WireClock::ForWorldState(int64_t sim_time_ns, double unix_now, double* out) {
  if (mode_ != ClockMode::kRun) return ForState(sim_time_ns, unix_now, out);
  if (sim_time_ns < 0) return VisionError::kTimeNotPositive;
  // A teleport republishes the state at the same sim time: only a step back is a new timeline.
  Stream fresh;
  int64_t epoch_ns = 0;
  const VisionError e = EpochFor(state_ ? &*state_ : &fresh, state_.has_value(), sim_time_ns, false, &epoch_ns);
  if (e != VisionError::kOk) return e;
  if (!state_) state_ = fresh;
  FrameTimes t{};
  const VisionError te = RunTimes(epoch_ns, sim_time_ns, sim_time_ns, &t);
  if (te == VisionError::kOk) *out = t.t_capture;
  return te;
}

VisionError WireClock::ForFrame(int64_t capture_time_ns, int64_t sent_time_ns, double unix_now, FrameTimes* out) const {
  if (capture_time_ns <= 0) return VisionError::kTimeNotPositive;
  if (sent_time_ns < capture_time_ns) return VisionError::kTimeOrder;
  FrameTimes t{};
  if (mode_ == ClockMode::kRun) {
    if (epochs_.empty()) return VisionError::kNoEpoch;
    return RunTimes(epochs_.back(), capture_time_ns, sent_time_ns, out);
  }
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
  switch (mode_) {
    case ClockMode::kRun: {
      if (sim_time_ns < 0) return VisionError::kTimeNotPositive;
      if (epochs_.empty()) return VisionError::kNoEpoch;
      FrameTimes t{};
      const VisionError e = RunTimes(epochs_.back(), sim_time_ns, sim_time_ns, &t);
      if (e == VisionError::kOk) *out = t.t_capture;
      return e;
    }
    case ClockMode::kUnix: {
      const VisionError e = CheckWallClock(unix_now);
      if (e != VisionError::kOk) return e;
      *out = unix_now;
      return VisionError::kOk;
    }
    case ClockMode::kSim:
      break;
  }
  if (sim_time_ns <= 0) return VisionError::kTimeNotPositive;
  *out = static_cast<double>(sim_time_ns) * 1e-9;
  return VisionError::kOk;
}

}  // namespace turf::vision
