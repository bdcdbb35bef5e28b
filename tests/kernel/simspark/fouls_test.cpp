// rcssserver3d's incapable foul (kernel/simspark/fouls.h) against the reference's rule as its code states it
// (SoccerRuleAspect::ProcessAgentState, AnalyseFouls, ClearPlayersAutomatic, RepositionOutsidePos;
// naosoccersim.rb's times): who is judged, after how many cycles, the hold in the air and the spot outside.
#include "kernel/simspark/fouls.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "tests/support/state_round_trip.h"

namespace turf::simspark {
namespace {

const Eigen::Vector3d kBall(1.0, 2.0, 0.042);

RefereePlayer At(double x, double y, double z, int unum = 4, Side side = Side::kLeft) {
  return {side, unum, {x, y, z}, Eigen::Vector3d::Zero(), false};
}

// Runs `cycle` until it returns a move, at most `max` times: that cycle's number (from 1), or 0.
int CyclesUntilMoved(const std::function<std::vector<RefereeMove>()>& cycle, int max,
                     std::vector<RefereeMove>* moves = nullptr) {
  for (int i = 1; i <= max; ++i) {
    std::vector<RefereeMove> m = cycle();
    if (!m.empty()) {
      if (moves != nullptr) *moves = m;
      return i;
    }
  }
  return 0;
}

// Cycles (not paused) with the torso at `torso` until the referee moves the player.
int CyclesUntilMoved(FoulReferee* rule, const RefereePlayer& torso, int max,
                     std::vector<RefereeMove>* moves = nullptr) {
  return CyclesUntilMoved([&] { return rule->Update(false, {torso}, {}, kBall); }, max, moves);
}

// On the ground (torso below 0.15 m) for more than 15 s (750 cycles): the foul at the 751st cycle.
TEST(FoulReferee, FieldPlayerOnTheGroundMoreThanFifteenSeconds) {
  FoulReferee rule;
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
TEST(FoulReferee, HeldHalfASecondThenPutOutsideAwayFromTheBall) {
  FoulReferee rule;
  ASSERT_EQ(CyclesUntilMoved(&rule, At(3, 1, 0.1), 2000), 751);
  int held = 1;
  std::vector<RefereeMove> m;
  for (double z = 1.02; held < 100; ++held) {
    m = rule.Update(false, {At(3, 1, z)}, {}, kBall);
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
  FoulReferee right;
  for (int i = 0; i < 751 + 24; ++i) right.Update(false, {At(0, 0, 0.1, 9, Side::kRight)}, {}, {0, -1, 0});
  const std::vector<RefereeMove> out = right.Update(false, {At(0, 0, 1.2, 9, Side::kRight)}, {}, {0, -1, 0});
  ASSERT_EQ(out.size(), 1u);
  ASSERT_TRUE(out[0].outside);
  EXPECT_NEAR(out[0].position.x(), 0.6 * (7 - 9), 1e-12);
  EXPECT_NEAR(out[0].position.y(), 10.5, 1e-12);
}

// Sitting (0.15 to 0.25 m) is not on the ground, but not standing: more than 30 s (1500 cycles).
TEST(FoulReferee, NotStandingMoreThanThirtySeconds) {
  FoulReferee rule;
  EXPECT_EQ(CyclesUntilMoved(&rule, At(0, 0, 0.2), 3000), 1501);
}

// The goalie (number 1): 30 s on the ground, 60 s not standing.
TEST(FoulReferee, TheGoalieHasTwiceTheTime) {
  FoulReferee ground;
  EXPECT_EQ(CyclesUntilMoved(&ground, At(-14, 0, 0.1, 1), 4000), 1501);
  FoulReferee sitting;
  EXPECT_EQ(CyclesUntilMoved(&sitting, At(-14, 0, 0.2, 1), 4000), 3001);
}

// One cycle standing ends the ground count; the not-standing count ends only after more than 0.5 s standing.
TEST(FoulReferee, StandingUpEndsTheCounts) {
  FoulReferee rule;
  for (int i = 0; i < 700; ++i) ASSERT_TRUE(rule.Update(false, {At(0, 0, 0.1)}, {}, kBall).empty());
  ASSERT_TRUE(rule.Update(false, {At(0, 0, 0.3)}, {}, kBall).empty());
  EXPECT_EQ(CyclesUntilMoved(&rule, At(0, 0, 0.1), 2000), 751) << "the ground count started again";

  FoulReferee sit;
  for (int i = 0; i < 1400; ++i) ASSERT_TRUE(sit.Update(false, {At(0, 0, 0.2)}, {}, kBall).empty());
  for (int i = 0; i < 25; ++i) ASSERT_TRUE(sit.Update(false, {At(0, 0, 0.3)}, {}, kBall).empty());
  EXPECT_EQ(CyclesUntilMoved(&sit, At(0, 0, 0.2), 2000), 101) << "25 cycles standing are not enough";
}

TEST(FoulReferee, PausedJudgesNothingAndEndsTheCounts) {
  FoulReferee rule;
  for (int i = 0; i < 5000; ++i) ASSERT_TRUE(rule.Update(true, {At(0, 0, 0.1)}, {}, kBall).empty());
  for (int i = 0; i < 700; ++i) ASSERT_TRUE(rule.Update(false, {At(0, 0, 0.1)}, {}, kBall).empty());
  ASSERT_TRUE(rule.Update(true, {At(0, 0, 0.1)}, {}, kBall).empty());
  EXPECT_EQ(CyclesUntilMoved(&rule, At(0, 0, 0.1), 2000), 751);
}

// A torso that is not finite (a bad sample from another participant) counts nothing and is never moved.
TEST(FoulReferee, NonFiniteTorsoCountsNothing) {
  FoulReferee rule;
  for (int i = 0; i < 700; ++i) ASSERT_TRUE(rule.Update(false, {At(0, 0, 0.1)}, {}, kBall).empty());
  for (int i = 0; i < 2000; ++i) ASSERT_TRUE(rule.Update(false, {At(NAN, 0, 0.1)}, {}, kBall).empty()) << i;
  EXPECT_EQ(CyclesUntilMoved(&rule, At(0, 0, 0.1), 100), 51) << "the count went on from 700";
}

TEST(FoulReferee, SnapshotContinuesTheCountsAndRefusesDamage) {
  FoulReferee rule;
  for (int i = 0; i < 740; ++i) rule.Update(false, {At(0, 0, 0.1)}, {}, kBall);
  const std::string bytes = test::Saved(rule);
  FoulReferee copy;
  ASSERT_EQ(test::RestoreAll(bytes, &copy), "");
  EXPECT_EQ(CyclesUntilMoved(&copy, At(0, 0, 0.1), 100), 11);
  for (size_t n = 0; n < bytes.size(); ++n) {
    FoulReferee fresh;
    EXPECT_NE(test::RestoreAll(bytes.substr(0, n), &fresh), "") << n;
    EXPECT_EQ(CyclesUntilMoved(&fresh, At(0, 0, 0.1), 100), 0) << "a refused snapshot changes nothing";
  }
}

// --- Charging (AnalyseChargingFouls, with the judgement of charging.h) ---

const Eigen::Vector3d kFarBall(8.0, 6.0, 0.042);

// Left 4 running at 0.6 m/s into right 5, who stands 0.3 m ahead; both standing upright.
struct Collision {
  RefereePlayer charger{Side::kLeft, 4, {0.0, 0.0, 0.35}, {0.6, 0.0, 0.0}, false};
  RefereePlayer victim{Side::kRight, 5, {0.3, 0.0, 0.35}, Eigen::Vector3d::Zero(), false};
  PlayerContact contact{Side::kLeft, 4, Side::kRight, 5, {0.15, 0.0, 0.3}};

  std::vector<RefereeMove> Cycle(FoulReferee* referee, bool touching = true, bool paused = false) const {
    return referee->Update(paused, {charger, victim},
                           touching ? std::vector<PlayerContact>{contact} : std::vector<PlayerContact>{}, kFarBall);
  }
  // Cycles with the contact from now on until the referee moves someone: that cycle (counting from 1), or 0.
  int CyclesUntilMoved(FoulReferee* referee, int max) const {
    return simspark::CyclesUntilMoved([&] { return Cycle(referee); }, max);
  }
};

// The speed is the mean of the last three cycles' velocities: after three cycles of running the contact charges.
// The charger is held in the air for 0.5 s, then put outside; the opponent it ran into is not moved.
TEST(FoulReferee, ChargingHoldsThenPutsTheChargerOutside) {
  FoulReferee referee;
  const Collision c;
  for (int i = 0; i < 3; ++i) ASSERT_TRUE(c.Cycle(&referee, false).empty());
  std::vector<RefereeMove> m = c.Cycle(&referee);
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].side, Side::kLeft);
  EXPECT_EQ(m[0].unum, 4);
  EXPECT_EQ(m[0].foul, Foul::kCharging);
  EXPECT_FALSE(m[0].outside);
  EXPECT_NEAR(m[0].position.z(), 1.02, 1e-12);
  int held = 1;
  for (; held < 100; ++held) {
    m = c.Cycle(&referee, false);
    ASSERT_EQ(m.size(), 1u);
    if (m[0].outside) break;
  }
  EXPECT_EQ(held, 25) << "cycles held before the move out";
  EXPECT_EQ(m[0].unum, 4);
  EXPECT_EQ(m[0].foul, Foul::kCharging);
  EXPECT_NEAR(m[0].position.x(), -0.6 * (7 - 4), 1e-12);
  EXPECT_NEAR(m[0].position.y(), -10.5, 1e-12) << "away from the ball (y > 0)";
}

// A contact in the first cycle of running at 0.9 m/s: the mean speed is 0.3 m/s, no charge. A contact in which
// nobody charged makes both wait 0.2 s before a charge counts: from the second cycle on (mean 0.6 m/s) the contact
// charges, and the foul comes at the 12th (the reference's float setting: 0.2f / 0.02 is just above 10 cycles).
TEST(FoulReferee, AContactWithoutChargeRestartsTheWaitForTheNext) {
  FoulReferee referee;
  Collision c;
  c.charger.velocity.x() = 0.9;
  EXPECT_EQ(c.CyclesUntilMoved(&referee, 100), 12);
}

// A player that touched the ball within 1 s charges nobody.
TEST(FoulReferee, TouchingTheBallGivesASecondOfImmunity) {
  FoulReferee referee;
  Collision c;
  c.charger.touching_ball = true;
  for (int i = 0; i < 3; ++i) ASSERT_TRUE(c.Cycle(&referee, false).empty());
  c.charger.touching_ball = false;
  EXPECT_EQ(c.CyclesUntilMoved(&referee, 200), 50) << "50 cycles after the last touch";
}

// The goalie in its own penalty area (also behind its goal line) is not called for charging; elsewhere it is.
TEST(FoulReferee, TheGoalieInItsOwnPenaltyAreaDoesNotCharge) {
  Collision c;
  c.charger.unum = 1;
  c.contact.unum_a = 1;
  c.charger.torso = {-14.0, 1.0, 0.35};
  c.victim.torso = {-13.7, 1.0, 0.35};
  c.contact.point = {-13.85, 1.0, 0.3};
  FoulReferee in_area;
  for (int i = 0; i < 3; ++i) c.Cycle(&in_area, false);
  EXPECT_EQ(c.CyclesUntilMoved(&in_area, 200), 0);
  c.charger.torso = {-13.0, 1.0, 0.35};  // 0.2 m in front of its area
  c.victim.torso = {-12.7, 1.0, 0.35};
  c.contact.point = {-12.85, 1.0, 0.3};
  FoulReferee outside;
  for (int i = 0; i < 3; ++i) c.Cycle(&outside, false);
  EXPECT_EQ(c.CyclesUntilMoved(&outside, 200), 1);
}

// A player not standing since it last stood 0.5 s is not judged for charging, nor is one the referee moved within 1 s.
TEST(FoulReferee, APlayerGettingUpIsNotJudgedForCharging) {
  FoulReferee referee;
  Collision c;
  c.charger.torso.z() = 0.2;
  for (int i = 0; i < 3; ++i) ASSERT_TRUE(c.Cycle(&referee, false).empty());
  c.charger.torso.z() = 0.35;
  EXPECT_EQ(c.CyclesUntilMoved(&referee, 200), 26)
      << "more than 0.5 s standing (26 cycles) ends the not-standing count";
}

TEST(FoulReferee, PausedJudgesNoCharging) {
  FoulReferee referee;
  const Collision c;
  for (int i = 0; i < 200; ++i) ASSERT_TRUE(c.Cycle(&referee, true, true).empty());
  EXPECT_EQ(c.CyclesUntilMoved(&referee, 10), 1) << "the velocities were kept while paused";
}

// A player whose velocity is not finite (a bad sample from elsewhere) is judged for nothing.
TEST(FoulReferee, NonFiniteVelocityIsJudgedForNothing) {
  FoulReferee referee;
  Collision c;
  for (int i = 0; i < 3; ++i) c.Cycle(&referee, false);
  c.charger.velocity.x() = NAN;
  EXPECT_EQ(c.CyclesUntilMoved(&referee, 100), 0);
  c.charger.velocity.x() = 0.6;
  c.contact.point.x() = INFINITY;
  EXPECT_EQ(c.CyclesUntilMoved(&referee, 100), 0);
}

TEST(FoulReferee, SnapshotKeepsTheVelocitiesAndTimes) {
  FoulReferee referee;
  Collision c;
  c.charger.touching_ball = true;
  c.Cycle(&referee, false);
  c.charger.touching_ball = false;
  for (int i = 0; i < 30; ++i) c.Cycle(&referee, false);
  FoulReferee copy;
  ASSERT_EQ(test::RestoreAll(test::Saved(referee), &copy), "");
  EXPECT_EQ(c.CyclesUntilMoved(&copy, 100), 20) << "the time since the ball touch went on";
  EXPECT_EQ(c.CyclesUntilMoved(&referee, 100), 20);
}

// --- Touching (touch_groups.h) ---

// A player lying 14 s joins two touching team mates: it is pushed out of the group (its robot moved, nothing held),
// and its counts start again: the incapable foul comes 15 s after the push, not 1 s.
TEST(FoulReferee, TouchingPushesTheNewcomerAndStartsItsCountsAgain) {
  FoulReferee referee;
  const RefereePlayer two{Side::kLeft, 2, {0.0, 0.0, 0.35}, Eigen::Vector3d::Zero(), false};
  const RefereePlayer three{Side::kLeft, 3, {0.3, 0.0, 0.35}, Eigen::Vector3d::Zero(), false};
  const RefereePlayer four = At(-0.3, 0.0, 0.1);
  const PlayerContact pair{Side::kLeft, 2, Side::kLeft, 3, {0.15, 0, 0.3}};
  const PlayerContact joins{Side::kLeft, 4, Side::kLeft, 2, {-0.15, 0, 0.2}};
  for (int i = 0; i < 700; ++i) ASSERT_TRUE(referee.Update(false, {two, three, four}, {pair}, kBall).empty());
  const std::vector<RefereeMove> m = referee.Update(false, {two, three, four}, {pair, joins}, kBall);
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].unum, 4);
  EXPECT_EQ(m[0].foul, Foul::kTouching);
  EXPECT_EQ(m[0].group_size, 3);
  EXPECT_FALSE(m[0].outside);
  EXPECT_LT(m[0].position.x(), -0.3) << "away from the group";
  EXPECT_NEAR(m[0].position.z(), 0.1, 1e-12) << "its height kept";
  const RefereePlayer pushed = At(m[0].position.x(), m[0].position.y(), 0.1);
  int cycles = 1;
  for (; cycles < 2000; ++cycles)
    if (!referee.Update(false, {two, three, pushed}, {pair}, kBall).empty()) break;
  EXPECT_EQ(cycles, 751) << "the ground count started again at the push";
}

