// turf-render: renders the robots' cameras of a legged scene offscreen (EGL, MuJoCo's renderer) from the body
// poses turf-sim publishes, and publishes them as ROS 2 images. Topics and behaviour: render_node.h, README.md.
#include <mujoco/mujoco.h>
#include <spdlog/spdlog.h>

#include <cstdio>
#include <sstream>

#include "core/legged/legged_cameras.h"
#include "core/legged/legged_mjcf.h"
#include "core/mj_state.h"
#include "loader/legged_scene_yaml.h"
#include "participants/common/participant_main.h"
#include "participants/common/process.h"
#include "participants/render/render_flags.h"
#include "participants/render/render_node.h"
#include "participants/render/switch_command.h"

namespace {

std::vector<std::string> SplitIds(const std::vector<std::string>& args) {
  std::vector<std::string> ids;
  for (const std::string& a : args) {
    std::stringstream in(a);
    std::string id;
    while (std::getline(in, id, ','))
      if (!id.empty()) ids.push_back(id);
  }
  return ids;
}

// The scene and its cameras, or std::invalid_argument naming every problem.
std::pair<turf::LeggedScene, std::vector<turf::CameraSpec>> LoadScene(const std::string& file) {
  if (!turf::IsLeggedSceneFile(file))
    throw std::invalid_argument("--scene " + file + ": not a legged scene file (kind: legged); cameras need one");
  turf::LeggedSceneLoadResult r = turf::LoadLeggedSceneFile(file);
  if (!r.scene) throw std::invalid_argument("--scene " + file + ": " + r.errors.front());
  const turf::LeggedMjcf mjcf = turf::ComposeLeggedMjcf(*r.scene);
  if (!mjcf.errors.empty()) throw std::invalid_argument("--scene " + file + ": " + mjcf.errors.front());
  turf::MjModelPtr model(turf::CompileLeggedMjcf(mjcf.xml));
  turf::LeggedCameras cameras = turf::ResolveLeggedCameras(*r.scene, model.get());
  if (!cameras.errors.empty()) {
    std::string all;
    for (const std::string& e : cameras.errors) all += "\n  " + e;
    throw std::invalid_argument("--scene " + file + ": cameras:" + all);
  }
  return {std::move(*r.scene), std::move(cameras.cameras)};
}

}  // namespace

int main(int argc, char** argv) {
  turf::ParticipantMain participant(
      "turf-render: renders the robots' cameras of a legged scene (offscreen, EGL) from the body poses turf-sim "
      "publishes, and publishes ROS 2 images (rt/<prefix>/<robot>/<camera>/image_raw, camera_info)");
  turf::RenderCommandLine command_line;
  turf::AddRenderFlags(participant, command_line);
  turf::RenderOptions& options = command_line.options;
  return participant.Run(argc, argv, [&] {
    if (!command_line.switches.empty()) {
      std::vector<turf::CameraControlRequest> requests;
      for (const std::string& text : command_line.switches) {
        std::string why;
        auto r = turf::ParseCameraSwitch(text, &why);
        if (!r) throw std::invalid_argument("--switch " + why);
        requests.push_back(*r);
      }
      return static_cast<turf::ExitCode>(turf::SendCameraSwitches(options, requests));
    }
    if (options.scene_file.empty()) throw std::invalid_argument("--scene is required (but with --switch)");
    auto [scene, all] = LoadScene(options.scene_file);
    if (options.list_cameras) {
      for (const turf::CameraSpec& c : all)
        std::printf("%s: body %s, %dx%d, %.1f deg, %g Hz, %s%s\n", turf::CameraId(c).c_str(), c.body.c_str(), c.width,
                    c.height, c.hfov * 180.0 / M_PI, c.rate_hz, turf::EncodingName(c.encoding),
                    c.enabled ? "" : " (disabled)");
      return turf::kExitClean;
    }
    options.team_colours = !command_line.no_team_colours;
    options.cameras = SplitIds(command_line.cameras);
    options.cameras_off = options.cameras.size() == 1 && options.cameras[0] == "off";
    if (options.cameras_off) options.cameras.clear();
    std::vector<turf::CameraSpec> selected = turf::RenderSet(all, options.cameras, options.cameras_off);
    size_t on = 0;
    for (const turf::CameraSpec& c : selected) on += c.enabled;
    if (selected.empty()) spdlog::warn("no camera to render: the scene declares none");
    spdlog::info("scene {}: {} camera(s), {} in this renderer's set, {} on at start", options.scene_file, all.size(),
                 selected.size(), on);
    turf::RenderNode(options, std::move(scene), std::move(selected)).Run(turf::StopRequested);
    return turf::kExitClean;
  });
}
