#include "core/drive.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

namespace turf {

namespace {

// Row i maps a robot-frame velocity to wheel i's rim speed: the wheel at angle
// phi rolls along the tangent (-sin phi, cos phi) and turns with the body.
Eigen::Matrix<double, 4, 3> WheelJacobian(const DriveParams& drive) {
  Eigen::Matrix<double, 4, 3> j;
  for (int i = 0; i < 4; ++i) {
    const double phi = drive.wheel_angles[i];
    j.row(i) << -std::sin(phi), std::cos(phi), drive.wheel_distance;
  }
  return j;
}

}  // namespace

std::array<double, 4> LocalToWheels(const PlanarVelocity& local, const DriveParams& drive) {
  const Eigen::Vector4d w = WheelJacobian(drive) * Eigen::Vector3d(local.x, local.y, local.omega);
  return {w[0], w[1], w[2], w[3]};
}

PlanarVelocity WheelsToLocal(const std::array<double, 4>& wheels, const DriveParams& drive) {
  const Eigen::Matrix<double, 4, 3> j = WheelJacobian(drive);
  const Eigen::Vector4d w(wheels[0], wheels[1], wheels[2], wheels[3]);
  const Eigen::Vector3d v = (j.transpose() * j).ldlt().solve(j.transpose() * w);
  return {v[0], v[1], v[2]};
}

PlanarVelocity DesiredVelocity(const RobotCommand& command, double yaw, const DriveParams& drive) {
  PlanarVelocity local;
  bool field_frame = false;
  switch (command.move) {
    case MoveKind::kNone:
      return {};
    case MoveKind::kLocalVelocity:
      local = {command.velocity.x, command.velocity.y, command.velocity.z};
      break;
    case MoveKind::kGlobalVelocity:
      local = {command.velocity.x, command.velocity.y, command.velocity.z};
      field_frame = true;
      break;
    case MoveKind::kWheelVelocity:
      local = WheelsToLocal(command.wheel_velocity, drive);
      break;
  }
  PlanarVelocity v = local;
  if (!field_frame) {
    const double c = std::cos(yaw), s = std::sin(yaw);
    v.x = c * local.x - s * local.y;
    v.y = s * local.x + c * local.y;
  }
  const double speed = std::hypot(v.x, v.y);
  if (speed > drive.max_speed) {
    v.x *= drive.max_speed / speed;
    v.y *= drive.max_speed / speed;
  }
  v.omega = std::clamp(v.omega, -drive.max_angular_speed, drive.max_angular_speed);
  return v;
}

PlanarForce DriveForce(const PlanarVelocity& current, const PlanarVelocity& desired, double mass, double inertia,
                       double dt, const DriveParams& drive) {
  double dx = desired.x - current.x;
  double dy = desired.y - current.y;
  // Speeding up when the change points along the motion, braking otherwise.
  const bool speeding_up = dx * current.x + dy * current.y >= 0.0;
  const double max_dv = (speeding_up ? drive.acc_speedup : drive.acc_brake) * dt;
  const double dv = std::hypot(dx, dy);
  if (dv > max_dv) {
    dx *= max_dv / dv;
    dy *= max_dv / dv;
  }
  const double max_dw = drive.acc_angular * dt;
  const double dw = std::clamp(desired.omega - current.omega, -max_dw, max_dw);
  return {mass * dx / dt, mass * dy / dt, inertia * dw / dt};
}

}  // namespace turf
