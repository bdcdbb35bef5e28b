// rcssserver3d's self-collision rule (kernel/simspark/self_collision.h) against the reference's code as the facts
// describe it (shared/protocols/simspark.md, "Self-collision rule"): the box test with its tolerance, which pairs
// are tested, which joints freeze, for how long, and when the game counts as paused.
#include "kernel/simspark/self_collision.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "tests/support/state_round_trip.h"

namespace turf::simspark {
namespace {

Eigen::Matrix3d Turn(double deg, const Eigen::Vector3d& axis) {
  return Eigen::AngleAxisd(deg * M_PI / 180, axis.normalized()).toRotationMatrix();
}

PlacedBox Box(const Eigen::Vector3d& centre, const Eigen::Matrix3d& axes, const Eigen::Vector3d& half) {
  return {centre, axes, half};
}

const Eigen::Vector3d kCube(0.05, 0.05, 0.05);

TEST(BoxesOverlap, ApartBoxesNeverOverlap) {
  const PlacedBox a = Box({0, 0, 0}, Turn(30, {1, 2, 3}), kCube);
  const PlacedBox b = Box({0.5, 0, 0}, Turn(70, {3, -1, 2}), kCube);
  EXPECT_LT(OverlapDepth(a, b), 0.0);
  EXPECT_FALSE(BoxesOverlap(a, b, 0.0));
}

// Two cubes at one centre, turned against each other about a skew axis: deep overlap, found at the 0.04 tolerance.
TEST(BoxesOverlap, CubesInsideEachOtherAtSkewAnglesOverlap) {
  const PlacedBox a = Box({0, 0, 0}, Turn(40, {1, 2, 3}), kCube);
  const PlacedBox b = Box({0.01, 0, 0}, Turn(50, {-2, 1, 1}) * Turn(40, {1, 2, 3}), kCube);
  EXPECT_GT(OverlapDepth(a, b), kSelfCollisionTolerance);
  EXPECT_TRUE(BoxesOverlap(a, b, kSelfCollisionTolerance));
}

// The reference's edge-edge axes are not normalised: for nearly parallel edges |a x b| is small, so the radii
// shrink with it while the tolerance does not. Two cubes at one centre, turned 5 degrees apart, are "apart" at the
// 0.04 tolerance (with the axes normalised they would overlap by nearly a whole cube).
TEST(BoxesOverlap, NearlyParallelEdgesSeparateAsInTheReference) {
  const PlacedBox a = Box({0, 0, 0}, Eigen::Matrix3d::Identity(), kCube);
  const PlacedBox b = Box({0, 0, 0}, Turn(5, {1, 2, 3}), kCube);
  EXPECT_FALSE(BoxesOverlap(a, b, kSelfCollisionTolerance));
  EXPECT_GT(OverlapDepth(a, b), 0.0) << "they do overlap at tolerance 0";
  // Exactly parallel: the edge-edge axis z x z is 0, and 0 + tolerance > 0 separates at any positive tolerance.
  EXPECT_FALSE(BoxesOverlap(a, a, 1e-9));
}

// BoxesOverlap is OverlapDepth >= tolerance, and neither depends on the order of the boxes.
TEST(BoxesOverlap, DepthIsTheLargestToleranceAndSymmetric) {
  for (int i = 0; i < 50; ++i) {
    const PlacedBox a = Box({0.001 * i, -0.002 * i, 0.0005 * i}, Turn(7.0 * i, {1, i % 3, 2}), {0.025, 0.055, 0.025});
    const PlacedBox b = Box({0, 0.01, 0}, Turn(11.0 * i, {i % 4, 1, -1}), {0.035, 0.035, 0.07});
    const double depth = OverlapDepth(a, b);
    EXPECT_NEAR(OverlapDepth(b, a), depth, 1e-12);
    EXPECT_TRUE(BoxesOverlap(a, b, depth - 1e-9));
    EXPECT_FALSE(BoxesOverlap(a, b, depth + 1e-9));
  }
}

TEST(NaoBoxes, TheReferencesCollidersPerType) {
  for (int type = 0; type < 4; ++type) {
    const std::vector<NaoBox>& boxes = NaoBoxes(type);
    ASSERT_EQ(boxes.size(), 11u) << "torso, 2 x (upper arm, lower arm, thigh, shank, foot)";
    EXPECT_EQ(boxes[0].link, "torso");
    EXPECT_TRUE(boxes[0].freeze.empty()) << "the torso freezes nothing";
  }
  ASSERT_EQ(NaoBoxes(4).size(), 13u) << "type 4 adds a toe per leg";
  EXPECT_TRUE(NaoBoxes(5).empty());
  EXPECT_TRUE(NaoBoxes(-1).empty());
  for (const NaoBox& b : NaoBoxes(4)) {
    if (b.link == "rtoe") {
      EXPECT_EQ(b.freeze, (std::vector<std::string>{"rlj1", "rlj2", "rlj3", "rlj4", "rlj5", "rlj6", "rlj7"}));
    }
    if (b.link == "llowerarm") EXPECT_EQ(b.freeze, (std::vector<std::string>{"laj1", "laj2", "laj3", "laj4"}));
  }
  EXPECT_TRUE(NeverTested("rthigh", "torso"));
  EXPECT_TRUE(NeverTested("lshank", "lthigh"));
  EXPECT_FALSE(NeverTested("rlowerarm", "rthigh"));
  EXPECT_FALSE(NeverTested("rthigh", "lshank"));
}

// A type-1 player whose right lower arm sits inside its right thigh (turned against each other), every other box
// far away.
PlayerLinks ArmInThigh(bool inside) {
  PlayerLinks p{Side::kLeft, 2, 1, {}};
  double x = 0.0;
  for (const NaoBox& b : NaoBoxes(1)) {
    p.links.push_back({b.link, Eigen::Vector3d(x, 0, 0), Eigen::Quaterniond::Identity()});
    x += 1.0;
  }
  for (PlayerLinks::Link& l : p.links) {
    if (l.name == "rthigh") l.orientation = Eigen::Quaterniond(Turn(35, {1, 1, 0}));
    if (l.name == "rlowerarm" && inside) {
      const auto thigh = std::find_if(p.links.begin(), p.links.end(), [](const auto& t) { return t.name == "rthigh"; });
      l.position = thigh->position;
      l.orientation = Eigen::Quaterniond(Turn(60, {0, 1, 1}));
    }
  }
  return p;
}

const std::vector<std::string> kRightArmAndLeg = {"raj1", "raj2", "raj3", "raj4", "rlj1",
                                                  "rlj2", "rlj3", "rlj4", "rlj5", "rlj6"};

TEST(SelfCollisionRule, ArmInsideTheThighFreezesThatArmAndLeg) {
  SelfCollisionRule rule;
  EXPECT_TRUE(rule.Update(false, 10.0, {ArmInThigh(false)}).empty()) << "arm out of the thigh";
  const std::vector<SelfCollision> now = rule.Update(false, 10.02, {ArmInThigh(true)});
  ASSERT_EQ(now.size(), 1u);
  EXPECT_EQ(now[0].link1, "rlowerarm");
  EXPECT_EQ(now[0].link2, "rthigh");
  EXPECT_GE(now[0].depth, kSelfCollisionTolerance);
  EXPECT_EQ(now[0].frozen, kRightArmAndLeg);
  for (const std::string& j : kRightArmAndLeg) EXPECT_TRUE(rule.Frozen(Side::kLeft, 2, j)) << j;
  for (const char* j : {"laj1", "llj1", "hj1"}) EXPECT_FALSE(rule.Frozen(Side::kLeft, 2, j)) << j;
  EXPECT_FALSE(rule.Frozen(Side::kRight, 2, "raj1")) << "another player";
}

// Frozen for 1 s of game time, then free; no new freeze until 3 s after the first, however long the overlap lasts.
TEST(SelfCollisionRule, OneSecondFrozenThenTwoSecondsImmune) {
  SelfCollisionRule rule;
  const double frozen_at = 5.0;
  ASSERT_EQ(rule.Update(false, frozen_at, {ArmInThigh(true)}).size(), 1u);
  int cycles_frozen = 0;
  double refrozen_at = -1.0;
  for (int i = 1; i < 200 && refrozen_at < 0; ++i) {
    const double t = frozen_at + 0.02 * i;
    if (!rule.Update(false, t, {ArmInThigh(true)}).empty()) {
      refrozen_at = t;
    } else if (rule.Frozen(Side::kLeft, 2, "raj3")) {
      ++cycles_frozen;
    }
  }
  EXPECT_EQ(cycles_frozen + 1, 50) << "1 s at 50 cycles a second, the freezing cycle included";
  EXPECT_NEAR(refrozen_at - frozen_at, 3.02, 1e-6) << "free to freeze again only after more than 3 s";
}

// While the game is paused (Game::paused(), tested in game_test.cpp) nothing is judged and every freeze ends.
TEST(SelfCollisionRule, PausedJudgesNothingAndEndsEveryFreeze) {
  SelfCollisionRule rule;
  EXPECT_TRUE(rule.Update(true, 1.0, {ArmInThigh(true)}).empty());
  ASSERT_EQ(rule.Update(false, 1.02, {ArmInThigh(true)}).size(), 1u);
  EXPECT_TRUE(rule.Frozen(Side::kLeft, 2, "raj1"));
  EXPECT_TRUE(rule.Update(true, 1.04, {ArmInThigh(true)}).empty());
  EXPECT_FALSE(rule.Frozen(Side::kLeft, 2, "raj1"));
  EXPECT_EQ(rule.Update(false, 1.06, {ArmInThigh(true)}).size(), 1u) << "and may freeze again at once";
}

TEST(SelfCollisionRule, PairsTheReferenceNeverTestsFreezeNothing) {
  SelfCollisionRule rule;
  PlayerLinks p = ArmInThigh(false);
  const auto thigh = std::find_if(p.links.begin(), p.links.end(), [](const auto& l) { return l.name == "rthigh"; });
  ASSERT_NE(thigh, p.links.end());
  p.links[0].position = thigh->position;  // the torso inside the thigh
  p.links[0].orientation = Eigen::Quaterniond(Turn(241, {0, 1, 1}));
  ASSERT_EQ(p.links[0].name, "torso");
  const PlacedBox torso = Box(p.links[0].position, p.links[0].orientation.toRotationMatrix(), NaoBoxes(1)[0].half);
  const PlacedBox in = Box(thigh->position, thigh->orientation.toRotationMatrix(), {0.035, 0.035, 0.07});
  ASSERT_GE(OverlapDepth(torso, in), kSelfCollisionTolerance) << "deep enough to count if the pair were tested";
  EXPECT_TRUE(rule.Update(false, 0.02, {p}).empty());
}

// A link pose that is not finite (a bad sample from another participant) is no box.
TEST(SelfCollisionRule, NonFinitePosesFreezeNothing) {
  SelfCollisionRule rule;
  for (double bad : {double(NAN), double(INFINITY)}) {
    PlayerLinks p = ArmInThigh(true);
    for (PlayerLinks::Link& l : p.links)
      if (l.name == "rlowerarm") l.position.x() = bad;
    EXPECT_TRUE(rule.Update(false, 1.0, {p}).empty());
    p = ArmInThigh(true);
    for (PlayerLinks::Link& l : p.links)
      if (l.name == "rthigh") l.orientation.coeffs() << bad, 0, 0, 1;
    EXPECT_TRUE(rule.Update(false, 1.0, {p}).empty());
  }
  EXPECT_FALSE(rule.Frozen(Side::kLeft, 2, "raj1"));
}

TEST(SelfCollisionRule, SnapshotRestoresFreezesAndRefusesDamage) {
  SelfCollisionRule rule;
  ASSERT_EQ(rule.Update(false, 2.0, {ArmInThigh(true)}).size(), 1u);
  const std::string bytes = test::Saved(rule);
  SelfCollisionRule copy;
  ASSERT_EQ(test::RestoreAll(bytes, &copy), "");
  for (const std::string& j : kRightArmAndLeg) EXPECT_TRUE(copy.Frozen(Side::kLeft, 2, j));
  // The same future: thawed at the same cycle.
  for (double t = 2.02; t < 3.1; t += 0.02) {
    rule.Update(false, t, {});
    copy.Update(false, t, {});
    ASSERT_EQ(rule.Frozen(Side::kLeft, 2, "raj1"), copy.Frozen(Side::kLeft, 2, "raj1")) << t;
  }
  // Truncated: refused, the rule as it was.
  for (size_t n = 0; n < bytes.size(); ++n) {
    SelfCollisionRule fresh;
    EXPECT_NE(test::RestoreAll(bytes.substr(0, n), &fresh), "") << n;
    EXPECT_FALSE(fresh.Frozen(Side::kLeft, 2, "raj1")) << n;
  }
}

}  // namespace
}  // namespace turf::simspark
