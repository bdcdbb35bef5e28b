// turf-sim's node with lockstep front-ends served in its own process (turf-sim --simproto, --simspark): the node
// runs on a dds::FanoutBus over its DDS participant and an in-process dds::MemoryBus; each front-end runs on the
// MemoryBus alone, on a thread of its own. Remote participants keep seeing turf-sim on DDS, and a front-end's
// synchronous cycle (a SimControl STEP, its reply and what the step published) pays no DDS round trip: every
// sample is handed over synchronously on the writer's thread. No sample is seen twice: the front-ends write only
// to the MemoryBus, remote participants only to DDS (fanout_bus.h).
//
// Front-ends: the SSL simulation protocol (participants/simproto_bridge/: control, team and sync ports) for SSL
// scenes, the SimSpark agent and monitor ports (participants/simspark_bridge/) or the RCSSServerMJ ones
// (participants/rcssservermj_bridge/) for legged scenes, and for legged scenes also the Booster SDK's DDS topics
// (participants/booster_bridge/). The separate-process bridges stay available and work against the same turf-sim. When
// a front-end's loop ends by itself (a SimSpark trainer's killsim, or an error), the node stops too.
#pragma once

#include <functional>
#include <memory>
#include <optional>

#include "core/legged/legged_scene.h"
#include "core/pinned.h"
#include "core/scene.h"
#include "participants/booster_bridge/booster_sdk_bridge.h"
#include "participants/rcssservermj_bridge/rcssservermj_bridge.h"
#include "participants/sim/node_options.h"
#include "participants/simproto_bridge/simproto_bridge.h"
#include "participants/simspark_bridge/simspark_bridge.h"

namespace turf {

class SimNode;
namespace dds {
class Participant;
}  // namespace dds

struct InProcessFrontEnds {
  std::optional<SimprotoBridgeOptions> simproto;    // --simproto: its listen address and ports (SSL scenes)
  std::optional<SimSparkBridgeOptions> simspark;    // --simspark: its listen address, ports, sync mode (legged scenes)
  std::optional<RcssServerMjOptions> rcssservermj;  // --rcssservermj: address, ports, modes (legged scenes, T1/K1)
  std::optional<BoosterSdkOptions> booster;         // --booster-sdk: the Booster SDK's topics (legged scenes)
};

class SimHost : Pinned {
 public:
  // The node on DDS (the options' domain, name, prefix and QoS file) and on the in-process bus. Throws as SimNode
  // and the bridges do (a bad scene, DDS, a port that cannot be bound); std::invalid_argument for a front-end of
  // the other kind of scene.
  SimHost(Scene scene, SimNodeOptions options, InProcessFrontEnds front_ends);
  SimHost(LeggedScene scene, SimNodeOptions options, InProcessFrontEnds front_ends);
  ~SimHost();

  // Runs the node on the calling thread and each front-end on its own until `stop()` answers true, the node's
  // duration is reached or a front-end's loop ends; the front-ends stop with the node.
  void Run(const std::function<bool()>& stop);
  SimNode& node();
  // The node's DDS participant (what remote participants see of turf-sim).
  dds::Participant& participant();
  // The in-process front-ends, if any.
  SimprotoBridge* simproto();
  SimSparkBridge* simspark();
  RcssServerMjBridge* rcssservermj();
  BoosterSdkBridge* booster();

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace turf
