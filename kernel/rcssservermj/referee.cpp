#include "kernel/rcssservermj/referee.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace turf::rcssservermj {

namespace {

constexpr const char* kModeNames[] = {
#define TURF_MJ_NAME(id, name) name,
    TURF_MJ_PLAY_MODES(TURF_MJ_NAME)
#undef TURF_MJ_NAME
};

// The facts name each rule book's half and extra half and the hl books' field;
// the player limit (11) and the ssim books' field (fifa) are the defaults.
const RuleBook kRuleBooks[] = {
    {"fifa", 11, 45 * 60, 15 * 60, "fifa"},
    {"ssim", 11, 5 * 60, 3 * 60, "fifa"},
    {"ssim_2025", 11, 5 * 60, 3 * 60, "fifa"},
    {"hl_adult", 11, 10 * 60, 5 * 60, "hl_adult_2020"},
    {"hl_adult_2025", 11, 10 * 60, 5 * 60, "hl_adult_2020"},
};

constexpr size_t kModeCount = sizeof(kModeNames) / sizeof(kModeNames[0]);
constexpr int kMaxScore = 1'000'000;
constexpr int64_t kMaxTimeMs = 24LL * 3600 * 1000;  // a day: far beyond any match's halves

constexpr double kMovedFromPlacement = 0.05;  // m: a restart's ball in play

PlayMode ForSide(Side side, PlayMode left, PlayMode right) { return side == Side::kLeft ? left : right; }
Side Other(Side side) { return side == Side::kLeft ? Side::kRight : Side::kLeft; }

bool IsRestart(PlayMode m) {
  return m != PlayMode::kBeforeKickOff && m != PlayMode::kPlayOn && m != PlayMode::kGameOver &&
         m != PlayMode::kGoalLeft && m != PlayMode::kGoalRight;
}

}  // namespace

const char* PlayModeName(PlayMode mode) { return kModeNames[static_cast<int>(mode)]; }

std::optional<PlayMode> ParsePlayMode(std::string_view name) {
  for (size_t i = 0; i < sizeof(kModeNames) / sizeof(kModeNames[0]); ++i)
    if (name == kModeNames[i]) return static_cast<PlayMode>(i);
  return std::nullopt;
}

const RuleBook* FindRuleBook(std::string_view name) {
  for (const RuleBook& r : kRuleBooks)
    if (name == r.name) return &r;
  return nullptr;
}

Referee::Referee(const RuleBook& rules, const MjField& field, double ball_radius)
    : rules_(rules), field_(field), ball_radius_(ball_radius) {}

std::optional<Side> Referee::Join(const std::string& team) {
  for (Side side : {Side::kLeft, Side::kRight})
    if (teams_[Index(side)] == team) return side;
  for (Side side : {Side::kLeft, Side::kRight}) {
    if (!teams_[Index(side)]) {
      teams_[Index(side)] = team;
      return side;
    }
  }
  return std::nullopt;
}

void Referee::Leave(Side side) { teams_[Index(side)].reset(); }

void Referee::Restart(PlayMode mode, const Eigen::Vector3d& ball) {
  mode_ = mode;
  mode_ms_ = 0;
  placed_ = ball;
}

void Referee::KickOff(Side side) {
  Restart(ForSide(side, PlayMode::kKickOffLeft, PlayMode::kKickOffRight), Eigen::Vector3d(0, 0, ball_radius_));
  pending_place_ = *placed_;
}

void Referee::DropBall() {
  mode_ = PlayMode::kPlayOn;
  mode_ms_ = 0;
  placed_.reset();
}

void Referee::SetPlayMode(PlayMode mode) {
  mode_ = mode;
  mode_ms_ = 0;
  placed_.reset();
}

bool Referee::BeamAllowed() const {
  return mode_ == PlayMode::kBeforeKickOff || mode_ == PlayMode::kGoalLeft || mode_ == PlayMode::kGoalRight;
}

