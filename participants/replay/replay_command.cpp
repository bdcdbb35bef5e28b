#include "participants/replay/replay_command.h"

#include <fmt/format.h>

#include <cmath>

namespace turf {
namespace {

ReplayRefusal SpeedRefusal(idl::TimeMode mode, double speed) {
  if (mode == idl::TIME_LOCKSTEP) return {idl::CONTROL_NOT_ALLOWED, "a replay has no lockstep: it plays a recording"};
  if (mode != idl::TIME_SCALED) return {};
  if (!std::isfinite(speed)) return {idl::CONTROL_NOT_FINITE, "speed is not a finite number"};
  if (std::string problem = ReplaySpeedProblem(speed); !problem.empty())
    return {idl::CONTROL_OUT_OF_RANGE, std::move(problem)};
  return {};
}

std::variant<ReplayCommand, ReplayRefusal> TimeModeCommand(const idl::SimControl& request) {
  const idl::TimeMode mode = request.time_mode();
  if (mode > idl::TIME_LOCKSTEP)
    return ReplayRefusal{idl::CONTROL_UNKNOWN_ENUM, fmt::format("unknown time mode {}", static_cast<int>(mode))};
  ReplayRefusal refusal = SpeedRefusal(mode, request.speed());
  if (refusal.code != idl::CONTROL_OK) return refusal;
  const double speed = mode == idl::TIME_REALTIME ? 1.0 : mode == idl::TIME_SCALED ? request.speed() : 0.0;
  return ReplayCommand{ReplayCommand::Kind::kSpeed, speed, 0, request};
}

}  // namespace

std::string ReplaySpeedProblem(double speed) {
  if (speed >= kMinReplaySpeed && speed <= kMaxReplaySpeed) return "";
  return fmt::format("speed {} is outside [{}, {}]", speed, kMinReplaySpeed, kMaxReplaySpeed);
}

std::variant<ReplayCommand, ReplayRefusal> ReplayCommandOf(const idl::SimControl& request) {
  switch (request.op()) {
    case idl::OP_PAUSE:
      return ReplayCommand{ReplayCommand::Kind::kPause, 1, 0, request};
    case idl::OP_RESUME:
      return ReplayCommand{ReplayCommand::Kind::kResume, 1, 0, request};
    case idl::OP_SET_TIME_MODE:
      return TimeModeCommand(request);
    case idl::OP_SEEK:
      if (request.seek_time_ns() < 0)
        return ReplayRefusal{idl::CONTROL_OUT_OF_RANGE,
                             fmt::format("seek to {} ns: simulation time is never negative", request.seek_time_ns())};
      return ReplayCommand{ReplayCommand::Kind::kSeek, 1, request.seek_time_ns(), request};
    case idl::OP_TELEPORT_BALL:
    case idl::OP_TELEPORT_ROBOT:
    case idl::OP_STEP:
    case idl::OP_RESET:
    case idl::OP_SET_REALISM:
      return ReplayRefusal{idl::CONTROL_NOT_ALLOWED, "a replay shows the recorded match and changes nothing in it"};
  }
  return ReplayRefusal{idl::CONTROL_UNKNOWN_OP, fmt::format("unknown op {}", static_cast<int>(request.op()))};
}

}  // namespace turf
