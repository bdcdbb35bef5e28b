// The soccer game behind GS, init and beam, and rcssserver3d's automatic
// referee for the ball (shared/protocols/simspark.md: "Connection sequence",
// "Team composition", "Play modes", beam effector). Pure: time arrives as dt,
// the ball as a position, touches as the players touching it this cycle; the
// caller applies what an update asks for (ball placement, the clearings of
// players, clearing.h). The automatic referee's player rules have files of
// their own (self_collision.h, fouls.h). Not modelled: the positional fouls
// (crowding, off in naosoccersim.rb), offside, the pass mode's score ban and the
// agents' pass command.
//
// Flow, as rcssserver3d's soccer plugin runs it with naosoccersim.rb's
// settings (references: SoccerRuleAspect::<function> in
// plugin/soccer/soccerruleaspect/soccerruleaspect.cpp, GameStateAspect in
// plugin/soccer/gamestateaspect/gamestateaspect.cpp, BallStateAspect in
// plugin/soccer/ballstateaspect/ballstateaspect.cpp; settings in
// rcssserver3d/naosoccersim.rb):
// - Game time runs in every mode except BeforeKickOff and GameOver
//   (GameStateAspect::UpdateTime), on the reference's float clock (TTime:
//   sums of 0.02f, and the rules compare float sums and differences, so they
//   fire on the same cycles as the reference's); a mode's time is the game time since the
//   mode began (GameStateAspect::GetModeTime), the simulation time in those
//   two. The halves are checked before the mode's rule each cycle
//   (SoccerRuleAspect::Update -> CheckTime): half 1 ends in BeforeKickOff of
//   half 2 at half_time, half 2 in GameOver at 2 * half_time. No side change.
// - The ball (BallStateAspect): the last player to touch it and the game time
//   of that touch are kept, across modes (several touching at once: the first
//   listed). The ball is on the field while |x| < L/2 + r + 1 mm and
//   |y| < W/2 + r + 1 mm; where it last was on the field is kept.
// - The free-kick spot: every placement of the ball by the game moves it there
//   (SoccerRuleAspect::MoveBall); in PlayOn it follows the ball on the field.
// - BeforeKickOff (with a player registered): the ball is held at the centre,
//   each team is cleared from the other's half (random order). No automatic
//   kick-off (AutomaticKickOff false): a trainer calls KickOff.
// - KickOff_X: each cycle the other team is cleared from X's half and the
//   centre circle, X's players from the other half unless wholly in the circle
//   (ClearPlayersBeforeKickOff); the same in Goal_Y for the team that will kick
//   off. -> PlayOn at the first touch after the mode began; untouched for more
//   than drop_ball_time -> drop ball.
// - A drop ball (trainer, timeouts): the ball to its drop position (out of the
//   penalty areas, within the touch lines), both teams (random order) cleared
//   from its 2 m circle, PlayOn, the kick checks end.
// - Kicks taken: a kick-off (with more than 2 players), kick-in or indirect
//   free kick is indirect; a corner, goal kick or direct free kick direct. The
//   taker may not touch the ball again, 0.1 s or more after the kick, before
//   another player has: indirect free kick for the other team. A goal whose
//   last touch was the taker's within 0.1 s of an indirect kick, or an own goal
//   so from a direct kick (more than 2 players): a goal kick for the team
//   scored on, or a corner for the other team after an own goal. A kick-off
//   taker's team may not score before it touched the ball outside the centre
//   circle or the other team touched it: goal kick for the team scored on.
// - In PlayOn (and pass modes), after the taker's check: a goal when the ball
//   meets the goal's box (the reference's recorder: from a radius behind the
//   goal line to a radius before the net, a radius inside the posts, up to the
//   bar; so a ball whose centre is over the line in the mouth), or, as the
//   reference's fallback, its centre is beyond the line by more than a radius
//   in the mouth (|y| < goal_width/2, z < goal_height) -> Goal_Left if it is in
//   the right goal (left scored), else Goal_Right; goal_pause later -> KickOff
//   of the other team, ball to the centre.
// - Ball off the field (CheckBallLeftField), by the last toucher's team: over a
//   touch line -> kick-in for the other team at the point where it left, a
//   radius inside the line; over a goal line -> a goal kick for the defending team (spot 1 m in
//   front of its goal) when the attackers touched it last, else a corner for
//   the attackers at ((W + goal width) / 4 - r) from the middle, on the ball's
//   side (the reference's "temp value for RoboCup 2012"). Nobody touched the
//   ball yet: nothing happens.
// - Set pieces (kick-in, corner, goal kick, free kicks): for kick_in_pause
//   nothing; then each cycle the kick checks reset, the other team is cleared
//   from the spot's 2 m circle (a goal kick: from the penalty area), a drop ball
//   after more than drop_ball_time of the mode, and until a touch counts the
//   ball is held on the spot, the taking team's players within 0.5 m of it
//   pushed to 0.5 m once. A free kick's spot in a penalty area moves to the
//   area's front corner. A touch counts more than kick_in_pause + 0.03 s into
//   the mode, after the push; it takes the kick (a goal kick: once the ball is
//   out of the penalty area; it is no longer held meanwhile). A corner or goal
//   kick is not held before anybody ever touched the ball. Pass modes -> PlayOn
//   at a touch or after pass_duration; while in one, the other team's players
//   within 1 m of the ball are moved to 1.1 m. Offside modes: nothing (the reference's rule is
//   compiled out), they last until a trainer changes the mode.
#pragma once

