// grSim commands and replacement (grSim_Packet, codecs/proto/grsim.proto) ->
// turf's SslRobotCommand and SimControl. A pure function: no sockets, clocks or
// globals. Wire facts: shared/protocols/grsim.md.
//
// Policy: any bad field refuses the whole datagram, so no robot moves because
// of a bad packet. Errors are named values with the offending field.
//
// Differences from the reference simulator, on purpose:
// - Kick speeds are not clamped here beyond the sanity limits (turf-sim clamps
//   to the scene's kicker); the config may carry the field's limits to clamp.
// - A ball replacement's absent fields are 0 (older grSim); newer grSim keeps
//   the ball's current value, which a pure codec cannot know.
// - wheelsspeed = true needs all of wheel1..4 (the reference keeps an absent
//   wheel's previous speed; turf commands are whole).
#pragma once

#include <turf/idl/SimControl.h>
#include <turf/idl/SslRobot.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/errors.h"

namespace turf::grsim {

struct GrsimCodecConfig {
  double wheel_radius = 0.027;  // m: wheel rad/s -> rim m/s (SslField.wheel_radius)
  // grSim wheel (0 = wheel1) for each of turf's wheels: front_right, back_right,
  // back_left, front_left. Assumption, from grSim's robot model: wheel1..4 sit at
  // 60, 135, 225 and 300 degrees counter-clockwise from the kicker (front left,
  // back left, back right, front right), in rad/s, positive turning the robot
  // counter-clockwise, as turf's rim speeds do. Hence turf i <- grSim wheel 4-i.
  std::array<int, 4> wheel_source = {3, 2, 1, 0};
  int robots_per_team = 16;          // ids >= this are unknown (SslField.robots_per_team)
  double dribbler_rpm = 1000.0;      // dribbler_speed for spinner = true
  size_t max_datagram_size = 16384;  // bytes; larger is refused as oversized
  // > 0: clamp kicks to these (SslField.max_flat/chip_kick_speed); 0: leave it to turf-sim.
  double max_flat_kick_speed = 0.0;
  double max_chip_kick_speed = 0.0;
  // > 0: the walls (SslField: |x| <= length / 2 + boundary_width_goal_line, |y| <= width / 2 + boundary_width),
  // which a replacement's ball (less ball_radius) and robots on the field (less robot_radius) must fit inside, so a
  // packet turf-sim would refuse in part is refused whole here; 0: unknown (turf-sim checks).
  double wall_x = 0.0;
  double wall_y = 0.0;
  double ball_radius = 0.0;
  double robot_radius = 0.0;
};

// Empty if `config` is usable, else why not. Decode assumes a usable config.
std::string CheckConfig(const GrsimCodecConfig& config);

// turf's one taxonomy (core/errors.h). The codec answers kEmpty, kOversized (more
// than max_datagram_size bytes), kMalformed, kMissingRequired, kNotFinite,
// kOutOfRange (also a negative kick), kUnknownRobot (id >= robots_per_team), kDuplicateRobot (a robot replaced
// twice in one packet) and kOutsideField (a replacement beyond the walls, when they are known).
using GrsimError = turf::Error;
inline const char* GrsimErrorName(GrsimError error) { return turf::ErrorName(error); }

// What one datagram asks for.
struct GrsimRequests {
  // The team of grSim_Commands, when present (also with no robot command):
  // robot status goes to the address that last sent this team's commands.
  std::optional<idl::Team> command_team;
  std::vector<idl::SslRobotCommand> commands;  // all of command_team
  // OP_TELEPORT_ROBOT per replaced robot, then OP_TELEPORT_BALL (grSim's order).
  // `client` and `request_id` are left for the sender to fill.
  std::vector<idl::SimControl> controls;
};

struct GrsimDecodeResult {
  GrsimError error = GrsimError::kOk;
  std::string detail;      // for an error: the field, e.g. "robot_commands[2].kickspeedx"
  GrsimRequests requests;  // empty unless ok()
  bool ok() const { return error == GrsimError::kOk; }
};

GrsimDecodeResult Decode(const uint8_t* bytes, size_t size, const GrsimCodecConfig& config);

}  // namespace turf::grsim