// A pause keeps who was touching whom before it: a player that joins a pair during the pause is the newcomer when
// play resumes.
TEST(FoulReferee, APauseKeepsTheGroupsOfBeforeIt) {
  const RefereePlayer two = At(0.0, 0.0, 0.35, 2);
  const RefereePlayer three = At(0.3, 0.0, 0.35, 3);
  const RefereePlayer four = At(-0.3, 0.0, 0.35, 4);
  const PlayerContact pair{Side::kLeft, 2, Side::kLeft, 3, {0.15, 0, 0.3}};
  const PlayerContact joins{Side::kLeft, 4, Side::kLeft, 2, {-0.15, 0, 0.3}};
  for (uint64_t seed = 0; seed < 10; ++seed) {  // whatever the referee's random orders
    FoulReferee referee({}, seed);
    for (int i = 0; i < 3; ++i) ASSERT_TRUE(referee.Update(false, {two, three, four}, {pair}, kBall).empty());
    for (int i = 0; i < 10; ++i) ASSERT_TRUE(referee.Update(true, {two, three, four}, {pair, joins}, kBall).empty());
    const std::vector<RefereeMove> m = referee.Update(false, {two, three, four}, {pair, joins}, kBall);
    ASSERT_EQ(m.size(), 1u);
    EXPECT_EQ(m[0].unum, 4) << "seed " << seed;
  }
}

