#include "kernel/simspark/game.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/state_io.h"

namespace turf::simspark {

namespace {

// What a cycle beginning in `mode` does to the reference's paused flag (SoccerRuleAspect::Update's mode rules:
// UpdateBeforeKickOff and UpdateGoal set it; UpdatePlayOn, UpdateGameOver and the kick-off, kick-in, free kick,
// goal kick, corner kick and pass modes' rules clear it; UpdateOffside leaves it).
bool PausedAfter(PlayMode mode, bool paused) {
  switch (mode) {
    case PlayMode::kBeforeKickOff:
    case PlayMode::kGoalLeft:
    case PlayMode::kGoalRight:
      return true;
    case PlayMode::kOffsideLeft:
    case PlayMode::kOffsideRight:
      return paused;
    default:
      return false;
  }
}

// Degrees into (-180, 180].
double NormalizeDeg(double deg) {
  double r = std::remainder(deg, 360.0);
  if (r <= -180.0) r += 360.0;
  return r;
}

Side Opponent(Side side) { return side == Side::kLeft ? Side::kRight : Side::kLeft; }

// rcssserver3d's times are floats (TTime): its game clock sums 0.02f each cycle and its rules compare float sums
// and differences, so they fire on those (an untouched kick-off's 15 s are over after 750 cycles, at 15.00015; the
// first half ends after 15001, at 300.01). turf's clock keeps the same float values (in doubles).
float F(double x) { return static_cast<float>(x); }

// A touch 0.1 s after the kick is a second kick (SoccerRuleAspect::
// WasLastKickFromFreeKick: "kickTime - mLastFreeKickKickTime < 0.1", floats
// against a double).
constexpr double kKickDuration = 0.1;
// A set piece's touch counts when it comes more than the pause plus 0.03 s
// into the mode (SoccerRuleAspect::UpdateKickIn / UpdateFreeKick /
// UpdateCornerKick / UpdateGoalKick: time > lastChange + mKickInPauseTime + 0.03).
constexpr double kSetPieceTouchMargin = 0.03;

// The team taking a set piece (kick-in, corner, goal kick, free kicks).
Side SetPieceTeam(PlayMode mode) {
  switch (mode) {
    case PlayMode::kKickInLeft:
    case PlayMode::kCornerKickLeft:
    case PlayMode::kGoalKickLeft:
    case PlayMode::kFreeKickLeft:
    case PlayMode::kDirectFreeKickLeft:
      return Side::kLeft;
    default:
      return Side::kRight;
  }
}

}  // namespace

Game::Game(GameRules rules, uint64_t seed) : rules_(rules), rng_(seed) {
  free_kick_pos_ = {0.0, 0.0, rules_.ball_radius};  // SoccerRuleAspect's constructor
}

std::optional<std::string> Game::CompositionError(const Team& team, int robot_type) const {
  std::array<int, kRobotTypes> count{};
  for (const auto& [unum, type] : team.players) ++count[type];
  if (count[robot_type] >= rules_.max_of_one_type) return "no more robots of this type allowed";
  for (int other = 0; other < kRobotTypes; ++other) {
    if (other != robot_type && count[robot_type] + 1 + count[other] > rules_.max_of_two_types)
      return "too many robots of two types together";
  }
  const int used_types = static_cast<int>(std::count_if(count.begin(), count.end(), [](int n) { return n > 0; }));
  const int free_slots = rules_.max_players - static_cast<int>(team.players.size());
  if (free_slots <= rules_.min_types - used_types && count[robot_type] != 0)
    return "too few robot types: only an unused type may join";
  return std::nullopt;
}

InitResult Game::Init(const std::string& team_name, int requested_unum, int robot_type) {
  InitResult result;
  if (team_name.empty()) {
    result.error = "empty team name";
    return result;
  }
  std::optional<Side> side;
  for (const Side s : {Side::kLeft, Side::kRight}) {
    const Team& t = teams_[Index(s)];
    if (!t.name || *t.name == team_name) {
      side = s;
      break;
    }
  }
  if (!side) {
    result.error = "two teams are registered already";
    return result;
  }
  Team& team = teams_[Index(*side)];
  if (static_cast<int>(team.players.size()) >= rules_.max_players) {
    result.error = "team is full";
    return result;
  }
  int unum = requested_unum;
  if (unum == 0) {
    for (int n = 1; n <= 11 && unum == 0; ++n)
      if (team.players.count(n) == 0) unum = n;
    if (unum == 0) {
      result.error = "no free uniform number 1..11";
      return result;
    }
  } else if (team.players.count(unum) != 0) {
    result.error = "uniform number taken";
    return result;
  }
  if (robot_type < 0 || robot_type >= kRobotTypes) {
    result.error = "unknown robot type";
    return result;
  }
  if (rules_.check_composition) {
    if (auto error = CompositionError(team, robot_type)) {
      result.error = *error;
      return result;
    }
  }
  team.name = team_name;
  team.players[unum] = robot_type;
  result.ok = true;
  result.side = *side;
  result.unum = unum;
  return result;
}

void Game::Leave(Side side, int unum, int /*robot_type: the one registered at init is used*/) {
  Team& team = teams_[Index(side)];
  team.players.erase(unum);
  if (team.players.empty()) team.name.reset();
}

void Game::ResetTeam(Side side) { teams_[Index(side)] = Team{}; }

std::optional<std::string> Game::TeamName(Side side) const { return teams_[Index(side)].name; }

int Game::PlayerCount(Side side) const { return static_cast<int>(teams_[Index(side)].players.size()); }

bool Game::BeamAllowed() const {
  return mode_ == PlayMode::kBeforeKickOff || mode_ == PlayMode::kGoalLeft || mode_ == PlayMode::kGoalRight;
}

Pose2 Game::BeamPose(Side side, double x, double y, double rot_deg, Rng* rng) const {
  if (rng != nullptr) {
    x += rules_.beam_noise_xy * (2.0 * rng->Uniform() - 1.0);
    y += rules_.beam_noise_xy * (2.0 * rng->Uniform() - 1.0);
    rot_deg += rules_.beam_noise_deg * (2.0 * rng->Uniform() - 1.0);
  }
  x = std::clamp(x, -rules_.field_length / 2.0, 0.0);
  y = std::clamp(y, -rules_.field_width / 2.0, rules_.field_width / 2.0);
  if (side == Side::kLeft) return {x, y, NormalizeDeg(rot_deg)};
  return {-x, -y, NormalizeDeg(rot_deg + 180.0)};
}

Pose2 Game::StartPose(Side side, int unum) const {
  const int k = ((unum - 1) % 11 + 11) % 11;
  const double x = rules_.field_length / 2.0 - 0.8;  // 2 agent radii in from the goal line
  const double y = rules_.field_width / 2.0 - 0.8 - 1.2 * k;
  if (side == Side::kLeft) return {-x, y, 0.0};
  return {x, y, 180.0};
}

double Game::mode_time() const {
  // GameStateAspect::GetModeTime: mLeadTime in BeforeKickOff, mFupTime in
  // GameOver, else mTime - mLastModeChange (game time).
  if (mode_ == PlayMode::kBeforeKickOff || mode_ == PlayMode::kGameOver) return idle_time_;
  return F(F(game_time_) - F(mode_start_));
}

void Game::ChangeMode(PlayMode mode) {
  if (mode == mode_) return;
  mode_ = mode;
  mode_start_ = game_time_;  // GameStateAspect::SetPlayMode: mLastModeChange = mTime
  idle_time_ = 0.0;
}

void Game::StartKickOff(Side side) {
  ChangeMode(side == Side::kLeft ? PlayMode::kKickOffLeft : PlayMode::kKickOffRight);
  last_kick_off_half_ = half_;  // GameStateAspect::KickOff: mLastKickOffGameHalf
}

Eigen::Vector3d Game::OutOfPenaltyAreas(Eigen::Vector3d p) const {
  // SoccerRuleAspect::DropBall and UpdateFreeKick: a ball in a penalty box (edges included) goes to the box's front
  // corner on its side of the x axis (y < 0: -, else +).
  for (const Side side : {Side::kLeft, Side::kRight}) {
    const Eigen::AlignedBox2d area = PenaltyArea(side);
    if (!area.contains(p.head<2>())) continue;
    p.x() = side == Side::kLeft ? area.max().x() : area.min().x();
    p.y() = p.y() < 0.0 ? area.min().y() : area.max().y();
    break;
  }
  return p;
}

Eigen::Vector3d Game::DropPosition(const Eigen::Vector3d& ball) const {
  // SoccerRuleAspect::DropBall: out of the penalty areas, and a ball on or beyond a touch line to a radius inside.
  const double hw = rules_.field_width / 2.0;
  const double r = rules_.ball_radius;
  Eigen::Vector3d p = OutOfPenaltyAreas(ball);
  if (p.y() <= -hw) p.y() = -hw + r;
  if (p.y() >= hw) p.y() = hw - r;
  return p;
}

Eigen::AlignedBox2d Game::Half(Side side) const {
  // SoccerRuleAspect::UpdateCachedInternal: 10 m beyond the field on three sides, "so that no opponents sneak up
  // from behind".
  const double hl = rules_.field_length / 2.0 + 10.0;
  const double hw = rules_.field_width / 2.0 + 10.0;
  if (side == Side::kLeft) return Eigen::AlignedBox2d(Eigen::Vector2d(-hl, -hw), Eigen::Vector2d(0.0, hw));
  return Eigen::AlignedBox2d(Eigen::Vector2d(0.0, -hw), Eigen::Vector2d(hl, hw));
}

Eigen::AlignedBox2d Game::PenaltyArea(Side side) const {
  const double hl = rules_.field_length / 2.0;
  const double front = hl - rules_.penalty_depth;
  const double w = rules_.penalty_width / 2.0;
  if (side == Side::kLeft) return Eigen::AlignedBox2d(Eigen::Vector2d(-hl, -w), Eigen::Vector2d(-front, w));
  return Eigen::AlignedBox2d(Eigen::Vector2d(front, -w), Eigen::Vector2d(hl, w));
}

void Game::CheckHalfTime() {
  // SoccerRuleAspect::CheckTime (SingleHalfTime false, ChangeSidesInSecondHalf false).
  if (half_ == 1 && F(game_time_) >= F(rules_.half_time)) {
    half_ = 2;
    ChangeMode(PlayMode::kBeforeKickOff);
  } else if (half_ == 2 && F(game_time_) >= 2.0F * F(rules_.half_time)) {
    ChangeMode(PlayMode::kGameOver);
  }
}

void Game::TakeKick(const Toucher& taker, double time, bool indirect) {
  // SoccerRuleAspect::SetKickTakenValues: the taker and the game time of its touch.
  kick_check_ = true;
  kick_taker_ = taker;
  kick_time_ = time;
  indirect_kick_ = indirect;
}

void Game::ResetKickChecks() {
  kick_check_ = false;
  indirect_kick_ = false;
}

bool Game::LastTouchIsTheKick() const {
  return kick_taker_ && last_toucher_ && *last_toucher_ == *kick_taker_ &&
         F(F(last_touch_time_) - F(kick_time_)) < kKickDuration;
}

void Game::UpdateKickChecks(const Eigen::Vector3d& ball, const std::vector<Toucher>& touchers) {
  // SoccerRuleAspect::Update, before the mode's rule: the kick-off team may
  // score once the other team touched the ball or it touched the ball outside
  // the centre circle (FreeKickDistance).
  if (!kick_off_team_no_score_) return;
  const bool outside_circle = ball.head<2>().norm() > rules_.free_kick_distance;
  for (const Toucher& t : touchers) {
    if (t.side != *kick_off_team_no_score_ || outside_circle) kick_off_team_no_score_.reset();
    if (!kick_off_team_no_score_) break;
  }
}

// One Update in the making: what it asks of the caller, and the ball as the cycle's placements left it.
struct Game::Cycle {
  GameUpdate update;
  Eigen::Vector3d ball;
  bool on_field = true;

