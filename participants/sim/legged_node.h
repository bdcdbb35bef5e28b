// turf-sim's node for legged scenes (`kind: legged`): any MJCF robots, e.g.
// the Nao, on typed joint topics.
//
// Publishes (topic names <prefix>/..., QoS profiles in configs/qos/turf_qos.xml):
//   robots/joint_state  JointState       per robot (keyed), every 1/rates.joint_state_hz of sim time
//   robots/imu          ImuState         per robot, with every joint state
//   robots/force        ForceState       per robot, with every joint state
//   robots/links        LinkState        per robot, body poses, with every joint state
//   world_state         WorldState       the ball (scenes with one), with every joint state
//   legged/scene        LeggedSceneInfo  once, latched: field and robot shapes
//   clock               Clock            with every joint state
//   control_reply       SimControlReply  one per control request
// Subscribes:
//   robots/joint_command JointCommand    joint targets of one robot; each holds until replaced
//   control              SimControl      pause/resume, step, reset, time mode (control_loop.h, as for
//                                        SSL scenes); ball and robot teleports; STEP carries joint_commands
//                                        (all applied or the step refused); realism and SSL commands are refused
// Every sample from outside is validated; a refused one is counted per kind
// ("joint_command.unknown_joint", ...), logged (rate-limited) and changes
// nothing. Inputs are applied between physics steps, commands before control
// requests taken in the same poll.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "core/legged/legged_scene.h"
#include "participants/sim/node_options.h"

namespace turf {

class LeggedNode {
 public:
  // Throws std::invalid_argument for a bad scene, std::runtime_error for DDS.
  LeggedNode(LeggedScene scene, SimNodeOptions options);
  ~LeggedNode();
  LeggedNode(const LeggedNode&) = delete;
  LeggedNode& operator=(const LeggedNode&) = delete;

  // Runs until `stop()` answers true (checked every step and at least every
  // 50 ms while idle) or the duration is reached.
  void Run(const std::function<bool()>& stop);
  SimNodeStats Stats() const;
  uint64_t Rejected(const std::string& kind) const;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace turf