// The spot outside is the safe one nearest it (safe_spot.h): a robot already standing there pushes it along.
TEST(FoulReferee, TheSpotOutsideAvoidsARobotStandingOnIt) {
  FoulReferee referee;
  RefereePlayer standing = At(-1.8, -10.5, 0.35, 9, Side::kRight);
  standing.box = Eigen::AlignedBox3d(Eigen::Vector3d(-1.9, -10.6, 0.0), Eigen::Vector3d(-1.7, -10.4, 0.55));
  std::vector<RefereeMove> m;
  EXPECT_EQ(CyclesUntilMoved(
                [&] {
                  return referee.Update(false, {At(3, 1, 0.1), standing}, {}, kBall);
                },
                2000, &m),
            751);
  for (int i = 0; i < 25; ++i) m = referee.Update(false, {At(3, 1, 1.2), standing}, {}, kBall);
  ASSERT_EQ(m.size(), 1u);
  ASSERT_TRUE(m[0].outside);
  EXPECT_GT(standing.box.squaredExteriorDistance(m[0].position), 0.4 * 0.4) << m[0].position.transpose();
  EXPECT_LT((m[0].position - Eigen::Vector3d(-1.8, -10.5, 0.4)).norm(), 1.5) << "near the spot";
}

}  // namespace
}  // namespace turf::simspark

