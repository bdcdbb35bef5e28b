#include "kernel/simspark/incapable.h"

#include <algorithm>
#include <cmath>

namespace turf::simspark {

namespace {

constexpr double kCycle = 0.02;           // s
constexpr double kGroundHeight = 0.15;    // m: a torso below this lies on the ground
constexpr double kStandingHeight = 0.25;  // m: at or above this it stands (or tries to)
constexpr double kStandingReset = 0.5;    // s standing that ends the not-standing count
constexpr double kHoldHeight = 1.0;       // m, plus 1 cm per cycle of the foul
constexpr double kOutsideHeight = 0.4;    // m: the reference's agent radius
constexpr double kOutsideMargin = 0.5;    // m beyond the touch line
constexpr double kOutsideSpacing = 0.6;   // m along x per uniform number
constexpr size_t kMaxPlayers = 64;
constexpr int kMaxUnum = 99;
constexpr int kMaxCount = 1 << 30;

}  // namespace

// ProcessAgentState.
void IncapableRule::Count(const PlayerTorso& p, Counts* c) const {
  const bool inside = std::abs(p.position.y()) < rules_.field_width / 2 + 0.1;
  const double z = p.position.z();
  if (z < kStandingHeight && inside) {
    c->not_standing = std::min(c->not_standing + 1, kMaxCount);
    c->standing = 0;
  }
  if (z < kGroundHeight && inside) c->ground = std::min(c->ground + 1, kMaxCount);
  if (z >= kStandingHeight) {
    c->standing = std::min(c->standing + 1, kMaxCount);
    c->ground = 0;
  }
  if (c->standing > kStandingReset / kCycle) c->not_standing = 0;
}

// AnalyseFouls' FT_Incapable.
bool IncapableRule::Incapable(int unum, const Counts& c) const {
  const bool goalie = unum == 1;
  const double ground = goalie ? rules_.goalie_ground_max_time : rules_.ground_max_time;
  const double not_standing = goalie ? rules_.goalie_not_standing_max_time : rules_.not_standing_max_time;
  return c.ground > ground / kCycle || c.not_standing > not_standing / kCycle;
}

std::vector<RefereeMove> IncapableRule::Update(bool paused, const std::vector<PlayerTorso>& players,
                                               const Eigen::Vector3d& ball) {
  std::vector<RefereeMove> moves;
  if (paused) {
    counts_.clear();  // ResetFoulCounter
    return moves;
  }
  for (const PlayerTorso& p : players) {
    if (!p.position.allFinite()) continue;  // a bad sample from elsewhere: nothing counted, nobody moved
    Counts& c = counts_[{p.side, p.unum}];
    Count(p, &c);
    // A foul being enforced is not judged again (HaveEnforceableFoul).
    if (c.foul_time == 0) c.foul_time = Incapable(p.unum, c) ? 1 : 0;
    if (c.foul_time == 0) continue;
    // ClearPlayersAutomatic.
    if (c.foul_time <= rules_.hold_time / kCycle) {
      ++c.foul_time;
      moves.push_back({p.side, p.unum, {p.position.x(), p.position.y(), kHoldHeight + c.foul_time * 0.01}, false});
      continue;
    }
    const double x = (p.side == Side::kLeft ? -kOutsideSpacing : kOutsideSpacing) * (7 - p.unum);
    const double y = (rules_.field_width / 2 + kOutsideMargin) * (ball.y() < 0 ? 1.0 : -1.0);
    moves.push_back({p.side, p.unum, {x, y, kOutsideHeight}, true});
    c = Counts{};
  }
  return moves;
}

void IncapableRule::Save(StateWriter& out) const {
  out.Tag(StateTag("SINC"));
  out.Put<uint64_t>(counts_.size());
  for (const auto& [player, c] : counts_) {
    out.Put(player.first);
    out.Put<int32_t>(player.second);
    for (int v : {c.ground, c.not_standing, c.standing, c.foul_time}) out.Put<int32_t>(v);
  }
}

void IncapableRule::Restore(StateReader& in) {
  in.Tag(StateTag("SINC"));
  std::map<Player, Counts> restored;
  const size_t n = in.Count(kMaxPlayers);
  for (size_t i = 0; i < n && in.ok(); ++i) {
    const Side side = in.Enum(static_cast<Side>(2));
    const int unum = in.Get<int32_t>();
    if (unum < 0 || unum > kMaxUnum) in.Fail("referee count of a player number out of range");
    Counts c;
    for (int* v : {&c.ground, &c.not_standing, &c.standing, &c.foul_time}) {
      *v = in.Get<int32_t>();
      if (*v < 0 || *v > kMaxCount) in.Fail("referee count out of range");
    }
    restored[{side, unum}] = c;
  }
  if (in.ok()) counts_ = std::move(restored);
}

}  // namespace turf::simspark
