// SSL tracked data: a turf WorldState (topic world_state, ground truth) becomes
// a TrackerWrapperPacket (metres, m/s, rad). Pure.
//
// One TrackedBall (pos, vel, visibility 1), one TrackedRobot per robot on the
// field (RobotId with TeamColor, pos, orientation in [-pi, pi], vel,
// vel_angular, visibility 1), capabilities [DETECT_FLYING_BALLS] (the ball's
// height is real). frame_number is the world frame modulo 2^32.
#pragma once

#include <turf/idl/WorldState.h>

#include <cstdint>
#include <string>
#include <vector>

#include "codecs/proto/ssl_vision.pb.h"
#include "codecs/ssl_vision/errors.h"

namespace turf::vision {

struct TrackedSource {
  std::string uuid;         // stable for one tracker run (required by the protocol)
  std::string source_name;  // e.g. "turf"
};

// Refuses non-finite numbers, positions beyond 1 km, speeds beyond 1 km/s,
// unknown teams, robot ids > 15 and more than 64 robots.
VisionError CheckWorldState(const idl::WorldState& state);

// Fills `out` (cleared first) from a state that passed CheckWorldState.
// `timestamp`: seconds in the chosen clock (timestamps.h).
void FillTracked(const idl::WorldState& state, const TrackedSource& source, double timestamp,
                 wire::vision::TrackerWrapperPacket* out);

// Checks, then encodes; on an error `out` is left empty.
VisionError EncodeTracked(const idl::WorldState& state, const TrackedSource& source, double timestamp,
                          std::vector<uint8_t>* out);

}  // namespace turf::vision
