// rcssserver3d's automatic referee for players that cannot stand: the "incapable" foul (the reference's
// SoccerRuleAspect::ProcessAgentState, AnalyseFouls, ClearPlayersAutomatic and RepositionOutsidePos with
// naosoccersim.rb's settings: GroundMaxTime 15, NotStandingMaxTime 30, GoalieGroundMaxTime 30,
// GoalieNotStandingMaxTime 60, FoulHoldTime 0.5, MaxFoulTime 0).
//
// After every cycle in which the game is not paused (Game::paused()), for each player whose torso is within the
// field's width (|y| < W/2 + 0.1): a torso below 0.25 m counts a cycle not standing (and ends the standing streak),
// below 0.15 m also a cycle on the ground; at 0.25 m or above a cycle standing, which ends the ground count, and
// more than 0.5 s standing ends the not-standing count. A field player more than 15 s on the ground or 30 s not
// standing (the goalie, number 1: 30 s and 60 s) commits the foul: for 0.5 s its robot is held in the air where it
// is (torso at 1 m plus 1 cm per cycle, at rest, as it lies), then put outside the field, torso 0.4 m high with its
// orientation and joints as they were, at x = -0.6 (7 - number) for the left team (+ for the right) and
// y = W/2 + 0.5 on the touch line's side away from the ball. Its counts start again as if it had stood for 5 s.
// While paused every count and foul ends.
//
// The counts are kept per side and number, also after a player leaves (the reference's arrays). A torso position
// that is not finite counts nothing and moves nobody.
//
// Not modelled: the reference's other fouls that come first or reset a player's counts (charging, illegal
// defence, touching; crowding is off in naosoccersim.rb), and its GetSafeReposition, which nudges the outside spot
// away from other robots standing on it.
#pragma once

#include <Eigen/Core>
#include <map>
#include <utility>
#include <vector>

#include "core/state_io.h"
#include "kernel/simspark/types.h"

namespace turf::simspark {

struct IncapableRules {
  double field_width = 20.0;            // m (W)
  double ground_max_time = 15.0;        // s, a field player
  double not_standing_max_time = 30.0;  // s, a field player
  double goalie_ground_max_time = 30.0;
  double goalie_not_standing_max_time = 60.0;
  double hold_time = 0.5;  // s in the air before the move
};

// A player's torso after the cycle.
struct PlayerTorso {
  Side side = Side::kLeft;
  int unum = 0;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
};

// Where the referee puts a player's torso before the next step (orientation and joints as they are, at rest).
struct RefereeMove {
  Side side = Side::kLeft;
  int unum = 0;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  bool outside = false;  // the last move of a foul: out of the field (else held in the air)
};

class IncapableRule {
 public:
  explicit IncapableRule(IncapableRules rules = {}) : rules_(rules) {}

  // After a cycle; returns the moves for the players held or put outside now.
  std::vector<RefereeMove> Update(bool paused, const std::vector<PlayerTorso>& players, const Eigen::Vector3d& ball);

  // Every player's counts, for league snapshots. A restore that fails changes nothing.
  void Save(StateWriter& out) const;
  void Restore(StateReader& in);

 private:
  struct Counts {
    int ground = 0;        // cycles on the ground in a row
    int not_standing = 0;  // cycles not standing since the last 0.5 s standing
    int standing = 250;    // cycles standing in a row (5 s after a reset, as the reference's)
    int foul_time = 0;     // cycles of the foul (0: none); the move out comes when it passes the hold time
  };
  using Player = std::pair<Side, int>;
  void Count(const PlayerTorso& p, Counts* c) const;
  bool Incapable(int unum, const Counts& c) const;

  IncapableRules rules_;
  std::map<Player, Counts> counts_;
};

}  // namespace turf::simspark
