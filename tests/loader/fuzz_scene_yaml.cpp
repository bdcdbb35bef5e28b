// libFuzzer target for the scene and realism YAML readers (files and realism texts are outside input): any bytes
// give a value that passes its own validation, or errors, never both, never neither, and never a crash, a sanitizer
// report or an exception. The first byte picks the reader: even, a scene (ParseSceneYaml); odd, a realism map
// (ParseRealismYaml).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "core/scene.h"
#include "core/sensor_realism.h"
#include "loader/realism_yaml.h"
#include "loader/scene_yaml.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  if (data[0] % 2 == 0) {
    const turf::SceneLoadResult r = turf::ParseSceneYaml(text);
    if (r.scene.has_value() == !r.errors.empty()) std::abort();
    if (r.scene && !turf::ValidateScene(*r.scene).empty()) std::abort();
  } else {
    const turf::RealismLoadResult r = turf::ParseRealismYaml(text);
    if (r.realism.has_value() == !r.errors.empty()) std::abort();
    if (r.realism && turf::CheckRealism(*r.realism)[0] != '\0') std::abort();
  }
  return 0;
}