namespace turf::simspark {
namespace {

// Left players standing in their own penalty area (x from -15 to -13.2, |y| <= 1.95) and around it.
RefereePlayer Standing(int unum, double x, double y, Side side = Side::kLeft) {
  return {side, unum, {x, y, 0.35}, Eigen::Vector3d::Zero(), false};
}

// AnalyseFouls' illegal defence (MaxPlayersInsideOwnArea 3, IllegalDefenseBeamPenalty false): a fourth field player
// entering its own penalty area is moved out at once, to the nearer edge's side 0.4 m beyond it, with a note's
// foul; three in it is allowed, and the same player outside is left alone.
TEST(FoulReferee, AFourthPlayerEnteringItsOwnPenaltyAreaIsMovedOut) {
  FoulReferee referee;
  std::vector<RefereePlayer> team{Standing(2, -14.5, -1.0), Standing(3, -14.5, 0.0), Standing(4, -14.5, 1.0),
                                  Standing(5, -12.9, 0.5)};
  for (int i = 0; i < 10; ++i) ASSERT_TRUE(referee.Update(false, team, {}, kBall).empty()) << "three inside";
  team[3] = Standing(5, -13.4, 0.5);  // steps in, 0.2 m behind the front edge
  const std::vector<RefereeMove> m = referee.Update(false, team, {}, kBall);
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].unum, 5);
  EXPECT_EQ(m[0].foul, Foul::kIllegalDefence);
  EXPECT_FALSE(m[0].outside);
  EXPECT_NEAR(m[0].position.x(), -13.2 + 0.4, 1e-9) << "beyond the front edge, the nearer one";
  EXPECT_NEAR(m[0].position.y(), 0.5, 1e-9);
  EXPECT_NEAR(m[0].position.z(), 0.35, 1e-9);
  team[3] = Standing(5, m[0].position.x(), m[0].position.y());
  for (int i = 0; i < 10; ++i) EXPECT_TRUE(referee.Update(false, team, {}, kBall).empty()) << "out again";
}

