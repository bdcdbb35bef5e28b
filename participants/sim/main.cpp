// turf-sim: the physics participant. Loads a scene, steps the MuJoCo world and
// publishes it on DDS; see sim_node.h for its topics.
#include <mujoco/mujoco.h>
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include <cmath>
#include <optional>
#include <string>

#include "loader/legged_scene_yaml.h"
#include "loader/realism_yaml.h"
#include "loader/scene_yaml.h"
#include "participants/common/process.h"
#include "participants/sim/legged_node.h"
#include "participants/sim/sim_node.h"

namespace {

void MujocoWarning(const char* message) { spdlog::warn("MuJoCo: {}", message); }

// Scenes with `kind: legged`: any MJCF robots on joint topics (legged_node.h).
// The realism preset or file named on the command line, if any.
std::optional<turf::SensorRealism> LoadRealismOption(const std::string& realism) {
  const turf::RealismLoadResult r = turf::LoadRealism(realism);
  if (!r.realism) {
    spdlog::error("cannot load realism '{}':", realism);
    for (const std::string& e : r.errors) spdlog::error("  {}", e);
    return std::nullopt;
  }
  spdlog::info("sensor realism from '{}'", realism);
  return r.realism;
}

int RunLegged(const std::string& scene_path, const std::string& realism, const turf::SimNodeOptions& options) {
  turf::LeggedSceneLoadResult loaded = turf::LoadLeggedSceneFile(scene_path);
  if (!loaded.scene) {
    spdlog::error("cannot load legged scene {}:", scene_path);
    for (const std::string& e : loaded.errors) spdlog::error("  {}", e);
    return 2;
  }
  spdlog::info("legged scene file {}", scene_path);
  if (!realism.empty()) {
    const std::optional<turf::SensorRealism> r = LoadRealismOption(realism);
    if (!r) return 2;
    loaded.scene->realism = *r;  // encoders and IMU
  }
  turf::InstallStopSignals();
  try {
    turf::LeggedNode node(std::move(*loaded.scene), options);
    node.Run([] { return turf::StopRequested(); });
  } catch (const std::exception& e) {
    spdlog::critical("{}", e.what());
    return 1;
  }
  spdlog::info("stopped cleanly");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"turf-sim: the MuJoCo physics participant of turf (SSL scenes), publishing on DDS"};
  std::string scene_path = std::string(TURF_SOURCE_DIR) + "/configs/scenes/ssl_div_a.yaml";
  turf::SimNodeOptions options;
  std::string speed = "1";
  bool lockstep = false;
  std::string log_level = "info";
  std::string realism;
  app.add_option("-s,--scene", scene_path, "scene file (YAML)")->capture_default_str();
  app.add_option("-d,--domain", options.domain, "DDS domain id")->capture_default_str()->check(CLI::Range(0, 232));
  app.add_option("-p,--prefix", options.prefix, "topic name prefix (two matches on one network: use two)")
      ->capture_default_str();
  app.add_option("--qos", options.qos_file, "Fast DDS XML QoS profiles (default: configs/qos/turf_qos.xml)");
  app.add_option("--speed", speed, "multiple of real time, or 'max' to run free")->capture_default_str();
  app.add_flag("--lockstep", lockstep, "advance only on STEP control requests");
  app.add_flag("--paused", options.start_paused, "start paused");
  app.add_option("--realism", realism,
                 "sensor realism: a preset (ideal, realistic, harsh in configs/realism/) or a YAML file; "
                 "overrides the scene's");
  app.add_option("--duration", options.duration, "stop after this many simulated seconds (0: run until Ctrl-C)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--log-level", log_level, "trace, debug, info, warn, error")->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  if (!turf::SetupLogging("turf-sim", log_level)) return 2;
  if (lockstep) {
    options.mode = turf::TimeMode::kLockstep;
  } else if (speed == "max") {
    options.mode = turf::TimeMode::kFreeRunning;
  } else {
    try {
      options.speed = std::stod(speed);
    } catch (const std::exception&) {
      options.speed = NAN;
    }
    if (!(std::isfinite(options.speed) && options.speed > 0 && options.speed <= 1000)) {
      spdlog::error("--speed must be a number in (0, 1000] or 'max' (got '{}')", speed);
      return 2;
    }
    options.mode = options.speed == 1.0 ? turf::TimeMode::kRealtime : turf::TimeMode::kScaled;
  }

  mju_user_warning = MujocoWarning;
  if (turf::IsLeggedSceneFile(scene_path)) return RunLegged(scene_path, realism, options);
  turf::SceneLoadResult loaded = turf::LoadSceneFile(scene_path);
  if (!loaded.scene) {
    spdlog::error("cannot load scene {}:", scene_path);
    for (const std::string& e : loaded.errors) spdlog::error("  {}", e);
    return 2;
  }
  spdlog::info("scene file {}", scene_path);
  if (!realism.empty()) {
    const std::optional<turf::SensorRealism> r = LoadRealismOption(realism);
    if (!r) return 2;
    loaded.scene->realism = *r;
  }
  mju_user_warning = MujocoWarning;
  turf::InstallStopSignals();
  try {
    turf::SimNode node(std::move(*loaded.scene), options);
    node.Run([] { return turf::StopRequested(); });
  } catch (const std::exception& e) {
    spdlog::critical("{}", e.what());
    return 1;
  }
  spdlog::info("stopped cleanly");
  return 0;
}
