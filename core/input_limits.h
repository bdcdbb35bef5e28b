// Sanity limits for inputs from outside. A value past these is nonsense and is
// refused; a value within them but past a robot's ability (e.g. 5 m/s for a
// 3 m/s robot, an 8 m/s kick) is accepted and saturated by the drive or kicker,
// as a real robot saturates.
#pragma once

#include <cmath>

#include "core/scene.h"
#include "core/types.h"

namespace turf {

inline constexpr double kMaxCommandSpeed = 20.0;          // m/s, also wheel rim speeds
inline constexpr double kMaxCommandAngularSpeed = 100.0;  // rad/s
inline constexpr double kMaxKickSpeed = 30.0;             // m/s
inline constexpr double kMaxDribblerSpeed = 100000.0;     // rpm
inline constexpr double kMaxTeleportSpeed = 30.0;         // m/s
inline constexpr double kMaxTeleportHeight = 10.0;        // m
// A placement's coordinates and orientation, checked whatever the robot's on/off state (a robot taken off the
// field still carries them on every wire): past these they are nonsense. No field is near 1 km.
inline constexpr double kMaxPlacementCoordinate = 1000.0;  // m
inline constexpr double kMaxPlacementOrientation = 1e6;    // rad

// What is wrong with an input, and which of its fields (for a refusal that names it).
struct InputProblem {
  InputError error = InputError::kOk;
  const char* field = "";
  bool ok() const { return error == InputError::kOk; }
};

// The one sanity check of a robot placement, for every protocol (grSim replacement, the SSL simulation
// protocol's teleport, turf's SimControl): every number finite and within the limits above, on or off the field.
// Fields: "x", "y", "orientation", "velocity". The walls are the scene's business (CheckRobotTeleport). Inline:
// the codecs use it without linking the physics.
inline InputProblem CheckPlacementValues(const RobotTeleport& t) {
  const struct {
    const char* field;
    bool finite;
    bool in_range;
  } kChecks[] = {
      {"x", std::isfinite(t.x), std::abs(t.x) <= kMaxPlacementCoordinate},
      {"y", std::isfinite(t.y), std::abs(t.y) <= kMaxPlacementCoordinate},
      {"orientation", std::isfinite(t.orientation), std::abs(t.orientation) <= kMaxPlacementOrientation},
      {"velocity", std::isfinite(t.velocity.x) && std::isfinite(t.velocity.y) && std::isfinite(t.velocity.z),
       std::hypot(t.velocity.x, t.velocity.y) <= kMaxTeleportSpeed &&
           std::abs(t.velocity.z) <= kMaxCommandAngularSpeed},
  };
  for (const auto& c : kChecks) {
    if (!c.finite) return {InputError::kNotFinite, c.field};
    if (!c.in_range) return {InputError::kOutOfRange, c.field};
  }
  return {};
}

InputError CheckCommand(const RobotCommand& command);
InputError CheckBallTeleport(const BallTeleport& teleport, const Scene& scene);
InputError CheckRobotTeleport(const RobotTeleport& teleport, const Scene& scene);

}  // namespace turf
