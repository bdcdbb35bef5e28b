// The omni drive, modelled as grSim's authors argue: no simulated rollers, but
// every command passes through wheel kinematics, top-speed saturation and
// traction (acceleration) limits before it becomes a force on the body.
#pragma once

#include <array>

#include "core/scene.h"
#include "core/types.h"

namespace turf {

// Planar body velocity: x, y (m/s) and omega (rad/s), in the frame the
// function names.
struct PlanarVelocity {
  double x = 0.0;
  double y = 0.0;
  double omega = 0.0;
};

struct PlanarForce {
  double x = 0.0;
  double y = 0.0;
  double torque = 0.0;
};

// Wheel rim speeds from a robot-frame velocity, and the least-squares inverse
// (four wheels over-determine three body velocities).
std::array<double, 4> LocalToWheels(const PlanarVelocity& local, const DriveParams& drive);
PlanarVelocity WheelsToLocal(const std::array<double, 4>& wheels, const DriveParams& drive);

// The field-frame velocity a command asks for, saturated at the top speeds.
PlanarVelocity DesiredVelocity(const RobotCommand& command, double yaw, const DriveParams& drive);

// The force that brings `current` to `desired` in one step of `dt`, limited by
// the traction (acceleration) limits: speeding up and braking differ.
PlanarForce DriveForce(const PlanarVelocity& current, const PlanarVelocity& desired, double mass, double inertia,
                       double dt, const DriveParams& drive);

}  // namespace turf