#include <Eigen/Core>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/rng.h"
#include "core/state_io.h"
#include "kernel/simspark/clearing.h"
#include "kernel/simspark/types.h"

namespace turf::simspark {

struct GameRules {
  double half_time = 300.0;      // s of game time per half (naosoccersim.rb RuleHalfTime 5 * 60)
  double goal_pause = 3.0;       // s in Goal_X before the kick-off (RuleGoalPauseTime 3)
  double drop_ball_time = 15.0;  // s of a kick-off / set piece not taken before a drop ball (RuleDropBallTime 15)
  double kick_in_pause = 1.0;    // s of a set piece before it is held and may be taken (RuleKickInPauseTime 1)
  double pass_duration = 4.0;    // s in pass_left/right (PassModeDuration 4)
  double field_length = 30.0;
  double field_width = 20.0;
  double goal_width = 2.1;
  double goal_height = 0.8;
  double goal_depth = 0.6;
  // The rule aspect's penalty box (drop balls, goal kicks): PenaltyLength 1.8 deep,
  // PenaltyWidth 3.9 wide (SoccerRuleAspect::UpdateCachedInternal); the field's
  // drawn lines are 6.0 wide (field3d.h).
  double penalty_depth = 1.8;
  double penalty_width = 3.9;
  double free_kick_distance = 2.0;       // m, the centre circle's radius (FreeKickDistance 2)
  double goal_kick_distance = 1.0;       // m, a goal kick's spot in front of the goal line (GoalKickDist 1)
  double free_kick_move_distance = 2.5;  // m, how far the clearings move players (FreeKickMoveDist 2.5)
  double kick_repel_distance = 0.5;      // m, the taking team's push from the spot (KickRepelDist 0.5)
  double pass_mode_distance = 1.0;       // m, the other team's distance in pass mode (PassModeMinOppBallDist 1)
  double ball_radius = 0.042;
  double beam_noise_xy = 0.05;   // m, uniform +-
  double beam_noise_deg = 10.0;  // deg, uniform +-
  int max_players = 11;
  bool check_composition = true;  // robot-type rules at init
  int max_of_one_type = 7;
  int max_of_two_types = 9;
  int min_types = 3;
};

// Field frame; facing = direction the robot looks, degrees from +x, CCW, in (-180, 180].
struct Pose2 {
  double x = 0.0;
  double y = 0.0;
  double facing_deg = 0.0;
};

// A player touching the ball this cycle.
struct Toucher {
  Side side = Side::kLeft;
  int unum = 0;
  bool operator==(const Toucher& o) const { return side == o.side && unum == o.unum; }
};

struct InitResult {
  bool ok = false;
  std::string error;  // why not, when !ok
  Side side = Side::kLeft;
  int unum = 0;
};

// What one Update asks of the caller.
struct GameUpdate {
  bool goal = false;
  Side scored_by = Side::kLeft;
  bool place_ball_at_centre = false;  // also sets place_ball to (0, 0, ball_radius)
  bool play_mode_changed = false;     // since the previous Update (trainer changes included)
  // Move the ball here (world frame, centre) and zero its velocities.
  std::optional<Eigen::Vector3d> place_ball;
  bool dropped_ball = false;        // place_ball is a drop ball (trainer, kick-off / set-piece timeout)
  std::vector<Clearing> clearings;  // the game's moves of players this cycle, in order (clearing.h)
};

inline constexpr int kRobotTypes = 5;  // scene types 0..4

class Game {
 public:
  // seed: the clearings' random orders.
  explicit Game(GameRules rules = {}, uint64_t seed = 0);

