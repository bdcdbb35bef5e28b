#include "codecs/ssl_simulation/realism.h"

#include <fmt/format.h>

#include <vector>

namespace turf::simproto {

namespace ws = wire::simulation;

namespace {

bool IsErForce(const std::string& type_url) {
  const std::string name = "RealismConfigErForce";
  return type_url.size() >= name.size() && type_url.compare(type_url.size() - name.size(), name.size(), name) == 0 &&
         (type_url.size() == name.size() || type_url[type_url.size() - name.size() - 1] == '.' ||
          type_url[type_url.size() - name.size() - 1] == '/');
}

}  // namespace

std::string RealismYaml(const ws::RealismConfig& config, Problems* p) {
  std::vector<std::string> camera, link, command;
  for (int i = 0; i < config.custom_size(); ++i) {
    const auto& any = config.custom(i);
    if (!IsErForce(any.type_url())) {
      p->AddUnsupported(kUnsupportedRealism, fmt::format("config.realism_config.custom[{}]: {} is not a realism "
                                                         "config turf knows (RealismConfigErForce is)",
                                                         i, any.type_url()));
      continue;
    }
    ws::RealismConfigErForce e;
    if (!e.ParseFromString(any.value())) {
      p->Add(DecodeError::kMalformed, fmt::format("config.realism_config.custom[{}]: not a RealismConfigErForce", i));
      continue;
    }
    auto number = [&](bool has, double value, double hi, const char* knob, std::vector<std::string>* out,
                      const char* key, double scale) {
      if (!has || !p->Check(value, 0.0, hi, fmt::format("realism_config.{}", knob))) return;
      out->push_back(fmt::format("{}: {}", key, value * scale));
    };
    number(e.has_stddev_ball_p(), e.stddev_ball_p(), 1.0, "stddev_ball_p", &camera, "ball_position_stddev", 1.0);
    number(e.has_stddev_robot_p(), e.stddev_robot_p(), 1.0, "stddev_robot_p", &camera, "robot_position_stddev", 1.0);
    number(e.has_stddev_robot_phi(), e.stddev_robot_phi(), 3.1416, "stddev_robot_phi", &camera,
           "robot_orientation_stddev", 1.0);
    number(e.has_missing_ball_detections(), e.missing_ball_detections(), 1.0, "missing_ball_detections", &camera,
           "ball_vanish", 1.0);
    number(e.has_vision_processing_time(), static_cast<double>(e.vision_processing_time()), 1e10,
           "vision_processing_time", &camera, "processing_delay", 1e-9);
    number(e.has_vision_delay(), static_cast<double>(e.vision_delay()), 1e10, "vision_delay", &link, "latency", 1e-9);
    number(e.has_robot_command_loss(), e.robot_command_loss(), 1.0, "robot_command_loss", &command, "loss", 1.0);
    if (e.has_enable_invisible_ball())
      camera.push_back(fmt::format("ball_occlusion: {}", e.enable_invisible_ball() ? "true" : "false"));
    const std::pair<bool, const char*> unsupported[] = {
        {e.has_stddev_ball_area(), "stddev_ball_area"},
        {e.has_ball_visibility_threshold(), "ball_visibility_threshold"},
        {e.has_camera_overlap(), "camera_overlap (set cameras.overlap in the scene)"},
        {e.has_dribbler_ball_detections(), "dribbler_ball_detections"},
        {e.has_camera_position_error(), "camera_position_error"},
        {e.has_robot_response_loss(), "robot_response_loss"},
        {e.has_simulate_dribbling(), "simulate_dribbling (turf always simulates the dribbler)"}};
    for (const auto& [present, name] : unsupported)
      if (present) p->AddUnsupported(kUnsupportedRealism, fmt::format("realism_config.{}: not modelled by turf", name));
  }
  if (!link.empty()) camera.push_back(fmt::format("link: {{{}}}", fmt::join(link, ", ")));
  std::string yaml;
  if (!camera.empty()) yaml += fmt::format("camera: {{{}}}\n", fmt::join(camera, ", "));
  if (!command.empty()) yaml += fmt::format("command: {{{}}}\n", fmt::join(command, ", "));
  return yaml;
}

}  // namespace turf::simproto
