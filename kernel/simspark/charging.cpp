#include "kernel/simspark/charging.h"

#include <cmath>

namespace turf::simspark {

namespace {

constexpr double kDeg = 180.0 / M_PI;

// The angle between a velocity and a direction, both on the ground plane: 0..180 deg (salt's gNormalizeRad of the
// heading difference, in degrees, made positive).
double AngleBetween(const Eigen::Vector3d& velocity, const Eigen::Vector3d& direction) {
  double a = std::atan2(velocity.y(), velocity.x()) - std::atan2(direction.y(), direction.x());
  a = std::remainder(a, 2 * M_PI);
  return std::abs(a * kDeg);
}

double GroundDistance(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::hypot(a.x() - b.x(), a.y() - b.y());
}

}  // namespace

ChargingVerdict JudgeCollision(const std::array<ChargingParty, 2>& p, const Eigen::Vector3d& contact,
                               const Eigen::Vector3d& ball, const ChargingRules& rules) {
  double d[2], s[2], to_ball[2], to_opponent[2];
  for (int i = 0; i < 2; ++i) {
    d[i] = GroundDistance(p[i].torso, ball);
    s[i] = std::hypot(p[i].velocity.x(), p[i].velocity.y());
    to_ball[i] = AngleBetween(p[i].velocity, ball - p[i].torso);
    to_opponent[i] = AngleBetween(p[i].velocity, p[1 - i].torso - p[i].torso);
  }
  bool charging[2] = {true, true};
  if (d[0] < rules.max_ball_rules_dist || d[1] < rules.max_ball_rules_dist) {
    for (int i = 0; i < 2; ++i)
      charging[i] = to_ball[i] >= to_opponent[i] && to_ball[i] >= rules.min_ball_speed_angle && s[i] >= rules.min_speed;
    // Both heading for the ball: the one farther from it, unless they head the same way and both run.
    if (!charging[0] && !charging[1] && std::abs(d[0] - d[1]) > rules.min_delta_dist) {
      const bool apart = std::abs(to_opponent[0] - to_opponent[1]) > rules.min_delta_angle;
      charging[0] = d[0] > d[1] && (apart || s[1] < rules.min_speed);
      charging[1] = d[1] > d[0] && (apart || s[0] < rules.min_speed);
    }
  }
  ChargingVerdict v;
  for (int i = 0; i < 2; ++i) {
    // Towards the midpoint of the contact and the opponent, on the ground plane.
    Eigen::Vector3d towards = (contact + p[1 - i].torso) / 2 - p[i].torso;
    towards.z() = 0;
    const double norm = towards.norm();
    const double collision_speed =
        norm > 0 ? p[i].velocity.x() * towards.x() / norm + p[i].velocity.y() * towards.y() / norm : 0.0;
    v.moving_into[i] = charging[i] && s[i] >= rules.min_speed && collision_speed >= rules.min_collision_speed;
  }
  const bool exempt =
      (v.moving_into[0] && v.moving_into[1]) || GroundDistance(contact, ball) < rules.min_coll_ball_dist;
  for (int i = 0; i < 2; ++i) v.charging[i] = v.moving_into[i] && !exempt;
  return v;
}

}  // namespace turf::simspark
