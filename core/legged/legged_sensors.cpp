#include "core/legged/legged_sensors.h"

#include "core/joint_sensors.h"

namespace turf {

LeggedSensors::LeggedSensors(uint64_t seed, const std::vector<std::string>& robots) {
  for (const std::string& r : robots) {
    encoder_.push_back(StreamSeed(seed, "legged/" + r + "/encoder"));
    imu_.push_back(StreamSeed(seed, "legged/" + r + "/imu"));
  }
}

namespace {

// The generator of one stream at one frame (SplitMix64 of seed and frame).
Rng AtFrame(uint64_t stream_seed, uint64_t frame) {
  uint64_t z = stream_seed + (frame + 1) * 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return Rng(z ^ (z >> 31));
}

}  // namespace

void LeggedSensors::Apply(const SensorRealism& realism, LeggedWorldState* state) const {
  const bool encoders = realism.encoder.resolution > 0 || realism.encoder.noise_stddev > 0;
  const ImuRealism& i = realism.imu;
  const bool imu = i.gyro_bias != 0 || i.gyro_noise_stddev > 0 || i.accel_bias != 0 || i.accel_noise_stddev > 0;
  for (size_t r = 0; r < state->robots.size() && r < encoder_.size(); ++r) {
    LeggedRobotState& robot = state->robots[r];
    if (encoders) {
      Rng rng = AtFrame(encoder_[r], state->frame);
      for (double& q : robot.joint_positions) q = MeasureJoint(q, realism.encoder, rng);
    }
    if (imu && robot.has_imu) {
      Rng rng = AtFrame(imu_[r], state->frame);
      const Vec3 gyro = MeasureGyro({robot.gyro[0], robot.gyro[1], robot.gyro[2]}, i, rng);
      const Vec3 accel = MeasureAccel({robot.accelerometer[0], robot.accelerometer[1], robot.accelerometer[2]}, i, rng);
      robot.gyro = {gyro.x, gyro.y, gyro.z};
      robot.accelerometer = {accel.x, accel.y, accel.z};
    }
  }
}

}  // namespace turf
