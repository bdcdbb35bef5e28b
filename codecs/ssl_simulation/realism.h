// realism_config of the SSL simulation protocol -> turf's sensor realism.
//
// ER-Force's RealismConfigErForce (carried in RealismConfig.custom, matched by
// the Any's type name, whatever its package) is what SSL users know. Its knobs
// become one OP_SET_REALISM request with typed RealismValues (no preset), so
// only the named settings change. Units as ER-Force's simulator: metres,
// radians, probabilities, nanoseconds; turf's values are SI (seconds).
// The mapping is the table kErForceKnobs in realism.cpp, one row per knob:
//   stddev_ball_p            -> REALISM_CAMERA_BALL_POSITION_STDDEV
//   stddev_robot_p           -> REALISM_CAMERA_ROBOT_POSITION_STDDEV
//   stddev_robot_phi         -> REALISM_CAMERA_ROBOT_ORIENTATION_STDDEV
//   enable_invisible_ball    -> REALISM_CAMERA_BALL_OCCLUSION (0/1)
//   missing_ball_detections  -> REALISM_CAMERA_BALL_VANISH
//   vision_delay             -> REALISM_CAMERA_LINK_LATENCY (ns -> s)
//   vision_processing_time   -> REALISM_CAMERA_PROCESSING_DELAY (ns -> s)
//   robot_command_loss       -> REALISM_COMMAND_LOSS
// The other knobs (ball area, visibility threshold, camera overlap, dribbler
// detections, camera position error, response loss, simulate_dribbling) and
// other Any types get a TURF_UNSUPPORTED_CONFIG_REALISM error naming them.
#pragma once

#include <turf/idl/SimControl.h>

#include <vector>

#include "codecs/proto/ssl_simulation.pb.h"
#include "codecs/ssl_simulation/errors.h"

namespace turf::simproto {

// The values for OP_SET_REALISM, in the order of the knobs in the table (and
// of the Any messages); empty if nothing applicable was set (or a value was
// not finite / out of range, which `problems` records).
std::vector<idl::RealismValue> RealismValues(const wire::simulation::RealismConfig& config, Problems* problems);

}  // namespace turf::simproto
