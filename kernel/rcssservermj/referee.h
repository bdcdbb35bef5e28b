// RCSSServerMJ's referee as turf runs it (shared/protocols/rcssservermj.md,
// "Play modes", rule books): play modes, sides, kick-off by monitor command,
// goals, out of bounds and halves. Pure: the caller passes the ball after each
// cycle and who touched it; the referee answers where the ball must go.
//
// Decisions where the facts leave room (README, "Use turf with your 3D-league
// agents"):
// - Play time counts (0.02 s per cycle outside BeforeKickOff, Goal_X and
//   GameOver) and GS `t` reports it; the reference's `t` stays 0.0 and its
//   half-time never fires. At the end of the first half: BeforeKickOff of
//   the second half; of the second: GameOver. No extra time.
// - A restart (kick-off, kick-in, corner, goal kick, free kicks) turns into
//   PlayOn when the ball has moved 0.05 m from where it was placed, or after
//   the exclusive-ball time (15 s).
// - Goal: the ball wholly behind the goal line (|x| > half length + radius),
//   between the posts (|y| < goal width / 2) and under the bar (z < goal
//   height); Goal_Left when the left team scored. After 3 s: kick-off of the
//   team that conceded, ball in the centre.
// - Out over a touch line: kick-in of the team that did not touch the ball
//   last (with no touch yet: of the team whose half it left), ball on the
//   touch line where it crossed. Over a goal line: corner kick when the
//   defenders touched it last, else goal kick (ball at the goalie area's
//   front edge on the x axis).
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "core/state_io.h"
#include "kernel/rcssservermj/field.h"

namespace turf::rcssservermj {

enum class Side : uint8_t { kLeft, kRight };
constexpr Side EnumCount(Side) { return static_cast<Side>(2); }  // snapshots (core/state_io.h)

#define TURF_MJ_PLAY_MODES(X)                       \
  X(kBeforeKickOff, "BeforeKickOff")                \
  X(kKickOffLeft, "KickOff_Left")                   \
  X(kKickOffRight, "KickOff_Right")                 \
  X(kPlayOn, "PlayOn")                              \
  X(kKickInLeft, "KickIn_Left")                     \
  X(kKickInRight, "KickIn_Right")                   \
  X(kCornerKickLeft, "corner_kick_left")            \
  X(kCornerKickRight, "corner_kick_right")          \
  X(kGoalKickLeft, "goal_kick_left")                \
  X(kGoalKickRight, "goal_kick_right")              \
  X(kOffsideLeft, "offside_left")                   \
  X(kOffsideRight, "offside_right")                 \
  X(kGameOver, "GameOver")                          \
  X(kGoalLeft, "Goal_Left")                         \
  X(kGoalRight, "Goal_Right")                       \
  X(kFreeKickLeft, "free_kick_left")                \
  X(kFreeKickRight, "free_kick_right")              \
  X(kDirectFreeKickLeft, "direct_free_kick_left")   \
  X(kDirectFreeKickRight, "direct_free_kick_right") \
  X(kPenaltyKickLeft, "penalty_kick_left")          \
  X(kPenaltyKickRight, "penalty_kick_right")        \
  X(kPenaltyShootLeft, "penalty_shoot_left")        \
  X(kPenaltyShootRight, "penalty_shoot_right")

enum class PlayMode : uint8_t {
#define TURF_MJ_ENUM(id, name) id,
  TURF_MJ_PLAY_MODES(TURF_MJ_ENUM)
#undef TURF_MJ_ENUM
};

const char* PlayModeName(PlayMode mode);
std::optional<PlayMode> ParsePlayMode(std::string_view name);

struct RuleBook {
  const char* name;
  int max_players;
  double half_s;
  double extra_half_s;
  const char* field;
  double exclusive_s = 15.0;  // a restart's exclusive-ball time
  double goal_pause_s = 3.0;
};

// fifa, ssim, ssim_2025, hl_adult, hl_adult_2025; nullptr for others.
const RuleBook* FindRuleBook(std::string_view name);

class Referee {
 public:
  Referee(const RuleBook& rules, const MjField& field, double ball_radius);

  // Team sides: the first team name is left, the second right; nullopt for a third.
  std::optional<Side> Join(const std::string& team);
  void Leave(Side side);  // the side's last player left: its name is free again
  const std::optional<std::string>& team(Side side) const { return teams_[Index(side)]; }

  // Monitor commands (a random kick-off side is the caller's draw).
  void KickOff(Side side);
  void DropBall();
  void SetPlayMode(PlayMode mode);

  // After a cycle of `dt` s: the ball's centre now, the side that touched it
  // this cycle (if any). Returns where the ball must be placed (at rest), if anywhere.
  std::optional<Eigen::Vector3d> Update(double dt, const Eigen::Vector3d& ball, std::optional<Side> toucher);

  PlayMode play_mode() const { return mode_; }
  double play_time() const { return static_cast<double>(time_ms_) / 1000.0; }
  int half() const { return half_; }
  int score(Side side) const { return score_[Index(side)]; }
  // Beams are accepted in BeforeKickOff, Goal_Left and Goal_Right.
  bool BeamAllowed() const;
  const RuleBook& rules() const { return rules_; }
  const MjField& field() const { return field_; }

  // The referee's state for a league snapshot: play mode and its time, teams, score, half, last touch, the
  // ball's placements. Not its rules, field or ball radius (the session's options).
  void Save(StateWriter& out) const;
  // Restores what Save() wrote; on a bad value `in` fails and the referee stays as it was.
  void Restore(StateReader& in);

 private:
  template <class Io, class Self>
  static void Fields(Io& io, Self& r);
  static int Index(Side side) { return side == Side::kLeft ? 0 : 1; }
  void Restart(PlayMode mode, const Eigen::Vector3d& ball);
  std::optional<Eigen::Vector3d> CheckBall(const Eigen::Vector3d& ball);

  RuleBook rules_;
  MjField field_;
  double ball_radius_;
  PlayMode mode_ = PlayMode::kBeforeKickOff;
  std::array<std::optional<std::string>, 2> teams_;
  std::array<int, 2> score_{};
  int64_t time_ms_ = 0;
  int64_t mode_ms_ = 0;  // time in the current mode
  int half_ = 1;
  std::optional<Side> last_touch_;
  std::optional<Eigen::Vector3d> placed_;         // where a restart put the ball
  Side conceded_ = Side::kLeft;                   // who kicks off after a goal
  std::optional<Eigen::Vector3d> pending_place_;  // a monitor's kick-off: ball to the centre
};

}  // namespace turf::rcssservermj
