#include "kernel/simspark/safe_spot.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <list>

namespace turf::simspark {

namespace {

class Search {
 public:
  Search(Side side, int unum, const std::vector<SpotPlayer>& players, const Eigen::Vector3d& ball,
         const SafeSpotRules& rules, const SpotPlayer& self, bool avoid_ball)
      : side_(side),
        unum_(unum),
        players_(players),
        ball_(ball),
        rules_(rules),
        avoid_ball_(avoid_ball),
        r_(rules.agent_radius),
        agent_(self.torso.head<2>()) {
    inside_own_ = InOwnArea(agent_);
    for (const SpotPlayer& p : players)
      if (p.side == side && InOwnArea(p.torso.head<2>())) ++in_own_area_;
  }

  Eigen::Vector3d Find(const Eigen::Vector3d& wanted) {
    Eigen::Vector3d pos = wanted;
    Eigen::Vector2d initial = wanted.head<2>();
    if (AdjustForPenaltyArea(&initial)) {
      Sample(wanted.head<2>());
      if (candidates_.empty()) return wanted;
      pos.head<2>() = candidates_.front();
      candidates_.pop_front();
    }
    bool unsafe = false;
    for (int attempts = 0; attempts < rules_.max_attempts; ++attempts) {
      unsafe = Unsafe(pos);
      if (unsafe) Sample(pos.head<2>());
      if (!unsafe || candidates_.empty()) break;
      pos.head<2>() = candidates_.front();
      candidates_.pop_front();
    }
    return unsafe ? wanted : pos;
  }

 private:
  // The own penalty area (the reference's AABB2: x from the goal line to the area's front, |y| <= width / 2).
  bool InOwnArea(const Eigen::Vector2d& p) const {
    const double front = rules_.field_length / 2 - rules_.penalty_depth;
    const bool along = side_ == Side::kLeft ? p.x() >= -rules_.field_length / 2 && p.x() <= -front
                                            : p.x() >= front && p.x() <= rules_.field_length / 2;
    return along && std::abs(p.y()) <= rules_.penalty_width / 2;
  }

  bool Unsafe(const Eigen::Vector3d& pos) const {
    if (std::abs(pos.x()) > rules_.field_length / 2 && std::abs(pos.y()) < rules_.goal_width / 2 + r_) return true;
    if (avoid_ball_) {
      const double ball_distance = std::hypot(ball_.x() - pos.x(), ball_.y() - pos.y());
      if (ball_distance < std::max(2 * r_, rules_.min_ball_distance)) return true;
    }
    for (const SpotPlayer& p : players_) {
      if (p.side == side_ && p.unum == unum_) continue;
      const Eigen::AlignedBox3d box = p.box.isEmpty() ? Eigen::AlignedBox3d(p.torso, p.torso) : p.box;
      if (box.squaredExteriorDistance(pos) <= r_ * r_) return true;
    }
    return false;
  }

  // AdjustPositionForPenaltyArea: true when it moved `current` out of the own area.
  bool AdjustForPenaltyArea(Eigen::Vector2d* current) const {
    if (inside_own_ || in_own_area_ < rules_.max_players_in_own_area) return false;
    const double goal_line = rules_.field_length / 2;
    const double front = goal_line - rules_.penalty_depth;
    const double lo_x = side_ == Side::kLeft ? -goal_line : front;
    const double hi_x = side_ == Side::kLeft ? -front : goal_line;
    const double half_w = rules_.penalty_width / 2;
    Eigen::Vector2d& c = *current;
    if (!(c.x() > lo_x - r_ && c.x() < hi_x + r_ && c.y() > -half_w - r_ && c.y() < half_w + r_)) return false;
    const bool beyond_front = side_ == Side::kLeft ? c.x() > agent_.x() : c.x() < agent_.x();
    if (beyond_front) {
      c.x() = side_ == Side::kLeft ? hi_x + r_ : lo_x - r_;
    } else if (c.y() > agent_.y() || (c.y() == agent_.y() && c.y() < 0)) {
      c.y() = half_w + r_;
    } else {
      c.y() = -half_w - r_;
    }
    return true;
  }