  // SoccerRuleAspect::MoveBall: the ball, at rest, and the free-kick spot go there.
  void MoveBall(const Eigen::Vector3d& p, bool drop, Game* game) {
    update.place_ball = p;
    update.dropped_ball = drop;
    ball = p;
    game->free_kick_pos_ = {p.x(), p.y(), game->rules_.ball_radius};
  }
};

GameUpdate Game::Update(double dt, const Eigen::Vector3d& ball, const std::vector<Toucher>& touchers) {
  Cycle c{{}, ball};
  // GameStateAspect::UpdateTime: game time stops in BeforeKickOff and GameOver.
  if (mode_ != PlayMode::kBeforeKickOff && mode_ != PlayMode::kGameOver) {
    game_time_ = F(F(game_time_) + F(dt));
  } else {
    idle_time_ = F(F(idle_time_) + F(dt));
  }
  // BallStateAspect::Update: the last toucher, whether the ball is on the field, where it last was.
  if (!touchers.empty()) {
    last_toucher_ = touchers.front();
    last_touch_time_ = game_time_;
  }
  const double r = rules_.ball_radius;
  c.on_field = std::abs(c.ball.x()) < rules_.field_length / 2.0 + r + 0.001 &&
               std::abs(c.ball.y()) < rules_.field_width / 2.0 + r + 0.001;
  if (c.on_field) last_on_field_ = c.ball;
  CheckHalfTime();  // SoccerRuleAspect::Update checks the time first
  paused_ = PausedAfter(mode_, paused_);
  UpdateKickChecks(c.ball, touchers);

  switch (mode_) {
    case PlayMode::kBeforeKickOff:
      UpdateBeforeKickOff(c);
      break;
    case PlayMode::kKickOffLeft:
    case PlayMode::kKickOffRight:
      UpdateKickOff(c, mode_ == PlayMode::kKickOffLeft ? Side::kLeft : Side::kRight);
      break;
    case PlayMode::kGoalLeft:
    case PlayMode::kGoalRight: {
      // SoccerRuleAspect::Update clears for the coming kick-off; UpdateGoal: after RuleGoalPauseTime (mode time
      // >= 3 s) the ball goes to the centre and the team scored on kicks off.
      const Side kicks_off = mode_ == PlayMode::kGoalLeft ? Side::kRight : Side::kLeft;
      ClearBeforeKickOff(c, kicks_off);
      if (mode_time() >= rules_.goal_pause) {
        StartKickOff(kicks_off);
        c.update.place_ball_at_centre = true;
        c.MoveBall({0.0, 0.0, r}, false, this);
      }
      break;
    }
    case PlayMode::kGameOver:
    case PlayMode::kOffsideLeft:
    case PlayMode::kOffsideRight:
      break;
    case PlayMode::kPlayOn:
      UpdatePlayOn(c);
      break;
    case PlayMode::kPassLeft:
    case PlayMode::kPassRight: {
      // UpdatePassMode: PlayOn after PassModeDuration (4 s) or at a touch since the mode began; the PlayOn rules;
      // while still in the mode, the other team kept away from the ball.
      const PlayMode pass = mode_;
      if (mode_time() >= rules_.pass_duration || (last_toucher_ && last_touch_time_ >= mode_start_))
        ChangeMode(PlayMode::kPlayOn);
      UpdatePlayOn(c);
      if (mode_ == pass)
        Repel(c, c.ball, rules_.pass_mode_distance, 0.1, pass == PlayMode::kPassLeft ? Side::kRight : Side::kLeft);
      break;
    }
    default:
      UpdateSetPiece(c);
      break;
  }
  c.update.play_mode_changed = mode_ != reported_mode_;
  reported_mode_ = mode_;
  return c.update;
}

void Game::UpdateBeforeKickOff(Cycle& c) {
  // SoccerRuleAspect::UpdateBeforeKickOff: with an agent connected, the ball is held at the centre and each team
  // is cleared from the other's half, in a random order; AutomaticKickOff false (naosoccersim.rb), so no kick-off
  // after WaitBeforeKickOff.
  if (PlayerCount(Side::kLeft) + PlayerCount(Side::kRight) == 0) return;
  c.update.place_ball_at_centre = true;
  c.MoveBall({0.0, 0.0, rules_.ball_radius}, false, this);
  const bool left_first = rng_.Next() % 2 == 0;
  for (const Side team : {left_first ? Side::kLeft : Side::kRight, left_first ? Side::kRight : Side::kLeft})
    ClearBox(c, Half(Opponent(team)), team);
}

void Game::UpdateKickOff(Cycle& c, Side side) {
  // SoccerRuleAspect::UpdateKickOff: every cycle the kick checks reset, the kick-off team may score and the teams
  // are cleared;
  ResetKickChecks();
  kick_off_team_no_score_.reset();
  ClearBeforeKickOff(c, side);
  if (mode_time() > rules_.drop_ball_time) {
    // untouched for more than RuleDropBallTime (15 s): drop ball where it is, PlayOn, for nobody in particular;
    DropBallAt(c, c.ball);
    return;
  }
  // the first touch since the mode began: PlayOn. With more than 2 agents (GameControlServer::GetAgentCount() > 2;
  // here: registered players) the toucher took an indirect kick and its team may not score yet.
  if (!last_toucher_ || last_touch_time_ <= mode_start_) return;
  if (PlayerCount(Side::kLeft) + PlayerCount(Side::kRight) > 2) {
    TakeKick(*last_toucher_, last_touch_time_, true);
    kick_off_team_no_score_ = last_toucher_->side;
  }
  ChangeMode(PlayMode::kPlayOn);
}

void Game::UpdateSetPiece(Cycle& c) {
  // UpdateKickIn / UpdateFreeKick / UpdateCornerKick / UpdateGoalKick.
  const PlayMode mode = mode_;
  const Side team = SetPieceTeam(mode);
  const bool goal_kick = mode == PlayMode::kGoalKickLeft || mode == PlayMode::kGoalKickRight;
  const bool corner = mode == PlayMode::kCornerKickLeft || mode == PlayMode::kCornerKickRight;
  const bool free_kick = !goal_kick && !corner && mode != PlayMode::kKickInLeft && mode != PlayMode::kKickInRight;
  // Nothing during RuleKickInPauseTime but arming the push from the spot.
  if (mode_time() < rules_.kick_in_pause) {
    repel_for_kick_ = true;
    return;
  }
  ResetKickChecks();
  // A free kick is not taken in a penalty area: its spot moves to the area's front corner.
  if (free_kick) free_kick_pos_ = OutOfPenaltyAreas(free_kick_pos_);
  // The other team is cleared from the spot (a goal kick: from the penalty area).
  if (goal_kick) {
    ClearBox(c, PenaltyArea(team), Opponent(team));
  } else {
    ClearCircle(c, free_kick_pos_, Opponent(team));
  }
  if (mode_time() > rules_.drop_ball_time) {
    DropBallAt(c, free_kick_pos_);
    return;
  }
  if ((goal_kick || corner) && !last_toucher_) return;  // never touched: the ball is not held
  const bool taken = last_toucher_ &&
                     F(last_touch_time_) > F(F(mode_start_) + F(rules_.kick_in_pause)) + kSetPieceTouchMargin &&
                     !repel_for_kick_;
  if (goal_kick && taken) {
    // PlayOn once the ball, touched, is out of the team's penalty area: beyond its front edge or wider than it
    // (strictly), or off the field.
    const Eigen::AlignedBox2d area = PenaltyArea(team);
    const double x = c.ball.x();
    const bool beyond_front = team == Side::kLeft ? x > area.max().x() : x < area.min().x();
    if (!c.on_field || beyond_front || std::abs(c.ball.y()) > area.max().y()) {
      TakeKick(*last_toucher_, last_touch_time_, false);
      ChangeMode(PlayMode::kPlayOn);
    }
    return;
  }
  if (taken) {
    const bool indirect = mode == PlayMode::kKickInLeft || mode == PlayMode::kKickInRight ||
                          mode == PlayMode::kFreeKickLeft || mode == PlayMode::kFreeKickRight;
    TakeKick(*last_toucher_, last_touch_time_, indirect);
    ChangeMode(PlayMode::kPlayOn);
    return;
  }
  // RepelPlayersForKick: the taking team's players pushed off the spot once; the ball held on it.
  if (repel_for_kick_) {
    Repel(c, free_kick_pos_, rules_.kick_repel_distance, 0.0, team);
    repel_for_kick_ = false;
  }
  c.MoveBall(free_kick_pos_, false, this);
}

void Game::UpdatePlayOn(Cycle& c) {
  // SoccerRuleAspect::UpdatePlayOn: the taker's second touch, a goal, the ball off the field.
  if (CheckTakerFoul()) return;
  if (CheckGoal(c)) return;
  CheckBallLeftField(c);
}

bool Game::CheckTakerFoul() {
  // CheckFreeKickTakerFoul: once the last touch is no longer the kick, the check ends; a second touch of the
  // taker's is an indirect free kick for the other team (PunishFreeKickFoul -> AwardFreeKick).
  if (!kick_check_ || !kick_taker_ || LastTouchIsTheKick()) return false;
  ResetKickChecks();
  if (!last_toucher_ || !(*last_toucher_ == *kick_taker_)) return false;
  repel_for_kick_ = true;
  ChangeMode(kick_taker_->side == Side::kLeft ? PlayMode::kFreeKickRight : PlayMode::kFreeKickLeft);
  return true;
}

// BallStateAspect::UpdateGoalState: the ball meets the goal's box collider (goal.rsg: GoalDepth - 2r deep from a
// radius behind the goal line, GoalWidth - 2r wide, GoalHeight high); CheckGoal's fallback: its centre beyond the
// line by more than a radius, in the mouth.
bool Game::BallInGoal(const Eigen::Vector3d& ball) const {
  const double r = rules_.ball_radius;
  const double line = rules_.field_length / 2.0;
  const Eigen::AlignedBox3d box(
      Eigen::Vector3d(line + r, -(rules_.goal_width / 2.0 - r), 0.0),
      Eigen::Vector3d(line + rules_.goal_depth - r, rules_.goal_width / 2.0 - r, rules_.goal_height));
  const Eigen::Vector3d mirrored(std::abs(ball.x()), ball.y(), ball.z());
  if (box.squaredExteriorDistance(mirrored) < r * r) return true;
  return std::abs(ball.x()) > line + r && std::abs(ball.y()) < rules_.goal_width / 2.0 && ball.z() < rules_.goal_height;
}

bool Game::CheckGoal(Cycle& c) {
  const Eigen::Vector3d& ball = c.ball;
  if (!BallInGoal(ball)) return false;
  const Side scored_on = ball.x() > 0.0 ? Side::kRight : Side::kLeft;
  const Side scorer = Opponent(scored_on);
  if (kick_off_team_no_score_ == scorer) {
    // The kick-off team scored before it was allowed to (PunishIndirectKickGoal with the kick-off's taker): a goal
    // kick for the team scored on.
    indirect_kick_ = false;
    AwardGoalKick(scored_on);
    return true;
  }
  // No goal straight from an indirect kick, nor an own goal straight from a direct one (more than 2 agents).
  if (LastTouchIsTheKick() && (indirect_kick_ || last_toucher_->side == scored_on) &&
      PlayerCount(Side::kLeft) + PlayerCount(Side::kRight) > 2) {
    PunishIndirectKickGoal(*last_toucher_, scored_on, ball);
    return true;
  }
  c.update.goal = true;
  c.update.scored_by = scorer;
  ++score_[Index(scorer)];
  ChangeMode(scorer == Side::kLeft ? PlayMode::kGoalLeft : PlayMode::kGoalRight);
  return true;
}

void Game::PunishIndirectKickGoal(const Toucher& kicker, Side scored_on, const Eigen::Vector3d& ball) {
  indirect_kick_ = false;
  if (kicker.side == scored_on) {
    AwardCornerKick(Opponent(kicker.side), ball);
  } else {
    AwardGoalKick(scored_on);
  }
}

void Game::CheckBallLeftField(const Cycle& c) {
  // SoccerRuleAspect::CheckBallLeftField: on the field, the free-kick spot follows it.
  if (c.on_field) {
    free_kick_pos_ = {last_on_field_.x(), last_on_field_.y(), rules_.ball_radius};
    return;
  }
  if (!last_toucher_) return;
  const bool last_touch_left = last_toucher_->side == Side::kLeft;
  const bool ball_left = c.ball.x() < 0.0;
  if (std::abs(c.ball.x()) >= rules_.field_length / 2.0) {
    if (last_touch_left != ball_left) {
      AwardGoalKick(ball_left ? Side::kLeft : Side::kRight);  // over the attackers' goal line: the defenders'
    } else {
      AwardCornerKick(Opponent(last_toucher_->side), c.ball);  // over its own: the attackers'
    }
  } else if (std::abs(c.ball.y()) >= rules_.field_width / 2.0) {
    // AwardKickIn: where it last was on the field, on the touch line (a radius inside).
    const double y = rules_.field_width / 2.0 - rules_.ball_radius;
    AwardSetPiece(last_toucher_->side == Side::kLeft ? PlayMode::kKickInRight : PlayMode::kKickInLeft,
                  {last_on_field_.x(), last_on_field_.y() > 0.0 ? y : -y, rules_.ball_radius});
  }
}

void Game::AwardSetPiece(PlayMode mode, const Eigen::Vector3d& spot) {
  free_kick_pos_ = spot;
  repel_for_kick_ = true;
  ChangeMode(mode);
}

void Game::AwardGoalKick(Side side) {
  // AwardGoalKick: GoalKickDist in front of the goal line, on the middle.
  const double x = rules_.field_length / 2.0 - rules_.goal_kick_distance;
  AwardSetPiece(side == Side::kLeft ? PlayMode::kGoalKickLeft : PlayMode::kGoalKickRight,
                {side == Side::kLeft ? -x : x, 0.0, rules_.ball_radius});
}

void Game::AwardCornerKick(Side side, const Eigen::Vector3d& ball) {
  // AwardCornerKick: a radius in front of the other team's goal line, (W + goal width) / 4 - r from the middle on
  // the ball's side ("temp value for RoboCup 2012").
  const double x = rules_.field_length / 2.0 - rules_.ball_radius;
  const double y = (rules_.field_width + rules_.goal_width) / 4.0 - rules_.ball_radius;
  AwardSetPiece(side == Side::kLeft ? PlayMode::kCornerKickLeft : PlayMode::kCornerKickRight,
                {side == Side::kLeft ? x : -x, ball.y() > 0.0 ? y : -y, rules_.ball_radius});
}

void Game::DropBallAt(Cycle& c, const Eigen::Vector3d& at) {
  // SoccerRuleAspect::DropBall: the ball to its drop position, both teams cleared from it in a random order, the
  // kick checks end, PlayOn.
  const Eigen::Vector3d p = DropPosition(at);
  c.MoveBall(p, true, this);
  const bool left_first = rng_.Next() % 2 == 0;
  ClearCircle(c, p, left_first ? Side::kLeft : Side::kRight);
  ClearCircle(c, p, left_first ? Side::kRight : Side::kLeft);
  ResetKickChecks();
  ChangeMode(PlayMode::kPlayOn);
}

void Game::ClearBeforeKickOff(Cycle& c, Side side) {
  // ClearPlayersBeforeKickOff: the other team out of the kick-off team's half and the centre circle; the kick-off
  // team out of the other half unless wholly in the centre circle.
  const Side other = Opponent(side);
  ClearBox(c, Half(side), other);
  ClearCircle(c, Eigen::Vector3d::Zero(), other);
  ClearBox(c, Half(other), side, rules_.free_kick_distance);
}

void Game::ClearCircle(Cycle& c, const Eigen::Vector3d& centre, Side team) {
  Clearing k;
  k.kind = ClearingKind::kCircle;
  k.team = team;
  k.centre = centre;
  k.radius = rules_.free_kick_distance;
  k.distance = rules_.free_kick_move_distance;
  k.ball = c.ball;
  k.order_seed = rng_.Next();
  c.update.clearings.push_back(k);
}

void Game::ClearBox(Cycle& c, const Eigen::AlignedBox2d& box, Side team, double keep_in_circle) {
  Clearing k;
  k.kind = ClearingKind::kBox;
  k.team = team;
  k.box = box;
  k.keep_in_circle = keep_in_circle;
  k.distance = rules_.free_kick_move_distance;
  k.ball = c.ball;
  k.order_seed = rng_.Next();
  c.update.clearings.push_back(k);
}

void Game::Repel(Cycle& c, const Eigen::Vector3d& centre, double radius, double pad, Side team) {
  // RepelPlayers: the safe spot does not avoid the ball (fAvoidBall false).
  Clearing k;
  k.kind = ClearingKind::kRepel;
  k.team = team;
  k.centre = centre;
  k.radius = radius;
  k.distance = pad;
  k.avoid_ball = false;
  k.ball = c.ball;
  k.order_seed = rng_.Next();
  c.update.clearings.push_back(k);
}

void Game::SetPlayMode(PlayMode mode) {
  if (mode == PlayMode::kCount) return;
  ChangeMode(mode);
}

void Game::KickOff(std::optional<Side> side, Rng* rng) {
  if (!side) {
    // GameStateAspect::KickOff(TI_NONE): a coin toss, except for a half's first
    // kick-off, which goes to the team stored by the last half's first coin
    // toss (the other team: ChangeSidesInSecondHalf false).
    side = (rng != nullptr && rng->Uniform() >= 0.5) ? Side::kRight : Side::kLeft;
    if (half_ != last_kick_off_half_) {
      if (next_half_kick_off_) side = *next_half_kick_off_;
      next_half_kick_off_ = Opponent(*side);
    }
  }
  StartKickOff(*side);
}

void Game::SetGameTime(double t) { game_time_ = F(std::max(0.0, t)); }

void Game::SetScore(std::optional<int> left, std::optional<int> right) {
  if (left) score_[0] = *left;
  if (right) score_[1] = *right;
}

GameUpdate Game::DropBall(const Eigen::Vector3d& ball) {
  Cycle c{{}, ball};
  DropBallAt(c, ball);
  return c.update;  // play_mode_changed: reported by the next Update
}

}  // namespace turf::simspark

