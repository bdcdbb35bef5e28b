// Team ports of the SSL simulation protocol: RobotControl bytes -> turf robot
// commands, and RobotControlResponse (ball contact per commanded robot).
//
// The port decides the team, never the datagram: a blue port's id 3 is blue 3,
// so a team can never steer the other. The sync port (one socket for both
// teams; see sync.h) reads ids 0..15 as blue and 16..31 as yellow 0..15.
//
// Mapping (RobotCommand -> idl::SslRobotCommand):
//   move_command.wheel_velocity  -> MOVE_WHEEL_VELOCITY, rim m/s, FR, BR, BL, FL
//   move_command.local_velocity  -> MOVE_LOCAL_VELOCITY (forward, left, angular)
//   move_command.global_velocity -> MOVE_GLOBAL_VELOCITY (x, y, angular)
//   no move_command (or an empty one) -> MOVE_NONE: brake to a stop
//   kick_speed > 0, kick_angle 0 or absent -> KICK_FLAT; kick_angle > 0 (degrees)
//     -> KICK_CHIP with chip_angle in rad; kick_speed 0 or absent -> no kick
//   dribbler_speed (rpm) as is; absent -> 0 (off)
// Any NaN, infinity or value past core/input_limits.h (speeds, kick speed,
// kick angle in [0, 90), dribbler rpm >= 0), an id > 15 or >= robots_per_team,
// or one id twice refuses the whole datagram: no command of it is published.
#pragma once

#include <turf/idl/SslRobot.h>

#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "codecs/proto/ssl_simulation.pb.h"
#include "codecs/ssl_simulation/errors.h"

namespace turf::simproto {

// Which socket a RobotControl came in on; decides the team of its ids.
enum class Port : uint8_t { kBlue, kYellow, kSync };

inline constexpr uint32_t kMaxWireRobotId = 15;
inline constexpr uint32_t kSyncYellowOffset = 16;  // sync port: ids 16..31 are yellow 0..15

struct RobotControlDecode {
  DecodeError error = DecodeError::kOk;
  std::vector<idl::SslRobotCommand> commands;  // empty unless error == kOk
  std::vector<uint32_t> wire_ids;              // parallel to commands: the id as the client sent it
  std::vector<SimError> errors;                // why refused, and parts not applied (unknown fields)
};

RobotControlDecode DecodeRobotControl(const uint8_t* data, size_t size, Port port, int robots_per_team);
RobotControlDecode ConvertRobotControl(const wire::simulation::RobotControl& message, Port port, int robots_per_team);

// Latest ball contact per robot (from ssl/feedback/<team>); absent means no contact.
using ContactMap = std::map<std::pair<idl::Team, uint8_t>, bool>;

// Feedback for every commanded robot, then `decoded.errors` and `extra` errors.
void FillRobotControlResponse(const RobotControlDecode& decoded, const ContactMap& contacts,
                              const std::vector<SimError>& extra, wire::simulation::RobotControlResponse* out);
std::vector<uint8_t> EncodeRobotControlResponse(const RobotControlDecode& decoded, const ContactMap& contacts,
                                                const std::vector<SimError>& extra = {});

}  // namespace turf::simproto
