// rcssserver3d's automatic referee for fouls of single players (SoccerRuleAspect's ProcessAgentState,
// UpdateTimesSinceLastBallTouch, AnalyseChargingFouls, AnalyseFouls, AnalyseTouchGroups, ClearPlayersAutomatic and
// RepositionOutsidePos with naosoccersim.rb's settings): the incapable foul and charging, after which a player is
// held in the air for 0.5 s, then put outside the field; touching, after which it is pushed out of a crowd; and
// illegal defence, after which it is moved out of its own penalty area.
//
// Every cycle each present player's torso velocity joins its last three (paused or not). While the game is paused
// (Game::paused()) every count and foul ends and nothing is judged. Otherwise, in the reference's order:
// - Counts, for each player whose torso is within the field's width (|y| < W/2 + 0.1): a torso below 0.25 m counts a
//   cycle not standing (and ends the standing streak), below 0.15 m also a cycle on the ground; at 0.25 m or above a
//   cycle standing, which ends the ground count, and more than 0.5 s standing ends the not-standing count. Every
//   player also counts a cycle since it last touched the ball (0 if it touches it now), since its last contact that
//   was not charging, and since the referee last moved it.
// - Charging, for every pair of opponents touching (charging.h judges who ran into whom), unless either is not
//   standing (any cycle not standing since it last stood 0.5 s), was moved by the referee within 1 s, or has a foul
//   already. A player moving into the other hands it its own times: the other's time since the ball becomes the
//   smaller of the two if the mover touched the ball within 1 s (0 if the mover is a goalie in its own penalty
//   area), and likewise its time since a contact. The charger commits the foul unless it is the goalie in its own
//   penalty area (the box PenaltyLength 1.8 by PenaltyWidth 3.9 and behind the goal line), touched the ball within
//   1 s, or had a contact that was not charging within 0.2 s. A contact in which nobody charged restarts both
//   players' time since a contact.
// - Illegal defence (CalculateDistanceArrays, AnalyseFouls, PenalizeIllegelDefenseFoul; MaxPlayersInsideOwnArea 3,
//   IllegalDefenseBeamPenalty false), per team, numbers in a random order: with more than three of its players
//   without a foul in its own penalty area (torso in the box, edges included), a field player that entered it this
//   cycle, or, in the cycle the goalie entered it, the one of those already in it ranked fourth from the goal, is
//   moved out at once (one fewer counted): to the nearer of the box's x and y edges, 0.4 m beyond it (not into the
//   goal), or the safe spot nearest that; its counts start again. After a pause everyone in the box has just
//   entered it.
// - Incapable, for each player without a foul: a field player more than 15 s on the ground or 30 s not standing
//   (the goalie, number 1: 30 s and 60 s).
// - Touching (touch_groups.h): in a group of more than two players touching, one is pushed 0.4 m away from the
//   group's centre (the referee's move, with its 1 s without a charging judgement); its counts start again.
// - Enforcement: for 0.5 s the player's robot is held in the air where it is (torso at 1 m plus 1 cm per cycle of the
//   foul, at rest, as it lies), then put outside the field, torso 0.4 m high with its orientation and joints as they
//   were, at x = -0.6 (7 - number) for the left team (+ for the right) and y = W/2 + 0.5 on the touch line's side
//   away from the ball, or the safe spot nearest it (safe_spot.h); its counts start again as if it had stood for
//   5 s. A touching push goes to the safe spot nearest its 0.4 m, too. Each move sees the moves before it.
//
// The counts are kept per side and number, also after a player leaves (the reference's arrays). A player whose
// torso or velocity is not finite counts nothing, is judged for nothing and moved nowhere.
//
// The game's own moves of players (clearing.h) come before Update, which sees where they put the players; Moved()
// gives such a player the same 1 s without a charging judgement. The players touching the ball are the caller's
// (the SimSpark session: a body of the player in contact with the ball in a physics step of the cycle, as the
// reference's ball recorder).
//
// Not modelled: crowding (off in naosoccersim.rb); contacts and touch groups that pile up while the
// game is paused (here each cycle has its own), and the empty groups of the reference's first cycles of a match (no
// touching foul before its second cycle of play).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "core/rng.h"
#include "core/state_io.h"
#include "kernel/simspark/charging.h"
#include "kernel/simspark/safe_spot.h"
#include "kernel/simspark/types.h"

