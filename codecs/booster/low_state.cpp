#include "codecs/booster/low_state.h"

#include <algorithm>
#include <cmath>

namespace turf::booster {

namespace bi = booster_interface::msg::dds_;

std::array<float, 3> RollPitchYaw(const std::array<double, 4>& q) {
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  const double roll = std::atan2(2 * (w * x + y * z), 1 - 2 * (x * x + y * y));
  const double pitch = std::asin(std::clamp(2 * (w * y - z * x), -1.0, 1.0));
  const double yaw = std::atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z));
  return {static_cast<float>(roll), static_cast<float>(pitch), static_cast<float>(yaw)};
}

void EncodeLowState(const LeggedRobotState& robot, bi::LowState_* out) {
  bi::ImuState_& imu = out->imu_state();
  imu.rpy(RollPitchYaw(robot.orientation));
  for (int i = 0; i < 3; ++i) {
    imu.gyro()[i] = static_cast<float>(robot.gyro[i]);
    imu.acc()[i] = static_cast<float>(robot.accelerometer[i]);
  }
  std::vector<bi::MotorState_>& serial = out->motor_state_serial();
  serial.resize(robot.joint_positions.size());
  for (size_t j = 0; j < serial.size(); ++j) {
    bi::MotorState_& m = serial[j];
    m.mode(0);
    m.q(static_cast<float>(robot.joint_positions[j]));
    m.dq(static_cast<float>(j < robot.joint_velocities.size() ? robot.joint_velocities[j] : 0.0));
    m.ddq(0.0f);
    m.tau_est(static_cast<float>(j < robot.joint_efforts.size() ? robot.joint_efforts[j] : 0.0));
    m.temperature(kSimulatedTemperature);
    m.lost(0);
    m.reserve({0, 0});
  }
  out->motor_state_parallel(serial);
}

}  // namespace turf::booster
