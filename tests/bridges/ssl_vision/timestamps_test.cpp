// Wire timestamps: Unix mode (like SSL-Vision) and sim mode, and the frames
// refused rather than sent with a zero, negative or out-of-order time.
#include <gtest/gtest.h>

#include <cmath>

#include "bridges/ssl_vision/timestamps.h"

namespace turf::vision {
namespace {

constexpr double kNow = 1'700'000'000.25;  // a Unix time

TEST(SslVisionTimestamps, UnixModeSendsNowAndSubtractsTheSimulatedLatency) {
  const WireClock clock(ClockMode::kUnix);
  FrameTimes t{};
  ASSERT_EQ(clock.ForFrame(1'000'000'000, 1'004'000'000, kNow, &t), VisionError::kOk);
  EXPECT_DOUBLE_EQ(t.t_sent, kNow);
  EXPECT_NEAR(t.t_sent - t.t_capture, 0.004, 1e-6);
  EXPECT_GT(t.t_capture, 0.0);
  EXPECT_GE(t.t_sent, t.t_capture);
  // An ideal camera: captured and sent at once.
  ASSERT_EQ(clock.ForFrame(16'666'667, 16'666'667, kNow, &t), VisionError::kOk);
  EXPECT_EQ(t.t_capture, t.t_sent);
  EXPECT_EQ(clock.mode(), ClockMode::kUnix);
  EXPECT_EQ(WireClock().mode(), ClockMode::kUnix);  // the default
}

TEST(SslVisionTimestamps, SimModeIsExactSimulationSeconds) {
  const WireClock clock(ClockMode::kSim);
  FrameTimes t{};
  ASSERT_EQ(clock.ForFrame(16'666'667, 20'666'667, kNow, &t), VisionError::kOk);
  EXPECT_DOUBLE_EQ(t.t_capture, 0.016666667);
  EXPECT_DOUBLE_EQ(t.t_sent, 0.020666667);
  double s = 0;
  ASSERT_EQ(clock.ForState(2'500'000'000, kNow, &s), VisionError::kOk);
  EXPECT_DOUBLE_EQ(s, 2.5);
}

TEST(SslVisionTimestamps, RefusesFramesThatWouldBreakTheRules) {
  FrameTimes t{-7.0, -7.0};
  for (ClockMode mode : {ClockMode::kUnix, ClockMode::kSim}) {
    const WireClock clock(mode);
    EXPECT_EQ(clock.ForFrame(0, 0, kNow, &t), VisionError::kTimeNotPositive) << ClockModeName(mode);
    EXPECT_EQ(clock.ForFrame(-5, 10, kNow, &t), VisionError::kTimeNotPositive);
    EXPECT_EQ(clock.ForFrame(2'000, 1'000, kNow, &t), VisionError::kTimeOrder);
  }
  const WireClock unix_clock(ClockMode::kUnix);
  EXPECT_EQ(unix_clock.ForFrame(1'000, 1'000, 0.0, &t), VisionError::kTimeNotPositive);
  EXPECT_EQ(unix_clock.ForFrame(1'000, 1'000, -1.0, &t), VisionError::kTimeNotPositive);
  EXPECT_EQ(unix_clock.ForFrame(1'000, 1'000, NAN, &t), VisionError::kNotFinite);
  EXPECT_EQ(unix_clock.ForFrame(1'000, 1'000, INFINITY, &t), VisionError::kNotFinite);
  // A simulated latency longer than the wall clock has run would capture before 1970.
  EXPECT_EQ(unix_clock.ForFrame(1'000, 5'000'000'000, 2.0, &t), VisionError::kTimeNotPositive);
  double s = -7.0;
  EXPECT_EQ(WireClock(ClockMode::kSim).ForState(0, kNow, &s), VisionError::kTimeNotPositive);
  EXPECT_EQ(unix_clock.ForState(0, NAN, &s), VisionError::kNotFinite);
  // A refused frame leaves the output untouched.
  EXPECT_EQ(t.t_capture, -7.0);
  EXPECT_EQ(s, -7.0);
}

TEST(SslVisionTimestamps, ClockModeNames) {
  EXPECT_STREQ(ClockModeName(ClockMode::kUnix), "unix");
  EXPECT_STREQ(ClockModeName(ClockMode::kSim), "sim");
  EXPECT_EQ(ParseClockMode("sim"), ClockMode::kSim);
  EXPECT_EQ(ParseClockMode("unix"), ClockMode::kUnix);
  EXPECT_FALSE(ParseClockMode("wall").has_value());
}

}  // namespace
}  // namespace turf::vision
