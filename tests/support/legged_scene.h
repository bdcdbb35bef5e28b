// A legged scene of configs/scenes/, loaded for a test (link turf_legged_loader).
#pragma once

#include <stdexcept>
#include <string>

#include "loader/legged_scene_yaml.h"

namespace turf::test {

// configs/scenes/<file>, or an exception with the loader's first error.
inline LeggedScene LoadScene(const std::string& file) {
  LeggedSceneLoadResult r = LoadLeggedSceneFile(std::string(TURF_SOURCE_DIR) + "/configs/scenes/" + file);
  if (!r.scene) throw std::runtime_error(file + ": " + r.errors.front());
  return std::move(*r.scene);
}

}  // namespace turf::test
