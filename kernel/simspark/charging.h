// rcssserver3d's charging judgement on one collision between two opponents (SoccerRuleAspect::AnalyseChargingFouls
// with naosoccersim.rb's settings), as a pure function: who ran into whom. The referee (fouls.h) keeps the times
// the foul also depends on and decides what follows.
//
// For each of the two players: s its speed (the mean of its torso's last three velocities, on the ground plane),
// d its distance to the ball, aVB and aVO the angles (0..180 deg) between its velocity and the direction to the
// ball, to the opponent. Both are first taken to be charging. If either is within max_ball_rules_dist of the
// ball, a player charges only if it runs more towards the opponent than the ball (aVB >= aVO), at least
// min_ball_speed_angle away from the ball and at least min_speed fast; if that makes neither a charger and their
// distances to the ball differ by more than min_delta_dist, the one farther from the ball charges if the angles
// to the opponent differ by more than min_delta_angle or the other is slower than min_speed. Then a charger must
// also be at least min_speed fast and run at min_collision_speed or more towards the collision (the midpoint of the
// contact point and the opponent). That is `moving_into`. A foul (`charging`) needs exactly one of them moving
// into the other and the contact at least min_coll_ball_dist from the ball (else both were playing it).
#pragma once

#include <Eigen/Core>
#include <array>

namespace turf::simspark {

struct ChargingRules {
  double min_speed = 0.4;            // m/s (ChargingMinSpeed)
  double min_ball_speed_angle = 30;  // deg (ChargingMinBallSpeedAngle)
  double min_delta_dist = 0.05;      // m (ChargingMinDeltaDist)
  double min_delta_angle = 15;       // deg (ChargingMinDeltaAng)
  double immunity_time = 1.0;        // s after touching the ball (ChargingImmunityTime)
  double collision_min_time = 0.2;   // s without a contact that was not charging (ChargingCollisionMinTime)
  double max_ball_rules_dist = 1.0;  // m (ChargingMaxBallRulesDist)
  double min_coll_ball_dist = 0.1;   // m (ChargingMinCollBallDist)
  double min_collision_speed = 0.2;  // m/s (ChargingMinCollisionSpeed)
};

// One of the two players of a collision.
struct ChargingParty {
  Eigen::Vector3d torso = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  // the mean of the last three, m/s
};

struct ChargingVerdict {
  std::array<bool, 2> moving_into{};  // ran into the other (before the both-or-near-the-ball exemption)
  std::array<bool, 2> charging{};     // committed the foul, if its times allow (fouls.h)
};

ChargingVerdict JudgeCollision(const std::array<ChargingParty, 2>& players, const Eigen::Vector3d& contact,
                               const Eigen::Vector3d& ball, const ChargingRules& rules = {});

}  // namespace turf::simspark
