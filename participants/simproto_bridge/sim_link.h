// The simulation-protocol bridge's DDS side: what turf-sim said last, robot
// commands out, and control requests through the one control client
// (dds/control_client.h). Thread-safe: the bridge's port threads share one SimLink.
//
// Writes: ssl/command/blue, ssl/command/yellow (SslRobotCommand), control (SimControl).
// Reads:  control_reply (SimControlReply), ssl/feedback/<team> (SslRobotFeedback),
//         ssl/field (SslField, latched), clock (Clock), world_state (WorldState),
//         ssl/camera (CameraFrame; the newest kMaxBufferedFrames kept for sync mode).
#pragma once

#include <turf/idl/Clock.h>
#include <turf/idl/SimControl.h>
#include <turf/idl/SslRobot.h>
#include <turf/idl/SslVision.h>
#include <turf/idl/WorldState.h>

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "codecs/ssl_simulation/robot_control.h"
#include "core/pinned.h"
#include "dds/control_client.h"
#include "dds/participant.h"

namespace turf {

class SimLink : Pinned {
 public:
  static constexpr size_t kMaxBufferedFrames = 4096;

  // What turf-sim said last; each part is null until it first arrives. The parts are shared and never change (a
  // new sample replaces its part), so a View is cheap to take and keep.
  struct View {
    std::shared_ptr<const idl::SslField> field;
    std::shared_ptr<const idl::WorldState> world;
    std::optional<idl::Clock> clock;
    std::shared_ptr<const simproto::ContactMap> contacts = std::make_shared<const simproto::ContactMap>();
  };

  // On a DDS participant of its own. Throws std::runtime_error if the DDS entities cannot be created.
  explicit SimLink(const dds::ParticipantOptions& options);
  // On `bus` (a dds::MemoryBus shared with turf-sim's node, for a front-end in turf-sim's process), which must
  // outlive the link; `name` is the control client's.
  SimLink(dds::Bus& bus, const std::string& name);
  ~SimLink();

  std::string TopicName(dds::Topic topic) const;
  // The bus's start-up line (Bus::Describe()).
  std::string DescribeBus() const;
  View Now();
  // Publishes on the topic of the command's team.
  void Command(const idl::SslRobotCommand& command);
  // Sends the requests in order (as client `name`) once turf-sim is matched,
  // and waits for every reply until `timeout` (or until `stop()` answers true): one outcome each, in order.
  std::vector<dds::ControlOutcome> Control(std::vector<idl::SimControl> requests, std::chrono::milliseconds timeout,
                                           const dds::ControlClient::StopFn& stop = {});
  // Camera frames are numbered in arrival order. FrameCursor() is the number
  // received so far; FramesSince(c) returns those received after cursor `c`
  // (the newest kMaxBufferedFrames at most).
  uint64_t FrameCursor();
  std::vector<std::shared_ptr<const idl::CameraFrame>> FramesSince(uint64_t cursor);
  // DDS samples turf-sim's writers could not hand over in time (reader queues full).
  uint64_t Overflowed() const;
  // The link's own participant's (dds::Participant::AuthenticationsNow); none on a shared bus.
  dds::Authentications AuthenticationsNow() const;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace turf
