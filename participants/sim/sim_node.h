// turf-sim's node: the SSL world on DDS.
//
// Publishes (topic names <prefix>/..., QoS profiles in configs/qos/turf_qos.xml):
//   world_state         WorldState        every 1/rates.world_state_hz of sim time
//   clock               Clock             with every world state
//   ssl/camera          CameraFrame       each camera, at cameras.rate_hz
//   ssl/field           SslField          once, latched (transient local)
//   ssl/feedback/<team> SslRobotFeedback  when ball contact or kick count change
//   control_reply       SimControlReply   one per control request
// Subscribes:
//   ssl/command/<team>  SslRobotCommand   newest per robot; team must match topic
//   control             SimControl        teleport, pause/resume, step, reset, time mode
// Time, pause/step/reset, the clock and replies: control_loop.h.
// Every sample from outside is validated; a refused one is counted, logged
// (rate-limited) and changes nothing. Commands and control requests are applied
// between physics steps, in arrival order.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "core/scene.h"
#include "participants/sim/node_options.h"

namespace turf {

class SimNode {
 public:
  // Throws std::invalid_argument for a bad scene, std::runtime_error for DDS.
  SimNode(Scene scene, SimNodeOptions options);
  ~SimNode();
  SimNode(const SimNode&) = delete;
  SimNode& operator=(const SimNode&) = delete;

  // Runs the loop until `stop()` answers true (checked every step and at least
  // every 50 ms while idle) or the duration is reached.
  void Run(const std::function<bool()>& stop);
  SimNodeStats Stats() const;
  // Refusals of one kind, e.g. "command.not_finite" (for tests and reports).
  uint64_t Rejected(const std::string& kind) const;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace turf
