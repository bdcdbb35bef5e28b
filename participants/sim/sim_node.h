// turf-sim's node: a simulation kernel (kernel/) on DDS (or any dds::Bus), with the time loop
// (control_loop.h: real time, scaled, free, lockstep, pause/step/reset, the
// clock and replies). One class for every kind of scene; what it publishes
// depends on the scene's kind.
//
// SSL scenes (kernel/ssl_kernel.h):
//   Publishes (topic names <prefix>/..., QoS profiles in configs/qos/turf_qos.xml):
//     world_state         WorldState        every 1/rates.world_state_hz of sim time
//     clock               Clock             with every world state
//     ssl/camera          CameraFrame       each camera, at cameras.rate_hz
//     ssl/field           SslField          once, latched (transient local)
//     ssl/feedback/<team> SslRobotFeedback  when ball contact or kick count change
//     stats               SensorStats       every second of sim time: cameras, radio links
//     control_reply       SimControlReply   one per control request
//   Subscribes:
//     ssl/command/<team>  SslRobotCommand   newest per robot; team must match topic
//     control             SimControl        teleport, pause/resume, step, reset, time mode
//   Every sample from outside is validated; a refused one is counted, logged
//   (rate-limited) and changes nothing. Commands and control requests are applied
//   between physics steps, in arrival order.
//
// Legged scenes (`kind: legged`, kernel/legged_kernel.h): any MJCF robots,
// e.g. the Nao, on typed joint topics.
//   Publishes:
//     robots/joint_state  JointState       per robot (keyed), measured every 1/rates.joint_state_hz
//                                          of sim time, published when its modelled link delivers it
//     robots/imu          ImuState         per robot, likewise
//     robots/force        ForceState       per robot, likewise
//     robots/state        LeggedState      every robot's four samples of one frame and the ball, no link
//     robots/links        LinkState        per robot, body poses, with robots/state
//     world_state         WorldState       the ball (scenes with one), with every joint state
//     legged/scene        LeggedSceneInfo  once, latched: field and robot shapes
//     clock               Clock            with every joint state
//     stats               SensorStats      every second of sim time: each robot's three streams
//     control_reply       SimControlReply  one per control request
//   Subscribes:
//     robots/joint_command JointCommand    joint targets of one robot; each holds until replaced
//     control              SimControl      pause/resume, step, reset, time mode (control_loop.h, as for
//                                          SSL scenes); ball and robot teleports; STEP carries joint_commands
//                                          (all applied or the step refused); realism and SSL commands are refused
//   Every sample from outside is validated; a refused one is counted per kind
//   ("joint_command.unknown_joint", ...), logged (rate-limited) and changes
//   nothing. Inputs are applied between physics steps, commands before control
//   requests taken in the same poll.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "core/legged/legged_scene.h"
#include "core/pinned.h"
#include "core/scene.h"
#include "dds/bus_fwd.h"
#include "participants/sim/node_options.h"

namespace turf {

class SimNode : Pinned {
 public:
  // Throw std::invalid_argument for a bad scene, std::runtime_error for DDS.
  // On a DDS participant of the node's own, from the options' domain, name, prefix and QoS file:
  SimNode(Scene scene, SimNodeOptions options);
  SimNode(LeggedScene scene, SimNodeOptions options);
  // On `bus` (a dds::MemoryBus in tests; it keeps its own prefix), which must outlive the node.
  SimNode(Scene scene, SimNodeOptions options, dds::Bus& bus);
  SimNode(LeggedScene scene, SimNodeOptions options, dds::Bus& bus);
  ~SimNode();

  // Runs the loop until `stop()` answers true (checked every step and at least
  // every 50 ms while idle) or the duration is reached.
  void Run(const std::function<bool()>& stop);
  SimNodeStats Stats() const;
  // Refusals of one kind, e.g. "command.not_finite" (for tests and reports).
  uint64_t Rejected(const std::string& kind) const;

  // What each kind of node implements (sim_node.cpp, legged_node.cpp).
  class Impl {
   public:
    virtual ~Impl() = default;
    virtual void Run(const std::function<bool()>& stop) = 0;
    virtual SimNodeStats Stats() const = 0;
    virtual uint64_t Rejected(const std::string& kind) const = 0;
  };

 private:
  std::unique_ptr<Impl> impl_;
};

// `bus` null: the node makes its own participant (MakeNodeParticipant, control_loop.h).
std::unique_ptr<SimNode::Impl> MakeSslNode(Scene scene, SimNodeOptions options, dds::Bus* bus);
std::unique_ptr<SimNode::Impl> MakeLeggedNode(LeggedScene scene, SimNodeOptions options, dds::Bus* bus);

}  // namespace turf