  // Registers a player. The first team name becomes left, the second right, a
  // third is rejected. unum 0 = lowest free 1..11; others any int, unique per
  // team; at most max_players; robot type 0..4 and the composition rules
  // (when check_composition): at most 7 of one type, at most 9 of any two
  // types, and when the free slots no longer exceed the missing types (of 3),
  // only an unused type. A rejected init changes nothing (the reference server
  // keeps a new team name even then).
  InitResult Init(const std::string& team, int requested_unum, int robot_type);
  // A player leaves. When the last one of its team leaves, the team's name is
  // freed and the next new team name takes the side (turf's choice: the
  // reference server keeps a name until it restarts, so two throwaway agents
  // could lock the real teams out). A team that reconnects all its players
  // gets its side back unless another team claimed it meanwhile.
  void Leave(Side side, int unum, int robot_type);
  // The trainer's (turfResetTeam): the side's players leave and its name is
  // freed. The caller disconnects the players' agents.
  void ResetTeam(Side side);
  std::optional<std::string> TeamName(Side side) const;
  int PlayerCount(Side side) const;

  // Beam is realised only in BeforeKickOff, Goal_Left and Goal_Right.
  bool BeamAllowed() const;
  // Team frame (own goal at -x) -> field frame: x, y += U(+-beam_noise_xy),
  // rot += U(+-beam_noise_deg) (no noise if rng is null), x clamped to
  // [-length/2, 0], y to [-width/2, width/2]; the right team is point-mirrored
  // (x, y negated, facing rot + 180).
  Pose2 BeamPose(Side side, double x, double y, double rot_deg, Rng* rng) const;
  // Where init puts a player: left (-14.2, 9.2 - 1.2 k) facing +x, k = (unum - 1)
  // mod 11; right (14.2, 9.2 - 1.2 k) facing -x. The right side is mirrored in
  // x only, as the reference server does (its right start row also runs from +y
  // to -y).
  Pose2 StartPose(Side side, int unum) const;

  // Once per cycle after physics. ball = ball centre, field frame; touchers =
  // the players touching the ball this cycle.
  GameUpdate Update(double dt, const Eigen::Vector3d& ball, const std::vector<Toucher>& touchers);

  // Trainer commands.
  void SetPlayMode(PlayMode mode);
  // nullopt = coin toss (left if rng is null), except for the first kick-off of
  // half 2 when half 1's first kick-off was a coin toss: the other team.
  void KickOff(std::optional<Side> side, Rng* rng);
  void SetGameTime(double t);  // clamped to >= 0
  void SetScore(std::optional<int> left, std::optional<int> right);
  // The trainer's dropBall, at once (before the next step, as the reference's monitor commands): the ball at its
  // drop position of `ball` (where it is), both teams cleared from it, PlayOn.
  GameUpdate DropBall(const Eigen::Vector3d& ball);

  PlayMode play_mode() const { return mode_; }
  double game_time() const { return game_time_; }
  // The reference's "game paused" flag (GameStateAspect::IsPaused), under which its automatic referee judges no
  // player (self_collision.h, fouls.h): set by a cycle that begins in BeforeKickOff or a goal, kept by one in
  // an offside mode, cleared by every other; set at the start.
  bool paused() const { return paused_; }
  // s in the current mode: game time since the mode began (a trainer's time
  // change shifts it); simulation time in BeforeKickOff and GameOver.
  double mode_time() const;
  int half() const { return half_; }
  int score(Side side) const { return score_[Index(side)]; }
  const GameRules& rules() const { return rules_; }

  // Where a drop ball at `ball` goes: out of the penalty areas (to their front
  // corner on the ball's side), within the touch lines (a radius inside), at its
  // height (SoccerRuleAspect::DropBall: x is not limited).
  Eigen::Vector3d DropPosition(const Eigen::Vector3d& ball) const;
  // Where the next set piece is taken (SoccerRuleAspect's mFreeKickPos).
  const Eigen::Vector3d& free_kick_spot() const { return free_kick_pos_; }

