#include "python/src/scene_source.h"

#include <sys/stat.h>
#include <stdexcept>

#include "loader/legged_scene_yaml.h"
#include "loader/realism_yaml.h"
#include "loader/scene_yaml.h"

namespace turf::py {

namespace {

bool IsFile(const std::string& path) {
  struct stat st {};
  return stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

std::string Joined(const std::vector<std::string>& errors) {
  std::string s;
  for (const std::string& e : errors) s += (s.empty() ? "" : "; ") + e;
  return s;
}

template <typename SceneT>
void Apply(const SceneRequest& request, SceneT* scene) {
  if (request.seed) scene->seed = *request.seed;
  if (request.physics_step) scene->physics.step = *request.physics_step;
  if (request.realism.empty()) return;
  const RealismLoadResult r = LoadRealism(request.realism);
  if (!r.realism) throw std::invalid_argument("realism '" + request.realism + "': " + Joined(r.errors));
  scene->realism = *r.realism;
}

}  // namespace

std::string ScenePath(const std::string& scene) {
  if (IsFile(scene)) return scene;
  const bool name = scene.find('/') == std::string::npos && scene.find('.') == std::string::npos;
  const std::string shipped = std::string(TURF_SOURCE_DIR) + "/configs/scenes/" + scene + ".yaml";
  if (name && !scene.empty() && IsFile(shipped)) return shipped;
  throw std::invalid_argument("no scene '" + scene +
                              "': neither a file nor a name in " TURF_SOURCE_DIR "/configs/scenes/");
}

bool IsLeggedScene(const std::string& scene) { return IsLeggedSceneFile(ScenePath(scene)); }

Scene LoadSsl(const SceneRequest& request) {
  SceneLoadResult r = LoadSceneFile(ScenePath(request.scene));
  if (!r.scene) throw std::invalid_argument(Joined(r.errors));
  Scene& scene = *r.scene;
  Apply(request, &scene);
  if (request.wall_segments) scene.physics.wall_segments = *request.wall_segments;
  if (request.robots_per_team) {
    scene.robots_per_team = *request.robots_per_team;
    std::vector<RobotSetup> kept;
    for (const RobotSetup& robot : scene.robots)
      if (robot.id < scene.robots_per_team) kept.push_back(robot);
    scene.robots = std::move(kept);
  }
  if (const std::vector<std::string> errors = ValidateScene(scene); !errors.empty())
    throw std::invalid_argument(Joined(errors));
  return std::move(scene);
}

LeggedScene LoadLegged(const SceneRequest& request) {
  if (request.robots_per_team || request.wall_segments)
    throw std::invalid_argument("robots_per_team and wall_segments: SSL scenes only");
  LeggedSceneLoadResult r = LoadLeggedSceneFile(ScenePath(request.scene));
  if (!r.scene) throw std::invalid_argument(Joined(r.errors));
  Apply(request, &*r.scene);
  if (const std::vector<std::string> errors = ValidateLeggedScene(*r.scene); !errors.empty())
    throw std::invalid_argument(Joined(errors));
  return std::move(*r.scene);
}

}  // namespace turf::py
