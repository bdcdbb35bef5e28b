// Composition of robot MJCF files into one legged scene.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "core/legged/legged_mjcf.h"
#include "core/legged/legged_world.h"
#include "tests/core/legged/nao_fixture.h"

namespace turf {
namespace {

using testing::NaoScene;

TEST(LeggedMjcfTest, PrefixesEveryInstance) {
  const LeggedMjcf m = ComposeLeggedMjcf(NaoScene(2));
  ASSERT_TRUE(m.errors.empty()) << m.errors.front();
  EXPECT_NE(m.xml.find("name=\"nao_1/rlj4\""), std::string::npos);
  EXPECT_NE(m.xml.find("name=\"nao_2/rlj4\""), std::string::npos);
  EXPECT_NE(m.xml.find("body1=\"nao_2/torso\""), std::string::npos);
  EXPECT_NE(m.xml.find("site=\"nao_1/lf\""), std::string::npos);
}

TEST(LeggedMjcfTest, PlacesRobotsWithYaw) {
  LeggedScene s = NaoScene(1);
  s.robots[0].x = 1.5;
  s.robots[0].y = -2.0;
  s.robots[0].yaw = -M_PI / 2;  // SimSpark's left team: model +y faces field +x
  LeggedWorld w(std::move(s));
  const LeggedRobotState r = w.State().robots[0];
  EXPECT_NEAR(r.base_position[0], 1.5, 1e-9);
  EXPECT_NEAR(r.base_position[1], -2.0, 1e-9);
  EXPECT_NEAR(r.base_orientation[0], std::cos(-M_PI / 4), 1e-9);
  EXPECT_NEAR(r.base_orientation[3], std::sin(-M_PI / 4), 1e-9);
}

TEST(LeggedMjcfTest, ARobotOfAnyMjcfWorks) {
  LeggedScene s;
  LeggedRobot arm;
  arm.name = "arm";
  arm.model = "inline";
  arm.model_xml = R"(<mujoco><compiler angle="radian"/><worldbody>
      <body name="base" pos="0 0 0.5"><joint name="shoulder" axis="0 1 0" range="-1 1"/>
        <geom type="capsule" fromto="0 0 0 0.3 0 0" size="0.03" mass="1"/></body>
    </worldbody></mujoco>)";
  s.robots.push_back(arm);
  LeggedWorld w(std::move(s));
  ASSERT_EQ(w.JointIndex(0, "shoulder"), 0);
  ASSERT_EQ(w.SetJointCommand(0, {"shoulder", JointMode::kPosition, 0.5, 100.0, 5.0}), JointCommandError::kOk);
  for (int i = 0; i < 1000; ++i) w.Step();
  EXPECT_NEAR(w.State().robots[0].joint_positions[0], 0.5, 0.05);
  EXPECT_FALSE(w.State().robots[0].has_imu);
}

TEST(LeggedMjcfTest, RefusesBadRobotFiles) {
  LeggedScene s = NaoScene(1);
  s.robots[0].model_xml = "<mujoco><worldbody/></mujoco>";
  EXPECT_FALSE(ComposeLeggedMjcf(s).errors.empty());  // no angle="radian"
  s.robots[0].model_xml = "not xml <";
  EXPECT_FALSE(ComposeLeggedMjcf(s).errors.empty());
  EXPECT_THROW(LeggedWorld{s}, std::invalid_argument);
  s.robots.push_back(s.robots[0]);
  EXPECT_FALSE(ValidateLeggedScene(s).empty());  // duplicate name
}

}  // namespace
}  // namespace turf
