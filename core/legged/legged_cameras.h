// The cameras of a legged scene: every MJCF <camera> of each robot file, with the scene's robots[].cameras
// applied (overrides by name, or new cameras on a named body), resolved against the compiled model into
// CameraSpecs (core/camera/camera_model.h). Each problem is an error naming the robot and camera.
#pragma once

#include <mujoco/mujoco.h>

#include <string>
#include <vector>

#include "core/camera/camera_model.h"
#include "core/legged/legged_scene.h"

namespace turf {

struct LeggedCameras {
  std::vector<CameraSpec> cameras;  // scene order: robots, then each robot's MJCF cameras, then new ones
  std::vector<std::string> errors;  // each names robots[i] (<name>) and the camera
};

// `model` is the scene's composed model (ComposeLeggedMjcf), compiled.
LeggedCameras ResolveLeggedCameras(const LeggedScene& scene, const mjModel* model);

// Checks a resolved camera's values; empty when valid.
std::vector<std::string> ValidateCamera(const CameraSpec& camera);

}  // namespace turf
