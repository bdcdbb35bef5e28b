// Small value types shared by the core's inputs and outputs.
#pragma once

#include <array>
#include <cstdint>

#include "core/errors.h"
#include "core/scene.h"

namespace turf {

struct Vec3 {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;
};

enum class MoveKind : uint8_t { kNone, kLocalVelocity, kGlobalVelocity, kWheelVelocity };
enum class KickKind : uint8_t { kNone, kFlat, kChip };

// What a team asks of one robot. The latest command per robot holds until the
// next one or until the watchdog (scene.rates.command_timeout) stops it.
struct RobotCommand {
  Team team = Team::kBlue;
  int id = 0;
  MoveKind move = MoveKind::kNone;
  // kLocalVelocity: x forward, y left; kGlobalVelocity: field frame. z: rad/s.
  Vec3 velocity;
  // kWheelVelocity: rim speeds (m/s) front_right, back_right, back_left,
  // front_left; positive turns the robot counter-clockwise.
  std::array<double, 4> wheel_velocity = {0, 0, 0, 0};
  KickKind kick = KickKind::kNone;
  double kick_speed = 0.0;      // m/s along the launch direction
  double chip_angle = 0.0;      // rad; 0 = the scene's default
  double dribbler_speed = 0.0;  // rpm; > 0 is on
};

struct BallTeleport {
  Vec3 position;
  Vec3 velocity;
  bool roll = false;  // spin to match the velocity instead of sliding
};

struct RobotTeleport {
  Team team = Team::kBlue;
  int id = 0;
  bool on_field = true;
  double x = 0.0;
  double y = 0.0;
  double orientation = 0.0;
  Vec3 velocity;  // x, y field frame (m/s), z rad/s
};

// Why an input was refused. Every refusal is one of these, so callers can
// count them per kind and say why a robot did not move.

}  // namespace turf
