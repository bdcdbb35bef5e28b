// Time modes, pause and STEP requests as a pure state machine: who may step,
// when a request is done, what a reset cancels. No clock, no DDS.
#include "kernel/time_control.h"

#include <gtest/gtest.h>

#include <cmath>

namespace turf {
namespace {

// Steps while allowed (at most `limit`), as turf-sim's loop does; returns the
// tokens finished, in order, and advances `frame`.
std::vector<uint64_t> StepWhileAllowed(TimeControl& t, uint64_t* frame, int limit) {
  std::vector<uint64_t> done;
  for (int i = 0; i < limit && t.CanStep(); ++i) t.Stepped(++*frame, &done);
  return done;
}

TEST(TimeControlTest, RunningTimeStepsAndPacesOnlyInRealOrScaledTime) {
  TimeControl t(TimeMode::kRealtime, 5.0, false);
  EXPECT_EQ(t.speed(), 1.0);  // real time is speed 1 whatever was asked
  EXPECT_TRUE(t.CanStep());
  EXPECT_TRUE(t.Paces());
  EXPECT_EQ(t.SetMode(TimeMode::kFreeRunning, 0.0), Error::kOk);
  EXPECT_TRUE(t.CanStep());
  EXPECT_FALSE(t.Paces());
  EXPECT_EQ(t.SetMode(TimeMode::kScaled, 2.5), Error::kOk);
  EXPECT_TRUE(t.Paces());
  EXPECT_EQ(t.speed(), 2.5);
  EXPECT_EQ(t.SetMode(TimeMode::kLockstep, 0.0), Error::kOk);
  EXPECT_FALSE(t.CanStep());
}

TEST(TimeControlTest, BadModesAndSpeedsAreRefusedAndChangeNothing) {
  TimeControl t(TimeMode::kScaled, 3.0, false);
  EXPECT_EQ(t.SetMode(TimeMode::kScaled, NAN), Error::kNotFinite);
  EXPECT_EQ(t.SetMode(TimeMode::kScaled, 0.0), Error::kOutOfRange);
  EXPECT_EQ(t.SetMode(TimeMode::kScaled, kMaxTimeSpeed * 2), Error::kOutOfRange);
  // A speed so small that one step would wait minutes (1e-6) or past the clock's range (1e-300).
  EXPECT_EQ(t.SetMode(TimeMode::kScaled, 1e-6), Error::kOutOfRange);
  EXPECT_EQ(t.SetMode(TimeMode::kScaled, 1e-300), Error::kOutOfRange);
  EXPECT_EQ(t.SetMode(TimeMode::kCount, 1.0), Error::kUnknownEnum);
  EXPECT_EQ(t.mode(), TimeMode::kScaled);
  EXPECT_EQ(t.speed(), 3.0);
  EXPECT_EQ(t.SetMode(TimeMode::kScaled, kMinTimeSpeed), Error::kOk);
}

// Steps are answered when done, so queued ones are bounded: at most kMaxStepRequest at once, whatever the requests.
TEST(TimeControlTest, QueuedStepsStopAtTheLimitOfOneRequest) {
  TimeControl t(TimeMode::kRealtime, 1.0, true);
  ASSERT_EQ(t.CheckSteps(kMaxStepRequest - 1), Error::kOk);
  t.QueueSteps(kMaxStepRequest - 1, 0, 1);
  EXPECT_EQ(t.CheckSteps(2), Error::kOutOfRange);
  ASSERT_EQ(t.CheckSteps(1), Error::kOk);
  t.QueueSteps(1, 0, 2);
  EXPECT_EQ(t.CheckSteps(1), Error::kOutOfRange);
  EXPECT_EQ(t.pending_steps(), kMaxStepRequest);
  std::vector<uint64_t> done;
  t.Stepped(1, &done);
  EXPECT_EQ(t.CheckSteps(1), Error::kOk);  // one step done: room for one more
}

TEST(TimeControlTest, StepsNeedPauseOrLockstepAndFinishAtTheirFrame) {
  TimeControl t(TimeMode::kRealtime, 1.0, false);
  EXPECT_EQ(t.CheckSteps(10), Error::kNotAllowed);  // time runs: a STEP makes no sense
  t.Pause();
  EXPECT_FALSE(t.CanStep());
  EXPECT_EQ(t.CheckSteps(0), Error::kOutOfRange);
  EXPECT_EQ(t.CheckSteps(kMaxStepRequest + 1), Error::kOutOfRange);
  ASSERT_EQ(t.CheckSteps(10), Error::kOk);
  uint64_t frame = 100;
  t.QueueSteps(10, frame, 7);
  t.QueueSteps(5, frame, 8);  // queued behind the first: done at 115
  EXPECT_TRUE(t.CanStep());
  EXPECT_FALSE(t.Paces());  // queued steps run at once, also in real time
  const std::vector<uint64_t> first = StepWhileAllowed(t, &frame, 10);
  EXPECT_EQ(first, std::vector<uint64_t>{7});
  EXPECT_EQ(frame, 110u);
  const std::vector<uint64_t> second = StepWhileAllowed(t, &frame, 100);
  EXPECT_EQ(second, std::vector<uint64_t>{8});
  EXPECT_EQ(frame, 115u);  // then paused again: no further step
  EXPECT_FALSE(t.CanStep());
}

TEST(TimeControlTest, AResetCancelsEveryQueuedRequest) {
  TimeControl t(TimeMode::kLockstep, 1.0, false);
  t.QueueSteps(4, 0, 1);
  t.QueueSteps(4, 0, 2);
  uint64_t frame = 0;
  EXPECT_EQ(StepWhileAllowed(t, &frame, 2), std::vector<uint64_t>{});
  EXPECT_EQ(t.Reset(), (std::vector<uint64_t>{1, 2}));
  EXPECT_EQ(t.pending_steps(), 0u);
  EXPECT_FALSE(t.CanStep());
}

}  // namespace
}  // namespace turf
