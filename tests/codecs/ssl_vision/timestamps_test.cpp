// Wire timestamps: run mode (the default: turf-sim's run epoch + sim time),
// Unix mode (like SSL-Vision) and sim mode, and the frames refused rather than
// sent with a zero, negative, out-of-order or epoch-less time.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "codecs/ssl_vision/timestamps.h"

namespace turf::vision {
namespace {

constexpr double kNow = 1'700'000'000.25;              // a Unix time
constexpr int64_t kEpoch = 1'700'000'000'123'456'789;  // a run epoch, Unix ns
constexpr int64_t kMs = 1'000'000;
constexpr int64_t kFrame = 16'666'667;  // a 60 Hz camera's period, ns

// The Unix seconds of epoch + t, computed apart from the code under test.
double RunSeconds(int64_t epoch_ns, int64_t t_ns) {
  return static_cast<double>((epoch_ns + t_ns) / 1'000'000'000) +
         static_cast<double>((epoch_ns + t_ns) % 1'000'000'000) * 1e-9;
}

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
}

TEST(SslVisionTimestamps, RunModeIsTheDefaultAndStampsEpochPlusSimTime) {
  WireClock clock;
  EXPECT_EQ(clock.mode(), ClockMode::kRun);
  ASSERT_EQ(clock.AddRunEpoch(kEpoch), VisionError::kOk);
  ASSERT_EQ(clock.run_epoch_ns(), kEpoch);
  FrameTimes t{};
  // The wall clock passed in is ignored: the stamp is the run's, not the bridge's.
  ASSERT_EQ(clock.ForCamera(0, 1'000'000'000, 1'004'000'000, kNow + 1234.5, &t), VisionError::kOk);
  EXPECT_DOUBLE_EQ(t.t_capture, RunSeconds(kEpoch, 1'000'000'000));
  EXPECT_DOUBLE_EQ(t.t_sent, RunSeconds(kEpoch, 1'004'000'000));
  EXPECT_NEAR(t.t_sent - t.t_capture, 0.004, 1e-6);  // the modelled latency, in the same clock
  EXPECT_GE(t.t_sent, t.t_capture);
  double s = 0;
  ASSERT_EQ(clock.ForWorldState(2'500'000'000, kNow, &s), VisionError::kOk);
  EXPECT_DOUBLE_EQ(s, RunSeconds(kEpoch, 2'500'000'000));
  // Sim time 0 is the epoch itself: a valid run-clock stamp (sim mode refuses it).
  WireClock fresh;
  ASSERT_EQ(fresh.AddRunEpoch(kEpoch), VisionError::kOk);
  ASSERT_EQ(fresh.ForWorldState(0, kNow, &s), VisionError::kOk);
  EXPECT_DOUBLE_EQ(s, RunSeconds(kEpoch, 0));
  ASSERT_EQ(fresh.ForState(3 * kMs, kNow, &s), VisionError::kOk);  // the stateless form: the newest epoch
  EXPECT_DOUBLE_EQ(s, RunSeconds(kEpoch, 3 * kMs));
}

// turf at speed 2 (or slowed down by a loaded machine): the stamps advance with
// the simulation, not with the wall clock the frames happened to be sent at.
TEST(SslVisionTimestamps, RunModeFollowsSimulationTimeAtAnySpeed) {
  for (const double speed : {2.0, 0.5}) {
    WireClock run;
    const WireClock unix_clock(ClockMode::kUnix);
    ASSERT_EQ(run.AddRunEpoch(kEpoch), VisionError::kOk);
    std::vector<double> run_stamps, unix_stamps;
    for (int64_t sim_ns = kFrame; sim_ns <= 3'000'000'000; sim_ns += kFrame) {
      const double wall = kNow + static_cast<double>(sim_ns) * 1e-9 / speed;  // when the bridge sends it
      FrameTimes r{}, u{};
      ASSERT_EQ(run.ForCamera(0, sim_ns, sim_ns, wall, &r), VisionError::kOk);
      ASSERT_EQ(unix_clock.ForFrame(sim_ns, sim_ns, wall, &u), VisionError::kOk);
      run_stamps.push_back(r.t_capture);
      unix_stamps.push_back(u.t_capture);
    }
    // One wall second apart: `speed` seconds of stamps in run mode, one in unix mode.
    const size_t per_wall_s = static_cast<size_t>(std::llround(60.0 * speed));
    const double run_step = run_stamps[per_wall_s] - run_stamps[0];
    const double unix_step = unix_stamps[per_wall_s] - unix_stamps[0];
    EXPECT_NEAR(run_step, static_cast<double>(per_wall_s * kFrame) * 1e-9, 1e-6) << "speed " << speed;
    EXPECT_NEAR(run_step / unix_step, speed, 1e-5) << "speed " << speed;
    for (size_t i = 1; i < run_stamps.size(); ++i) ASSERT_GT(run_stamps[i], run_stamps[i - 1]);
  }
}

// One timeline's stamps, frame by frame, for cameras 0 and 1 from `from_ns` up to `to_ns`.
void Capture(WireClock* clock, int64_t from_ns, int64_t to_ns, std::vector<double>* stamps) {
  for (int64_t t = from_ns; t <= to_ns; t += kFrame) {
    for (uint32_t camera : {0u, 1u}) {
      FrameTimes ft{};
      ASSERT_EQ(clock->ForCamera(camera, t, t + 2 * kMs, kNow, &ft), VisionError::kOk) << t;
      ASSERT_GE(ft.t_sent, ft.t_capture);
      stamps->push_back(ft.t_capture);
    }
  }
}

void ExpectNonDecreasing(const std::vector<double>& stamps) {
  for (size_t i = 1; i < stamps.size(); ++i) ASSERT_GE(stamps[i], stamps[i - 1]) << "at " << i;
}

TEST(SslVisionTimestamps, RunModeStaysMonotonicAcrossAReset) {
  WireClock clock;
  ASSERT_EQ(clock.AddRunEpoch(kEpoch), VisionError::kOk);
  std::vector<double> stamps;
  const int64_t reached = 300 * kFrame + 5 * kMs;  // sim time at the reset
  Capture(&clock, kFrame, 300 * kFrame, &stamps);
  // turf-sim resets: the epoch advances by the sim time reached, sim time restarts.
  ASSERT_EQ(clock.AddRunEpoch(kEpoch + reached), VisionError::kOk);
  Capture(&clock, kFrame, 120 * kFrame, &stamps);
  ExpectNonDecreasing(stamps);
  // The new timeline's first frame is stamped with the new epoch, just after the old one's last.
  EXPECT_DOUBLE_EQ(stamps[600], RunSeconds(kEpoch + reached, kFrame));
  EXPECT_GT(stamps[600], stamps[599]);
  // A second reset, also seen by the world state stream.
  double before = 0, after = 0;
  ASSERT_EQ(clock.ForWorldState(120 * kFrame, kNow, &before), VisionError::kOk);
  ASSERT_EQ(clock.AddRunEpoch(kEpoch + reached + 120 * kFrame), VisionError::kOk);
  ASSERT_EQ(clock.ForWorldState(0, kNow, &after), VisionError::kOk);
  EXPECT_GE(after, before);
  EXPECT_DOUBLE_EQ(after, RunSeconds(kEpoch + reached + 120 * kFrame, 0));
}

// The epoch comes on the clock topic and the frames on another: either can be
// taken first. Old frames taken after the new epoch keep the old one; new
// frames taken before it wait (are refused) rather than go back in time.
TEST(SslVisionTimestamps, RunModeResetRacesWithTheClockTopic) {
  WireClock clock;
  ASSERT_EQ(clock.AddRunEpoch(kEpoch), VisionError::kOk);
  FrameTimes t{};
  ASSERT_EQ(clock.ForCamera(0, 100 * kFrame, 100 * kFrame, kNow, &t), VisionError::kOk);
  ASSERT_EQ(clock.ForCamera(1, 100 * kFrame, 100 * kFrame, kNow, &t), VisionError::kOk);
  const int64_t epoch2 = kEpoch + 101 * kFrame + kMs;
  ASSERT_EQ(clock.AddRunEpoch(epoch2), VisionError::kOk);
  // Camera 1's last frame of the old timeline, taken after the new epoch.
  ASSERT_EQ(clock.ForCamera(1, 101 * kFrame, 101 * kFrame, kNow, &t), VisionError::kOk);
  EXPECT_DOUBLE_EQ(t.t_capture, RunSeconds(kEpoch, 101 * kFrame));
  const double old_last = t.t_capture;
  ASSERT_EQ(clock.ForCamera(1, kFrame, kFrame, kNow, &t), VisionError::kOk);  // and its first new one
  EXPECT_DOUBLE_EQ(t.t_capture, RunSeconds(epoch2, kFrame));
  EXPECT_GT(t.t_capture, old_last);

  // Camera 0 sees the next reset before its epoch arrives: refused, output untouched.
  ASSERT_EQ(clock.ForCamera(0, 50 * kFrame, 50 * kFrame, kNow, &t), VisionError::kOk);
  FrameTimes untouched{-7.0, -7.0};
  EXPECT_EQ(clock.ForCamera(0, kFrame, kFrame, kNow, &untouched), VisionError::kNoEpoch);
  EXPECT_EQ(clock.ForCamera(0, 2 * kFrame, 2 * kFrame, kNow, &untouched), VisionError::kNoEpoch);
  EXPECT_EQ(untouched.t_capture, -7.0);
  const int64_t epoch3 = epoch2 + 50 * kFrame + kMs;
  ASSERT_EQ(clock.AddRunEpoch(epoch3), VisionError::kOk);
  ASSERT_EQ(clock.ForCamera(0, 3 * kFrame, 3 * kFrame, kNow, &t), VisionError::kOk);
  EXPECT_DOUBLE_EQ(t.t_capture, RunSeconds(epoch3, 3 * kFrame));

  // The world state written before its clock: the same wait.
  WireClock states;
  double s = -7.0;
  ASSERT_EQ(states.AddRunEpoch(kEpoch), VisionError::kOk);
  ASSERT_EQ(states.ForWorldState(10 * kMs, kNow, &s), VisionError::kOk);
  ASSERT_EQ(states.ForWorldState(10 * kMs, kNow, &s), VisionError::kOk);  // a teleport: same time, same timeline
  EXPECT_DOUBLE_EQ(s, RunSeconds(kEpoch, 10 * kMs));
  EXPECT_EQ(states.ForWorldState(0, kNow, &s), VisionError::kNoEpoch);
  ASSERT_EQ(states.AddRunEpoch(kEpoch + 10 * kMs), VisionError::kOk);
  ASSERT_EQ(states.ForWorldState(10 * kMs, kNow, &s), VisionError::kOk);
  EXPECT_DOUBLE_EQ(s, RunSeconds(kEpoch + 10 * kMs, 10 * kMs));
}

// Two resets while a camera saw nothing of the timeline between them (it was
// shorter than its frames): the camera's new frames skip that timeline's epoch.
TEST(SslVisionTimestamps, RunModeSkipsATimelineTooShortForTheFrame) {
  WireClock clock;
  ASSERT_EQ(clock.AddRunEpoch(kEpoch), VisionError::kOk);
  FrameTimes t{};
  ASSERT_EQ(clock.ForCamera(0, 60 * kFrame, 60 * kFrame, kNow, &t), VisionError::kOk);
  const int64_t epoch2 = kEpoch + 61 * kFrame;
  const int64_t epoch3 = epoch2 + 10 * kMs;  // reset again after 10 ms of sim time: no frame captured
  ASSERT_EQ(clock.AddRunEpoch(epoch2), VisionError::kOk);
  ASSERT_EQ(clock.AddRunEpoch(epoch3), VisionError::kOk);
  ASSERT_EQ(clock.ForCamera(0, kFrame, kFrame, kNow, &t), VisionError::kOk);
  EXPECT_DOUBLE_EQ(t.t_capture, RunSeconds(epoch3, kFrame));
}

TEST(SslVisionTimestamps, RunModeRefusesMissingAndImplausibleEpochs) {
  WireClock clock;
  FrameTimes t{-7.0, -7.0};
  double s = -7.0;
  // No epoch received yet: a named error, not a stamp near 1970.
  EXPECT_FALSE(clock.run_epoch_ns().has_value());
  EXPECT_EQ(clock.ForCamera(0, kFrame, kFrame, kNow, &t), VisionError::kNoEpoch);
  EXPECT_EQ(clock.ForFrame(kFrame, kFrame, kNow, &t), VisionError::kNoEpoch);
  EXPECT_EQ(clock.ForWorldState(kFrame, kNow, &s), VisionError::kNoEpoch);
  EXPECT_EQ(clock.ForState(kFrame, kNow, &s), VisionError::kNoEpoch);
  for (int64_t bad : {int64_t{0}, int64_t{-1}, std::numeric_limits<int64_t>::min(), int64_t{1'000'000'000},
                      kMinRunEpochNs - 1, kMaxRunEpochNs + 1, std::numeric_limits<int64_t>::max()}) {
    EXPECT_EQ(clock.AddRunEpoch(bad), VisionError::kBadEpoch) << bad;
    EXPECT_EQ(CheckRunEpoch(bad), VisionError::kBadEpoch) << bad;
  }
  EXPECT_FALSE(clock.run_epoch_ns().has_value());
  EXPECT_EQ(clock.ForCamera(0, kFrame, kFrame, kNow, &t), VisionError::kNoEpoch);
  EXPECT_EQ(t.t_capture, -7.0);
  EXPECT_EQ(s, -7.0);
  // A good one, then garbage: the good one stays.
  ASSERT_EQ(clock.AddRunEpoch(kEpoch), VisionError::kOk);
  EXPECT_EQ(clock.AddRunEpoch(-5), VisionError::kBadEpoch);
  ASSERT_EQ(clock.ForCamera(0, kFrame, kFrame, kNow, &t), VisionError::kOk);
  EXPECT_DOUBLE_EQ(t.t_capture, RunSeconds(kEpoch, kFrame));
  EXPECT_EQ(clock.run_epoch_ns(), kEpoch);
  // Times that would overflow epoch + sim time are refused, not wrapped.
  EXPECT_EQ(clock.ForCamera(1, std::numeric_limits<int64_t>::max() - 10, std::numeric_limits<int64_t>::max(), kNow, &t),
            VisionError::kOutOfRange);
  EXPECT_EQ(clock.ForWorldState(std::numeric_limits<int64_t>::max(), kNow, &s), VisionError::kOutOfRange);
  EXPECT_EQ(clock.ForWorldState(-1, kNow, &s), VisionError::kTimeNotPositive);
  // Camera ids are untrusted: at most 64 timelines are kept.
  WireClock many;
  ASSERT_EQ(many.AddRunEpoch(kEpoch), VisionError::kOk);
  for (uint32_t id = 0; id < 64; ++id) ASSERT_EQ(many.ForCamera(id, kFrame, kFrame, kNow, &t), VisionError::kOk);
  EXPECT_EQ(many.ForCamera(1000, kFrame, kFrame, kNow, &t), VisionError::kTooMany);
  EXPECT_EQ(many.ForCamera(5, 2 * kFrame, 2 * kFrame, kNow, &t), VisionError::kOk);
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
  for (ClockMode mode : {ClockMode::kRun, ClockMode::kUnix, ClockMode::kSim}) {
    WireClock clock(mode);
    ASSERT_EQ(clock.AddRunEpoch(kEpoch), VisionError::kOk);
    EXPECT_EQ(clock.ForFrame(0, 0, kNow, &t), VisionError::kTimeNotPositive) << ClockModeName(mode);
    EXPECT_EQ(clock.ForFrame(-5, 10, kNow, &t), VisionError::kTimeNotPositive);
    EXPECT_EQ(clock.ForFrame(2'000, 1'000, kNow, &t), VisionError::kTimeOrder);
    EXPECT_EQ(clock.ForCamera(0, 0, 0, kNow, &t), VisionError::kTimeNotPositive) << ClockModeName(mode);
    EXPECT_EQ(clock.ForCamera(0, 2'000, 1'000, kNow, &t), VisionError::kTimeOrder);
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
  EXPECT_STREQ(ClockModeName(ClockMode::kRun), "run");
  EXPECT_EQ(ParseClockMode("run"), ClockMode::kRun);
  EXPECT_EQ(ParseClockMode("sim"), ClockMode::kSim);
  EXPECT_EQ(ParseClockMode("unix"), ClockMode::kUnix);
  EXPECT_FALSE(ParseClockMode("wall").has_value());
}

}  // namespace
}  // namespace turf::vision
