#include "kernel/simspark/game.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/state_io_eigen.h"

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

// A touch 0.1 s after the kick is a second kick (SoccerRuleAspect::
// WasLastKickFromFreeKick: "kick duration = 0.1"); the tolerance absorbs the
// sum of 0.02 s cycles.
constexpr double kKickDuration = 0.1 - 1e-6;
// A set piece's touch counts when it comes more than the pause plus 0.03 s
// into the mode (SoccerRuleAspect::UpdateKickIn / UpdateFreeKick /
// UpdateCornerKick / UpdateGoalKick: time > lastChange + mKickInPauseTime + 0.03).
constexpr double kSetPieceTouchMargin = 0.03;

// KickIn, corner, goal kick and the free kicks (offside's rule is compiled out
// in the reference: SoccerRuleAspect::UpdateOffside is "#if 0").
bool IsSetPiece(PlayMode mode) {
  switch (mode) {
    case PlayMode::kKickInLeft:
    case PlayMode::kKickInRight:
    case PlayMode::kCornerKickLeft:
    case PlayMode::kCornerKickRight:
    case PlayMode::kGoalKickLeft:
    case PlayMode::kGoalKickRight:
    case PlayMode::kFreeKickLeft:
    case PlayMode::kFreeKickRight:
    case PlayMode::kDirectFreeKickLeft:
    case PlayMode::kDirectFreeKickRight:
      return true;
    default:
      return false;
  }
}

}  // namespace

Game::Game(GameRules rules) : rules_(rules) {}

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

bool Game::InPlay() const {
  return mode_ == PlayMode::kPlayOn || mode_ == PlayMode::kPassLeft || mode_ == PlayMode::kPassRight;
}

double Game::mode_time() const {
  // GameStateAspect::GetModeTime: mLeadTime in BeforeKickOff, mFupTime in
  // GameOver, else mTime - mLastModeChange (game time).
  if (mode_ == PlayMode::kBeforeKickOff || mode_ == PlayMode::kGameOver) return idle_time_;
  return game_time_ - mode_start_;
}

void Game::ChangeMode(PlayMode mode) {
  if (mode == mode_) return;
  mode_ = mode;
  mode_start_ = game_time_;  // GameStateAspect::SetPlayMode: mLastModeChange = mTime
  idle_time_ = 0.0;
  out_position_.reset();
  goal_kick_touched_ = false;
}

void Game::StartKickOff(Side side) {
  ChangeMode(side == Side::kLeft ? PlayMode::kKickOffLeft : PlayMode::kKickOffRight);
  last_kick_off_half_ = half_;  // GameStateAspect::KickOff: mLastKickOffGameHalf
}

Eigen::Vector3d Game::DropPosition(const Eigen::Vector3d& ball) const {
  const double hl = rules_.field_length / 2.0;
  const double hw = rules_.field_width / 2.0;
  const double r = rules_.ball_radius;
  // x: turf's own clamp (turf drops an out ball; the reference awards a set piece).
  Eigen::Vector3d p(std::clamp(ball.x(), -hl + r, hl - r), ball.y(), r);
  // SoccerRuleAspect::DropBall: a ball in a penalty box (edges included) goes to
  // the box's front corner on its side of the x axis (y < 0: -, else +)...
  const double front = hl - rules_.penalty_depth;
  const double side = rules_.penalty_width / 2.0;
  if (std::abs(p.x()) >= front && std::abs(p.y()) <= side) {
    p.x() = std::copysign(front, p.x());
    p.y() = p.y() < 0.0 ? -side : side;
  }
  // ...and one on or beyond a touch line to a radius inside it.
  if (p.y() <= -hw) p.y() = -hw + r;
  if (p.y() >= hw) p.y() = hw - r;
  return p;
}

void Game::CheckHalfTime() {
  // SoccerRuleAspect::CheckTime (SingleHalfTime false, ChangeSidesInSecondHalf false).
  if (half_ == 1 && game_time_ >= rules_.half_time) {
    half_ = 2;
    ChangeMode(PlayMode::kBeforeKickOff);
  } else if (half_ == 2 && game_time_ >= 2.0 * rules_.half_time) {
    ChangeMode(PlayMode::kGameOver);
  }
}

void Game::TakeKick(const Toucher& taker) {
  // SoccerRuleAspect::SetKickTakenValues: the taker and the game time of its touch.
  kick_check_ = taker.known;
  kick_taker_ = taker;
  kick_time_ = game_time_;
}

