// rcssserver3d's incapable foul (kernel/simspark/incapable.h) against the reference's rule as its code states it
// (SoccerRuleAspect::ProcessAgentState, AnalyseFouls, ClearPlayersAutomatic, RepositionOutsidePos;
// naosoccersim.rb's times): who is judged, after how many cycles, the hold in the air and the spot outside.
#include "kernel/simspark/incapable.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "tests/support/state_round_trip.h"

namespace turf::simspark {
namespace {

const Eigen::Vector3d kBall(1.0, 2.0, 0.042);

PlayerTorso At(double x, double y, double z, int unum = 4, Side side = Side::kLeft) { return {side, unum, {x, y, z}}; }

// Cycles (not paused) with the torso at `torso` until the referee moves the player; that cycle's number, or 0.
int CyclesUntilMoved(IncapableRule* rule, const PlayerTorso& torso, int max,
                     std::vector<RefereeMove>* moves = nullptr) {
  for (int i = 1; i <= max; ++i) {
    std::vector<RefereeMove> m = rule->Update(false, {torso}, kBall);
    if (!m.empty()) {
      if (moves != nullptr) *moves = m;
      return i;
    }
  }
  return 0;
}

// On the ground (torso below 0.15 m) for more than 15 s (750 cycles): the foul at the 751st cycle.
TEST(IncapableRule, FieldPlayerOnTheGroundMoreThanFifteenSeconds) {
  IncapableRule rule;
  std::vector<RefereeMove> moves;
  EXPECT_EQ(CyclesUntilMoved(&rule, At(3, 1, 0.1), 2000, &moves), 751);
  ASSERT_EQ(moves.size(), 1u);
  EXPECT_EQ(moves[0].unum, 4);
  EXPECT_FALSE(moves[0].outside);
  EXPECT_NEAR(moves[0].position.x(), 3.0, 1e-12) << "held where it is";
  EXPECT_NEAR(moves[0].position.y(), 1.0, 1e-12);
  EXPECT_NEAR(moves[0].position.z(), 1.02, 1e-12) << "1 m and 1 cm per cycle of the foul";
}

// Held in the air for 0.5 s (25 cycles in all), then put outside: x = -0.6 (7 - 4) for the left team, on the touch
// line away from the ball (ball at y > 0: y = -(10 + 0.5)), torso 0.4 m high.
TEST(IncapableRule, HeldHalfASecondThenPutOutsideAwayFromTheBall) {
  IncapableRule rule;
  ASSERT_EQ(CyclesUntilMoved(&rule, At(3, 1, 0.1), 2000), 751);
  int held = 1;
  std::vector<RefereeMove> m;
  for (double z = 1.02; held < 100; ++held) {
    m = rule.Update(false, {At(3, 1, z)}, kBall);
    ASSERT_EQ(m.size(), 1u);
    if (m[0].outside) break;
    EXPECT_NEAR(m[0].position.z(), z + 0.01, 1e-9);
    z = m[0].position.z();
  }
  EXPECT_EQ(held, 25) << "cycles held before the move out";
  EXPECT_NEAR(m[0].position.x(), -1.8, 1e-12);
  EXPECT_NEAR(m[0].position.y(), -10.5, 1e-12);
  EXPECT_NEAR(m[0].position.z(), 0.4, 1e-12);
  // Lying outside the field's width: never judged again there.
  EXPECT_EQ(CyclesUntilMoved(&rule, At(-1.8, -10.5, 0.1), 3000), 0);
  // The right team's spot mirrors x; a ball at y < 0 sends it to y > 0.
  IncapableRule right;
  for (int i = 0; i < 751 + 24; ++i) right.Update(false, {At(0, 0, 0.1, 9, Side::kRight)}, {0, -1, 0});
  const std::vector<RefereeMove> out = right.Update(false, {At(0, 0, 1.2, 9, Side::kRight)}, {0, -1, 0});
  ASSERT_EQ(out.size(), 1u);
  ASSERT_TRUE(out[0].outside);
  EXPECT_NEAR(out[0].position.x(), 0.6 * (7 - 9), 1e-12);
  EXPECT_NEAR(out[0].position.y(), 10.5, 1e-12);
}

// Sitting (0.15 to 0.25 m) is not on the ground, but not standing: more than 30 s (1500 cycles).
TEST(IncapableRule, NotStandingMoreThanThirtySeconds) {
  IncapableRule rule;
  EXPECT_EQ(CyclesUntilMoved(&rule, At(0, 0, 0.2), 3000), 1501);
}

// The goalie (number 1): 30 s on the ground, 60 s not standing.
TEST(IncapableRule, TheGoalieHasTwiceTheTime) {
  IncapableRule ground;
  EXPECT_EQ(CyclesUntilMoved(&ground, At(-14, 0, 0.1, 1), 4000), 1501);
  IncapableRule sitting;
  EXPECT_EQ(CyclesUntilMoved(&sitting, At(-14, 0, 0.2, 1), 4000), 3001);
}

// One cycle standing ends the ground count; the not-standing count ends only after more than 0.5 s standing.
TEST(IncapableRule, StandingUpEndsTheCounts) {
  IncapableRule rule;
  for (int i = 0; i < 700; ++i) ASSERT_TRUE(rule.Update(false, {At(0, 0, 0.1)}, kBall).empty());
  ASSERT_TRUE(rule.Update(false, {At(0, 0, 0.3)}, kBall).empty());
  EXPECT_EQ(CyclesUntilMoved(&rule, At(0, 0, 0.1), 2000), 751) << "the ground count started again";

  IncapableRule sit;
  for (int i = 0; i < 1400; ++i) ASSERT_TRUE(sit.Update(false, {At(0, 0, 0.2)}, kBall).empty());
  for (int i = 0; i < 25; ++i) ASSERT_TRUE(sit.Update(false, {At(0, 0, 0.3)}, kBall).empty());
  EXPECT_EQ(CyclesUntilMoved(&sit, At(0, 0, 0.2), 2000), 101) << "25 cycles standing are not enough";
}

TEST(IncapableRule, PausedJudgesNothingAndEndsTheCounts) {
  IncapableRule rule;
  for (int i = 0; i < 5000; ++i) ASSERT_TRUE(rule.Update(true, {At(0, 0, 0.1)}, kBall).empty());
  for (int i = 0; i < 700; ++i) ASSERT_TRUE(rule.Update(false, {At(0, 0, 0.1)}, kBall).empty());
  ASSERT_TRUE(rule.Update(true, {At(0, 0, 0.1)}, kBall).empty());
  EXPECT_EQ(CyclesUntilMoved(&rule, At(0, 0, 0.1), 2000), 751);
}

// A torso that is not finite (a bad sample from another participant) counts nothing and is never moved.
TEST(IncapableRule, NonFiniteTorsoCountsNothing) {
  IncapableRule rule;
  for (int i = 0; i < 700; ++i) ASSERT_TRUE(rule.Update(false, {At(0, 0, 0.1)}, kBall).empty());
  for (int i = 0; i < 2000; ++i) ASSERT_TRUE(rule.Update(false, {At(NAN, 0, 0.1)}, kBall).empty()) << i;
  EXPECT_EQ(CyclesUntilMoved(&rule, At(0, 0, 0.1), 100), 51) << "the count went on from 700";
}

TEST(IncapableRule, SnapshotContinuesTheCountsAndRefusesDamage) {
  IncapableRule rule;
  for (int i = 0; i < 740; ++i) rule.Update(false, {At(0, 0, 0.1)}, kBall);
  const std::string bytes = test::Saved(rule);
  IncapableRule copy;
  ASSERT_EQ(test::RestoreAll(bytes, &copy), "");
  EXPECT_EQ(CyclesUntilMoved(&copy, At(0, 0, 0.1), 100), 11);
  for (size_t n = 0; n < bytes.size(); ++n) {
    IncapableRule fresh;
    EXPECT_NE(test::RestoreAll(bytes.substr(0, n), &fresh), "") << n;
    EXPECT_EQ(CyclesUntilMoved(&fresh, At(0, 0, 0.1), 100), 0) << "a refused snapshot changes nothing";
  }
}

}  // namespace
}  // namespace turf::simspark
