// Sensor and link models, checked statistically with fixed seeds and at least
// 20,000 samples each, against stated tolerances.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numeric>
#include <optional>

#include "core/joint_sensors.h"
#include "core/link_model.h"
#include "core/ssl_cameras.h"
#include "tests/core/test_scenes.h"

namespace turf {
namespace {

constexpr int kSamples = 40000;
constexpr int64_t kPeriodNs = 16'666'667;  // 60 Hz

struct MeanStd {
  double mean = 0.0;
  double stddev = 0.0;
};
MeanStd Stats(const std::vector<double>& v) {
  const double mean = std::accumulate(v.begin(), v.end(), 0.0) / v.size();
  double ss = 0.0;
  for (double x : v) ss += (x - mean) * (x - mean);
  return {mean, std::sqrt(ss / (v.size() - 1))};
}

TEST(LinkModel, BernoulliLossMatchesTheSetting) {
  for (double loss : {0.01, 0.1, 0.3}) {
    LinkParams p;
    p.loss = loss;
    Link link(p, 42);
    int lost = 0;
    for (int i = 0; i < kSamples; ++i) lost += !link.Transmit(i * kPeriodNs).has_value();
    EXPECT_NEAR(static_cast<double>(lost) / kSamples, loss, 0.005) << "loss " << loss;
  }
}

TEST(LinkModel, DelayMeanAndStddevMatchEachJitterKind) {
  struct Case {
    JitterKind kind;
    double jitter, expected_std, expected_extra_mean;
  };
  // Uniform on [-w, w] has stddev w / sqrt(3); exponential with mean m has stddev m.
  for (const Case& c :
       {Case{JitterKind::kGaussian, 0.003, 0.003, 0.0}, Case{JitterKind::kUniform, 0.004, 0.004 / std::sqrt(3.0), 0.0},
        Case{JitterKind::kExponential, 0.002, 0.002, 0.002}}) {
    LinkParams p;
    p.latency = 0.020;
    p.jitter = c.jitter;
    p.jitter_kind = c.kind;
    Link link(p, 7);
    std::vector<double> delays;
    for (int i = 0; i < kSamples; ++i) {
      const int64_t sent = i * kPeriodNs;
      const std::optional<int64_t> arrival = link.Transmit(sent);
      ASSERT_TRUE(arrival) << "lost on a link without loss";
      delays.push_back((*arrival - sent) * 1e-9);
    }
    const MeanStd s = Stats(delays);
    const double mean = p.latency + c.expected_extra_mean;
    EXPECT_NEAR(s.mean, mean, 0.05 * mean) << static_cast<int>(c.kind);
    EXPECT_NEAR(s.stddev, c.expected_std, 0.05 * c.expected_std) << static_cast<int>(c.kind);
  }
}

TEST(LinkModel, KeepsOrder) {
  LinkParams p;
  p.latency = 0.01;
  p.jitter = 0.05;  // far more than the sending period
  Link link(p, 3);
  int64_t last = 0;
  for (int i = 0; i < kSamples; ++i) {
    const std::optional<int64_t> arrival = link.Transmit(static_cast<int64_t>(i) * 1'000'000);
    ASSERT_TRUE(arrival) << "lost on a link without loss";
    ASSERT_GE(*arrival, last);
    last = *arrival;
  }
}

TEST(LinkModel, GilbertElliottBurstsHaveTheExpectedLengthAndRate) {
  LinkParams p;
  p.burst = {true, 0.02, 0.25, 0.0, 1.0};  // mean burst 4 samples, loss 0.02 / 0.27
  Link link(p, 11);
  std::vector<double> bursts;
  int run = 0, lost = 0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    if (!link.Transmit(i * kPeriodNs)) {
      ++run;
      ++lost;
    } else if (run > 0) {
      bursts.push_back(run);
      run = 0;
    }
  }
  ASSERT_GT(bursts.size(), 3000u);
  EXPECT_NEAR(Stats(bursts).mean, 1.0 / 0.25, 0.05 * 4.0);
  EXPECT_NEAR(static_cast<double>(lost) / n, 0.02 / 0.27, 0.005);
}

TEST(LinkModel, SameSeedSameFateOtherSeedOther) {
  LinkParams p;
  p.latency = 0.01;
  p.jitter = 0.002;
  p.loss = 0.2;
  auto run = [&](uint64_t seed) {
    Link link(p, seed);
    std::vector<int64_t> out;
    for (int i = 0; i < 1000; ++i) out.push_back(link.Transmit(i * kPeriodNs).value_or(-1));
    return out;
  };
  EXPECT_EQ(run(5), run(5));
  EXPECT_NE(run(5), run(6));
}

WorldSnapshot RobotsAndBall(const std::vector<std::pair<double, double>>& robots, Vec3 ball) {
  WorldSnapshot s;
  s.ball.position = ball;
  int id = 0;
  for (auto [x, y] : robots) {
    RobotSnapshot r;
    r.id = id++;
    r.on_field = true;
    r.x = x;
    r.y = y;
    s.robots.push_back(r);
  }
  return s;
}

// One robot at (2, 2) and the ball at (3, 1) under the first camera of an empty division A field.
class CameraModelOneRobot : public ::testing::Test {
 protected:
  const Scene scene = test::EmptyDivA();
  const CameraSpec cam = CameraLayout(scene)[0];
  const WorldSnapshot w = RobotsAndBall({{2.0, 2.0}}, {3.0, 1.0, 0.0215});
};

TEST_F(CameraModelOneRobot, PositionAndOrientationNoiseHaveTheConfiguredStddev) {
  CameraRealism r;
  r.robot_position_stddev = 0.01;
  r.robot_orientation_stddev = 0.02;
  r.ball_position_stddev = 0.003;
  Rng rng(StreamSeed(1, "test"));
  std::vector<double> dx, dphi, bx;
  for (int i = 0; i < kSamples; ++i) {
    CameraFrame f = Detect(cam, w, 0.15, 0.0215);
    ApplyValueModel(cam, r, w, scene.robot, rng, &f);
    dx.push_back(f.robots[0].x - 2.0);
    dphi.push_back(f.robots[0].orientation);
    bx.push_back(f.balls[0].position.x - 3.0);
  }
  EXPECT_NEAR(Stats(dx).stddev, 0.01, 0.05 * 0.01);
  EXPECT_NEAR(Stats(dx).mean, 0.0, 0.0005);
  EXPECT_NEAR(Stats(dphi).stddev, 0.02, 0.05 * 0.02);
  EXPECT_NEAR(Stats(bx).stddev, 0.003, 0.05 * 0.003);
}

TEST_F(CameraModelOneRobot, VanishingMatchesTheSetting) {
  CameraRealism r;
  r.robot_vanish = 0.05;
  r.ball_vanish = 0.2;
  Rng rng(9);
  int robots = 0, balls = 0;
  for (int i = 0; i < kSamples; ++i) {
    CameraFrame f = Detect(cam, w, 0.15, 0.0215);
    ApplyValueModel(cam, r, w, scene.robot, rng, &f);
    robots += static_cast<int>(f.robots.size());
    balls += static_cast<int>(f.balls.size());
  }
  EXPECT_NEAR(1.0 - static_cast<double>(robots) / kSamples, 0.05, 0.005);
  EXPECT_NEAR(1.0 - static_cast<double>(balls) / kSamples, 0.2, 0.005);
}

TEST(CameraModel, BallBehindARobotSeenFromTheCameraIsMissing) {
  const Scene scene = test::EmptyDivA();
  const CameraSpec cam = CameraLayout(scene)[0];  // above (3.3, 2.4) at 4 m
  CameraRealism r;
  r.ball_occlusion = true;
  Rng rng(1);
  // Ball far out at (5.5, 4.0); a robot just in front of it on the sight line.
  const Vec3 ball{5.5, 4.0, 0.0215};
  const double t = 0.96;  // a point on the ground track of the sight line, near the ball
  const double rx = cam.position.x + t * (ball.x - cam.position.x);
  const double ry = cam.position.y + t * (ball.y - cam.position.y);
  const WorldSnapshot hidden = RobotsAndBall({{rx, ry}}, ball);
  ASSERT_TRUE(BallOccluded(cam, ball, hidden, scene.robot.radius, scene.robot.height));
  CameraFrame f = Detect(cam, hidden, 0.15, 0.0215);
  ApplyValueModel(cam, r, hidden, scene.robot, rng, &f);
  EXPECT_TRUE(f.balls.empty());
  EXPECT_EQ(f.robots.size(), 1u);
  // The same robot beside the sight line, or behind the ball, hides nothing.
  const WorldSnapshot beside = RobotsAndBall({{rx, ry - 0.3}}, ball);
  EXPECT_FALSE(BallOccluded(cam, ball, beside, scene.robot.radius, scene.robot.height));
  const WorldSnapshot behind = RobotsAndBall({{ball.x + 0.3, ball.y}}, ball);
  EXPECT_FALSE(BallOccluded(cam, ball, behind, scene.robot.radius, scene.robot.height));
  // A flying ball above the robots is seen.
  EXPECT_FALSE(BallOccluded(cam, {ball.x, ball.y, 0.5}, hidden, scene.robot.radius, scene.robot.height));
}

TEST(CameraModel, ObjectsInTheOverlapAppearTwiceWithDifferentNoise) {
  Scene scene = test::Teams(1);
  scene.robots[0].pose = {0.05, 2.0, 0.0};  // in the strip cameras 0 and 1 share
  SslCameraSystem cams(scene);
  CameraRealism r;
  r.robot_position_stddev = 0.005;
  cams.SetRealism(r);
  WorldSnapshot w = RobotsAndBall({{0.05, 2.0}}, {3.0, -3.0, 0.0215});
  w.time_ns = kPeriodNs;
  cams.Capture(w);
  std::vector<CameraFrame> frames;
  cams.Release(w.time_ns, &frames);
  std::vector<double> xs;
  for (const CameraFrame& f : frames)
    for (const DetectedRobot& d : f.robots) xs.push_back(d.x);
  ASSERT_EQ(xs.size(), 2u);
  EXPECT_NE(xs[0], xs[1]);
  EXPECT_NEAR(xs[0], 0.05, 0.03);
  EXPECT_NEAR(xs[1], 0.05, 0.03);
}

std::vector<CameraFrame> RunCameras(uint64_t seed, const CameraRealism& r, int captures) {
  Scene scene = test::Teams(3);
  scene.seed = seed;
  SslCameraSystem cams(scene);
  cams.SetRealism(r);
  WorldSnapshot w = RobotsAndBall({{1, 1}, {-1, 1}, {-2, -2}, {3, -1}}, {0.5, 0.5, 0.0215});
  std::vector<CameraFrame> all, out;
  for (int64_t t = 0; t < captures * kPeriodNs; t += 2'000'000) {
    w.time_ns = t;
    if (cams.Due(t)) cams.Capture(w);
    cams.Release(t, &out);
    all.insert(all.end(), out.begin(), out.end());
  }
  return all;
}

bool SameFrames(const std::vector<CameraFrame>& a, const std::vector<CameraFrame>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    if (a[i].camera_id != b[i].camera_id || a[i].sent_time_ns != b[i].sent_time_ns ||
        a[i].robots.size() != b[i].robots.size() || a[i].balls.size() != b[i].balls.size())
      return false;
    for (size_t j = 0; j < a[i].robots.size(); ++j)
      if (a[i].robots[j].x != b[i].robots[j].x || a[i].robots[j].orientation != b[i].robots[j].orientation)
        return false;
  }
  return true;
}

