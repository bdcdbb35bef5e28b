#include "kernel/simspark/clearing.h"

#include <cmath>
#include <utility>

#include "core/rng.h"

namespace turf::simspark {

namespace {

// The box that holds all the player's parts; an empty one (or one not finite): the torso's point.
Eigen::AlignedBox3d BoxOf(const SpotPlayer& p) {
  if (p.box.isEmpty() || !p.box.min().allFinite() || !p.box.max().allFinite())
    return Eigen::AlignedBox3d(p.torso, p.torso);
  return p.box;
}

// salt's BoundingSphere::Intersects(AABB3): the squared distance from the centre to the box, summed over the axes
// on which the centre is outside it; more than r^2 is a miss.
bool SphereMeetsBox(const Eigen::Vector3d& centre, double radius, const Eigen::AlignedBox3d& box) {
  const double radius_sq = radius * radius;
  double distance_sq = 0.0;
  for (int k = 0; k < 3; ++k) {
    if (centre[k] < box.min()[k]) {
      distance_sq += (centre[k] - box.min()[k]) * (centre[k] - box.min()[k]);
    } else if (centre[k] > box.max()[k]) {
      distance_sq += (centre[k] - box.max()[k]) * (centre[k] - box.max()[k]);
    }
    if (distance_sq > radius_sq) return false;
  }
  return true;
}

// salt's AABB2::Intersects: closed intervals on x and y.
bool RectsMeet(const Eigen::AlignedBox2d& a, const Eigen::AlignedBox2d& b) {
  return !(a.min().x() > b.max().x() || a.max().x() < b.min().x() || a.min().y() > b.max().y() ||
           a.max().y() < b.min().y());
}

// ClearPlayersBeforeKickOff's exemption: all four corners of the rectangle strictly within `radius` of the centre.
bool WhollyInCircle(const Eigen::AlignedBox2d& rect, double radius) {
  const double radius_sq = radius * radius;
  for (const Eigen::Vector2d& corner : {rect.min(), rect.max(), Eigen::Vector2d(rect.min().x(), rect.max().y()),
                                        Eigen::Vector2d(rect.max().x(), rect.min().y())})
    if (!(corner.squaredNorm() < radius_sq)) return false;
  return true;
}

// Where the clearing wants the player, or false when it does not apply to it.
bool Wanted(const Clearing& c, double field_length, const SpotPlayer& p, Eigen::Vector3d* wanted) {
  *wanted = p.torso;
  const bool left = c.team == Side::kLeft;
  switch (c.kind) {
    case ClearingKind::kCircle: {
      if (!SphereMeetsBox(c.centre, c.radius, BoxOf(p))) return false;
      const double x = left ? c.centre.x() - c.distance : c.centre.x() + c.distance;
      const bool behind_goal_line = left ? x < -field_length / 2 : x > field_length / 2;
      if (behind_goal_line) {
        wanted->y() = c.centre.y() < 0 ? c.centre.y() + c.distance : c.centre.y() - c.distance;
      } else {
        wanted->x() = x;
      }
      return true;
    }
    case ClearingKind::kBox: {
      const Eigen::AlignedBox3d box = BoxOf(p);
      const Eigen::AlignedBox2d rect(box.min().head<2>(), box.max().head<2>());
      if (!RectsMeet(c.box, rect)) return false;
      if (c.keep_in_circle > 0 && WhollyInCircle(rect, c.keep_in_circle)) return false;
      wanted->x() = left ? c.box.min().x() - c.distance : c.box.max().x() + c.distance;
      return true;
    }
    case ClearingKind::kRepel: {
      const Eigen::Vector2d from_centre = p.torso.head<2>() - c.centre.head<2>();
      const double d = from_centre.norm();
      if (!(d < c.radius)) return false;
      const Eigen::Vector2d direction = d > 0 ? Eigen::Vector2d(from_centre / d) : Eigen::Vector2d::UnitX();
      wanted->head<2>() = c.centre.head<2>() + direction * (c.radius + c.distance);
      return true;
    }
  }
  return false;
}

}  // namespace

std::vector<ClearingMove> Clear(const std::vector<Clearing>& clearings, double field_length, SpotBoard* board) {
  std::vector<ClearingMove> moves;
  for (const Clearing& c : clearings) {
    board->set_ball(c.ball);
    std::vector<int> team;
    for (const SpotPlayer& p : board->players())
      if (p.side == c.team) team.push_back(p.unum);
    Rng rng(c.order_seed);
    Shuffle(&team, rng);
    for (int unum : team) {
      const SpotPlayer* p = board->Find(c.team, unum);
      if (p == nullptr || !p->torso.allFinite()) continue;
      Eigen::Vector3d wanted;
      if (!Wanted(c, field_length, *p, &wanted) || !wanted.allFinite()) continue;
      moves.push_back({c.team, unum, board->Place(c.team, unum, wanted, /*safe=*/true, c.avoid_ball)});
    }
  }
  return moves;
}

}  // namespace turf::simspark
