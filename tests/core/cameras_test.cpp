#include "core/ssl_cameras.h"

#include <gtest/gtest.h>

#include "tests/core/test_scenes.h"

namespace turf {
namespace {

WorldSnapshot OneRobotAt(double x, double y, Vec3 ball) {
  WorldSnapshot s;
  s.time_ns = 0;
  s.ball.position = ball;
  RobotSnapshot r;
  r.on_field = true;
  r.x = x;
  r.y = y;
  s.robots.push_back(r);
  RobotSnapshot parked;
  parked.id = 1;
  parked.on_field = false;
  s.robots.push_back(parked);
  return s;
}

std::vector<int> CamerasSeeingRobot(const std::vector<CameraSpec>& cams, const WorldSnapshot& s) {
  std::vector<int> ids;
  for (const CameraSpec& c : cams)
    if (!Detect(c, s, 0.15).robots.empty()) ids.push_back(c.id);
  return ids;
}

TEST(Cameras, DivisionAHasFourQuadrantsWithOverlap) {
  const Scene scene = test::EmptyDivA();
  const auto cams = CameraLayout(scene);
  ASSERT_EQ(cams.size(), 4u);
  const Vec3 far_ball{100, 100, 0};
  EXPECT_EQ(CamerasSeeingRobot(cams, OneRobotAt(3, 2, far_ball)), std::vector<int>({0}));
  EXPECT_EQ(CamerasSeeingRobot(cams, OneRobotAt(-3, 2, far_ball)), std::vector<int>({1}));
  EXPECT_EQ(CamerasSeeingRobot(cams, OneRobotAt(-3, -2, far_ball)), std::vector<int>({2}));
  EXPECT_EQ(CamerasSeeingRobot(cams, OneRobotAt(3, -2, far_ball)), std::vector<int>({3}));
  // Within the 0.2 m overlap strip at x = 0: both cameras of that side.
  EXPECT_EQ(CamerasSeeingRobot(cams, OneRobotAt(0.05, 2, far_ball)), std::vector<int>({0, 1}));
  EXPECT_EQ(CamerasSeeingRobot(cams, OneRobotAt(0.15, 2, far_ball)), std::vector<int>({0}));
  // The centre is seen by all four.
  EXPECT_EQ(CamerasSeeingRobot(cams, OneRobotAt(0.0, 0.0, far_ball)), std::vector<int>({0, 1, 2, 3}));
  // Up to the walls, incl. the boundary.
  const FieldParams& f = scene.field;
  EXPECT_EQ(CamerasSeeingRobot(cams, OneRobotAt(f.length / 2 + 0.5, f.width / 2 + 0.25, far_ball)),
            std::vector<int>({0}));
}

TEST(Cameras, DivisionBHasTwoHalves) {
  Scene scene = test::EmptyDivA();
  scene.field = FieldForDivision(Division::kB);
  const auto cams = CameraLayout(scene);
  ASSERT_EQ(cams.size(), 2u);
  const Vec3 far_ball{100, 100, 0};
  EXPECT_EQ(CamerasSeeingRobot(cams, OneRobotAt(-2, 2, far_ball)), std::vector<int>({0}));
  EXPECT_EQ(CamerasSeeingRobot(cams, OneRobotAt(2, -2, far_ball)), std::vector<int>({1}));
  EXPECT_EQ(CamerasSeeingRobot(cams, OneRobotAt(0.0, 0.0, far_ball)), std::vector<int>({0, 1}));
}

TEST(Cameras, ReportsExactPosesAndSkipsParkedRobots) {
  const auto cams = CameraLayout(test::EmptyDivA());
  WorldSnapshot s = OneRobotAt(1.5, 1.0, {2.0, 3.0, 0.0215});
  s.robots[0].yaw = 0.7;
  const CameraFrame f = Detect(cams[0], s, 0.15);
  ASSERT_EQ(f.robots.size(), 1u);
  EXPECT_DOUBLE_EQ(f.robots[0].x, 1.5);
  EXPECT_DOUBLE_EQ(f.robots[0].orientation, 0.7);
  ASSERT_EQ(f.balls.size(), 1u);
  EXPECT_DOUBLE_EQ(f.balls[0].position.y, 3.0);
}

TEST(Cameras, CaptureAtTheConfiguredRateOnTheSimulationClock) {
  Scene scene = test::EmptyDivA();
  scene.cameras.rate_hz = 60.0;
  SslCameraSystem cams(scene);
  WorldSnapshot s = OneRobotAt(1, 1, {0, 0, 0});
  std::vector<CameraFrame> frames;
  int captures = 0;
  const int64_t step = 2000000;  // 2 ms
  for (int64_t t = 0; t < 10'000'000'000; t += step) {
    s.time_ns = t;
    if (cams.Due(t)) {
      cams.Capture(s);
      cams.Release(t, &frames);
      ++captures;
      ASSERT_EQ(frames.size(), 4u);
      EXPECT_EQ(frames[0].frame_number, static_cast<uint64_t>(captures));
      EXPECT_EQ(frames[0].capture_time_ns, t);
      EXPECT_GT(t, 0);  // never a frame at time zero
    }
  }
  EXPECT_EQ(captures, 599);  // 10 s at 60 Hz, no drift: 1/60 s .. 599/60 s
}

}  // namespace
}  // namespace turf
