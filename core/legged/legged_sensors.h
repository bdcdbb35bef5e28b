// What a legged robot's own sensors report: the joint encoder and IMU models
// of core/joint_sensors.h applied to a legged world's state. The noise is a
// function of (scene seed, robot, sensor, frame): measuring a frame twice
// gives the same values, so readings never depend on how often, when or by
// whom the state is read, nor on another robot. Ideal realism (the default)
// leaves the state exact.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/legged/legged_world.h"
#include "core/rng.h"
#include "core/sensor_realism.h"

namespace turf {

class LeggedSensors {
 public:
  LeggedSensors(uint64_t seed, const std::vector<std::string>& robots);
  // Encoders: joint positions quantised and noisy. IMU: gyro and accelerometer
  // with bias and noise. Velocities, efforts, forces and poses stay exact.
  // The noise of `state->frame`.
  void Apply(const SensorRealism& realism, LeggedWorldState* state) const;

 private:
  std::vector<uint64_t> encoder_;  // per robot: the stream's seed
  std::vector<uint64_t> imu_;
};

}  // namespace turf
