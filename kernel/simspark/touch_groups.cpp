#include "kernel/simspark/touch_groups.h"

#include <algorithm>
#include <numeric>
#include <optional>

namespace turf::simspark {

namespace {

constexpr double kPush = 0.4;  // m: the reference's agent radius

class Analysis {
 public:
  Analysis(const std::vector<TouchPlayer>& players, const std::vector<std::pair<size_t, size_t>>& touching, Rng& rng,
           int max_size)
      : players_(players), rng_(rng), max_size_(max_size), group_of_(players.size()), fouled_(players.size()) {
    std::iota(group_of_.begin(), group_of_.end(), 0);
    for (size_t i = 0; i < players.size(); ++i) fouled_[i] = players[i].fouled;
    for (const auto& [a, b] : touching)
      if (a < players.size() && b < players.size()) Join(a, b);
    groups_.resize(players.size());
    for (size_t i = 0; i < players.size(); ++i) {
      group_of_[i] = Root(i);
      groups_[group_of_[i]].push_back(i);
    }
  }

  TouchGroups Run() {
    const bool left_first = rng_.Next() % 2 == 0;
    for (Side side : {left_first ? Side::kLeft : Side::kRight, left_first ? Side::kRight : Side::kLeft})
      Team(side, true);
    TouchGroups out;
    out.fouls = std::move(fouls_);
    for (size_t i = 0; i < players_.size(); ++i) out.group_sizes.push_back(Size(i));
    return out;
  }

 private:
  size_t Root(size_t i) {
    while (group_of_[i] != i) i = group_of_[i] = group_of_[group_of_[i]];
    return i;
  }
  void Join(size_t a, size_t b) {
    a = Root(a);
    b = Root(b);
    if (a != b) group_of_[std::max(a, b)] = std::min(a, b);
  }
  int Size(size_t i) const { return static_cast<int>(groups_[group_of_[i]].size()); }
  void Leave(size_t i) {
    std::vector<size_t>& g = groups_[group_of_[i]];
    g.erase(std::remove(g.begin(), g.end(), i), g.end());
  }

  void Team(Side side, bool only_newcomers) {
    std::vector<size_t> team;
    for (size_t i = 0; i < players_.size(); ++i)
      if (players_[i].side == side) team.push_back(i);
    Shuffle(&team, rng_);
    for (size_t i : team) {
      if (fouled_[i]) {
        if (Size(i) > 1) Leave(i);
        continue;
      }
      if ((players_[i].last_group_size == 1 || !only_newcomers) && Size(i) > max_size_) Judge(i, side);
    }
    if (!only_newcomers) return;
    for (size_t i : team) {
      if (Size(i) > max_size_) {
        Team(side, false);
        return;
      }
    }
  }

  // The group of `i` (of `side`), too big: who is pushed.
  void Judge(size_t i, Side side) {
    std::vector<size_t> members = groups_[group_of_[i]];
    Shuffle(&members, rng_);
    int fouled = 0;
    int same_side = 0;
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    std::optional<size_t> mate, opponent;
    for (size_t m : members) {
      if (fouled_[m]) {
        ++fouled;
        continue;
      }
      sum += players_[m].torso;
      if (players_[m].side == side) ++same_side;
      if (players_[m].unum == 1) continue;  // a goalie is never the one pushed for another
      (players_[m].side == side ? mate : opponent) = m;
    }
    const int size = static_cast<int>(members.size());
    if (size - fouled <= max_size_) return;
    const Eigen::Vector3d centre = sum / (size - fouled);
    std::optional<size_t> pushed = opponent;
    if (same_side >= size - same_side) pushed = players_[i].unum == 1 ? mate : std::optional<size_t>(i);
    if (!pushed) return;
    Push(*pushed, centre, size);
    Leave(*pushed);
  }

  void Push(size_t p, const Eigen::Vector3d& centre, int group_size) {
    fouled_[p] = true;
    Eigen::Vector3d away = players_[p].torso - centre;
    away.z() = 0;
    const double norm = away.norm();
    Eigen::Vector3d to = players_[p].torso;
    if (norm > 0) to += away / norm * kPush;  // at the centre the reference's direction is not a number: stay
    fouls_.push_back({p, to, group_size});
  }

  const std::vector<TouchPlayer>& players_;
  Rng& rng_;
  int max_size_;
  std::vector<size_t> group_of_;
  std::vector<std::vector<size_t>> groups_;
  std::vector<bool> fouled_;
  std::vector<TouchingFoul> fouls_;
};

}  // namespace

TouchGroups AnalyseTouchGroups(const std::vector<TouchPlayer>& players,
                               const std::vector<std::pair<size_t, size_t>>& touching, Rng& rng, int max_group_size) {
  return Analysis(players, touching, rng, max_group_size).Run();
}

}  // namespace turf::simspark