namespace turf::simspark {

template <class Io>
void Fields(Io& io, IoRef<Io, Toucher> t) {
  io(t.side, t.unum);
}

// Listed once (core/state_io.h).
template <class Io, class Self>
void Game::Fields(Io& io, Self& g) {
  io.Tag(StateTag("SGAM"));
  for (auto& team : g.teams_) {
    io(team.name, Sized(team.players, static_cast<size_t>(std::max(g.rules_.max_players, 0))));
    for (const auto& [unum, type] : team.players) io.Check(type >= 0 && type < kRobotTypes, "robot type out of range");
    io.Check(team.players.empty() || team.name, "players in a team without a name");
  }
  io(g.mode_, g.reported_mode_, FiniteValue(g.game_time_), FiniteValue(g.mode_start_), FiniteValue(g.idle_time_),
     g.half_, g.last_kick_off_half_, g.next_half_kick_off_, g.kick_check_, g.paused_, g.kick_taker_,
     FiniteValue(g.kick_time_), g.indirect_kick_, g.kick_off_team_no_score_, g.score_, g.last_toucher_,
     FiniteValue(g.last_touch_time_), g.last_on_field_, g.free_kick_pos_, g.repel_for_kick_, g.rng_);
  io.Check(g.half_ >= 1 && g.half_ <= 2 && g.last_kick_off_half_ >= 0 && g.last_kick_off_half_ <= 2,
           "half out of range");
  io.Check(g.score_[0] >= 0 && g.score_[1] >= 0, "negative score");
}

void Game::Save(StateWriter& out) const { Fields(out, *this); }

void Game::Restore(StateReader& in) {
  Game g(rules_, 0);
  Fields(in, g);
  if (in.ok()) *this = std::move(g);
}

}  // namespace turf::simspark
