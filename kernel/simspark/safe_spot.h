// rcssserver3d's search for a safe spot for a referee's move of a player (SoccerRuleAspect::GetSafeReposition with
// its helpers SamplePositions and AdjustPositionForPenaltyArea; naosoccersim.rb: AgentRadius 0.4,
// MaxNumSafeRepositionAttempts 100, PassModeMinOppBallDist 1.0, MaxPlayersInsideOwnArea 3).
//
// A spot is unsafe inside or behind a goal (|x| > L/2 and |y| < goal width / 2 + r), within max(2 r, 1 m) of the
// ball (on the ground plane), or where a sphere of radius r (0.4 m) around it meets another player's bounding box.
// From an unsafe spot the search samples spots r further along x (away from where the player stands, towards its
// own goal when level with it) and along y (towards the player, or both ways when level), keeps the candidates in
// order of their distance from the player (dropping one within r/2 of another), and tries the nearest next, at most
// 100 times; if none is safe the spot wanted is kept. A spot in the player's own penalty area (grown by r) while
// three of its team mates are in it, and it is not, is moved out of the area first (beyond its front or sides).
// The spot's height is the wanted one's.
//
// Not modelled: the reference counts players moved into a penalty area earlier in the same cycle and leaves out
// players with a foul from the count in it; here the count is of torsos in the area now.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <utility>
#include <vector>

#include "kernel/simspark/types.h"

namespace turf::simspark {

struct SafeSpotRules {
  double field_length = 30.0;
  double goal_width = 2.1;
  double penalty_depth = 1.8;  // the referee's box (PenaltyLength)
  double penalty_width = 3.9;
  double agent_radius = 0.4;
  double min_ball_distance = 1.0;  // PassModeMinOppBallDist (the larger of it and 2 r is used)
  int max_attempts = 100;
  int max_players_in_own_area = 3;
};

// A player as the referee sees it: where its torso is and the box that holds all its parts.
struct SpotPlayer {
  Side side = Side::kLeft;
  int unum = 0;
  Eigen::Vector3d torso = Eigen::Vector3d::Zero();
  Eigen::AlignedBox3d box;  // empty: the torso's point
};

// Where the referee puts player (side, unum) that it wants at `wanted`, among `players` (it included) and the ball
// (avoid_ball false: the ball is no reason to move on, as for the reference's RepelPlayersForKick).
Eigen::Vector3d SafeSpot(const Eigen::Vector3d& wanted, Side side, int unum, const std::vector<SpotPlayer>& players,
                         const Eigen::Vector3d& ball, const SafeSpotRules& rules = {}, bool avoid_ball = true);

// The players as the referee's moves in one cycle leave them: each move sees the ones before it (the reference
// moves the bodies at once).
class SpotBoard {
 public:
  SpotBoard(std::vector<SpotPlayer> players, const Eigen::Vector3d& ball, SafeSpotRules rules)
      : players_(std::move(players)), ball_(ball), rules_(rules) {}

  // Moves the player's torso (and its box) to `wanted`, or to the safe spot nearest it when `safe`; where it went.
  Eigen::Vector3d Place(Side side, int unum, const Eigen::Vector3d& wanted, bool safe, bool avoid_ball = true);
  const SpotPlayer* Find(Side side, int unum) const;
  const std::vector<SpotPlayer>& players() const { return players_; }
  const Eigen::Vector3d& ball() const { return ball_; }
  void set_ball(const Eigen::Vector3d& ball) { ball_ = ball; }

 private:
  std::vector<SpotPlayer> players_;
  Eigen::Vector3d ball_;
  SafeSpotRules rules_;
};

}  // namespace turf::simspark
