// rt/low_state from a simulated Booster robot's state (shared/protocols/booster-sdk-dds.md):
//  - imu_state: roll, pitch, yaw of the trunk (the robot's IMU orientation, Z-Y-X angles), its gyro (rad/s) and
//    accelerometer (specific force, m/s^2), in the IMU frame (x forward, y left, z up);
//  - motor_state_serial: per joint in the SDK's order, position, velocity and the motor's torque of the last step;
//  - motor_state_parallel: the same values. turf's ankles are serial joints only (as every published model's), so
//    both lists carry joint space (the facts' documented deviation for the crank motors).
// Not simulated: ddq (0), temperature (a constant 40 deg C), lost packets (0).
#pragma once

#include "codecs/booster/robots.h"
#include "core/legged/legged_world.h"
#include "turf/idl/BoosterLowLevel.h"

namespace turf::booster {

inline constexpr uint8_t kSimulatedTemperature = 40;  // deg C, below the SDK users' "hot" thresholds (76)

// `robot`'s joints must be in the SDK's order (IdentifyRobot(robot.joint_names) answered a model).
void EncodeLowState(const LeggedRobotState& robot, booster_interface::msg::dds_::LowState_* out);

// Z-Y-X (yaw, pitch, roll) angles of a w, x, y, z quaternion, as roll, pitch, yaw.
std::array<float, 3> RollPitchYaw(const std::array<double, 4>& q);

}  // namespace turf::booster