CameraRealism Realistic() {
  CameraRealism r;
  r.robot_position_stddev = 0.002;
  r.robot_orientation_stddev = 0.01;
  r.ball_position_stddev = 0.002;
  r.robot_vanish = 0.01;
  r.ball_vanish = 0.02;
  r.ball_occlusion = true;
  r.confidence_spread = 0.1;
  r.processing_delay = 0.004;
  r.link.latency = 0.002;
  r.link.jitter = 0.001;
  r.link.loss = 0.01;
  return r;
}

TEST(CameraSystem, SameSeedGivesTheSameStreamOtherSeedAnother) {
  const auto a = RunCameras(1, Realistic(), 300);
  const auto b = RunCameras(1, Realistic(), 300);
  const auto c = RunCameras(2, Realistic(), 300);
  EXPECT_TRUE(SameFrames(a, b));
  EXPECT_FALSE(SameFrames(a, c));
}

TEST(CameraSystem, IdealIsExactGroundTruthReleasedAtCapture) {
  const auto frames = RunCameras(1, CameraRealism{}, 100);
  ASSERT_EQ(frames.size(), 4u * 99u);  // 4 cameras, captures at 1..99 periods before 100
  for (const CameraFrame& f : frames) {
    EXPECT_EQ(f.sent_time_ns, f.capture_time_ns);
    for (const DetectedRobot& r : f.robots) {
      EXPECT_EQ(r.confidence, 1.0f);
      EXPECT_TRUE((r.x == 1 && r.y == 1) || (r.x == -1 && r.y == 1) || (r.x == -2 && r.y == -2) ||
                  (r.x == 3 && r.y == -1));
    }
  }
}

