#include "participants/common/legged_lockstep.h"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>

#include "participants/common/process.h"

namespace turf {

LeggedLockstep::LeggedLockstep(std::unique_ptr<dds::Participant> own, dds::Bus& bus, const char* client,
                               bool need_force)
    : need_force_(need_force),
      own_(std::move(own)),
      bus_(bus),
      control_(bus_, client, Wake()),
      scene_(bus_.MakeReader(dds::Topic::kLeggedScene, Wake())),
      clock_(bus_.MakeReader(dds::Topic::kClock, Wake())),
      state_(bus_.MakeReader(dds::Topic::kRobotsState, Wake())) {}

LeggedLockstep::~LeggedLockstep() = default;

idl::Vec3 LeggedLockstep::V3(const Eigen::Vector3d& v) {
  idl::Vec3 out;
  out.x(v.x());
  out.y(v.y());
  out.z(v.z());
  return out;
}

std::function<void()> LeggedLockstep::Wake() {
  return [this] { wakeup_.Notify(); };
}

void LeggedLockstep::Drain() {
  if (scene_->Take(&scene_in_)) scene_info_ = scene_in_.back();
  if (clock_->Take(&clock_in_)) step_s_ = clock_in_.back().step_s();
  if (state_->Take(&state_in_)) state_now_ = std::move(state_in_.back());
}

bool LeggedLockstep::WaitFor(const std::function<bool()>& done, Clock::time_point deadline, const StopFn& stop) {
  while (true) {
    Drain();
    if (done()) return true;
    if (Clock::now() >= deadline || (stop && stop())) return false;
    wakeup_.WaitUntil(std::min(deadline, Clock::now() + std::chrono::milliseconds(50)));
  }
}

bool LeggedLockstep::WaitForScene(Clock::time_point deadline, const StopFn& stop) {
  return WaitFor([this] { return scene_info_.has_value() && control_.ServerMatched(); }, deadline, stop);
}

dds::ControlOutcome LeggedLockstep::SwitchToLockstep(Clock::time_point deadline, const StopFn& stop) {
  idl::SimControl lockstep;
  lockstep.op(idl::OP_SET_TIME_MODE);
  lockstep.time_mode(idl::TIME_LOCKSTEP);
  dds::ControlOutcome answer;
  while (Clock::now() < deadline && !(stop && stop())) {
    const auto wait = std::chrono::duration_cast<std::chrono::milliseconds>(
        std::min(deadline - Clock::now(), Clock::duration(std::chrono::milliseconds(500))));
    answer = control_.Call(lockstep, wait, stop);
    if (answer.reply) break;
  }
  if (answer.reply && answer.ok()) frame_ = answer.reply->frame();
  return answer;
}

bool LeggedLockstep::Attach(std::chrono::milliseconds timeout, const StopFn& stop) {
  spdlog::info("waiting for turf-sim's legged scene on {} ({})", DescribeBus(), TopicName(dds::Topic::kLeggedScene));
  std::string error;
  if (TryAttach(timeout, stop, &error)) return true;
  if (!(stop && stop()) && !RestartRequested()) spdlog::error("{}", error);
  return false;
}

bool LeggedLockstep::TryAttach(std::chrono::milliseconds timeout, const StopFn& outer_stop, std::string* error) {
  const auto deadline = Clock::now() + timeout;
  // Stalls told before this wait (while the link had turf-sim) do not count.
  if (own_) restart_.Check(own_->AuthenticationsNow(), false);
  const StopFn stop = [&] {
    return (outer_stop && outer_stop()) ||
           (own_ && (restart_.Check(own_->AuthenticationsNow(), true) || RestartRequested()));
  };
  if (!WaitForScene(deadline, stop)) {
    *error = "no legged scene from turf-sim (is it running a `kind: legged` scene on this domain and prefix?)";
    return false;
  }
  const dds::ControlOutcome answer = SwitchToLockstep(deadline, stop);
  if (!answer.reply) {
    *error = "turf-sim did not answer the switch to lockstep (" + answer.Describe() + ")";
    return false;
  }
  if (!answer.ok()) {
    *error = "turf-sim refused lockstep: " + answer.reply->reason();
    return false;
  }
  std::vector<std::string> robots;
  for (const idl::RobotDescription& r : scene_info().robots()) robots.push_back(r.robot());
  if (!WaitForFrame(robots, deadline, stop)) {
    *error = fmt::format("turf-sim did not publish the state of its {} robots at frame {}", robots.size(), frame());
    return false;
  }
  return true;
}

bool LeggedLockstep::WaitForFrame(const std::vector<std::string>& robots, Clock::time_point deadline,
                                  const StopFn& stop) {
  robots_ = robots;
  return WaitFor([&] { return step_s_ > 0 && Complete(frame_); }, deadline, stop);
}

void LeggedLockstep::SendMove(const std::string& robot, const Eigen::Vector3d& position,
                              const Eigen::Quaterniond& orientation, bool reset_joints,
                              std::chrono::milliseconds timeout) {
  idl::SimControl move;
  move.op(idl::OP_TELEPORT_ROBOT);
  move.legged().robot(robot);
  move.legged().position(V3(position));
  move.legged().orientation().w(orientation.w());
  move.legged().orientation().x(orientation.x());
  move.legged().orientation().y(orientation.y());
  move.legged().orientation().z(orientation.z());
  move.legged().reset_joints(reset_joints);
  const std::string what = "move " + robot;
  control_.Send(std::move(move), timeout, [this, what](const dds::ControlOutcome& o) {
    if (!o.ok()) move_warnings_.push_back(what + ": " + o.Describe());
  });
}

void LeggedLockstep::SendBall(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity,
                              std::chrono::milliseconds timeout) {
  idl::SimControl ball;
  ball.op(idl::OP_TELEPORT_BALL);
  ball.ball().position(V3(position));
  ball.ball().velocity(V3(velocity));
  control_.Send(std::move(ball), timeout, [this](const dds::ControlOutcome& o) {
    if (!o.ok()) move_warnings_.push_back("ball: " + o.Describe());
  });
}

bool LeggedLockstep::Step(idl::SimControl step, uint32_t steps, std::chrono::milliseconds timeout, const StopFn& stop,
                          std::string* error, std::vector<std::string>* warnings) {
  const uint64_t id = control_.Send(std::move(step), timeout);
  const auto deadline = Clock::now() + timeout;
  // The world after the step usually arrives before the step's reply (turf-sim writes robots/state first): take it
  // at the expected frame at once; the reply's frame counts when someone else stepped too (a viewer's step).
  const uint64_t expected = frame_ + steps;
  std::optional<dds::ControlOutcome> answer;
  auto done = [&] {
    if (Complete(expected)) return true;
    answer = control_.Peek(id);
    return answer && (!answer->reply || !answer->ok() || Complete(answer->reply->frame()));
  };
  const bool finished = WaitFor(done, deadline, stop);
  control_.Forget(id);
  control_.Dispatch();
  warnings->insert(warnings->end(), move_warnings_.begin(), move_warnings_.end());
  move_warnings_.clear();
  if (!finished || (answer && !answer->reply)) {
    *error = "turf-sim did not answer the step" + (answer ? " (" + answer->Describe() + ")" : std::string());
    return false;
  }
  if (answer && !answer->ok()) {
    *error = "turf-sim refused the step: " + answer->reply->reason();
    return false;
  }
  frame_ = state_now_->frame();
  return true;
}

bool LeggedLockstep::Complete(uint64_t frame) const {
  if (!state_now_ || state_now_->frame() != frame) return false;
  const idl::LeggedState& s = *state_now_;
  const size_t n = s.joints().size();
  if (n != robots_.size() || s.imu().size() != n || s.links().size() != n) return false;
  if (need_force_ && s.force().size() != n) return false;
  for (size_t i = 0; i < n; ++i)
    if (s.joints()[i].robot() != robots_[i] || s.links()[i].links().empty()) return false;
  return true;
}

uint64_t LeggedLockstep::Overflowed() const { return control_.Overflowed() + state_->Overflowed(); }

}  // namespace turf
