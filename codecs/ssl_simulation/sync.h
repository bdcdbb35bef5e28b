// The drafted synchronous mode of the SSL simulation protocol: one
// SimulationSyncRequest = apply simulator_command, apply robot_control, step
// sim_step seconds; the SimulationSyncResponse carries the detections of every
// camera frame captured during that step and the robot control response.
//
// turf's choices where the draft is silent:
//  - Port: one sync socket (default 10303) for both teams. RobotControl ids
//    0..15 are blue robots 0..15, ids 16..31 are yellow robots 0..15; feedback
//    answers with the same ids.
//  - sim_step: any positive, finite value up to kMaxSyncStep seconds; absent,
//    0, negative, NaN, infinite or larger is refused. It need not be a whole
//    number of physics steps: the bridge's StepPlanner (step_planner.h) runs
//    the nearest whole number of steps to the session's requested total and
//    carries the remainder (1/60 s at 2 ms: 8, 9, 8, 8, 9, 8, ...). A request
//    whose share rounds to zero steps runs none; its commands and teleports
//    still apply and it answers with no detections.
//  - The response has no time field (the draft defines none): the time reached
//    shows in the detections, which are those turf-sim released up to the time
//    actually reached (not the time asked for).
//  - Detections: every camera frame turf-sim released during the step, i.e.
//    what a vision client would have received in that time. With ideal cameras
//    these are exactly the frames captured in (t_before, t_after]; with a
//    modelled vision latency a frame captured late in a step comes with the
//    next one, and a lost frame never comes.
//  - The response must fit one UDP datagram: if it would not, the oldest
//    detections are left out and TURF_SYNC_RESPONSE_TOO_LARGE says how many.
//  - simulation_speed in the sync command is refused (TURF_UNSUPPORTED_SPEED_IN_SYNC_MODE):
//    sync mode runs in lockstep. Other unsupported parts answer as on the control port.
//  - The request is atomic: any fatal problem in any part refuses all of it
//    (no teleport, no command, no step) and the errors come back in
//    robot_control_response.errors, the response's only error list.
//  - Detection times are simulation time in seconds (vision::ClockMode::kSim),
//    so two runs of the same requests give the same bytes.
#pragma once

#include <turf/idl/SslVision.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "codecs/proto/ssl_simulation.pb.h"
#include "codecs/ssl_simulation/errors.h"
#include "codecs/ssl_simulation/robot_control.h"
#include "codecs/ssl_simulation/simulator_command.h"

namespace turf::simproto {

inline constexpr double kMaxSyncStep = 1.0;         // s of simulation per request
inline constexpr size_t kMaxResponseBytes = 65507;  // one IPv4 UDP datagram
inline constexpr char kSyncResponseTooLarge[] = "TURF_SYNC_RESPONSE_TOO_LARGE";

struct SyncDecode {
  DecodeError error = DecodeError::kOk;
  int64_t sim_step_ns = 0;  // requested simulation time, rounded to ns (0 if refused)
  SimulatorCommandDecode command;
  RobotControlDecode robots;
  std::vector<SimError> errors;  // all of them: the request's own, the command's, the robots'
};

// `step_s`: turf-sim's physics step (Clock.step_s). `context.sync` is forced on.
SyncDecode DecodeSyncRequest(const uint8_t* data, size_t size, const ControlContext& context, double step_s);

// The camera frames a response carries, by reference: a sync request's frames are kept once by whoever received
// them (participants/simproto_bridge/sim_link.h shares them), not copied for each response.
struct SyncFrames {
  std::vector<const idl::CameraFrame*> refs;
  SyncFrames() = default;
  SyncFrames(const std::vector<idl::CameraFrame>& frames);                         // NOLINT: implicit on purpose
  SyncFrames(const std::vector<std::shared_ptr<const idl::CameraFrame>>& frames);  // NOLINT
};

// Detections of `frames` (sorted by capture time, then camera), feedback for
// every robot `request` commanded, and `request.errors` plus `extra` errors.
// A frame the vision codec refuses is left out and named in the errors.
void FillSyncResponse(const SyncFrames& frames, const idl::SslField& field, const SyncDecode& request,
                      const ContactMap& contacts, const std::vector<SimError>& extra,
                      wire::simulation::SimulationSyncResponse* out);
std::vector<uint8_t> EncodeSyncResponse(const SyncFrames& frames, const idl::SslField& field, const SyncDecode& request,
                                        const ContactMap& contacts, const std::vector<SimError>& extra);

}  // namespace turf::simproto
