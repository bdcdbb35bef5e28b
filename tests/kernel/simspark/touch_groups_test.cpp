// rcssserver3d's touching foul (kernel/simspark/touch_groups.h) against the reference's AnalyseTouchGroups and
// PenalizeTouchingFoul as their code states them (MaxTouchGroupSize 2): who is pushed out of a crowd, and where.
// The reference draws its orders at random; where the outcome depends on them, the tests check what holds for every
// order, over many seeds.
#include "kernel/simspark/touch_groups.h"

#include <gtest/gtest.h>

namespace turf::simspark {
namespace {

TouchPlayer P(Side side, int unum, double x, double y, int last_group_size = 1, bool fouled = false) {
  return {side, unum, {x, y, 0.35}, fouled, last_group_size};
}

constexpr Side L = Side::kLeft;
constexpr Side R = Side::kRight;

// The analysis with each of the first `seeds` seeds (the reference's orders are random).
std::vector<TouchGroups> OverSeeds(const std::vector<TouchPlayer>& players,
                                   const std::vector<std::pair<size_t, size_t>>& touching, int seeds = 20) {
  std::vector<TouchGroups> out;
  for (int seed = 0; seed < seeds; ++seed) {
    Rng rng(seed);
    out.push_back(AnalyseTouchGroups(players, touching, rng));
  }
  return out;
}

TEST(TouchGroups, TwoTouchingIsNoFoul) {
  Rng rng(1);
  const TouchGroups g = AnalyseTouchGroups({P(L, 2, 0, 0), P(R, 3, 0.3, 0)}, {{0, 1}}, rng);
  EXPECT_TRUE(g.fouls.empty());
  EXPECT_EQ(g.group_sizes, (std::vector<int>{2, 2}));
}

// Team mates 2 and 3 touched the cycle before; 4 joins them: 4 is pushed 0.4 m away from the three's centre, and
// the group it leaves counts as its last (so it is no newcomer the next cycle).
TEST(TouchGroups, TheNewcomerToAPairIsPushedAwayFromTheCentre) {
  for (const TouchGroups& g : OverSeeds({P(L, 2, 0, 0, 2), P(L, 3, 0.3, 0, 2), P(L, 4, -0.3, 0.3)}, {{0, 1}, {2, 0}})) {
    ASSERT_EQ(g.fouls.size(), 1u);
    EXPECT_EQ(g.fouls[0].player, 2u);
    EXPECT_EQ(g.fouls[0].group_size, 3);
    // Centre (0, 0.1): 4 is at (-0.3, 0.2) from it, pushed 0.4 m along that, height kept.
    const Eigen::Vector3d away = Eigen::Vector3d(-0.3, 0.2, 0).normalized() * 0.4;
    EXPECT_NEAR(g.fouls[0].position.x(), -0.3 + away.x(), 1e-12);
    EXPECT_NEAR(g.fouls[0].position.y(), 0.3 + away.y(), 1e-12);
    EXPECT_NEAR(g.fouls[0].position.z(), 0.35, 1e-12);
    EXPECT_EQ(g.group_sizes, (std::vector<int>{2, 2, 2}));
  }
}

// A newcomer whose team has fewer than half of the group: one of the other team is pushed, whatever the order.
TEST(TouchGroups, TheTeamWithMoreInTheGroupLosesAPlayer) {
  for (const TouchGroups& g :
       OverSeeds({P(R, 3, 0, 0, 2), P(R, 5, 0.3, 0, 2), P(L, 2, -0.3, 0)}, {{0, 1}, {2, 0}}, 40)) {
    ASSERT_EQ(g.fouls.size(), 1u);
    EXPECT_NE(g.fouls[0].player, 2u) << "the right team has two of the three";
  }
}

// A goalie joining team mates pushes one of them instead.
TEST(TouchGroups, AGoalieJoiningPushesATeamMate) {
  for (const TouchGroups& g : OverSeeds({P(L, 2, 0, 0, 2), P(L, 3, 0.3, 0, 2), P(L, 1, -0.3, 0)}, {{0, 1}, {2, 0}})) {
    ASSERT_EQ(g.fouls.size(), 1u);
    EXPECT_NE(g.fouls[0].player, 2u) << "the goalie is not pushed";
  }
}

// Players with a foul already do not make a group too big.
TEST(TouchGroups, PlayersWithAFoulDoNotCount) {
  for (const TouchGroups& g :
       OverSeeds({P(L, 2, 0, 0, 2), P(L, 3, 0.3, 0, 2, true), P(L, 4, -0.3, 0)}, {{0, 1}, {2, 0}}))
    EXPECT_TRUE(g.fouls.empty());
}

// A chain of four (touching through each other) with no newcomer: the team is analysed again without that condition
// until no group is too big: two are pushed.
TEST(TouchGroups, AnOldCrowdIsThinnedToTwo) {
  for (const TouchGroups& g : OverSeeds({P(L, 2, 0, 0, 4), P(L, 3, 0.3, 0, 4), P(L, 4, 0.6, 0, 4), P(L, 5, 0.9, 0, 4)},
                                        {{0, 1}, {1, 2}, {2, 3}})) {
    EXPECT_EQ(g.fouls.size(), 2u);
  }
}

}  // namespace
}  // namespace turf::simspark
