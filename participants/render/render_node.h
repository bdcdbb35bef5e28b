// turf-render's node: reads turf-sim's legged state (robots/state: every body's pose and the ball), renders each
// selected camera at its rate in simulation time, encodes and publishes it on the camera topics
// (dds/camera_topics.h). It never makes turf-sim wait: it reads a KEEP_LAST topic, takes the newest state whenever
// it is free, and frames whose time passed while it was busy are dropped and counted (FrameSchedule), never
// rendered late. Each frame is stamped with the simulation time of the state it shows.
//
// Run-time switch: a camera of the set is rendered only while it is on (camera_switch.h); it starts as the scene
// or --cameras says (--cameras off: all off) and <prefix>/cameras/control switches it. With every camera off the
// node takes states and discards them: no GL work, no encoding, nothing published.
//
// Reads:  <prefix>/robots/state (turf::idl::LeggedState, turf.state)
//         <prefix>/cameras/control (turf::idl::CameraControl, best effort, on the images' participant)
// Writes: rt/<prefix>/<robot>/<camera>/image_raw (rgb8, yuv422) or image_raw/compressed (jpeg), and camera_info,
//         on a participant of its own for large samples (best effort, keep last 1, asynchronous, paced).
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/camera/camera_model.h"
#include "core/legged/legged_scene.h"
#include "participants/common/participant_options.h"

namespace turf {

struct RenderOptions : ParticipantOptions {
  RenderOptions() { name = "turf-render"; }
  std::string scene_file;            // --scene: the scene turf-sim runs
  std::vector<std::string> cameras;  // --cameras: "<robot>/<camera>" ids; empty: every camera of the scene
  bool cameras_off = false;          // --cameras off: every camera of the set starts off
  bool list_cameras = false;         // --list-cameras
  double status_every = 10.0;        // --status-every: seconds between status lines
  bool team_colours = true;          // --no-team-colours turns it off (scene_renderer.h: RenderLook)
  double brightness = 1.0;           // --brightness
};

// The cameras to render: `requested` ids (in the scene's order), or every enabled one when empty. An unknown id
// is an error naming the scene's cameras (std::invalid_argument).
std::vector<CameraSpec> SelectCameras(const std::vector<CameraSpec>& all, const std::vector<std::string>& requested);
// The set a renderer may render, each camera's `enabled` its state at start: the `requested` ids (on), or with none
// every camera of the scene as it is declared; `off` switches every one off. Throws as SelectCameras.
std::vector<CameraSpec> RenderSet(const std::vector<CameraSpec>& all, const std::vector<std::string>& requested,
                                  bool off);

struct RenderStats {
  uint64_t states = 0;             // robots/state samples taken
  uint64_t states_superseded = 0;  // taken together with a newer one, so not looked at
  uint64_t states_refused = 0;     // not finite, or naming bodies the scene lacks
  uint64_t frames = 0;             // rendered and published
  uint64_t dropped = 0;            // due by simulation time but not rendered (busy, or states too sparse)
  uint64_t encode_errors = 0;
  uint64_t controls = 0;          // camera control samples that switched one of this renderer's cameras
  uint64_t controls_refused = 0;  // control samples refused (a bad rate)
  size_t cameras_on = 0;          // cameras on now
  double render_seconds = 0;      // wall time spent rendering, reading back and encoding
};

class RenderNode {
 public:
  RenderNode(RenderOptions options, LeggedScene scene, std::vector<CameraSpec> cameras);
  ~RenderNode();

  // Makes the GL context on this thread, the DDS participants, and renders until stop() (polled every 100 ms).
  void Run(const std::function<bool()>& stop);
  RenderStats Stats() const;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace turf