  // SamplePositions: the next spots around `current`, into the candidates ordered by distance from the player.
  void Sample(const Eigen::Vector2d& current) {
    std::vector<Eigen::Vector2d> fresh;
    Eigen::Vector2d x_move = current;
    if (side_ == Side::kLeft) {
      x_move.x() = current.x() + r_ * (agent_.x() < current.x() ? 1 : -1);
    } else {
      x_move.x() = current.x() + r_ * (agent_.x() > current.x() ? -1 : 1);
    }
    AddIfOnField(x_move, &fresh);
    if (current.x() == agent_.x()) {
      Eigen::Vector2d x_move2 = current;
      x_move2.x() = current.x() + (side_ == Side::kLeft ? r_ : -r_);
      AddIfOnField(x_move2, &fresh);
    }
    Eigen::Vector2d y_move = current;
    if (current.y() == agent_.y()) {
      y_move.y() = current.y() + r_ * (agent_.y() < 0 ? 1 : -1);  // towards the field's centre line
      AdjustForPenaltyArea(&y_move);
      fresh.push_back(y_move);
      Eigen::Vector2d y_move2 = current;
      y_move2.y() = current.y() + r_ * (agent_.y() < 0 ? -1 : 1);
      AdjustForPenaltyArea(&y_move2);
      fresh.push_back(y_move2);
    } else {
      y_move.y() = current.y() + r_ * (agent_.y() < current.y() ? 1 : -1);
      AdjustForPenaltyArea(&y_move);
      fresh.push_back(y_move);
    }
    for (const Eigen::Vector2d& p : fresh) Insert(p);
  }

  void AddIfOnField(Eigen::Vector2d p, std::vector<Eigen::Vector2d>* out) const {
    if (std::abs(p.x()) > rules_.field_length / 2) return;
    AdjustForPenaltyArea(&p);
    out->push_back(p);
  }

  // From the farthest candidate back: none within r/2 of `p`, which goes after the last one not farther away.
  void Insert(const Eigen::Vector2d& p) {
    const double d = (p - agent_).norm();
    auto at = candidates_.end();
    while (at != candidates_.begin()) {
      const Eigen::Vector2d& c = *std::prev(at);
      if ((c - p).norm() < r_ / 2) return;
      if (d >= (c - agent_).norm()) break;
      --at;
    }
    candidates_.insert(at, p);
  }

  Side side_;
  int unum_;
  const std::vector<SpotPlayer>& players_;
  Eigen::Vector3d ball_;
  const SafeSpotRules& rules_;
  bool avoid_ball_;
  double r_;
  Eigen::Vector2d agent_;
  bool inside_own_ = false;
  int in_own_area_ = 0;
  std::list<Eigen::Vector2d> candidates_;
};

}  // namespace

Eigen::Vector3d SafeSpot(const Eigen::Vector3d& wanted, Side side, int unum, const std::vector<SpotPlayer>& players,
                         const Eigen::Vector3d& ball, const SafeSpotRules& rules, bool avoid_ball) {
  const auto self = std::find_if(players.begin(), players.end(),
                                 [&](const SpotPlayer& p) { return p.side == side && p.unum == unum; });
  if (self == players.end() || !wanted.allFinite() || (avoid_ball && !ball.allFinite())) return wanted;
  return Search(side, unum, players, ball, rules, *self, avoid_ball).Find(wanted);
}

// MoveAgent: the move, through GetSafeReposition when `safe`; the bodies move at once, so later moves see it.
Eigen::Vector3d SpotBoard::Place(Side side, int unum, const Eigen::Vector3d& wanted, bool safe, bool avoid_ball) {
  if (Find(side, unum) == nullptr) return wanted;
  const Eigen::Vector3d to = safe ? SafeSpot(wanted, side, unum, players_, ball_, rules_, avoid_ball) : wanted;
  for (SpotPlayer& p : players_) {
    if (p.side != side || p.unum != unum) continue;
    if (!p.box.isEmpty()) p.box.translate(to - p.torso);
    p.torso = to;
  }
  return to;
}

const SpotPlayer* SpotBoard::Find(Side side, int unum) const {
  for (const SpotPlayer& p : players_)
    if (p.side == side && p.unum == unum) return &p;
  return nullptr;
}

}  // namespace turf::simspark
