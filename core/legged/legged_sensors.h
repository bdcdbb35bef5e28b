// What a legged robot's own sensors report: the joint encoder and IMU models
// of core/joint_sensors.h applied to a legged world's state. One random
// stream per robot and sensor (seeded from the scene seed and the robot's
// name), so a robot's readings never depend on another robot or on timing.
// Ideal realism (the default) leaves the state exact.
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
  LeggedSensors(uint64_t seed, std::vector<std::string> robots);
  void Reset();  // every stream back to its start (a world reset)
  // Encoders: joint positions quantised and noisy. IMU: gyro and accelerometer
  // with bias and noise. Velocities, efforts, forces and poses stay exact.
  void Apply(const SensorRealism& realism, LeggedWorldState* state);

 private:
  uint64_t seed_;
  std::vector<std::string> robots_;
  std::vector<Rng> encoder_;
  std::vector<Rng> imu_;
};

}  // namespace turf
