#include "core/input_limits.h"

#include <cmath>

namespace turf {

namespace {

bool Finite(double v) { return std::isfinite(v); }
bool Finite(const Vec3& v) { return Finite(v.x) && Finite(v.y) && Finite(v.z); }

}  // namespace

InputError CheckCommand(const RobotCommand& c) {
  bool finite = Finite(c.velocity) && Finite(c.kick_speed) && Finite(c.chip_angle) && Finite(c.dribbler_speed);
  for (double w : c.wheel_velocity) finite = finite && Finite(w);
  if (!finite) return InputError::kNotFinite;
  if (static_cast<int>(c.team) > 1 || static_cast<int>(c.move) > 3 || static_cast<int>(c.kick) > 2)
    return InputError::kOutOfRange;
  if (std::hypot(c.velocity.x, c.velocity.y) > kMaxCommandSpeed || std::abs(c.velocity.z) > kMaxCommandAngularSpeed)
    return InputError::kOutOfRange;
  for (double w : c.wheel_velocity)
    if (std::abs(w) > kMaxCommandSpeed) return InputError::kOutOfRange;
  if (c.kick_speed < 0 || c.kick_speed > kMaxKickSpeed) return InputError::kOutOfRange;
  if (c.chip_angle < 0 || c.chip_angle >= M_PI / 2) return InputError::kOutOfRange;
  if (c.dribbler_speed < 0 || c.dribbler_speed > kMaxDribblerSpeed) return InputError::kOutOfRange;
  return InputError::kOk;
}

InputError CheckBallTeleport(const BallTeleport& t, const Scene& scene) {
  if (!Finite(t.position) || !Finite(t.velocity)) return InputError::kNotFinite;
  const FieldParams& f = scene.field;
  const double r = scene.ball.radius;
  if (std::abs(t.position.x) > f.length / 2 + f.boundary_width_goal_line - r ||
      std::abs(t.position.y) > f.width / 2 + f.boundary_width - r || t.position.z < 0 ||
      t.position.z > kMaxTeleportHeight)
    return InputError::kOutsideField;
  const Vec3& v = t.velocity;
  if (std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z) > kMaxTeleportSpeed) return InputError::kOutOfRange;
  return InputError::kOk;
}

InputError CheckRobotTeleport(const RobotTeleport& t, const Scene& scene) {
  if (const InputProblem p = CheckPlacementValues(t); !p.ok()) return p.error;
  if (!t.on_field) return InputError::kOk;  // parked: the pose is not used, but nonsense is still refused
  const FieldParams& f = scene.field;
  const double r = scene.robot.radius;
  if (std::abs(t.x) > f.length / 2 + f.boundary_width_goal_line - r ||
      std::abs(t.y) > f.width / 2 + f.boundary_width - r)
    return InputError::kOutsideField;
  return InputError::kOk;
}

}  // namespace turf