void Game::UpdateKickChecks(const Eigen::Vector3d& ball, const std::vector<Toucher>& touchers) {
  // SoccerRuleAspect::Update, before the mode's rule: the kick-off team may
  // score once the other team touched the ball or it touched the ball outside
  // the centre circle (FreeKickDistance).
  if (kick_off_team_no_score_) {
    const bool outside_circle = ball.head<2>().norm() > rules_.free_kick_distance;
    for (const Toucher& t : touchers) {
      if (!t.known || t.side != *kick_off_team_no_score_ || outside_circle) kick_off_team_no_score_.reset();
      if (!kick_off_team_no_score_) break;
    }
  }
}

GameUpdate Game::Update(double dt, const Eigen::Vector3d& ball, bool touched) {
  std::vector<Toucher> touchers;
  if (touched) touchers.push_back(Toucher{Side::kLeft, 0, false});
  return Update(dt, ball, touchers);
}

GameUpdate Game::Update(double dt, const Eigen::Vector3d& ball, const std::vector<Toucher>& touchers) {
  GameUpdate update;
  const auto place = [&](const Eigen::Vector3d& p, bool drop) {
    update.place_ball = p;
    update.dropped_ball = drop;
  };
  // SoccerRuleAspect::DropBall: the ball moves, the kick checks end, PlayOn.
  const auto drop_ball = [&](const Eigen::Vector3d& at) {
    place(DropPosition(at), true);
    kick_check_ = false;
    ChangeMode(PlayMode::kPlayOn);
  };
  if (pending_drop_) {
    pending_drop_ = false;
    place(DropPosition(ball), true);
  }
  // GameStateAspect::UpdateTime: game time stops in BeforeKickOff and GameOver.
  if (mode_ != PlayMode::kBeforeKickOff && mode_ != PlayMode::kGameOver) {
    game_time_ += dt;
  } else {
    idle_time_ += dt;
  }
  CheckHalfTime();  // SoccerRuleAspect::Update checks the time first
  paused_ = PausedAfter(mode_, paused_);
  UpdateKickChecks(ball, touchers);
  const bool touched = !touchers.empty();

  const double hl = rules_.field_length / 2.0;
  const double hw = rules_.field_width / 2.0;
  const double r = rules_.ball_radius;
  switch (mode_) {
    case PlayMode::kBeforeKickOff:
      // SoccerRuleAspect::UpdateBeforeKickOff: with an agent connected, the ball
      // is held at the centre; AutomaticKickOff false (naosoccersim.rb), so no
      // kick-off after WaitBeforeKickOff.
      if (PlayerCount(Side::kLeft) + PlayerCount(Side::kRight) > 0) {
        update.place_ball_at_centre = true;
        place({0.0, 0.0, r}, false);
      }
      break;
    case PlayMode::kKickOffLeft:
    case PlayMode::kKickOffRight:
      // SoccerRuleAspect::UpdateKickOff: every cycle the kick checks reset and
      // the kick-off team may score;
      kick_check_ = false;
      kick_off_team_no_score_.reset();
      if (mode_time() > rules_.drop_ball_time) {
        // untouched for more than RuleDropBallTime (15 s): drop ball where it
        // is, PlayOn, for nobody in particular;
        drop_ball(ball);
      } else if (touched) {
        // the first touch: PlayOn. With more than 2 agents (GameControlServer::
        // GetAgentCount() > 2; here: registered players) the toucher took an
        // indirect kick and its team may not score yet.
        if (PlayerCount(Side::kLeft) + PlayerCount(Side::kRight) > 2) {
          TakeKick(touchers.front());
          if (touchers.front().known) kick_off_team_no_score_ = touchers.front().side;
        }
        ChangeMode(PlayMode::kPlayOn);
      }
      break;
    case PlayMode::kGoalLeft:
    case PlayMode::kGoalRight:
      // SoccerRuleAspect::UpdateGoal: after RuleGoalPauseTime (mode time >= 3 s)
      // the ball goes to the centre and the team scored on kicks off.
      if (mode_time() >= rules_.goal_pause) {
        StartKickOff(mode_ == PlayMode::kGoalLeft ? Side::kRight : Side::kLeft);
        update.place_ball_at_centre = true;
        place({0.0, 0.0, r}, false);
      }
      break;
    case PlayMode::kGameOver:
    case PlayMode::kOffsideLeft:
    case PlayMode::kOffsideRight:
      break;
    default:
      if (IsSetPiece(mode_)) {
        // UpdateKickIn / UpdateFreeKick / UpdateCornerKick / UpdateGoalKick:
        // nothing during RuleKickInPauseTime; then the kick checks reset, a drop
        // ball after more than RuleDropBallTime, PlayOn at a touch more than
        // 0.03 s after the pause, the toucher having taken the kick.
        if (mode_time() < rules_.kick_in_pause) break;
        kick_check_ = false;
        if (mode_time() > rules_.drop_ball_time) {
          drop_ball(ball);
          break;
        }
        const bool counts = touched && mode_time() > rules_.kick_in_pause + kSetPieceTouchMargin;
        if (mode_ == PlayMode::kGoalKickLeft || mode_ == PlayMode::kGoalKickRight) {
          // UpdateGoalKick: PlayOn once the ball, touched, is out of the team's
          // penalty box (or off the field); the last toucher took the kick.
          if (counts) {
            goal_kick_touched_ = true;
            kick_taker_ = touchers.front();
            kick_time_ = game_time_;
          }
          // Out of the box: beyond its front edge or wider than it (strictly),
          // or off the field (BallStateAspect::UpdateBallOnField).
          const double front = hl - rules_.penalty_depth;
          const bool left = mode_ == PlayMode::kGoalKickLeft;
          const bool off_field = std::abs(ball.x()) >= hl + r + 0.001 || std::abs(ball.y()) >= hw + r + 0.001;
          const bool out_of_box =
              (left ? ball.x() > -front : ball.x() < front) || std::abs(ball.y()) > rules_.penalty_width / 2.0;
          if (goal_kick_touched_ && (off_field || out_of_box)) {
            const Toucher taker = *kick_taker_;
            const double at = kick_time_;
            TakeKick(taker);
            kick_time_ = at;
            ChangeMode(PlayMode::kPlayOn);
          }
        } else if (counts) {
          TakeKick(touchers.front());
          ChangeMode(PlayMode::kPlayOn);
        }
        break;
      }
      // UpdatePassMode: PlayOn after PassModeDuration (4 s) or at a touch; then
      // the PlayOn rules in the same cycle.
      if ((mode_ == PlayMode::kPassLeft || mode_ == PlayMode::kPassRight) &&
          (mode_time() >= rules_.pass_duration || touched)) {
        ChangeMode(PlayMode::kPlayOn);
      }
      if (!InPlay()) break;
      // UpdatePlayOn -> CheckFreeKickTakerFoul: the kick's taker touching the
      // ball again 0.1 s or more after its kick, before anybody else did:
      // indirect free kick for the other team (AwardFreeKick). Another
      // player's touch ends the check (several at once: not the taker alone).
      if (kick_check_ && touched) {
        const bool taker_alone = std::all_of(touchers.begin(), touchers.end(),
                                             [&](const Toucher& t) { return kick_taker_ && t == *kick_taker_; });
        if (!taker_alone) {
          kick_check_ = false;
        } else if (game_time_ - kick_time_ >= kKickDuration) {
          kick_check_ = false;
          ChangeMode(kick_taker_->side == Side::kLeft ? PlayMode::kFreeKickRight : PlayMode::kFreeKickLeft);
          break;
        }
      }
      if (out_position_) {
        out_time_ += dt;
        if (out_time_ >= rules_.kick_in_pause) {
          place(DropPosition(*out_position_), true);
          out_position_.reset();
        }
        break;
      }
      if (std::abs(ball.x()) > hl + r && std::abs(ball.y()) < rules_.goal_width / 2.0 &&
          ball.z() < rules_.goal_height) {
        const Side scorer = ball.x() > 0.0 ? Side::kLeft : Side::kRight;
        if (kick_off_team_no_score_ == scorer) {
          // CheckGoal -> PunishIndirectKickGoal: the kick-off team scored before
          // it was allowed to: goal kick for the team scored on, the ball on its
          // spot GoalKickDist in front of the goal line (AwardGoalKick).
          const Side defender = Opponent(scorer);
          ChangeMode(defender == Side::kLeft ? PlayMode::kGoalKickLeft : PlayMode::kGoalKickRight);
          const double spot = hl - rules_.goal_kick_distance;
          place({defender == Side::kLeft ? -spot : spot, 0.0, r}, false);
          break;
        }
        update.goal = true;
        update.scored_by = scorer;
        ++score_[Index(update.scored_by)];
        ChangeMode(update.scored_by == Side::kLeft ? PlayMode::kGoalLeft : PlayMode::kGoalRight);
      } else if (std::abs(ball.x()) > hl + r || std::abs(ball.y()) > hw + r) {
        out_position_ = ball;
        out_time_ = 0.0;
      }
      break;
  }
  update.play_mode_changed = mode_ != reported_mode_;
  reported_mode_ = mode_;
  return update;
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

void Game::SetGameTime(double t) { game_time_ = std::max(0.0, t); }

void Game::SetScore(std::optional<int> left, std::optional<int> right) {
  if (left) score_[0] = *left;
  if (right) score_[1] = *right;
}

void Game::DropBall() {
  pending_drop_ = true;
  out_position_.reset();
  kick_check_ = false;  // SoccerRuleAspect::DropBall -> ResetKickChecks
  ChangeMode(PlayMode::kPlayOn);
}

}  // namespace turf::simspark

