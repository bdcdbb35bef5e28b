// Who may step, and how fast: the time modes (real time, scaled, free
// running, lockstep), pause and resume, STEP requests and what a reset does to
// them. A pure state machine: no clock and no transport. turf-sim's loop asks
// it whether to step and whether to pace; a STEP request is queued under a
// token the caller chooses and is reported done at the frame it finishes (or
// cancelled by a reset).
#pragma once

#include <cstdint>
#include <deque>
#include <iterator>
#include <vector>

#include "core/enum_names.h"
#include "core/errors.h"

namespace turf {

enum class TimeMode : uint8_t { kRealtime, kScaled, kFreeRunning, kLockstep, kCount };
// Their names in logs and reports, in enum order (core/enum_names.h).
inline constexpr const char* kTimeModeNames[] = {"realtime", "scaled", "free-running", "lockstep"};
static_assert(std::size(kTimeModeNames) == static_cast<std::size_t>(TimeMode::kCount));
inline const char* TimeModeName(TimeMode mode) { return EnumName(mode, kTimeModeNames, "?"); }

// A scaled speed, in multiples of real time. Below the minimum a 5 ms step would wait more than half a second of wall
// time (the loop paces one step at a time: it would answer requests and signals that late).
inline constexpr double kMinTimeSpeed = 0.01;
inline constexpr double kMaxTimeSpeed = 1000.0;
inline constexpr uint32_t kMaxStepRequest = 1000000;  // steps in one request, and queued at once

class TimeControl {
 public:
  TimeControl(TimeMode mode, double speed, bool paused);

  TimeMode mode() const { return mode_; }
  double speed() const { return speed_; }
  bool paused() const { return paused_; }
  uint64_t pending_steps() const { return pending_steps_; }

  // A step may run now: steps are queued, or time runs (not paused, not lockstep).
  bool CanStep() const { return pending_steps_ > 0 || (!paused_ && mode_ != TimeMode::kLockstep); }
  // The next step should wait for the wall clock (real time or scaled, no STEP queued).
  bool Paces() const { return pending_steps_ == 0 && (mode_ == TimeMode::kRealtime || mode_ == TimeMode::kScaled); }

  void Pause() { paused_ = true; }
  void Resume() { paused_ = false; }
  // kNotFinite or kOutOfRange for a scaled speed outside [kMinTimeSpeed, kMaxTimeSpeed];
  // kUnknownEnum for a mode past kCount. Real time sets speed 1.
  Error SetMode(TimeMode mode, double speed);

  // kNotAllowed unless paused or in lockstep; kOutOfRange for 0 steps, or more than kMaxStepRequest steps with
  // those already queued (requests are answered when done: a queue without bound would hold them for good).
  // Changes nothing.
  Error CheckSteps(uint32_t count) const;
  // Queues `count` more steps (checked first), done at frame `frame` + all
  // steps queued; `token` names the request in Stepped and Reset.
  void QueueSteps(uint32_t count, uint64_t frame, uint64_t token);
  // After a step that reached `frame`: appends the tokens of the requests it
  // finished to `done`, oldest first.
  void Stepped(uint64_t frame, std::vector<uint64_t>* done);
  // True if a queued request finishes at `frame` (its state is published then).
  bool FinishesAt(uint64_t frame) const { return !queue_.empty() && frame >= queue_.front().done_at_frame; }
  // A reset: every queued request is dropped; returns their tokens, oldest first.
  std::vector<uint64_t> Reset();

 private:
  struct Queued {
    uint64_t done_at_frame;
    uint64_t token;
  };

  TimeMode mode_;
  double speed_;
  bool paused_;
  uint64_t pending_steps_ = 0;
  std::deque<Queued> queue_;
};

}  // namespace turf