TEST(CameraSystem, ProcessingDelayAndLatencyDelayTheRelease) {
  CameraRealism r;
  r.processing_delay = 0.004;
  r.link.latency = 0.010;
  Scene scene = test::Teams(1);
  SslCameraSystem cams(scene);
  cams.SetRealism(r);
  WorldSnapshot w = RobotsAndBall({{1, 1}}, {0, 0, 0.0215});
  w.time_ns = kPeriodNs;
  cams.Capture(w);
  std::vector<CameraFrame> out;
  cams.Release(w.time_ns + 13'000'000, &out);
  EXPECT_TRUE(out.empty());
  cams.Release(w.time_ns + 14'000'000, &out);
  ASSERT_EQ(out.size(), 4u);
  EXPECT_EQ(out[0].sent_time_ns - out[0].capture_time_ns, 4'000'000);
}

TEST(JointSensors, EncoderQuantisesAndAddsNoise) {
  EncoderRealism e{0.01, 0.0, {}};
  Rng rng(1);
  EXPECT_DOUBLE_EQ(MeasureJoint(0.123, e, rng), 0.12);
  EXPECT_DOUBLE_EQ(MeasureJoint(-0.127, e, rng), -0.13);
  e = {0.0, 0.002, {}};
  std::vector<double> v;
  for (int i = 0; i < kSamples; ++i) v.push_back(MeasureJoint(0.5, e, rng));
  EXPECT_NEAR(Stats(v).mean, 0.5, 1e-4);
  EXPECT_NEAR(Stats(v).stddev, 0.002, 0.05 * 0.002);
}

TEST(JointSensors, ImuHasBiasAndNoise) {
  ImuRealism imu{0.01, 0.005, 0.2, 0.05, {}};
  Rng rng(2);
  std::vector<double> gz, ax;
  for (int i = 0; i < kSamples; ++i) {
    gz.push_back(MeasureGyro({0, 0, 1.0}, imu, rng).z);
    ax.push_back(MeasureAccel({0, 0, 9.81}, imu, rng).x);
  }
  EXPECT_NEAR(Stats(gz).mean, 1.01, 1e-3);
  EXPECT_NEAR(Stats(gz).stddev, 0.005, 0.05 * 0.005);
  EXPECT_NEAR(Stats(ax).mean, 0.2, 2e-3);
  EXPECT_NEAR(Stats(ax).stddev, 0.05, 0.05 * 0.05);
}

}  // namespace
}  // namespace turf
