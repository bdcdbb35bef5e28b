// realism_config of the SSL simulation protocol -> turf's sensor realism.
//
// ER-Force's RealismConfigErForce (carried in RealismConfig.custom, matched by
// the Any's type name, whatever its package) is what SSL users know. Its knobs
// become an OP_SET_REALISM request with YAML text that changes only the named
// settings (loader/realism_yaml.h). Units as ER-Force's simulator: metres,
// radians, probabilities, nanoseconds.
//   stddev_ball_p            -> camera.ball_position_stddev
//   stddev_robot_p           -> camera.robot_position_stddev
//   stddev_robot_phi         -> camera.robot_orientation_stddev
//   enable_invisible_ball    -> camera.ball_occlusion
//   missing_ball_detections  -> camera.ball_vanish
//   vision_delay             -> camera.link.latency
//   vision_processing_time   -> camera.processing_delay
//   robot_command_loss       -> command.loss
// The other knobs (ball area, visibility threshold, camera overlap, dribbler
// detections, camera position error, response loss, simulate_dribbling) and
// other Any types get a TURF_UNSUPPORTED_CONFIG_REALISM error naming them.
#pragma once

#include <string>

#include "codecs/proto/ssl_simulation.pb.h"
#include "codecs/ssl_simulation/errors.h"

namespace turf::simproto {

// YAML for OP_SET_REALISM, or "" if nothing applicable was set (or a value was
// not finite / out of range, which `problems` records).
std::string RealismYaml(const wire::simulation::RealismConfig& config, Problems* problems);

}  // namespace turf::simproto
