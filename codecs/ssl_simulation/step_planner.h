// How many physics steps one sync request runs. A sync request asks for
// `sim_step` seconds, which need not be a whole number of physics steps (the
// usual 1/60 s is 8.33 steps of 2 ms). The planner runs the whole number of
// steps that keeps the session's total simulated time within half a physics
// step of the total it was asked for, and carries the remainder to the next
// request: 1/60 s at 2 ms gives 8, 9, 8, 8, 9, 8, ... steps, exactly 500 in 60
// requests (1.000 s). Everything is integer nanoseconds, so nothing drifts.
//
// A request whose share rounds to zero steps gets zero (e.g. 1 ms at 2 ms: 0,
// 1, 0, 1, ...); its time is carried, never lost.
//
// The carry belongs to one sync session. It is forgotten when the physics step
// changes (Plan notices) and when the caller calls Rebase or Reset (the bridge
// does when turf-sim's time did not continue from the session's last step:
// a reset, a restarted turf-sim, another client's steps).
//
// Pure: no clocks, no I/O.
#pragma once

#include <cstdint>

namespace turf::simproto {

// Seconds to integer nanoseconds, rounded to nearest; `seconds` must be finite
// and well within +-9e9 s (the caller checks).
int64_t ToNanoseconds(double seconds);
// The same for the protocol's float sim_step, read as the shortest decimal that
// gives back the same float (what the client wrote): 0.016f is 16000000 ns, not
// the 16000001 of its binary value, so a multiple of the step stays one.
int64_t FloatSecondsToNanoseconds(float seconds);

class StepPlanner {
 public:
  // Steps to run for a request of `request_ns` at a physics step of `step_ns`;
  // 0 (carry unchanged) unless both are in (0, 1000 s].
  // A `step_ns` other than the previous call's starts over (carry 0).
  uint32_t Plan(int64_t request_ns, int64_t step_ns);
  // Forget everything before the last request: it becomes the session's first
  // (asked for `request_ns`, ran `steps_run` steps). That request may be off by
  // up to one step; the following ones are back within half a step.
  void Rebase(int64_t request_ns, uint32_t steps_run);
  // Start over: no carry, no physics step known.
  void Reset();

  // Requested minus simulated time so far: in [-step/2, step/2), except
  // just after a Rebase (then within one step).
  int64_t carry_ns() const { return carry_ns_; }
  int64_t step_ns() const { return step_ns_; }

 private:
  int64_t step_ns_ = 0;
  int64_t carry_ns_ = 0;
};

}  // namespace turf::simproto
