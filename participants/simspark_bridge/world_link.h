// The SimSpark bridge's DDS side: it drives turf-sim (a legged scene) in
// lockstep, one SimSpark cycle at a time, and assembles what the world looks
// like after each cycle.
//
// Writes: control (SimControl: OP_SET_TIME_MODE, OP_TELEPORT_*, OP_STEP with joint commands).
// Reads:  legged/scene (latched), robots/state (every robot and the ball in one
//         sample per frame), clock, control_reply.
#pragma once

#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "codecs/simspark/session.h"
#include "core/pinned.h"
#include "dds/participant.h"

namespace turf {

class WorldLink : Pinned {
 public:
  // Throws std::runtime_error if the DDS entities cannot be created.
  explicit WorldLink(const dds::ParticipantOptions& options);
  // On `bus` (a dds::MemoryBus shared with turf-sim's node), which must outlive the link.
  explicit WorldLink(dds::Bus& bus);
  ~WorldLink();

  std::string TopicName(dds::Topic topic) const;
  // The bus's start-up line (Bus::Describe()).
  std::string DescribeBus() const;

  struct Scene {
    std::string name;
    std::vector<std::string> robots;
    std::vector<simspark::RobotMove> park;  // each robot's torso pose now
  };
  // Waits for turf-sim's scene, switches it to lockstep and reads where each
  // robot stands; nullopt (error set) on timeout or refusal.
  std::optional<Scene> Attach(std::chrono::milliseconds timeout, const std::function<bool()>& stop, std::string* error);
  // Moves, then one step of `steps` physics steps with the joint velocities;
  // waits for the reply and the world after it. nullopt (error set) when
  // turf-sim refused the step or did not answer within `timeout`. A refused
  // move is reported in `warnings` and does not stop the step.
  std::optional<simspark::WorldSnapshot> Cycle(const simspark::WorldRequests& requests, uint32_t steps,
                                               std::chrono::milliseconds timeout, const std::function<bool()>& stop,
                                               std::string* error, std::vector<std::string>* warnings);
  double step_s() const;  // turf-sim's physics step (after Attach)
  uint64_t Overflowed() const;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace turf
