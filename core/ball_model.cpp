#include "core/ball_model.h"

#include <algorithm>
#include <cmath>

#include "core/mjcf.h"

namespace turf {

namespace {
// Slip below which the ball counts as rolling (friction keeps it near zero).
constexpr double kSlipTolerance = 0.01;  // m/s
constexpr double kRelativeSlipTolerance = 0.01;
}  // namespace

double BallSlipSpeed(const BallState& ball, double radius) {
  // Contact point velocity: v + w x (0, 0, -r).
  const double cx = ball.velocity.x - radius * ball.angular_velocity.y;
  const double cy = ball.velocity.y + radius * ball.angular_velocity.x;
  return std::hypot(cx, cy);
}

Wrench CarpetFriction(const BallState& ball, double normal_force, const BallParams& params, double inertia, double dt) {
  if (normal_force <= 0.0) return {};
  const double r = params.radius;
  const double sx = ball.velocity.x - r * ball.angular_velocity.y;
  const double sy = ball.velocity.y + r * ball.angular_velocity.x;
  const double slip = std::hypot(sx, sy);
  if (slip < 1e-12) return {};
  // Force F at the contact point changes the slip by F dt (1/m + r^2/I).
  const double compliance = 1.0 / params.mass + r * r / inertia;
  const double mu = -params.acc_slide / kGravity;
  const double f = std::min(mu * normal_force, slip / (dt * compliance));
  const double fx = -f * sx / slip, fy = -f * sy / slip;
  // Torque of F at (0, 0, -r) from the centre: (r fy, -r fx, 0).
  return {{fx, fy, 0.0}, {r * fy, -r * fx, 0.0}};
}

Wrench RollingResistance(const BallState& ball, double normal_force, const BallParams& params, double inertia,
                         double dt) {
  const double speed = std::hypot(ball.velocity.x, ball.velocity.y);
  if (normal_force <= 0.0 || speed < 1e-9) return {};
  if (BallSlipSpeed(ball, params.radius) > kSlipTolerance + kRelativeSlipTolerance * speed) return {};
  const double load = normal_force / (params.mass * kGravity);
  const double decel = std::min(-params.acc_roll * load, speed / dt);
  const double ux = ball.velocity.x / speed, uy = ball.velocity.y / speed;
  const double tau = inertia * decel / params.radius;
  // The spin axis of rolling along u is z x u = (-uy, ux, 0).
  return {{-params.mass * decel * ux, -params.mass * decel * uy, 0.0}, {tau * uy, -tau * ux, 0.0}};
}

}  // namespace turf
