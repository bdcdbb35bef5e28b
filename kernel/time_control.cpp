#include "kernel/time_control.h"

#include <cmath>
#include <iterator>

namespace turf {

TimeControl::TimeControl(TimeMode mode, double speed, bool paused)
    : mode_(mode), speed_(mode == TimeMode::kScaled ? speed : 1.0), paused_(paused) {}

Error TimeControl::SetMode(TimeMode mode, double speed) {
  if (mode >= TimeMode::kCount) return Error::kUnknownEnum;
  if (mode == TimeMode::kScaled) {
    if (!std::isfinite(speed)) return Error::kNotFinite;
    if (!(speed >= kMinTimeSpeed && speed <= kMaxTimeSpeed)) return Error::kOutOfRange;
    speed_ = speed;
  } else if (mode == TimeMode::kRealtime) {
    speed_ = 1.0;
  }
  mode_ = mode;
  return Error::kOk;
}

Error TimeControl::CheckSteps(uint32_t count) const {
  if (!paused_ && mode_ != TimeMode::kLockstep) return Error::kNotAllowed;
  if (count == 0 || pending_steps_ + count > kMaxStepRequest) return Error::kOutOfRange;
  return Error::kOk;
}

void TimeControl::QueueSteps(uint32_t count, uint64_t frame, uint64_t token) {
  pending_steps_ += count;
  queue_.push_back({frame + pending_steps_, token});
}

void TimeControl::Stepped(uint64_t frame, std::vector<uint64_t>* done) {
  if (pending_steps_ > 0) --pending_steps_;
  while (FinishesAt(frame)) {
    done->push_back(queue_.front().token);
    queue_.pop_front();
  }
}

std::vector<uint64_t> TimeControl::Reset() {
  std::vector<uint64_t> cancelled;
  for (const Queued& q : queue_) cancelled.push_back(q.token);
  queue_.clear();
  pending_steps_ = 0;
  return cancelled;
}

}  // namespace turf
