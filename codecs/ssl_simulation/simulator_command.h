// Control port of the SSL simulation protocol: SimulatorCommand bytes -> turf
// control requests, and SimulatorResponse.
//
// Mapping (each becomes one idl::SimControl, in this order):
//   control.teleport_ball     -> OP_TELEPORT_BALL (x, y, z, vx, vy, vz, roll)
//   control.teleport_robot[i] -> OP_TELEPORT_ROBOT (x, y, orientation, v_x, v_y,
//                                v_angular; present -> on_field)
//   control.simulation_speed  -> 0: OP_PAUSE; 1: OP_SET_TIME_MODE TIME_REALTIME
//                                then OP_RESUME; other > 0 (<= 1000): TIME_SCALED
//                                at that speed, then OP_RESUME
//
// Absent fields. turf needs a full pose, so an absent position or orientation
// keeps the current one, taken from the newest world state the caller passes
// (as ER-Force's simulator keeps it); absent velocities are 0 (the protocol's
// defaults). An absent `present` keeps the robot on or off the field as it is.
// A robot off the field needs x and y to come on; its orientation defaults to 0.
//
// teleport_safely (ball): robots the ball would land in (centre closer than
// robot radius + ball radius + 5 cm, ball below robot height) are pushed
// radially out to that distance, with zero velocity, before the ball arrives.
// by_force (ball or robot): turf has no force-driven placement; that teleport
// is not done and TURF_UNSUPPORTED_BY_FORCE says so.
// config.realism_config: ER-Force's realism knobs -> OP_SET_REALISM (see
// realism.h); knobs turf does not model are named in errors.
// config (geometry, robot_specs, vision_port): turf's scene is immutable at run
// time; each present part gets its TURF_UNSUPPORTED_CONFIG_* error and changes
// nothing. The rest of the command still applies.
// NaN, infinity, a value past the sanity limits, a target beyond the walls or
// an unknown robot anywhere refuses the whole command: no request at all.
#pragma once

#include <turf/idl/SimControl.h>
#include <turf/idl/SslVision.h>
#include <turf/idl/WorldState.h>

#include <cstdint>
#include <vector>

#include "codecs/proto/ssl_simulation.pb.h"
#include "codecs/ssl_simulation/errors.h"

namespace turf::simproto {

// turf-sim's own limits (kernel/time_control.h's kMinTimeSpeed, kMaxTimeSpeed; a test holds them equal): a speed
// turf-sim refuses must be refused here, before any other request of the command is applied. 0 pauses.
inline constexpr double kMinSimulationSpeed = 0.01;
inline constexpr double kMaxSimulationSpeed = 1000.0;
inline constexpr double kSafeTeleportMargin = 0.05;  // m between a pushed robot and the ball

struct ControlContext {
  const idl::SslField* field = nullptr;    // robots_per_team, walls, radii; nullptr: not known yet
  const idl::WorldState* world = nullptr;  // newest ground truth, for absent fields; nullptr: none yet
  bool sync = false;                       // sync port: lockstep owns time, simulation_speed is refused
};

struct SimulatorCommandDecode {
  DecodeError error = DecodeError::kOk;
  // In order; `client` and `request_id` are left for the caller. Empty unless error == kOk.
  std::vector<idl::SimControl> requests;
  std::vector<SimError> errors;  // why refused, and every part not applied
};

SimulatorCommandDecode DecodeSimulatorCommand(const uint8_t* data, size_t size, const ControlContext& context);
SimulatorCommandDecode ConvertSimulatorCommand(const wire::simulation::SimulatorCommand& message,
                                               const ControlContext& context);

// A request turf-sim refused, as the error the client sees (TURF_REJECTED_BY_SIM).
SimError RejectedBySim(const idl::SimControlReply& reply);

std::vector<uint8_t> EncodeSimulatorResponse(const std::vector<SimError>& errors);

}  // namespace turf::simproto
