#include "core/legged/legged_sensors.h"

#include "core/joint_sensors.h"

namespace turf {

LeggedSensors::LeggedSensors(uint64_t seed, std::vector<std::string> robots) : seed_(seed), robots_(std::move(robots)) {
  Reset();
}

void LeggedSensors::Reset() {
  encoder_.clear();
  imu_.clear();
  for (const std::string& r : robots_) {
    encoder_.emplace_back(StreamSeed(seed_, "legged/" + r + "/encoder"));
    imu_.emplace_back(StreamSeed(seed_, "legged/" + r + "/imu"));
  }
}

void LeggedSensors::Apply(const SensorRealism& realism, LeggedWorldState* state) {
  const bool encoders = realism.encoder.resolution > 0 || realism.encoder.noise_stddev > 0;
  const ImuRealism& i = realism.imu;
  const bool imu = i.gyro_bias != 0 || i.gyro_noise_stddev > 0 || i.accel_bias != 0 || i.accel_noise_stddev > 0;
  for (size_t r = 0; r < state->robots.size() && r < robots_.size(); ++r) {
    LeggedRobotState& robot = state->robots[r];
    if (encoders) {
      for (double& q : robot.joint_positions) q = MeasureJoint(q, realism.encoder, encoder_[r]);
    }
    if (imu && robot.has_imu) {
      const Vec3 gyro = MeasureGyro({robot.gyro[0], robot.gyro[1], robot.gyro[2]}, i, imu_[r]);
      const Vec3 accel =
          MeasureAccel({robot.accelerometer[0], robot.accelerometer[1], robot.accelerometer[2]}, i, imu_[r]);
      robot.gyro = {gyro.x, gyro.y, gyro.z};
      robot.accelerometer = {accel.x, accel.y, accel.z};
    }
  }
}

}  // namespace turf
