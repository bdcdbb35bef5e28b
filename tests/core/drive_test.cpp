#include "core/drive.h"

#include <gtest/gtest.h>

#include <cmath>

namespace turf {
namespace {

TEST(Drive, WheelKinematicsRoundTrip) {
  const DriveParams d;
  const PlanarVelocity v{0.7, -0.4, 2.5};
  const PlanarVelocity back = WheelsToLocal(LocalToWheels(v, d), d);
  EXPECT_NEAR(back.x, v.x, 1e-12);
  EXPECT_NEAR(back.y, v.y, 1e-12);
  EXPECT_NEAR(back.omega, v.omega, 1e-12);
}

TEST(Drive, PositiveWheelSpeedsTurnCounterClockwise) {
  const DriveParams d;
  const PlanarVelocity v = WheelsToLocal({1.0, 1.0, 1.0, 1.0}, d);
  EXPECT_NEAR(v.x, 0.0, 1e-12);
  EXPECT_NEAR(v.y, 0.0, 1e-12);
  EXPECT_NEAR(v.omega, 1.0 / d.wheel_distance, 1e-9);
}

TEST(Drive, ForwardMovesFrontWheelsOppositely) {
  const DriveParams d;
  const auto w = LocalToWheels({1.0, 0.0, 0.0}, d);
  // front_right at -60 deg rolls along (sin 60, cos 60): +0.866; front_left -0.866.
  EXPECT_NEAR(w[0], std::sin(M_PI / 3), 1e-12);
  EXPECT_NEAR(w[3], -std::sin(M_PI / 3), 1e-12);
}

TEST(Drive, DesiredVelocityRotatesLocalIntoFieldAndSaturates) {
  DriveParams d;
  d.max_speed = 2.0;
  RobotCommand c;
  c.move = MoveKind::kLocalVelocity;
  c.velocity = {1.0, 0.0, 50.0};
  const PlanarVelocity v = DesiredVelocity(c, M_PI / 2, d);
  EXPECT_NEAR(v.x, 0.0, 1e-12);
  EXPECT_NEAR(v.y, 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(v.omega, d.max_angular_speed);
  c.velocity = {6.0, 8.0, 0.0};
  const PlanarVelocity fast = DesiredVelocity(c, 0.0, d);
  EXPECT_NEAR(std::hypot(fast.x, fast.y), 2.0, 1e-12);
  EXPECT_NEAR(fast.y / fast.x, 8.0 / 6.0, 1e-12);
}

TEST(Drive, GlobalVelocityIgnoresHeading) {
  const DriveParams d;
  RobotCommand c;
  c.move = MoveKind::kGlobalVelocity;
  c.velocity = {0.5, -0.5, 0.0};
  const PlanarVelocity v = DesiredVelocity(c, 1.234, d);
  EXPECT_DOUBLE_EQ(v.x, 0.5);
  EXPECT_DOUBLE_EQ(v.y, -0.5);
}

TEST(Drive, ForceRespectsSpeedupAndBrakeLimits) {
  DriveParams d;
  d.acc_speedup = 3.0;
  d.acc_brake = 5.0;
  const double m = 2.0, dt = 0.002;
  const PlanarForce up = DriveForce({0, 0, 0}, {2.0, 0, 0}, m, 0.01, dt, d);
  EXPECT_NEAR(up.x, m * 3.0, 1e-9);
  const PlanarForce brake = DriveForce({2.0, 0, 0}, {0, 0, 0}, m, 0.01, dt, d);
  EXPECT_NEAR(brake.x, -m * 5.0, 1e-9);
  // A change smaller than one step's limit is reached exactly.
  const PlanarForce small = DriveForce({1.0, 0, 0}, {1.001, 0, 0}, m, 0.01, dt, d);
  EXPECT_NEAR(small.x, m * 0.001 / dt, 1e-9);
}

}  // namespace
}  // namespace turf
