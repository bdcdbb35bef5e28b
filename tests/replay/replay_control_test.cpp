// turf-replay's control requests: what each op asks a replay to do, and the named refusals of the rest.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <variant>

#include "participants/replay/replay_control.h"

namespace turf {
namespace {

idl::SimControl Request(idl::ControlOp op) {
  idl::SimControl r;
  r.client("test");
  r.request_id(7);
  r.op(op);
  return r;
}

ReplayCommand Command(const idl::SimControl& request) {
  auto result = ReplayCommandOf(request);
  const auto* refusal = std::get_if<ReplayRefusal>(&result);
  EXPECT_EQ(refusal, nullptr) << (refusal ? refusal->reason : "");
  return refusal ? ReplayCommand{} : std::get<ReplayCommand>(result);
}

idl::ControlError Refused(const idl::SimControl& request) {
  auto result = ReplayCommandOf(request);
  const auto* refusal = std::get_if<ReplayRefusal>(&result);
  EXPECT_NE(refusal, nullptr);
  if (refusal) EXPECT_FALSE(refusal->reason.empty());
  return refusal ? refusal->code : idl::CONTROL_OK;
}

idl::SimControl TimeMode(idl::TimeMode mode, double speed) {
  idl::SimControl r = Request(idl::OP_SET_TIME_MODE);
  r.time_mode(mode);
  r.speed(speed);
  return r;
}

TEST(ReplayControl, PauseResumeSpeedAndSeek) {
  EXPECT_EQ(Command(Request(idl::OP_PAUSE)).kind, ReplayCommand::Kind::kPause);
  EXPECT_EQ(Command(Request(idl::OP_RESUME)).kind, ReplayCommand::Kind::kResume);
  const ReplayCommand scaled = Command(TimeMode(idl::TIME_SCALED, 2.5));
  EXPECT_EQ(scaled.kind, ReplayCommand::Kind::kSpeed);
  EXPECT_EQ(scaled.speed, 2.5);
  EXPECT_EQ(scaled.request.request_id(), 7u);
  EXPECT_EQ(Command(TimeMode(idl::TIME_REALTIME, 9)).speed, 1.0);  // real time ignores `speed`
  EXPECT_EQ(Command(TimeMode(idl::TIME_FREE_RUNNING, 9)).speed, 0.0);
  idl::SimControl seek = Request(idl::OP_SEEK);
  seek.seek_time_ns(12'500'000'000);
  const ReplayCommand s = Command(seek);
  EXPECT_EQ(s.kind, ReplayCommand::Kind::kSeek);
  EXPECT_EQ(s.seek_time_ns, 12'500'000'000);
}

TEST(ReplayControl, RefusesWhatAReplayCannotDoWithNamedErrors) {
  for (idl::ControlOp op :
       {idl::OP_TELEPORT_BALL, idl::OP_TELEPORT_ROBOT, idl::OP_STEP, idl::OP_RESET, idl::OP_SET_REALISM})
    EXPECT_EQ(Refused(Request(op)), idl::CONTROL_NOT_ALLOWED) << op;
  EXPECT_EQ(Refused(Request(static_cast<idl::ControlOp>(200))), idl::CONTROL_UNKNOWN_OP);
  EXPECT_EQ(Refused(TimeMode(idl::TIME_LOCKSTEP, 1)), idl::CONTROL_NOT_ALLOWED);
  EXPECT_EQ(Refused(TimeMode(static_cast<idl::TimeMode>(9), 1)), idl::CONTROL_UNKNOWN_ENUM);
  EXPECT_EQ(Refused(TimeMode(idl::TIME_SCALED, std::nan(""))), idl::CONTROL_NOT_FINITE);
  EXPECT_EQ(Refused(TimeMode(idl::TIME_SCALED, std::numeric_limits<double>::infinity())), idl::CONTROL_NOT_FINITE);
  EXPECT_EQ(Refused(TimeMode(idl::TIME_SCALED, 0)), idl::CONTROL_OUT_OF_RANGE);
  EXPECT_EQ(Refused(TimeMode(idl::TIME_SCALED, -2)), idl::CONTROL_OUT_OF_RANGE);
  EXPECT_EQ(Refused(TimeMode(idl::TIME_SCALED, 2e6)), idl::CONTROL_OUT_OF_RANGE);
  EXPECT_EQ(Refused(TimeMode(idl::TIME_SCALED, 1e-300)), idl::CONTROL_OUT_OF_RANGE);  // past the clock's range
  EXPECT_TRUE(std::holds_alternative<ReplayCommand>(ReplayCommandOf(TimeMode(idl::TIME_SCALED, kMinReplaySpeed))));
  idl::SimControl seek = Request(idl::OP_SEEK);
  seek.seek_time_ns(-1);
  EXPECT_EQ(Refused(seek), idl::CONTROL_OUT_OF_RANGE);
}

}  // namespace
}  // namespace turf
