// rcssserver3d's touching foul (SoccerRuleAspect::AnalyseTouchGroups and PenalizeTouchingFoul with
// naosoccersim.rb's MaxTouchGroupSize 2 and TouchingFoulBeamPenalty false), as a pure function of one cycle: players
// touching each other, directly or through others, of either team, form a group; in a group of more than two (not
// counting players with a foul already) one player is pushed 0.4 m away from the group's centre.
//
// Teams in random order; each team's players in random order; for each player without a foul whose group is too
// big and who was not touching anyone the cycle before (its last group had one member): the group's members in
// random order give the centre (of those without a foul) and, of its non-goalies, the last team mate and the last
// opponent. If the player's team has at least half the group, the player is pushed (a goalie pushes that team mate
// instead), else that opponent; the one pushed leaves the group. If a group of the team is still too big after
// that, the team is analysed again without the "was not touching" condition. A group's size counts the players with
// a foul (the reference's quirk); a push with nobody to push (no such team mate or opponent) is skipped, where the
// reference reads an unset iterator.
#pragma once

#include <Eigen/Core>
#include <map>
#include <utility>
#include <vector>

#include "core/rng.h"
#include "kernel/simspark/types.h"

namespace turf::simspark {

struct TouchPlayer {
  Side side = Side::kLeft;
  int unum = 0;
  Eigen::Vector3d torso = Eigen::Vector3d::Zero();
  bool fouled = false;      // has a foul being enforced
  int last_group_size = 1;  // members of its group at the end of the cycle before
};

struct TouchingFoul {
  size_t player = 0;                                   // index into the players
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // where its torso goes (height kept)
  int group_size = 0;                                  // of the group it was pushed out of, itself included
};

struct TouchGroups {
  std::vector<TouchingFoul> fouls;  // in the order called
  std::vector<int> group_sizes;     // per player: its group's members at the end (after the pushed left)
};

// `touching`: pairs of indices into `players`.
TouchGroups AnalyseTouchGroups(const std::vector<TouchPlayer>& players,
                               const std::vector<std::pair<size_t, size_t>>& touching, Rng& rng,
                               int max_group_size = 2);

}  // namespace turf::simspark
