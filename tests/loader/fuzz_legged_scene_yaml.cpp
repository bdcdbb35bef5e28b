// libFuzzer target for the legged scene reader (scene files are outside input): any bytes give a scene that passes
// its own validation, or errors, never both, never neither, and never a crash, a sanitizer report or an exception.
// Robot model paths resolve against configs/scenes/, so the shipped robot files can be named.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "loader/legged_scene_yaml.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const turf::LeggedSceneLoadResult r = turf::ParseLeggedSceneYaml(text, TURF_SCENE_DIR);
  if (r.scene.has_value() == !r.errors.empty()) std::abort();
  if (r.scene && !turf::ValidateLeggedScene(*r.scene).empty()) std::abort();
  return 0;
}
