// The RCSSServerMJ front-end's DDS side: it drives turf-sim (a legged scene) in lockstep, one 20 ms cycle at a time,
// and reads what the world looks like after each cycle. Same protocol as the SimSpark bridge's WorldLink
// (participants/simspark_bridge/world_link.h), with per-joint PD commands and joint velocities.
//
// Writes: control (SimControl: OP_SET_TIME_MODE, OP_TELEPORT_*, OP_STEP with joint commands).
// Reads:  legged/scene (latched), robots/state (every robot and the ball in one sample per frame), clock,
//         control_reply.
#pragma once

#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "codecs/rcssservermj/session.h"
#include "core/pinned.h"
#include "dds/participant.h"

namespace turf::idl {
class JointTarget;
}  // namespace turf::idl

namespace turf {

// One PD command as turf's joint-command type carries it: the adapter seam between the session and the legged
// world's motor mode (rcssservermj_pd.cpp).
idl::JointTarget ToJointTarget(const rcssservermj::PdCommand& command);
// "T1" for a robot file label "../robots/t1.xml" (its file name's stem, upper case).
std::string ModelOfLabel(const std::string& label);

class MjLeggedLink : Pinned {
 public:
  explicit MjLeggedLink(const dds::ParticipantOptions& options);  // throws std::runtime_error
  explicit MjLeggedLink(dds::Bus& bus);                           // the bus outlives the link
  ~MjLeggedLink();

  std::string TopicName(dds::Topic topic) const;
  std::string DescribeBus() const;

  struct Scene {
    std::string name;
    std::vector<rcssservermj::SceneRobot> robots;  // each with its model and torso pose now (its park)
    bool has_field = false;
    double field_length = 0, field_width = 0;
  };
  // Waits for turf-sim's scene, switches it to lockstep and reads where each robot stands.
  std::optional<Scene> Attach(std::chrono::milliseconds timeout, const std::function<bool()>& stop, std::string* error);
  // Moves and ball placement, then `steps` physics steps with the joint commands; the world after them.
  std::optional<rcssservermj::MjWorldSnapshot> Cycle(const rcssservermj::WorldRequests& requests, uint32_t steps,
                                                     std::chrono::milliseconds timeout,
                                                     const std::function<bool()>& stop, std::string* error,
                                                     std::vector<std::string>* warnings);
  double step_s() const;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace turf