namespace turf::simspark {

namespace {

constexpr size_t kMaxTeamName = 256;  // far above any team name an init accepts

}  // namespace

void Game::Save(StateWriter& out) const {
  out.Tag(StateTag("SGAM"));
  for (const Team& team : teams_) {
    PutOptional(team.name, out, [&](const std::string& name) { out.Str(name); });
    out.Put<uint64_t>(team.players.size());
    for (const auto& [unum, type] : team.players) {
      out.Put<int32_t>(unum);
      out.Put<int32_t>(type);
    }
  }
  out.Put(mode_);
  out.Put(reported_mode_);
  out.Put(game_time_);
  out.Put(mode_start_);
  out.Put(idle_time_);
  out.Put<int32_t>(half_);
  out.Put<int32_t>(last_kick_off_half_);
  PutOptional(next_half_kick_off_, out, [&](Side side) { out.Put(side); });
  out.Put(kick_check_);
  out.Put<uint8_t>(paused_ ? 1 : 0);
  PutOptional(kick_taker_, out, [&](const Toucher& t) {
    out.Put(t.side);
    out.Put<int32_t>(t.unum);
    out.Put(t.known);
  });
  out.Put(kick_time_);
  PutOptional(kick_off_team_no_score_, out, [&](Side side) { out.Put(side); });
  out.Put(goal_kick_touched_);
  out.Put<int32_t>(score_[0]);
  out.Put<int32_t>(score_[1]);
  out.Put(pending_drop_);
  PutOptional(out_position_, out, [&](const Eigen::Vector3d& v) { PutVector(v, out); });
  out.Put(out_time_);
}

void Game::Restore(StateReader& in) {
  Game g(rules_);
  in.Tag(StateTag("SGAM"));
  for (Team& team : g.teams_) {
    if (in.Bool()) team.name = in.Str(kMaxTeamName);
    const size_t n = in.Count(static_cast<size_t>(std::max(rules_.max_players, 0)));
    for (size_t i = 0; i < n && in.ok(); ++i) {
      const int unum = in.Get<int32_t>();
      const int type = in.Get<int32_t>();
      if (type < 0 || type >= kRobotTypes) in.Fail("robot type out of range");
      if (!team.players.emplace(unum, type).second) in.Fail("player number twice in a team");
    }
    if (!team.players.empty() && !team.name) in.Fail("players in a team without a name");
  }
  g.mode_ = in.Enum(PlayMode::kCount);
  g.reported_mode_ = in.Enum(PlayMode::kCount);
  g.game_time_ = GetFinite(in);
  g.mode_start_ = GetFinite(in);
  g.idle_time_ = GetFinite(in);
  g.half_ = in.Get<int32_t>();
  g.last_kick_off_half_ = in.Get<int32_t>();
  if (g.half_ < 1 || g.half_ > 2 || g.last_kick_off_half_ < 0 || g.last_kick_off_half_ > 2)
    in.Fail("half out of range");
  if (in.Bool()) g.next_half_kick_off_ = in.Enum(static_cast<Side>(2));
  g.kick_check_ = in.Bool();
  g.paused_ = in.Bool();
  if (in.Bool()) {
    Toucher t;
    t.side = in.Enum(static_cast<Side>(2));
    t.unum = in.Get<int32_t>();
    t.known = in.Bool();
    g.kick_taker_ = t;
  }
  g.kick_time_ = GetFinite(in);
  if (in.Bool()) g.kick_off_team_no_score_ = in.Enum(static_cast<Side>(2));
  g.goal_kick_touched_ = in.Bool();
  g.score_[0] = in.Get<int32_t>();
  g.score_[1] = in.Get<int32_t>();
  if (g.score_[0] < 0 || g.score_[1] < 0) in.Fail("negative score");
  g.pending_drop_ = in.Bool();
  if (in.Bool()) {
    g.out_position_ = GetVector(in);
  }
  g.out_time_ = GetFinite(in);
  if (in.ok()) *this = std::move(g);
}

}  // namespace turf::simspark
