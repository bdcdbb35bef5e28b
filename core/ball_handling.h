// How a robot acts on the ball: the kicker launches it and the dribbler holds
// it, both only at the flat front face. Pure functions of poses and velocities.
#pragma once

#include <cstdint>

#include "core/scene.h"
#include "core/types.h"

namespace turf {

struct BallState {
  Vec3 position;
  Vec3 velocity;
  Vec3 angular_velocity;
};

struct RobotKinematics {
  double x = 0.0;
  double y = 0.0;
  double yaw = 0.0;
  double vx = 0.0;
  double vy = 0.0;
  double omega = 0.0;
};

// A kick the robot's kicker is armed with: it fires when the ball is within
// reach at a step at or before `until_ns` (simulation time). kNone: disarmed.
struct ArmedKick {
  KickKind kind = KickKind::kNone;
  double speed = 0.0;
  double chip_angle = 0.0;
  int64_t until_ns = 0;
};

// The ball's centre in the robot frame (x forward, y left, z up).
Vec3 BallInRobotFrame(const RobotKinematics& robot, const Vec3& ball);

// True while the ball touches the front face (within `reach` of it), low
// enough for the kicker to hit it.
bool BallAtFront(const RobotKinematics& robot, const Vec3& ball, const RobotParams& params, double ball_radius,
                 double reach);

// The ball's velocity after a kick: the robot's own velocity plus `speed` along
// the heading, raised by the chip angle, plus what the ball brought across the
// heading (its velocity relative to the robot, sideways: the kicker plate pushes
// along the heading only, so a redirected pass keeps it, as in grSim's kick and
// ER-Force's impulse); the total is clamped to the kicker's limit for that kind.
// `chip_angle` 0 means the scene's default.
Vec3 KickVelocity(const RobotKinematics& robot, const Vec3& ball_velocity, KickKind kind, double speed,
                  double chip_angle, const KickerParams& kicker);

// The dribbler's pull on a captured ball (field frame, horizontal): a damped
// spring to the hold point in front of the face, limited to max_force.
Vec3 DribblerForce(const RobotKinematics& robot, const BallState& ball, const RobotParams& params, double ball_radius);

}  // namespace turf
