#include "core/ssl_cameras.h"

#include <gtest/gtest.h>

#include <cmath>

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
    if (!Detect(c, s, 0.15, 0.0215).robots.empty()) ids.push_back(c.id);
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
  const CameraFrame f = Detect(cams[0], s, 0.15, 0.0215);
  ASSERT_EQ(f.robots.size(), 1u);
  EXPECT_DOUBLE_EQ(f.robots[0].x, 1.5);
  EXPECT_DOUBLE_EQ(f.robots[0].orientation, 0.7);
  ASSERT_EQ(f.balls.size(), 1u);
  EXPECT_DOUBLE_EQ(f.balls[0].position.y, 3.0);
}

// A chipped ball is reported as SSL-Vision reports it: its blob projected from the camera onto the plane of a ball on
// the carpet, so further from the camera than it is, by the similar triangles of the camera's height; two cameras
// report it at two places. On the carpet it is where it is.
TEST(Cameras, ABallInTheAirIsProjectedOntoTheCarpetFromEachCamera) {
  const auto cams = CameraLayout(test::EmptyDivA());
  ASSERT_GE(cams.size(), 2u);
  const double r = 0.0215;
  const Vec3 air{0.05, 0.05, 0.5};  // above the overlap of the cameras at the centre
  for (const CameraSpec& c : cams) {
    const Vec3 seen = SeenBallPosition(c.position, air, r);
    const double t = (c.position.z - r) / (c.position.z - air.z);  // > 1: beyond the ball, seen from the camera
    EXPECT_NEAR(seen.x, c.position.x + t * (air.x - c.position.x), 1e-12) << c.id;
    EXPECT_NEAR(seen.y, c.position.y + t * (air.y - c.position.y), 1e-12) << c.id;
    EXPECT_DOUBLE_EQ(seen.z, r);
    EXPECT_GT(std::hypot(seen.x - air.x, seen.y - air.y), 0.2) << c.id << ": a 0.5 m high ball moves visibly";
    const Vec3 resting = SeenBallPosition(c.position, {1.0, -2.0, r}, r);
    EXPECT_DOUBLE_EQ(resting.x, 1.0);
    EXPECT_DOUBLE_EQ(resting.y, -2.0);
  }
  const Vec3 in_quadrant{2.0, 1.5, 0.5};  // camera 0's (+x+y), its projection too
  const CameraFrame f = Detect(cams[0], OneRobotAt(3, 3, in_quadrant), 0.15, r);
  ASSERT_EQ(f.balls.size(), 1u);
  const Vec3 expected = SeenBallPosition(cams[0].position, in_quadrant, r);
  EXPECT_DOUBLE_EQ(f.balls[0].position.x, expected.x);
  EXPECT_DOUBLE_EQ(f.balls[0].position.y, expected.y);
  EXPECT_LT(expected.x, in_quadrant.x);  // away from the camera above the quadrant's middle
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
