#include "kernel/simspark/fouls.h"

#include <algorithm>
#include <cmath>

#include "kernel/simspark/touch_groups.h"

namespace turf::simspark {

namespace {

constexpr double kCycle = 0.02;           // s
constexpr double kGroundHeight = 0.15;    // m: a torso below this lies on the ground
constexpr double kStandingHeight = 0.25;  // m: at or above this it stands (or tries to)
constexpr double kStandingReset = 0.5;    // s standing that ends the not-standing count
constexpr double kMovedImmunity = 1.0;    // s after a referee's move without a charging judgement
constexpr double kHoldHeight = 1.0;       // m, plus 1 cm per cycle of the foul
constexpr double kOutsideHeight = 0.4;    // m: the reference's agent radius
constexpr double kOutsideMargin = 0.5;    // m beyond the touch line
constexpr double kOutsideSpacing = 0.6;   // m along x per uniform number
constexpr size_t kMaxPlayers = 64;
constexpr int kMaxUnum = 99;
constexpr int kMaxCount = 1 << 30;
constexpr int kTeamSize = 11;            // the reference's arrays: numbers 1..11
constexpr int kMaxInOwnArea = 3;         // MaxPlayersInsideOwnArea
constexpr double kFarFromGoal = 1000.0;  // the reference's "not ranked" distance

int Cycles(double seconds) { return static_cast<int>(std::lround(seconds / kCycle)); }
void Tick(int* count) { *count = std::min(*count + 1, kMaxCount); }

}  // namespace

SafeSpotRules SpotRulesOf(const FoulRules& rules) {
  SafeSpotRules spot;
  spot.field_length = rules.field_length;
  spot.goal_width = rules.goal_width;
  spot.penalty_depth = rules.penalty_depth;
  spot.penalty_width = rules.penalty_width;
  return spot;
}

const char* FoulName(Foul foul) {
  switch (foul) {
    case Foul::kNone:
      return "none";
    case Foul::kIncapable:
      return "incapable";
    case Foul::kCharging:
      return "charging";
    case Foul::kTouching:
      return "touching";
    case Foul::kIllegalDefence:
      return "illegal_defence";
  }
  return "?";
}

// ResetFoulCounterPlayer: the velocities and the time since the last move stay.
void FoulReferee::ResetCounts(Counts* c) {
  Counts fresh;
  fresh.velocities = c->velocities;
  fresh.since_moved = c->since_moved;
  fresh.last_group_size = c->last_group_size;
  *c = fresh;
}

// ProcessAgentState.
void FoulReferee::Count(const RefereePlayer& p, Counts* c) const {
  const bool inside = std::abs(p.torso.y()) < rules_.field_width / 2 + 0.1;
  const double z = p.torso.z();
  if (z < kStandingHeight && inside) {
    Tick(&c->not_standing);
    c->standing = 0;
  }
  if (z < kGroundHeight && inside) Tick(&c->ground);
  if (z >= kStandingHeight) {
    Tick(&c->standing);
    c->ground = 0;
  }
  if (c->standing > kStandingReset / kCycle) c->not_standing = 0;
  Tick(&c->since_ball);
  Tick(&c->since_contact);
  Tick(&c->since_moved);
}

// The reference's penalty box, stretched behind the goal line for a goalie.
bool FoulReferee::GoalieInOwnArea(Side side, int unum, const Eigen::Vector3d& torso) const {
  if (unum != 1 || std::abs(torso.y()) > rules_.penalty_width / 2) return false;
  const double front = rules_.field_length / 2 - rules_.penalty_depth;
  return side == Side::kLeft ? torso.x() <= -front : torso.x() >= front;
}

// AnalyseChargingFouls: every update is read from the counts before it (the reference's _new arrays).
void FoulReferee::JudgeCharging(const std::vector<RefereePlayer>& players, const std::vector<PlayerContact>& contacts,
                                const Eigen::Vector3d& ball) {
  std::map<Player, Counts> next = counts_;
  const ChargingRules& r = rules_.charging;
  for (const PlayerContact& contact : contacts) {
    if (contact.side_a == contact.side_b || !contact.point.allFinite()) continue;  // opponents only
    const bool a_left = contact.side_a == Side::kLeft;
    const Player who[2] = {{Side::kLeft, a_left ? contact.unum_a : contact.unum_b},
                           {Side::kRight, a_left ? contact.unum_b : contact.unum_a}};
    const RefereePlayer* p[2] = {nullptr, nullptr};
    for (const RefereePlayer& q : players)
      for (int i = 0; i < 2; ++i)
        if (q.side == who[i].first && q.unum == who[i].second) p[i] = &q;
    if (p[0] == nullptr || p[1] == nullptr) continue;
    const Counts* c[2] = {&counts_.at(who[0]), &counts_.at(who[1])};
    bool judged = true;
    for (const Counts* k : c)
      if (k->not_standing != 0 || k->since_moved < kMovedImmunity / kCycle || k->foul != Foul::kNone) judged = false;
    if (!judged) continue;
    std::array<ChargingParty, 2> parties;
    bool goalie[2];
    for (int i = 0; i < 2; ++i) {
      parties[i].torso = p[i]->torso;
      for (const Eigen::Vector3d& v : c[i]->velocities) parties[i].velocity += v / kVelocities;
      goalie[i] = GoalieInOwnArea(who[i].first, who[i].second, p[i]->torso);
    }
    const ChargingVerdict verdict = JudgeCollision(parties, contact.point, ball, r);
    for (int i = 0; i < 2; ++i) {
      if (!verdict.moving_into[i]) continue;
      Counts& other = next.at(who[1 - i]);
      if (goalie[i]) {
        other.since_ball = 0;
      } else if (c[i]->since_ball < r.immunity_time / kCycle) {
        other.since_ball = std::min(other.since_ball, c[i]->since_ball);
      }
      other.since_contact = std::min(other.since_contact, c[i]->since_contact);
    }
    for (int i = 0; i < 2; ++i) {
      // The reference's setting is a float: 0.2f / 0.02 is 10.0000001, so 11 cycles.
      const double min_contact_cycles = static_cast<float>(r.collision_min_time) / kCycle;
      if (verdict.charging[i] && !goalie[i] && c[i]->since_contact >= min_contact_cycles &&
          c[i]->since_ball >= r.immunity_time / kCycle) {
        Counts& mine = next.at(who[i]);
        mine.foul_time = c[i]->foul_time + 1;
        mine.foul = Foul::kCharging;
      }
    }
    if (!verdict.charging[0] && !verdict.charging[1]) {
      next.at(who[0]).since_contact = 0;
      next.at(who[1]).since_contact = 0;
    }
  }
  counts_ = std::move(next);
}

// AnalyseTouchGroups and PenalizeTouchingFoul: the pushes.
std::vector<RefereeMove> FoulReferee::JudgeTouching(const std::vector<RefereePlayer>& players,
                                                    const std::vector<PlayerContact>& contacts) {
  std::vector<TouchPlayer> touch;
  std::map<Player, size_t> index;
  for (const RefereePlayer& p : players) {
    const Counts& c = counts_.at({p.side, p.unum});
    index[{p.side, p.unum}] = touch.size();
    touch.push_back({p.side, p.unum, p.torso, c.foul != Foul::kNone, c.last_group_size});
  }
  std::vector<std::pair<size_t, size_t>> touching;
  for (const PlayerContact& contact : contacts) {
    const auto a = index.find({contact.side_a, contact.unum_a});
    const auto b = index.find({contact.side_b, contact.unum_b});
    if (a != index.end() && b != index.end()) touching.emplace_back(a->second, b->second);
  }
  const TouchGroups groups = AnalyseTouchGroups(touch, touching, rng_);
  std::vector<RefereeMove> moves;
  for (const TouchingFoul& f : groups.fouls) {
    const TouchPlayer& p = touch[f.player];
    Counts& c = counts_.at({p.side, p.unum});
    c.foul_time = 1;
    c.foul = Foul::kTouching;
    c.since_moved = 0;
    moves.push_back(
        {p.side, p.unum, board_->Place(p.side, p.unum, f.position, true), false, Foul::kTouching, f.group_size});
  }
  for (size_t i = 0; i < touch.size(); ++i)
    counts_.at({touch[i].side, touch[i].unum}).last_group_size = groups.group_sizes[i];
  return moves;
}

// AnalyseFouls' FT_Incapable.
bool FoulReferee::Incapable(int unum, const Counts& c) const {
  const bool goalie = unum == 1;
  const double ground = goalie ? rules_.goalie_ground_max_time : rules_.ground_max_time;
  const double not_standing = goalie ? rules_.goalie_not_standing_max_time : rules_.not_standing_max_time;
  return c.ground > ground / kCycle || c.not_standing > not_standing / kCycle;
}

// The referee's penalty box (PenaltyLength by PenaltyWidth from the goal line), edges included.
bool FoulReferee::InOwnArea(Side side, const Eigen::Vector3d& torso) const {
  const double line = rules_.field_length / 2;
  const double front = line - rules_.penalty_depth;
  const double x = side == Side::kLeft ? -torso.x() : torso.x();
  return x >= front && x <= line && std::abs(torso.y()) <= rules_.penalty_width / 2;
}

// PenalizeIllegelDefenseFoul: to the nearer of the box's x and y edges, AgentRadius (0.4 m) beyond it, not into the
// goal.
Eigen::Vector3d FoulReferee::OutOfOwnArea(Side side, const Eigen::Vector3d& torso) const {
  constexpr double kPad = 0.4;
  const double line = rules_.field_length / 2;
  const double front = line - rules_.penalty_depth;
  const double min_x = side == Side::kLeft ? -line : front;
  const double max_x = side == Side::kLeft ? -front : line;
  const double half_width = rules_.penalty_width / 2;
  const double to_x = std::abs(min_x - torso.x()) < std::abs(max_x - torso.x()) ? min_x - kPad : max_x + kPad;
  const double to_y =
      std::abs(-half_width - torso.y()) < std::abs(half_width - torso.y()) ? -half_width - kPad : half_width + kPad;
  Eigen::Vector3d to = torso;
  if (std::abs(to_y - torso.y()) < std::abs(to_x - torso.x())) {
    to.y() = to_y;
  } else {
    to.x() = to_x;
  }
  if (std::abs(to.x()) > line && std::abs(to.y()) < rules_.goal_width / 2 + kPad)
    to.y() = (rules_.goal_width / 2 + kPad + 0.001) * (to.y() < 0 ? -1.0 : 1.0);
  return to;
}

// CalculateDistanceArrays' own-area counts and AnalyseFouls' illegal defence: with more than three players of a
// team (no foul) in its own penalty area, a field player that has just entered it, or, when the goalie has just
// entered, the one ranked fourth from the goal of those that were in it, is moved out at once. The numbers are
// taken in a random order (the count drops with each move).
std::vector<RefereeMove> FoulReferee::JudgeIllegalDefence(Side side, const std::vector<RefereePlayer>& players) {
  std::array<const RefereePlayer*, kTeamSize + 1> player{};
  std::array<bool, kTeamSize + 1> entered{};
  std::array<double, kTeamSize + 1> from_goal;
  from_goal.fill(kFarFromGoal);
  int inside = 0;
  bool goalie_entered = false;
  const Eigen::Vector2d goal(side == Side::kLeft ? -rules_.field_length / 2 : rules_.field_length / 2, 0.0);
  for (const RefereePlayer& p : players) {
    if (p.side != side || p.unum < 1 || p.unum > kTeamSize) continue;
    player[p.unum] = &p;
    Counts& c = counts_.at({p.side, p.unum});
    const bool was_in = c.in_own_area;
    c.in_own_area = c.foul == Foul::kNone && InOwnArea(side, p.torso);
    if (!c.in_own_area) continue;
    ++inside;
    entered[p.unum] = !was_in;
    if (p.unum == 1) {
      from_goal[p.unum] = 0.0;
      goalie_entered = !was_in;
    } else if (was_in) {
      from_goal[p.unum] = (p.torso.head<2>() - goal).norm();
    }
  }
  // SimpleOrder: rank by distance from the goal among the numbers without a foul (ties: the lower number after).
  std::array<int, kTeamSize + 1> rank;
  rank.fill(1);
  const auto fouled = [&](int unum) { return player[unum] != nullptr && counts_.at({side, unum}).foul != Foul::kNone; };
  for (int a = 1; a <= kTeamSize; ++a) {
    if (fouled(a)) continue;
    for (int b = a + 1; b <= kTeamSize; ++b) {
      if (fouled(b)) continue;
      ++rank[from_goal[a] >= from_goal[b] ? a : b];
    }
  }
  std::vector<int> order;
  for (int unum = 1; unum <= kTeamSize; ++unum) order.push_back(unum);
  Shuffle(&order, rng_);
  std::vector<RefereeMove> moves;
  for (const int unum : order) {
    if (player[unum] == nullptr || unum == 1) continue;
    Counts& c = counts_.at({side, unum});
    if (c.foul != Foul::kNone || !c.in_own_area || inside <= kMaxInOwnArea) continue;
    if (!entered[unum] && !(goalie_entered && rank[unum] == kMaxInOwnArea + 1)) continue;
    --inside;
    c.foul = Foul::kIllegalDefence;
    c.foul_time = 1;
    c.since_moved = 0;
    const Eigen::Vector3d to = board_->Place(side, unum, OutOfOwnArea(side, player[unum]->torso), true);
    moves.push_back({side, unum, to, false, Foul::kIllegalDefence});
  }
  return moves;
}

// ClearPlayersAutomatic and RepositionOutsidePos.
std::vector<RefereeMove> FoulReferee::Enforce(const std::vector<RefereePlayer>& players, const Eigen::Vector3d& ball) {
  std::vector<RefereeMove> moves;
  for (const RefereePlayer& p : players) {
    Counts& c = counts_.at({p.side, p.unum});
    if (c.foul == Foul::kNone) continue;
    // Pushed already (JudgeTouching, JudgeIllegalDefence): not cleared, only its counts reset.
    if (c.foul == Foul::kTouching || c.foul == Foul::kIllegalDefence) {
      ResetCounts(&c);
      continue;
    }
    c.since_moved = 0;
    if (c.foul_time <= rules_.hold_time / kCycle) {
      Tick(&c.foul_time);
      const Eigen::Vector3d held(p.torso.x(), p.torso.y(), kHoldHeight + c.foul_time * 0.01);
      moves.push_back({p.side, p.unum, board_->Place(p.side, p.unum, held, false), false, c.foul});
      continue;
    }
    const double x = (p.side == Side::kLeft ? -kOutsideSpacing : kOutsideSpacing) * (7 - p.unum);
    const double y = (rules_.field_width / 2 + kOutsideMargin) * (ball.y() < 0 ? 1.0 : -1.0);
    moves.push_back({p.side, p.unum, board_->Place(p.side, p.unum, {x, y, kOutsideHeight}, true), true, c.foul});
    ResetCounts(&c);
  }
  return moves;
}

std::vector<RefereeMove> FoulReferee::Update(bool paused, const std::vector<RefereePlayer>& given,
                                             const std::vector<PlayerContact>& contacts, const Eigen::Vector3d& ball) {
  // A bad sample from elsewhere: that player counts nothing and is moved nowhere.
  std::vector<RefereePlayer> players;
  for (const RefereePlayer& p : given)
    if (p.torso.allFinite() && p.velocity.allFinite()) players.push_back(p);
  std::vector<SpotPlayer> spots;
  for (const RefereePlayer& p : players)
    spots.push_back(
        {p.side, p.unum, p.torso,
         p.box.isEmpty() || !p.box.min().allFinite() || !p.box.max().allFinite() ? Eigen::AlignedBox3d() : p.box});
  board_.emplace(std::move(spots), ball, SpotRulesOf(rules_));
  for (const RefereePlayer& p : players) {
    Counts& c = counts_[{p.side, p.unum}];
    std::rotate(c.velocities.rbegin(), c.velocities.rbegin() + 1, c.velocities.rend());
    c.velocities[0] = p.velocity;
  }
  if (paused) {
    for (auto& [player, c] : counts_) ResetCounts(&c);  // ResetFoulCounter; the touch groups stay as they were
    return {};
  }
  for (const RefereePlayer& p : players) {
    Counts& c = counts_.at({p.side, p.unum});
    Count(p, &c);
    if (p.touching_ball) c.since_ball = 0;  // UpdateTimesSinceLastBallTouch
  }
  if (ball.allFinite()) JudgeCharging(players, contacts, ball);
  std::vector<RefereeMove> moves;
  for (const Side side : {Side::kLeft, Side::kRight})
    for (const RefereeMove& m : JudgeIllegalDefence(side, players)) moves.push_back(m);
  for (const RefereePlayer& p : players) {
    Counts& c = counts_.at({p.side, p.unum});
    if (c.foul != Foul::kNone) continue;  // a foul being enforced is not judged again (HaveEnforceableFoul)
    const bool incapable = Incapable(p.unum, c);
    c.foul_time = incapable ? 1 : 0;
    c.foul = incapable ? Foul::kIncapable : Foul::kNone;
  }
  for (const RefereeMove& m : JudgeTouching(players, contacts)) moves.push_back(m);
  for (RefereeMove& m : Enforce(players, ball)) moves.push_back(m);
  return moves;
}

void FoulReferee::Save(StateWriter& out) const {
  out.Tag(StateTag("SFOU"));
  out(rng_, Sized(counts_, kMaxPlayers));
}

void FoulReferee::Restore(StateReader& in) {
  in.Tag(StateTag("SFOU"));
  Rng rng;
  std::map<Player, Counts> restored;
  in(rng, Sized(restored, kMaxPlayers));
  for (const auto& [player, c] : restored) {
    if (player.second < 0 || player.second > kMaxUnum) in.Fail("referee count of a player number out of range");
    for (int v : {c.ground, c.not_standing, c.standing, c.foul_time, c.since_ball, c.since_contact, c.since_moved,
                  c.last_group_size})
      if (v < 0 || v > kMaxCount) in.Fail("referee count out of range");
  }
  if (!in.ok()) return;
  rng_ = rng;
  counts_ = std::move(restored);
}

}  // namespace turf::simspark