namespace turf::simspark {

struct FoulRules {
  double field_length = 30.0;           // m (L)
  double field_width = 20.0;            // m (W)
  double goal_width = 2.1;              // m
  double penalty_depth = 1.8;           // m, the referee's box (PenaltyLength)
  double penalty_width = 3.9;           // m (PenaltyWidth)
  double ground_max_time = 15.0;        // s, a field player
  double not_standing_max_time = 30.0;  // s, a field player
  double goalie_ground_max_time = 30.0;
  double goalie_not_standing_max_time = 60.0;
  double hold_time = 0.5;  // s in the air before the move
  ChargingRules charging;
};

// The safe-spot search on the referee's field.
SafeSpotRules SpotRulesOf(const FoulRules& rules);

enum class Foul : uint8_t { kNone, kIncapable, kCharging, kTouching, kIllegalDefence };
constexpr Foul EnumCount(Foul) { return static_cast<Foul>(5); }  // snapshots (core/state_io.h)
// "none", "incapable", "charging", "touching", "illegal_defence"
const char* FoulName(Foul foul);

// A player after the cycle.
struct RefereePlayer {
  Side side = Side::kLeft;
  int unum = 0;
  Eigen::Vector3d torso = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  // the torso's, m/s
  bool touching_ball = false;
  Eigen::AlignedBox3d box;  // holds all its parts (for where a move may put another player); empty: the torso
};

// Two players touching in the cycle (of one team or both): the mean of their contact points.
struct PlayerContact {
  Side side_a = Side::kLeft;
  int unum_a = 0;
  Side side_b = Side::kRight;
  int unum_b = 0;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
};

// Where the referee puts a player's torso before the next step (orientation and joints as they are, at rest).
struct RefereeMove {
  Side side = Side::kLeft;
  int unum = 0;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  bool outside = false;  // the last move of a foul: out of the field (else held in the air, or pushed)
  Foul foul = Foul::kNone;
  int group_size = 0;  // kTouching: the players of the group it was pushed out of
};

class FoulReferee {
 public:
  // `seed`: the touching foul's random orders.
  explicit FoulReferee(FoulRules rules = {}, uint64_t seed = 0) : rules_(rules), rng_(seed) {}

  // After a cycle; returns the moves for the players held or put outside now.
  std::vector<RefereeMove> Update(bool paused, const std::vector<RefereePlayer>& players,
                                  const std::vector<PlayerContact>& contacts, const Eigen::Vector3d& ball);

  // The game moved the player (clearing.h) this cycle, before Update: as after the referee's own moves, it is not
  // judged for charging for 1 s (SoccerRuleAspect::MoveAgent resets its time since it was moved).
  void Moved(Side side, int unum) { counts_[{side, unum}].since_moved = 0; }

  // Every player's counts, for league snapshots. A restore that fails changes nothing.
  void Save(StateWriter& out) const;
  void Restore(StateReader& in);

 private:
  static constexpr int kVelocities = 3;  // the reference's AVERAGE_VELOCITY_MEASUREMENTS
  struct Counts {
    int ground = 0;        // cycles on the ground in a row
    int not_standing = 0;  // cycles not standing since the last 0.5 s standing
    int standing = 250;    // cycles standing in a row (5 s after a reset, as the reference's)
    int foul_time = 0;     // cycles of the foul; the move out comes when it passes the hold time
    Foul foul = Foul::kNone;
    int since_ball = 50;       // cycles since it touched the ball (1 s after a reset)
    int since_contact = 10;    // cycles since a contact that was not charging (0.2 s after a reset)
    int since_moved = 50;      // cycles since the referee moved it (1 s at first; a reset keeps it)
    int last_group_size = 1;   // players touching it, itself included, at the end of the cycle before
    bool in_own_area = false;  // its torso was in its own penalty area (without a foul) at the last count
    std::array<Eigen::Vector3d, kVelocities> velocities{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
                                                        Eigen::Vector3d::Zero()};
    template <class Io>
    friend void Fields(Io& io, IoRef<Io, Counts> c) {
      io(c.ground, c.not_standing, c.standing, c.foul_time, c.since_ball, c.since_contact, c.since_moved,
         c.last_group_size, c.foul, c.in_own_area, c.velocities);
    }
  };
  using Player = std::pair<Side, int>;
  void Count(const RefereePlayer& p, Counts* c) const;
  void JudgeCharging(const std::vector<RefereePlayer>& players, const std::vector<PlayerContact>& contacts,
                     const Eigen::Vector3d& ball);
  std::vector<RefereeMove> JudgeTouching(const std::vector<RefereePlayer>& players,
                                         const std::vector<PlayerContact>& contacts);
  bool Incapable(int unum, const Counts& c) const;
  std::vector<RefereeMove> JudgeIllegalDefence(Side side, const std::vector<RefereePlayer>& players);
  bool InOwnArea(Side side, const Eigen::Vector3d& torso) const;
  Eigen::Vector3d OutOfOwnArea(Side side, const Eigen::Vector3d& torso) const;
  bool GoalieInOwnArea(Side side, int unum, const Eigen::Vector3d& torso) const;
  std::vector<RefereeMove> Enforce(const std::vector<RefereePlayer>& players, const Eigen::Vector3d& ball);
  static void ResetCounts(Counts* c);

  FoulRules rules_;
  Rng rng_;
  std::map<Player, Counts> counts_;
  // During Update: every player as the moves so far left it, and the ball (the moves go through it).
  std::optional<SpotBoard> board_;
};

}  // namespace turf::simspark
