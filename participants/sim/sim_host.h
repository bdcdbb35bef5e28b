// turf-sim's SSL node with lockstep front-ends served in its own process (turf-sim --simproto): the node runs on a
// dds::FanoutBus over its DDS participant and an in-process dds::MemoryBus; each front-end runs on the MemoryBus
// alone, on a thread of its own. Remote participants keep seeing turf-sim on DDS, and a front-end's synchronous
// cycle (a SimControl STEP, its reply and the step's camera frames) pays no DDS round trip: every sample is
// handed over synchronously on the writer's thread. No sample is seen twice: the front-ends write only to the
// MemoryBus, remote participants only to DDS (fanout_bus.h).
//
// Front-ends today: the SSL simulation protocol (participants/simproto_bridge/, its control, team and sync ports).
// The separate-process bridges stay available and work against the same turf-sim.
#pragma once

#include <functional>
#include <memory>
#include <optional>

#include "core/pinned.h"
#include "core/scene.h"
#include "participants/sim/node_options.h"
#include "participants/simproto_bridge/simproto_bridge.h"

namespace turf {

class SimNode;

struct InProcessFrontEnds {
  std::optional<SimprotoBridgeOptions> simproto;  // --simproto: its listen address and ports
};

class SimHost : Pinned {
 public:
  // The node on DDS (the options' domain, name, prefix and QoS file) and on the in-process bus. Throws as SimNode
  // and SimprotoBridge do (a bad scene, DDS, a port that cannot be bound).
  SimHost(Scene scene, SimNodeOptions options, InProcessFrontEnds front_ends);
  ~SimHost();

  // Runs the node on the calling thread and each front-end on its own until `stop()` answers true or the node's
  // duration is reached; the front-ends stop with the node.
  void Run(const std::function<bool()>& stop);
  SimNode& node();
  // The in-process SSL simulation protocol front-end, if any.
  SimprotoBridge* simproto();

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace turf