  // Everything the game changes (teams, play mode, times, score, kick
  // checks), for snapshots; the rules are configuration, not saved. A restore
  // that fails (truncated, a value out of range) leaves the game unchanged.
  void Save(StateWriter& out) const;
  void Restore(StateReader& in);

 private:
  struct Team {
    std::optional<std::string> name;
    std::map<int, int> players;  // unum -> robot type
  };

  template <class Io, class Self>
  static void Fields(Io& io, Self& g);
  static int Index(Side side) { return side == Side::kLeft ? 0 : 1; }
  std::optional<std::string> CompositionError(const Team& team, int robot_type) const;
  void ChangeMode(PlayMode mode);
  void CheckHalfTime();
  Eigen::Vector3d OutOfPenaltyAreas(Eigen::Vector3d p) const;
  void StartKickOff(Side side);
  // The kick-off team's scoring ban, before the mode's rule.
  void UpdateKickChecks(const Eigen::Vector3d& ball, const std::vector<Toucher>& touchers);
  void TakeKick(const Toucher& taker, double time, bool indirect);
  void ResetKickChecks();
  // The reference's WasLastKickFromFreeKick: the last touch is the kick's taker's, within 0.1 s of its kick.
  bool LastTouchIsTheKick() const;
  // The mode rules; `c` is this cycle's update being built.
  struct Cycle;
  void UpdateBeforeKickOff(Cycle& c);
  void UpdateKickOff(Cycle& c, Side side);
  void UpdateSetPiece(Cycle& c);
  void UpdatePlayOn(Cycle& c);
  bool CheckTakerFoul();
  bool CheckGoal(Cycle& c);
  void CheckBallLeftField(const Cycle& c);
  void AwardSetPiece(PlayMode mode, const Eigen::Vector3d& spot);
  void AwardGoalKick(Side side);
  void AwardCornerKick(Side side, const Eigen::Vector3d& ball);
  void PunishIndirectKickGoal(const Toucher& kicker, Side scored_on, const Eigen::Vector3d& ball);
  bool BallInGoal(const Eigen::Vector3d& ball) const;
  void DropBallAt(Cycle& c, const Eigen::Vector3d& at);
  // ClearPlayersBeforeKickOff(side): side kicks off.
  void ClearBeforeKickOff(Cycle& c, Side side);
  void ClearCircle(Cycle& c, const Eigen::Vector3d& centre, Side team);
  void ClearBox(Cycle& c, const Eigen::AlignedBox2d& box, Side team, double keep_in_circle = 0.0);
  void Repel(Cycle& c, const Eigen::Vector3d& centre, double radius, double pad, Side team);
  Eigen::AlignedBox2d Half(Side side) const;         // the reference's mLeftHalf / mRightHalf (oversized)
  Eigen::AlignedBox2d PenaltyArea(Side side) const;  // the referee's box, edges included

  GameRules rules_;
  Team teams_[2];
  PlayMode mode_ = PlayMode::kBeforeKickOff;
  PlayMode reported_mode_ = PlayMode::kBeforeKickOff;
  double game_time_ = 0.0;
  double mode_start_ = 0.0;  // game time when the mode began
  double idle_time_ = 0.0;   // simulation time in BeforeKickOff / GameOver
  int half_ = 1;
  int last_kick_off_half_ = 0;              // half of the last kick-off (0: none yet)
  std::optional<Side> next_half_kick_off_;  // set by half 1's coin toss
  // The double-touch check: the kick's taker and the game time of the kick;
  // indirect: no goal straight from it.
  bool kick_check_ = false;
  bool paused_ = true;
  std::optional<Toucher> kick_taker_;
  double kick_time_ = 0.0;
  bool indirect_kick_ = false;
  // The kick-off taker's team while it may not score (nullopt: may score).
  std::optional<Side> kick_off_team_no_score_;
  int score_[2] = {0, 0};
  // The ball: its last toucher and the game time of that touch, where it last was on the field.
  std::optional<Toucher> last_toucher_;
  double last_touch_time_ = 0.0;
  Eigen::Vector3d last_on_field_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d free_kick_pos_ = Eigen::Vector3d::Zero();
  bool repel_for_kick_ = false;  // the taking team's push from the spot is still to come
  Rng rng_;
};

}  // namespace turf::simspark