// The right team's area mirrored, and a player nearer a side edge goes out sideways.
TEST(FoulReferee, IllegalDefenceGoesOutOverTheNearerEdge) {
  FoulReferee referee;
  std::vector<RefereePlayer> team{Standing(2, 14.5, -1.0, Side::kRight), Standing(3, 14.5, 0.0, Side::kRight),
                                  Standing(4, 14.5, 1.0, Side::kRight), Standing(6, 13.6, 2.5, Side::kRight)};
  referee.Update(false, team, {}, kBall);
  team[3] = Standing(6, 13.6, 1.8, Side::kRight);  // 0.15 m inside the side edge
  const std::vector<RefereeMove> m = referee.Update(false, team, {}, kBall);
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].side, Side::kRight);
  EXPECT_NEAR(m[0].position.x(), 13.6, 1e-9);
  EXPECT_NEAR(m[0].position.y(), 1.95 + 0.4, 1e-9);
}

// The goalie is never moved for it; when it enters a box with three team mates in it, the one of them ranked fourth
// from the goal (the farthest) goes out.
TEST(FoulReferee, WhenTheGoalieEntersTheFarthestOfTheOthersGoesOut) {
  FoulReferee referee;
  std::vector<RefereePlayer> team{Standing(1, -12.5, 0.0), Standing(2, -14.6, -0.5), Standing(3, -13.5, 1.5),
                                  Standing(4, -14.2, 0.6)};
  for (int i = 0; i < 5; ++i) ASSERT_TRUE(referee.Update(false, team, {}, kBall).empty());
  team[0] = Standing(1, -14.8, 0.0);
  const std::vector<RefereeMove> m = referee.Update(false, team, {}, kBall);
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].unum, 3) << "farthest from the goal (-15, 0)";
  EXPECT_NEAR(m[0].position.x(), -13.2 + 0.4, 1e-9);
}

// While the game is paused nobody is judged, and the areas are counted afresh after it: four in the box at the
// restart are all newcomers, so field players go out until three are left.
TEST(FoulReferee, AfterAPauseEveryoneInTheAreaHasJustEntered) {
  FoulReferee referee;
  const std::vector<RefereePlayer> team{Standing(2, -14.6, -1.5), Standing(3, -14.6, -0.5), Standing(4, -14.6, 0.5),
                                        Standing(5, -14.6, 1.5)};
  EXPECT_TRUE(referee.Update(true, team, {}, kBall).empty());
  const std::vector<RefereeMove> m = referee.Update(false, team, {}, kBall);
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].foul, Foul::kIllegalDefence);
}

}  // namespace
}  // namespace turf::simspark
