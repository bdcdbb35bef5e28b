// Sanity limits for inputs from outside. A value past these is nonsense and is
// refused; a value within them but past a robot's ability (e.g. 5 m/s for a
// 3 m/s robot, an 8 m/s kick) is accepted and saturated by the drive or kicker,
// as a real robot saturates.
#pragma once

#include "core/scene.h"
#include "core/types.h"

namespace turf {

inline constexpr double kMaxCommandSpeed = 20.0;          // m/s, also wheel rim speeds
inline constexpr double kMaxCommandAngularSpeed = 100.0;  // rad/s
inline constexpr double kMaxKickSpeed = 30.0;             // m/s
inline constexpr double kMaxDribblerSpeed = 100000.0;     // rpm
inline constexpr double kMaxTeleportSpeed = 30.0;         // m/s
inline constexpr double kMaxTeleportHeight = 10.0;        // m

InputError CheckCommand(const RobotCommand& command);
InputError CheckBallTeleport(const BallTeleport& teleport, const Scene& scene);
InputError CheckRobotTeleport(const RobotTeleport& teleport, const Scene& scene);

}  // namespace turf
