// turf-simproto-bridge's node: the SSL simulation protocol (UDP, protobuf) in
// front of turf-sim (DDS). Codecs: codecs/ssl_simulation/.
//
// UDP ports (answers go back to the sender's address and port; 0 disables one):
//   control 10300  SimulatorCommand -> SimulatorResponse, after turf-sim replied
//                  to every request it became (errors name each refused or
//                  unsupported part; empty errors: all done)
//   blue    10301  RobotControl -> RobotControlResponse: commands for blue only
//   yellow  10302  RobotControl -> RobotControlResponse: commands for yellow only
//   sync    10303  SimulationSyncRequest -> SimulationSyncResponse (turf's choice
//                  of port: the draft names none), bound to `sync_listen`
//                  (127.0.0.1 unless told). Only with `sync` (--sync): else each
//                  request is answered TURF_SYNC_DISABLED and changes nothing.
//                  Ids 0..15 blue, 16..31 yellow.
//                  Switches turf-sim to lockstep if it is not, applies the
//                  command, then ONE step request carrying the robot commands;
//                  answers after turf-sim's reply with the detections of the
//                  frames turf-sim released during the step (ideal cameras:
//                  those captured in (t_before, t_after]). One request at a time.
//                  The step count is the session's StepPlanner's (any sim_step:
//                  the total stays within half a physics step of the total asked
//                  for); a request whose share is 0 steps sends no step, and its
//                  robot commands go with the next one. The carry starts over
//                  when turf-sim's frame did not continue from the last step.
// In turf-sim's process (turf-sim --simproto), the same topics on an in-memory bus shared with turf-sim's
// node: no DDS between them.
// Writes (topic names <prefix>/..., QoS profiles in configs/qos/turf_qos.xml):
//   ssl/command/blue, ssl/command/yellow  SslRobotCommand  one per commanded robot
//   control                               SimControl       teleports, time mode, pause/resume, step
// Reads:
//   control_reply  SimControlReply   matched to our requests by client name and id
//   ssl/feedback/<team>  SslRobotFeedback  ball contact for the responses
//   ssl/field      SslField          latched: robots_per_team, walls, cameras
//   clock          Clock             physics step and time mode (sync mode)
//   world_state    WorldState        current poses, for teleports with absent fields
//   ssl/camera     CameraFrame       detections for sync responses
// Source allowlists (participants/common/source_gate.h; none given: anyone): the
// blue port takes datagrams only from `allow.blue`, the yellow port from
// `allow.yellow`, the control and sync ports (teleports, speed, steps) from
// `allow.operators`. Others are answered TURF_NOT_ALLOWED and change nothing,
// counted ("<port>.not_allowed", Stats().not_allowed) and logged at a limited rate.
// Until turf-sim's field and world state have arrived, every datagram is
// answered with TURF_SIM_NOT_AVAILABLE. Bad datagrams are counted per kind
// ("<port>.<error>", e.g. "blue.not_finite"), logged at a limited rate and
// answered with SimulatorErrors; they never move a robot.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "core/pinned.h"
#include "dds/bus_fwd.h"
#include "participants/common/participant_options.h"
#include "participants/common/source_gate.h"

namespace turf {

struct SimprotoBridgeOptions : ParticipantOptions {
  SimprotoBridgeOptions() { name = "turf-simproto-bridge"; }
  std::string listen = "0.0.0.0";  // IPv4 address the ports bind to
  uint16_t control_port = 10300;
  uint16_t blue_port = 10301;
  uint16_t yellow_port = 10302;
  uint16_t sync_port = 10303;
  // Synchronous mode is the choice of whoever starts the match: a sync request switches turf-sim to lockstep,
  // and vision stops for every team until someone resumes. Off: sync requests are answered TURF_SYNC_DISABLED.
  bool sync = false;
  std::string sync_listen = "127.0.0.1";          // the sync port's address (localhost unless told)
  std::chrono::milliseconds reply_timeout{2000};  // for turf-sim's control replies
  SourceAllowlists allow;                         // who may use the team ports, control and sync (empty: anyone)
};

struct SimprotoBridgeStats {
  uint64_t datagrams = 0;    // received on every port
  uint64_t answered = 0;     // responses sent
  uint64_t commands = 0;     // robot commands published (team ports and sync steps)
  uint64_t requests = 0;     // control requests sent to turf-sim
  uint64_t rejected = 0;     // refusals of every kind
  uint64_t not_allowed = 0;  // of those, datagrams refused for their source (the allowlists)
};

class SimprotoBridge : Pinned {
 public:
  // Throws std::invalid_argument for a bad address or allowlist entry, std::runtime_error if a
  // port cannot be bound or the DDS participant cannot be created.
  explicit SimprotoBridge(SimprotoBridgeOptions options);
  // On `bus` instead of a participant of its own (the options' domain, prefix and QoS file are not used): a
  // dds::MemoryBus shared with turf-sim's node, so the bridge runs in turf-sim's process (turf-sim --simproto) and a
  // sync request pays no DDS round trip. The bus must outlive the bridge.
  SimprotoBridge(SimprotoBridgeOptions options, dds::Bus& bus);
  ~SimprotoBridge();

  // Serves every port until `stop()` answers true (checked every 50 ms).
  void Run(const std::function<bool()>& stop);
  SimprotoBridgeStats Stats() const;
  // Refusals of one kind, e.g. "blue.unknown_robot", "control.unsupported".
  uint64_t Rejected(const std::string& kind) const;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace turf