std::optional<Eigen::Vector3d> Referee::CheckBall(const Eigen::Vector3d& ball) {
  const double hx = field_.half_length(), hy = field_.half_width(), r = ball_radius_;
  if (std::abs(ball.x()) > hx + r) {
    const Side goal_of = ball.x() > 0 ? Side::kRight : Side::kLeft;  // whose goal line
    if (std::abs(ball.y()) < field_.goal_width / 2 && ball.z() < field_.goal_height) {
      const Side scorer = Other(goal_of);
      ++score_[Index(scorer)];
      conceded_ = goal_of;
      mode_ = ForSide(scorer, PlayMode::kGoalLeft, PlayMode::kGoalRight);
      mode_ms_ = 0;
      placed_.reset();
      return std::nullopt;
    }
    const double sx = ball.x() > 0 ? 1.0 : -1.0;
    if (last_touch_ == goal_of) {  // the defenders: corner for the attackers
      const Side attackers = Other(goal_of);
      Restart(ForSide(attackers, PlayMode::kCornerKickLeft, PlayMode::kCornerKickRight),
              Eigen::Vector3d(sx * hx, ball.y() > 0 ? hy : -hy, r));
    } else {
      Restart(ForSide(goal_of, PlayMode::kGoalKickLeft, PlayMode::kGoalKickRight),
              Eigen::Vector3d(sx * (hx - field_.goalie_depth), 0, r));
    }
    return placed_;
  }
  if (std::abs(ball.y()) > hy + r) {
    const Side kicker = last_touch_ ? Other(*last_touch_) : (ball.x() < 0 ? Side::kLeft : Side::kRight);
    const double x = std::clamp(ball.x(), -hx, hx);
    Restart(ForSide(kicker, PlayMode::kKickInLeft, PlayMode::kKickInRight),
            Eigen::Vector3d(x, ball.y() > 0 ? hy : -hy, r));
    return placed_;
  }
  return std::nullopt;
}

std::optional<Eigen::Vector3d> Referee::Update(double dt, const Eigen::Vector3d& ball, std::optional<Side> toucher) {
  const auto dt_ms = static_cast<int64_t>(std::llround(dt * 1000.0));
  std::optional<Eigen::Vector3d> place = std::exchange(pending_place_, std::nullopt);
  if (toucher) last_touch_ = toucher;
  if (mode_ == PlayMode::kBeforeKickOff || mode_ == PlayMode::kGameOver) return place;
  mode_ms_ += dt_ms;
  if (mode_ == PlayMode::kGoalLeft || mode_ == PlayMode::kGoalRight) {
    if (mode_ms_ >= std::llround(rules_.goal_pause_s * 1000)) {
      KickOff(conceded_);
      last_touch_.reset();
      return std::exchange(pending_place_, std::nullopt);
    }
    return place;
  }
  time_ms_ += dt_ms;
  if (time_ms_ >= std::llround(rules_.half_s * 1000) * half_) {
    if (half_ == 1) {
      half_ = 2;
      mode_ = PlayMode::kBeforeKickOff;
    } else {
      mode_ = PlayMode::kGameOver;
    }
    mode_ms_ = 0;
    placed_.reset();
    return place;
  }
  if (IsRestart(mode_) && !place) {
    const bool moved = placed_ && (ball - *placed_).head<2>().norm() > kMovedFromPlacement;
    if (moved || mode_ms_ >= std::llround(rules_.exclusive_s * 1000)) {
      mode_ = PlayMode::kPlayOn;
      mode_ms_ = 0;
      placed_.reset();
    }
  }
  if (mode_ == PlayMode::kPlayOn && !place) return CheckBall(ball);
  return place;
}

// Listed once (core/state_io.h).
template <class Io, class Self>
void Referee::Fields(Io& io, Self& r) {
  io.Tag(StateTag("MREF"));
  io(InRange(r.mode_, static_cast<PlayMode>(kModeCount)), r.teams_, r.score_, r.time_ms_, r.mode_ms_, r.half_,
     r.last_touch_, r.placed_, r.conceded_, r.pending_place_);
  io.Check(!r.teams_[0] || r.teams_[0] != r.teams_[1], "one team on both sides");
  for (int score : r.score_) io.Check(score >= 0 && score <= kMaxScore, "score out of range");
  io.Check(r.time_ms_ >= 0 && r.mode_ms_ >= 0 && r.time_ms_ <= kMaxTimeMs && r.mode_ms_ <= kMaxTimeMs,
           "time out of range");
  io.Check(r.half_ >= 1 && r.half_ <= 2, "half out of range");
}

void Referee::Save(StateWriter& out) const { Fields(out, *this); }

void Referee::Restore(StateReader& in) {
  Referee r = *this;
  Fields(in, r);
  if (in.ok()) *this = std::move(r);
}

}  // namespace turf::rcssservermj
