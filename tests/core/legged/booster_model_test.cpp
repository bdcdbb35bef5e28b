// The Booster T1 and K1 robot files (configs/robots/t1.xml, k1.xml) against
// the facts (shared/protocols/booster-robots.md): joints in the SDK's index
// order with their ranges, effort limits and armatures; total masses; sensors.
#include <gtest/gtest.h>

#include <string>

#include "core/legged/legged_world.h"
#include "tests/core/legged/booster_fixture.h"

namespace turf {
namespace {

using testing::BoosterStandScene;

struct JointFact {
  const char* name;
  double lo;
  double hi;
  double effort;    // N m (the reference's actuatorfrcrange)
  double armature;  // kg m^2
};

// T1: shared/protocols/booster-robots.md, "T1 body tree and joints".
constexpr JointFact kT1Joints[] = {
    {"AAHead_yaw", -1.57, 1.57, 7, 0.01},
    {"Head_pitch", -0.35, 1.22, 7, 0.01},
    {"Left_Shoulder_Pitch", -3.31, 1.22, 18, 0.01},
    {"Left_Shoulder_Roll", -1.74, 1.57, 18, 0.01},
    {"Left_Elbow_Pitch", -2.27, 2.27, 18, 0.01},
    {"Left_Elbow_Yaw", -2.44, 0, 18, 0.01},
    {"Right_Shoulder_Pitch", -3.31, 1.22, 18, 0.01},
    {"Right_Shoulder_Roll", -1.57, 1.74, 18, 0.01},
    {"Right_Elbow_Pitch", -2.27, 2.27, 18, 0.01},
    {"Right_Elbow_Yaw", 0, 2.44, 18, 0.01},
    {"Waist", -1.57, 1.57, 30, 0.01},
    {"Left_Hip_Pitch", -1.8, 1.57, 45, 0.01},
    {"Left_Hip_Roll", -0.2, 1.57, 30, 0.01},
    {"Left_Hip_Yaw", -1, 1, 30, 0.01},
    {"Left_Knee_Pitch", 0, 2.34, 60, 0.01},
    {"Left_Ankle_Pitch", -0.87, 0.35, 20, 0.01},
    {"Left_Ankle_Roll", -0.44, 0.44, 15, 0.01},
    {"Right_Hip_Pitch", -1.8, 1.57, 45, 0.01},
    {"Right_Hip_Roll", -1.57, 0.2, 30, 0.01},
    {"Right_Hip_Yaw", -1, 1, 30, 0.01},
    {"Right_Knee_Pitch", 0, 2.34, 60, 0.01},
    {"Right_Ankle_Pitch", -0.87, 0.35, 20, 0.01},
    {"Right_Ankle_Roll", -0.44, 0.44, 15, 0.01},
};
// K1: shared/protocols/booster-robots.md, "K1 body tree and joints".
constexpr JointFact kK1Joints[] = {
    {"AAHead_yaw", -1, 1, 6, 0.002},
    {"Head_pitch", -0.349, 0.855, 6, 0.002},
    {"ALeft_Shoulder_Pitch", -3.316, 1.22, 14, 0.001},
    {"Left_Shoulder_Roll", -1.74, 1.57, 14, 0.001},
    {"Left_Elbow_Pitch", -2.27, 2.27, 14, 0.001},
    {"Left_Elbow_Yaw", -2.44, 0, 14, 0.001},
    {"ARight_Shoulder_Pitch", -3.316, 1.22, 14, 0.001},
    {"Right_Shoulder_Roll", -1.57, 1.74, 14, 0.001},
    {"Right_Elbow_Pitch", -2.27, 2.27, 14, 0.001},
    {"Right_Elbow_Yaw", 0, 2.44, 14, 0.001},
    {"Left_Hip_Pitch", -3, 2.21, 30, 0.0478125},
    {"Left_Hip_Roll", -0.4, 1.57, 35, 0.0339552},
    {"Left_Hip_Yaw", -1, 1, 20, 0.0282528},
    {"Left_Knee_Pitch", 0, 2.23, 40, 0.095625},
    {"Left_Ankle_Pitch", -0.87, 0.345, 20, 0.0565},
    {"Left_Ankle_Roll", -0.345, 0.345, 20, 0.0565},
    {"Right_Hip_Pitch", -3, 2.21, 30, 0.0478125},
    {"Right_Hip_Roll", -1.57, 0.4, 35, 0.0339552},
    {"Right_Hip_Yaw", -1, 1, 20, 0.0282528},
    {"Right_Knee_Pitch", 0, 2.23, 40, 0.095625},
    {"Right_Ankle_Pitch", -0.87, 0.345, 20, 0.0565},
    {"Right_Ankle_Roll", -0.345, 0.345, 20, 0.0565},
};

template <size_t N>
void ExpectJoints(const std::string& robot, const JointFact (&facts)[N]) {
  LeggedWorld w(BoosterStandScene(robot));
  const LeggedRobotState s = w.State().robots[0];
  ASSERT_EQ(s.joint_names.size(), N) << robot;
  for (size_t i = 0; i < N; ++i) {
    EXPECT_EQ(s.joint_names[i], facts[i].name) << robot << " index " << i;
    const LeggedJointInfo info = w.JointInfo(0, static_cast<int>(i));
    EXPECT_TRUE(info.limited) << facts[i].name;
    EXPECT_DOUBLE_EQ(info.lo, facts[i].lo) << facts[i].name;
    EXPECT_DOUBLE_EQ(info.hi, facts[i].hi) << facts[i].name;
    EXPECT_DOUBLE_EQ(info.effort_limit, facts[i].effort) << facts[i].name;
    EXPECT_DOUBLE_EQ(info.armature, facts[i].armature) << facts[i].name;
  }
}

TEST(BoosterModelTest, T1JointsAreTheFactsInSdkOrder) { ExpectJoints("t1", kT1Joints); }
TEST(BoosterModelTest, K1JointsAreTheFactsInSdkOrder) { ExpectJoints("k1", kK1Joints); }

TEST(BoosterModelTest, T1PassiveJointFrictionIsTheReferences) {
  LeggedWorld w(BoosterStandScene("t1"));
  for (int j = 0; j < 23; ++j) EXPECT_DOUBLE_EQ(w.JointInfo(0, j).frictionloss, 0.1) << j;
}

// Total masses within 1 % of the facts (T1 31.614 kg, K1 19.666 kg).
TEST(BoosterModelTest, TotalMassesAreTheFacts) {
  LeggedWorld t1(BoosterStandScene("t1"));
  LeggedWorld k1(BoosterStandScene("k1"));
  std::printf("mass: T1 %.4f kg, K1 %.4f kg\n", t1.RobotMass(0), k1.RobotMass(0));
  EXPECT_NEAR(t1.RobotMass(0), 31.614, 0.01 * 31.614);
  EXPECT_NEAR(k1.RobotMass(0), 19.666, 0.01 * 19.666);
}

// IMU (gyro, accelerometer, orientation) in the torso, touch on both soles,
// the head camera declared, and the start pose from the scene.
TEST(BoosterModelTest, SensorsCameraAndStartPose) {
  for (const char* robot : {"t1", "k1"}) {
    LeggedWorld w(BoosterStandScene(robot));
    const LeggedRobotState s = w.State().robots[0];
    EXPECT_TRUE(s.has_imu) << robot;
    ASSERT_EQ(s.forces.size(), 2u) << robot;
    EXPECT_EQ(s.forces[0].name, "lf");
    EXPECT_EQ(s.forces[1].name, "rf");
    EXPECT_NE(w.mjcf().find("<camera name=\"" + std::string(robot) + "/camera\""), std::string::npos) << robot;
    EXPECT_NEAR(s.joint_positions[w.JointIndex(0, "Left_Knee_Pitch")], 0.4, 1e-12) << robot;
    EXPECT_NEAR(s.joint_positions[w.JointIndex(0, "Right_Ankle_Pitch")], -0.2, 1e-12) << robot;
  }
}

}  // namespace
}  // namespace turf
