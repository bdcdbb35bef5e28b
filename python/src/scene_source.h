// Where a Python Sim's scene comes from: a shipped scene's name
// ("ssl_div_a": configs/scenes/ssl_div_a.yaml) or a path to a scene file, then
// the seed and realism the caller gives (none: the scene's own).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "core/legged/legged_scene.h"
#include "core/scene.h"

namespace turf::py {

struct SceneRequest {
  std::string scene = "ssl_div_a";  // a name in configs/scenes/ or a path
  std::optional<uint64_t> seed;
  std::string realism;  // a preset name, a YAML file or YAML text; empty: the scene's
  // Overrides of the scene's keys, checked as the scene file's are (ValidateScene): physics.step (s), and, SSL
  // only, robots_per_team (ids 0..n-1 exist; robots the file places beyond them are dropped) and
  // physics.wall_segments.
  std::optional<double> physics_step;
  std::optional<int> robots_per_team;
  std::optional<int> wall_segments;  // SSL only: core/scene.h's physics.wall_segments
};

// The file a request names. Throws std::invalid_argument if there is none.
std::string ScenePath(const std::string& scene);
bool IsLeggedScene(const std::string& scene);

// Loaded, with the seed and realism applied. Throw std::invalid_argument
// naming every problem of the file.
Scene LoadSsl(const SceneRequest& request);
LeggedScene LoadLegged(const SceneRequest& request);

}  // namespace turf::py
