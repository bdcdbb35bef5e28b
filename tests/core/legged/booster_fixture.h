// The Booster T1 and K1 scenes (configs/scenes/t1_stand.yaml, k1_stand.yaml)
// and measures of a robot's state for the Booster tests.
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/legged/legged_world.h"
#include "loader/legged_scene_yaml.h"

namespace turf::testing {

// "t1" or "k1": the shipped standing scene.
inline LeggedScene BoosterStandScene(const std::string& robot) {
  LeggedSceneLoadResult r = LoadLeggedSceneFile(TURF_SOURCE_DIR "/configs/scenes/" + robot + "_stand.yaml");
  if (!r.scene) throw std::runtime_error(r.errors.front());
  return std::move(*r.scene);
}

// Angle of the body's z axis from the vertical, rad (w, x, y, z quaternion).
inline double Tilt(const std::array<double, 4>& q) {
  const double zz = 1 - 2 * (q[1] * q[1] + q[2] * q[2]);
  return std::acos(std::clamp(zz, -1.0, 1.0));
}

inline bool Finite(const LeggedRobotState& s) {
  auto all = [](const auto& v) { return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); }); };
  return all(s.base_position) && all(s.base_orientation) && all(s.joint_positions) && all(s.joint_velocities) &&
         all(s.joint_efforts) && all(s.gyro) && all(s.accelerometer);
}

}  // namespace turf::testing
