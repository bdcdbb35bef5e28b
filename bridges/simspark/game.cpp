#include "bridges/simspark/game.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace turf::simspark {

namespace {

// Degrees into (-180, 180].
double NormalizeDeg(double deg) {
  double r = std::remainder(deg, 360.0);
  if (r <= -180.0) r += 360.0;
  return r;
}

bool IsSetPiece(PlayMode mode) {
  switch (mode) {
    case PlayMode::kKickInLeft:
    case PlayMode::kKickInRight:
    case PlayMode::kCornerKickLeft:
    case PlayMode::kCornerKickRight:
    case PlayMode::kGoalKickLeft:
    case PlayMode::kGoalKickRight:
    case PlayMode::kOffsideLeft:
    case PlayMode::kOffsideRight:
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
  teams_[Index(side)].players.erase(unum);
}

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

void Game::ChangeMode(PlayMode mode) {
  if (mode == mode_) return;
  mode_ = mode;
  mode_time_ = 0.0;
  out_position_.reset();
}

Eigen::Vector3d Game::DropPosition(const Eigen::Vector3d& ball) const {
  const double hl = rules_.field_length / 2.0;
  const double hw = rules_.field_width / 2.0;
  const double r = rules_.ball_radius;
  Eigen::Vector3d p(std::clamp(ball.x(), -hl + r, hl - r), std::clamp(ball.y(), -hw + r, hw - r), r);
  const double front = hl - rules_.penalty_depth;
  const double side = rules_.penalty_width / 2.0;
  if (std::abs(p.x()) >= front && std::abs(p.y()) <= side) {
    p.x() = std::copysign(front, p.x());
    p.y() = std::copysign(side, p.y());
  }
  return p;
}

void Game::CheckHalfTime() {
  if (half_ == 1 && game_time_ >= rules_.half_time) {
    half_ = 2;
    ChangeMode(PlayMode::kBeforeKickOff);
  } else if (half_ == 2 && game_time_ >= 2.0 * rules_.half_time) {
    ChangeMode(PlayMode::kGameOver);
  }
}

GameUpdate Game::Update(double dt, const Eigen::Vector3d& ball, bool touched) {
  GameUpdate update;
  const auto place = [&](const Eigen::Vector3d& p, bool drop) {
    update.place_ball = p;
    update.dropped_ball = drop;
  };
  if (pending_drop_) {
    pending_drop_ = false;
    place(DropPosition(ball), true);
  }
  if (mode_ != PlayMode::kBeforeKickOff && mode_ != PlayMode::kGameOver) game_time_ += dt;
  mode_time_ += dt;

  const double hl = rules_.field_length / 2.0;
  const double hw = rules_.field_width / 2.0;
  const double r = rules_.ball_radius;
  switch (mode_) {
    case PlayMode::kBeforeKickOff:
      if (PlayerCount(Side::kLeft) + PlayerCount(Side::kRight) > 0) {
        update.place_ball_at_centre = true;
        place({0.0, 0.0, r}, false);
      }
      break;
    case PlayMode::kKickOffLeft:
    case PlayMode::kKickOffRight:
      if (touched) {
        ChangeMode(PlayMode::kPlayOn);
      } else if (mode_time_ >= rules_.drop_ball_after) {
        place(DropPosition(ball), true);
        ChangeMode(PlayMode::kPlayOn);
      }
      break;
    case PlayMode::kGoalLeft:
    case PlayMode::kGoalRight:
      if (mode_time_ >= rules_.goal_pause) {
        ChangeMode(mode_ == PlayMode::kGoalLeft ? PlayMode::kKickOffRight : PlayMode::kKickOffLeft);
        update.place_ball_at_centre = true;
        place({0.0, 0.0, r}, false);
      }
      break;
    case PlayMode::kGameOver:
      break;
    default:
      if (IsSetPiece(mode_)) {
        if (touched && mode_time_ >= rules_.kick_in_pause) ChangeMode(PlayMode::kPlayOn);
        break;
      }
      if ((mode_ == PlayMode::kPassLeft || mode_ == PlayMode::kPassRight) && mode_time_ >= rules_.pass_duration) {
        ChangeMode(PlayMode::kPlayOn);
      }
      if (!InPlay()) break;
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
        update.goal = true;
        update.scored_by = ball.x() > 0.0 ? Side::kLeft : Side::kRight;
        ++score_[Index(update.scored_by)];
        ChangeMode(update.scored_by == Side::kLeft ? PlayMode::kGoalLeft : PlayMode::kGoalRight);
      } else if (std::abs(ball.x()) > hl + r || std::abs(ball.y()) > hw + r) {
        out_position_ = ball;
        out_time_ = 0.0;
      }
      break;
  }
  CheckHalfTime();
  update.play_mode_changed = mode_ != reported_mode_;
  reported_mode_ = mode_;
  return update;
}

void Game::SetPlayMode(PlayMode mode) {
  if (mode == PlayMode::kCount) return;
  ChangeMode(mode);
}

void Game::KickOff(std::optional<Side> side, Rng* rng) {
  if (!side) side = (rng != nullptr && rng->Uniform() >= 0.5) ? Side::kRight : Side::kLeft;
  ChangeMode(*side == Side::kLeft ? PlayMode::kKickOffLeft : PlayMode::kKickOffRight);
}

void Game::SetGameTime(double t) { game_time_ = std::max(0.0, t); }

void Game::SetScore(std::optional<int> left, std::optional<int> right) {
  if (left) score_[0] = *left;
  if (right) score_[1] = *right;
}

void Game::DropBall() {
  pending_drop_ = true;
  out_position_.reset();
  ChangeMode(PlayMode::kPlayOn);
}

}  // namespace turf::simspark
