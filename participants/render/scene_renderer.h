// Renders a legged scene's cameras offscreen with MuJoCo's own renderer (mjv_updateScene, mjr_render,
// mjr_readPixels) in the current OpenGL context (egl_context.h). The model is the scene's, composed as turf-sim
// composes it (ComposeLeggedMjcf) plus the field's look (field_look.h, visual only); the state comes as body
// poses (robots/state's links and ball), written into mjData's frames directly with no physics or kinematics of
// the joints, so an image shows exactly the poses turf-sim published.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/camera/camera_model.h"
#include "core/legged/legged_scene.h"

namespace turf {

// What a renderer may change of the scene's look.
struct RenderLook {
  bool team_colours = true;  // robots named for a team wear its colour (team_colours.h)
  double brightness = 1.0;   // scales every light (the sun, MuJoCo's headlight); 0..4
};

class SceneRenderer {
 public:
  // A GL context must be current on this thread for the object's life. Throws std::invalid_argument for a scene
  // that does not compose or compile, or a camera whose robot or body is not in it.
  SceneRenderer(const LeggedScene& scene, std::vector<CameraSpec> cameras, const RenderLook& look = {});
  ~SceneRenderer();
  SceneRenderer(const SceneRenderer&) = delete;
  SceneRenderer& operator=(const SceneRenderer&) = delete;

  const std::vector<CameraSpec>& cameras() const { return cameras_; }

  // A robot body's world pose (robot file's body name); false if the scene has no such body (nothing changes).
  bool SetBodyPose(const std::string& robot, const std::string& body, const Pose& pose);
  // The ball's centre; false if the scene has no ball.
  bool SetBallPosition(const std::array<double, 3>& position);
  // Moves every geom and light with its body after the Set* calls of one state.
  void UpdateFrames();

  // The camera's world pose in the current state.
  Pose CameraPose(size_t camera) const;
  // Renders camera `camera` into `rgb` (rgb8, rows top-down, width x height x 3).
  void Render(size_t camera, std::vector<uint8_t>* rgb);

 private:
  struct Impl;
  std::vector<CameraSpec> cameras_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace turf
