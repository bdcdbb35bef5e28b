// codecs/booster: the SDK's joint tables, rt/low_state from a robot's state.
#include <gtest/gtest.h>

#include <cmath>

#include "codecs/booster/low_cmd.h"
#include "codecs/booster/low_state.h"
#include "codecs/booster/robots.h"

namespace turf::booster {
namespace {

namespace bi = booster_interface::msg::dds_;

TEST(BoosterRobots, TablesHaveTheSdksJointCountsAndIdentifyOnlyExactLists) {
  EXPECT_EQ(SdkJoints(BoosterModel::kT1).size(), 23u);
  EXPECT_EQ(SdkJoints(BoosterModel::kK1).size(), 22u);
  EXPECT_EQ(SdkJoints(BoosterModel::kT1)[10], "Waist");             // kWaist, T1 only
  EXPECT_EQ(SdkJoints(BoosterModel::kT1)[15], "Left_Ankle_Pitch");  // kCrankUpLeft in SERIAL space
  EXPECT_EQ(SdkJoints(BoosterModel::kK1)[14], "Left_Ankle_Pitch");  // K1: one index lower (no waist)
  EXPECT_EQ(SdkJoints(BoosterModel::kK1)[21], "Right_Ankle_Roll");
  EXPECT_EQ(IdentifyRobot(SdkJoints(BoosterModel::kT1)), BoosterModel::kT1);
  EXPECT_EQ(IdentifyRobot(SdkJoints(BoosterModel::kK1)), BoosterModel::kK1);
  std::vector<std::string> swapped = SdkJoints(BoosterModel::kT1);
  std::swap(swapped[0], swapped[1]);
  EXPECT_FALSE(IdentifyRobot(swapped));
  EXPECT_FALSE(IdentifyRobot({"hj1", "hj2"}));
}

TEST(BoosterLowState, RollPitchYawOfKnownRotations) {
  const double h = std::sqrt(0.5);
  const auto yaw = RollPitchYaw({h, 0, 0, h});  // 90 deg about z
  EXPECT_NEAR(yaw[0], 0.0, 1e-6);
  EXPECT_NEAR(yaw[1], 0.0, 1e-6);
  EXPECT_NEAR(yaw[2], M_PI / 2, 1e-6);
  const double a = 0.3;  // pitch 0.3 rad about y
  const auto pitch = RollPitchYaw({std::cos(a / 2), 0, std::sin(a / 2), 0});
  EXPECT_NEAR(pitch[1], a, 1e-6);
  const auto roll = RollPitchYaw({std::cos(-a / 2), std::sin(-a / 2), 0, 0});
  EXPECT_NEAR(roll[0], -a, 1e-6);
  EXPECT_NEAR(roll[2], 0.0, 1e-6);
}

TEST(BoosterLowState, CarriesTheImuAndEveryJointInBothLists) {
  LeggedRobotState r;
  r.joint_names = SdkJoints(BoosterModel::kK1);
  for (size_t j = 0; j < r.joint_names.size(); ++j) {
    r.joint_positions.push_back(0.01 * j);
    r.joint_velocities.push_back(-0.1 * j);
    r.joint_efforts.push_back(0.5 * j);
  }
  r.gyro = {0.1, 0.2, 0.3};
  r.accelerometer = {0.0, 0.5, 9.8};
  r.orientation = {1, 0, 0, 0};
  bi::LowState_ s;
  EncodeLowState(r, &s);
  ASSERT_EQ(s.motor_state_serial().size(), 22u);
  ASSERT_EQ(s.motor_state_parallel().size(), 22u);
  EXPECT_FLOAT_EQ(s.motor_state_serial()[21].q(), 0.21f);
  EXPECT_FLOAT_EQ(s.motor_state_serial()[21].dq(), -2.1f);
  EXPECT_FLOAT_EQ(s.motor_state_serial()[21].tau_est(), 10.5f);
  EXPECT_EQ(s.motor_state_serial()[3].temperature(), kSimulatedTemperature);
  EXPECT_EQ(s.motor_state_parallel(), s.motor_state_serial());
  EXPECT_FLOAT_EQ(s.imu_state().gyro()[2], 0.3f);
  EXPECT_FLOAT_EQ(s.imu_state().acc()[2], 9.8f);
  EXPECT_FLOAT_EQ(s.imu_state().rpy()[0], 0.0f);
}

// The SDK's low_level_publisher: all joints limp except head pitch (index 1) to 0.785 rad, kp 4, kd 1, weight 1.
bi::LowCmd_ PublisherExample(size_t joints) {
  bi::LowCmd_ cmd;
  cmd.cmd_type(bi::PARALLEL);
  cmd.motor_cmd().resize(joints);
  if (joints < 2) return cmd;
  cmd.motor_cmd()[1].q(0.785f);
  cmd.motor_cmd()[1].kp(4.f);
  cmd.motor_cmd()[1].kd(1.f);
  cmd.motor_cmd()[1].weight(1.f);
  return cmd;
}

TEST(BoosterLowCmd, EveryEntryBecomesAPdCommandForTheJointOfItsIndex) {
  const LowCmdDecode d = DecodeLowCmd(PublisherExample(23), BoosterModel::kT1);
  ASSERT_EQ(d.error, Error::kOk) << d.detail;
  EXPECT_TRUE(d.parallel);  // taken as SERIAL, flagged
  ASSERT_EQ(d.commands.size(), 23u);
  const JointCommand& head = d.commands[1];
  EXPECT_EQ(head.joint, "Head_pitch");
  EXPECT_EQ(head.mode, JointMode::kPd);
  EXPECT_FLOAT_EQ(head.value, 0.785f);
  EXPECT_EQ(head.kp, 4.0);
  EXPECT_EQ(head.kd, 1.0);
  EXPECT_EQ(d.commands[0].kp, 0.0);  // limp
  EXPECT_EQ(d.commands[22].joint, "Right_Ankle_Roll");
  bi::LowCmd_ serial = PublisherExample(22);
  serial.cmd_type(bi::SERIAL);
  serial.motor_cmd()[5].dq(-0.5f);
  serial.motor_cmd()[5].tau(1.5f);
  const LowCmdDecode k1 = DecodeLowCmd(serial, BoosterModel::kK1);
  ASSERT_EQ(k1.error, Error::kOk) << k1.detail;
  EXPECT_FALSE(k1.parallel);
  EXPECT_EQ(k1.commands[5].joint, "Left_Elbow_Yaw");
  EXPECT_EQ(k1.commands[5].dq, -0.5);
  EXPECT_EQ(k1.commands[5].tau, 1.5);
}

TEST(BoosterLowCmd, RefusesWhatTheMessageItselfGetsWrong) {
  EXPECT_EQ(DecodeLowCmd(PublisherExample(22), BoosterModel::kT1).error, Error::kMalformed);  // K1-sized on a T1
  EXPECT_EQ(DecodeLowCmd(PublisherExample(0), BoosterModel::kK1).error, Error::kMalformed);
  bi::LowCmd_ nan = PublisherExample(23);
  nan.motor_cmd()[7].kd(std::nanf(""));
  const LowCmdDecode d = DecodeLowCmd(nan, BoosterModel::kT1);
  EXPECT_EQ(d.error, Error::kNotFinite);
  EXPECT_EQ(d.detail, "motor_cmd[7].kd");
  EXPECT_TRUE(d.commands.empty());
  bi::LowCmd_ inf = PublisherExample(23);
  inf.motor_cmd()[0].q(INFINITY);
  EXPECT_EQ(DecodeLowCmd(inf, BoosterModel::kT1).error, Error::kNotFinite);
  bi::LowCmd_ weight = PublisherExample(23);
  weight.motor_cmd()[2].weight(1.5f);
  EXPECT_EQ(DecodeLowCmd(weight, BoosterModel::kT1).error, Error::kOutOfRange);
  bi::LowCmd_ type = PublisherExample(23);
  type.cmd_type(static_cast<bi::CmdType>(7));
  EXPECT_EQ(DecodeLowCmd(type, BoosterModel::kT1).error, Error::kUnknownEnum);
}

}  // namespace
}  // namespace turf::booster
