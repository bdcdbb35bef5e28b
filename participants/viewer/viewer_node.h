// turf-viewer's node: turf's topics to the web page, the page's controls back
// to turf-sim.
//
// Subscribes (topic names <prefix>/..., QoS profiles in configs/qos/turf_qos.xml):
//   world_state    WorldState       100 Hz of sim time: ground truth
//   clock          Clock            with every world state: time, paused, speed, rtf
//   ssl/field      SslField         latched: what the page draws to scale
//   ssl/camera     CameraFrame      60 Hz per camera: what the cameras report
//   stats          SensorStats      every second of sim time: per-stream rate, loss, latency
//   control_reply  SimControlReply  answers to our requests (others' are ignored)
//   legged/scene   LeggedSceneInfo  latched, legged scenes: robots' shapes, 3D field size
//   robots/links   LinkState        legged scenes, 50 Hz of sim time per robot: body poses
//                                   (world_state then carries the ball only)
// Publishes:
//   control        SimControl       one per accepted page message (teleport, pause,
//                                   resume, step, reset, time mode, realism preset;
//                                   a legged robot's teleport as LeggedTeleport)
// Serves (web_server.h): the page at http://<listen>:<port>/, its WebSocket at /ws;
// state messages to every page at up to `rate_hz` (the newest state wins);
// turf-sim's reply to a request only to the page that made it.
// Page messages are untrusted (page_request.h): a refused one is counted per
// kind ("page.<error>"), logged at a limited rate, answered with a "refused"
// message to that page, and sends nothing to turf-sim.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/pinned.h"
#include "participants/common/participant_options.h"

namespace turf {

struct ViewerOptions : ParticipantOptions {
  ViewerOptions() { name = "turf-viewer"; }
  std::string listen = "127.0.0.1";
  uint16_t port = 8080;                  // 0: any free port (see ViewerNode::port())
  std::string web_root;                  // must hold index.html
  double rate_hz = 60.0;                 // state messages to the pages, at most
  std::string recording;                 // an MCAP file to show instead of DDS (recording_viewer.h); empty: live
  std::vector<std::string> allow_hosts;  // --allow-host: names the page may be reached by (non-loopback --listen)
};

struct ViewerStats {
  uint64_t pages = 0;            // open now
  bool control_matched = false;  // turf-sim's control reader is there: page actions can take effect
  uint64_t states_received = 0;  // world states taken from DDS
  uint64_t states_pushed = 0;    // state messages published to the pages
  uint64_t controls_sent = 0;    // SimControl requests written
  uint64_t replies = 0;          // answers to our requests
  uint64_t refused = 0;          // page messages and DDS samples of every kind
  uint64_t frames_dropped = 0;   // state messages slow pages skipped
};

class ViewerNode : Pinned {
 public:
  // Throws std::invalid_argument for a bad option (address, web root, rate),
  // std::runtime_error if the port cannot be bound or DDS fails.
  explicit ViewerNode(ViewerOptions options);
  ~ViewerNode();

  // Runs until `stop()` answers true (checked at least every 50 ms).
  void Run(const std::function<bool()>& stop);
  uint16_t port() const;
  std::string Url() const;
  ViewerStats Stats() const;
  // Refusals of one kind, e.g. "page.not_json", "page.rate_limited", "world_state.not_finite".
  uint64_t Rejected(const std::string& kind) const;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace turf
