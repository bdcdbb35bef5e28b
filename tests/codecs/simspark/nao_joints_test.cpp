#include "codecs/simspark/nao_joints.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace turf::simspark {
namespace {

// The sheet's joint table written out (perceptor, effector), in turf's documented order.
const std::vector<std::pair<std::string, std::string>> kSheet = {
    {"hj1", "he1"},   {"hj2", "he2"},   {"raj1", "rae1"}, {"raj2", "rae2"}, {"raj3", "rae3"}, {"raj4", "rae4"},
    {"laj1", "lae1"}, {"laj2", "lae2"}, {"laj3", "lae3"}, {"laj4", "lae4"}, {"rlj1", "rle1"}, {"rlj2", "rle2"},
    {"rlj3", "rle3"}, {"rlj4", "rle4"}, {"rlj5", "rle5"}, {"rlj6", "rle6"}, {"llj1", "lle1"}, {"llj2", "lle2"},
    {"llj3", "lle3"}, {"llj4", "lle4"}, {"llj5", "lle5"}, {"llj6", "lle6"}};

TEST(NaoJoints, TypesZeroToThreeHaveTheTwentyTwoJointsInOrder) {
  for (int type = 0; type < 4; ++type) {
    const auto& joints = NaoJoints(type);
    ASSERT_EQ(joints.size(), 22u) << type;
    for (size_t i = 0; i < kSheet.size(); ++i) {
      EXPECT_EQ(joints[i].perceptor, kSheet[i].first) << type << " " << i;
      EXPECT_EQ(joints[i].effector, kSheet[i].second) << type << " " << i;
    }
  }
}

TEST(NaoJoints, TypeFourAddsTheToesToEachLeg) {
  const auto& joints = NaoJoints(4);
  ASSERT_EQ(joints.size(), 24u);
  std::vector<std::string> perceptors;
  for (const NaoJoint& j : joints) perceptors.push_back(j.perceptor);
  EXPECT_EQ(perceptors[16], "rlj7");
  EXPECT_EQ(std::string(joints[16].effector), "rle7");
  EXPECT_EQ(perceptors[23], "llj7");
  EXPECT_EQ(std::string(joints[23].effector), "lle7");
  std::set<std::string> unique(perceptors.begin(), perceptors.end());
  EXPECT_EQ(unique.size(), 24u);
  for (const auto& [perceptor, effector] : kSheet) EXPECT_EQ(unique.count(perceptor), 1u) << perceptor;
}

TEST(NaoJoints, UnknownTypeHasNoJoints) {
  EXPECT_TRUE(NaoJoints(-1).empty());
  EXPECT_TRUE(NaoJoints(kNaoTypes).empty());
}

TEST(NaoJoints, EffectorMapsToItsJointPerType) {
  EXPECT_EQ(JointForEffector("he1", 0), "hj1");
  EXPECT_EQ(JointForEffector("rle4", 2), "rlj4");
  EXPECT_EQ(JointForEffector("lae3", 3), "laj3");
  EXPECT_EQ(JointForEffector("lle7", 4), "llj7");
  EXPECT_EQ(JointForEffector("lle7", 0), std::nullopt);  // no toes
  EXPECT_EQ(JointForEffector("rle7", 3), std::nullopt);
  EXPECT_EQ(JointForEffector("hj1", 0), std::nullopt);  // a perceptor name is not an effector
  EXPECT_EQ(JointForEffector("he1", 5), std::nullopt);
  EXPECT_EQ(JointForEffector("", 0), std::nullopt);
}

TEST(NaoJoints, HingeEffectorOfAnyType) {
  EXPECT_TRUE(IsNaoHingeEffector("he2"));
  EXPECT_TRUE(IsNaoHingeEffector("rle7"));
  EXPECT_FALSE(IsNaoHingeEffector("he3"));
  EXPECT_FALSE(IsNaoHingeEffector("rle8"));
  EXPECT_FALSE(IsNaoHingeEffector("beam"));
}

TEST(NaoJoints, MaxSpeeds) {
  EXPECT_DOUBLE_EQ(NaoMaxSpeed(0, "hj1"), 6.1395);
  EXPECT_DOUBLE_EQ(NaoMaxSpeed(0, "llj5"), 6.1395);
  EXPECT_DOUBLE_EQ(NaoMaxSpeed(1, "rlj6"), 6.1395);
  EXPECT_DOUBLE_EQ(NaoMaxSpeed(2, "llj5"), 8.80667);
  EXPECT_DOUBLE_EQ(NaoMaxSpeed(2, "rlj5"), 8.80667);
  EXPECT_DOUBLE_EQ(NaoMaxSpeed(2, "llj6"), 3.47234);
  EXPECT_DOUBLE_EQ(NaoMaxSpeed(2, "rlj6"), 3.47234);
  EXPECT_DOUBLE_EQ(NaoMaxSpeed(2, "llj4"), 6.1395);
  EXPECT_DOUBLE_EQ(NaoMaxSpeed(2, "hj2"), 6.1395);
  EXPECT_DOUBLE_EQ(NaoMaxSpeed(4, "rlj7"), 6.1395);
  EXPECT_DOUBLE_EQ(NaoMaxSpeed(3, "rlj7"), 0.0);  // no such joint
  EXPECT_DOUBLE_EQ(NaoMaxSpeed(0, "he1"), 0.0);
  EXPECT_DOUBLE_EQ(NaoMaxSpeed(7, "hj1"), 0.0);
}

}  // namespace
}  // namespace turf::simspark
