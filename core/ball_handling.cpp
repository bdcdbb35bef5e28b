#include "core/ball_handling.h"

#include <cmath>

namespace turf {

Vec3 BallInRobotFrame(const RobotKinematics& robot, const Vec3& ball) {
  const double dx = ball.x - robot.x, dy = ball.y - robot.y;
  const double c = std::cos(robot.yaw), s = std::sin(robot.yaw);
  return {c * dx + s * dy, -s * dx + c * dy, ball.z};
}

namespace {
// A ball placed exactly at the reach counts as within it, whatever the
// rounding of its position: 1 micrometre, far below any contact effect.
constexpr double kReachRounding = 1e-6;  // m
}  // namespace

bool BallAtFront(const RobotKinematics& robot, const Vec3& ball, const RobotParams& params, double ball_radius,
                 double reach) {
  const Vec3 b = BallInRobotFrame(robot, ball);
  const double half_face =
      std::sqrt(params.radius * params.radius - params.center_to_dribbler * params.center_to_dribbler);
  const double gap = b.x - params.center_to_dribbler - ball_radius;  // ball surface to face
  return gap > -ball_radius && gap <= reach + kReachRounding && std::abs(b.y) <= half_face && b.z <= 2.0 * ball_radius;
}

Vec3 KickVelocity(const RobotKinematics& robot, const Vec3& ball_velocity, KickKind kind, double speed,
                  double chip_angle, const KickerParams& kicker) {
  const bool chip = kind == KickKind::kChip;
  const double angle = chip ? (chip_angle > 0.0 ? chip_angle : kicker.default_chip_angle) : 0.0;
  const double horizontal = speed * std::cos(angle);
  const double c = std::cos(robot.yaw), s = std::sin(robot.yaw);
  // The ball's sideways velocity relative to the robot (along the heading's left normal).
  const double across = -(ball_velocity.x - robot.vx) * s + (ball_velocity.y - robot.vy) * c;
  Vec3 v{robot.vx + horizontal * c - across * s, robot.vy + horizontal * s + across * c, speed * std::sin(angle)};
  const double limit = chip ? kicker.max_chip_speed : kicker.max_flat_speed;
  const double total = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
  if (total > limit && total > 0.0) {
    const double k = limit / total;
    v = {v.x * k, v.y * k, v.z * k};
  }
  return v;
}

Vec3 DribblerForce(const RobotKinematics& robot, const BallState& ball, const RobotParams& params, double ball_radius) {
  const double c = std::cos(robot.yaw), s = std::sin(robot.yaw);
  const double reach = params.center_to_dribbler + ball_radius;
  // Hold point and its velocity (the face moves with the body and its turn).
  const double px = robot.x + c * reach, py = robot.y + s * reach;
  const double pvx = robot.vx - robot.omega * s * reach, pvy = robot.vy + robot.omega * c * reach;
  const DribblerParams& d = params.dribbler;
  double fx = d.stiffness * (px - ball.position.x) + d.damping * (pvx - ball.velocity.x);
  double fy = d.stiffness * (py - ball.position.y) + d.damping * (pvy - ball.velocity.y);
  const double f = std::hypot(fx, fy);
  if (f > d.max_force) {
    fx *= d.max_force / f;
    fy *= d.max_force / f;
  }
  return {fx, fy, 0.0};
}

}  // namespace turf
