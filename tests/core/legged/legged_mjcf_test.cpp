// Composition of robot MJCF files into one legged scene.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <tuple>

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
  // Position-mode gains are bounded as PD's (kp 1e308 made the motor's row infinite: the joint missed its target).
  EXPECT_EQ(w.SetJointCommand(0, {"shoulder", JointMode::kPosition, 0.1, 1e308, 1.79e308}),
            JointCommandError::kOutOfRange);
  EXPECT_EQ(w.SetJointCommand(0, {"shoulder", JointMode::kPosition, 0.1, kMaxPdKp * 1.01, 5.0}),
            JointCommandError::kOutOfRange);
  EXPECT_EQ(w.SetJointCommand(0, {"shoulder", JointMode::kPosition, 0.1, 100.0, kMaxPdKd * 1.01}),
            JointCommandError::kOutOfRange);
  EXPECT_EQ(w.SetJointCommand(0, {"shoulder", JointMode::kPosition, 0.1, kMaxPdKp, kMaxPdKd}), JointCommandError::kOk);
  EXPECT_EQ(w.SetJointCommand(0, {"shoulder", JointMode::kPosition, 0.1, -1.0, -1.0}), JointCommandError::kOk);
  for (int i = 0; i < 1000; ++i) w.Step();
  EXPECT_NEAR(w.State().robots[0].joint_positions[0], 0.1, 0.05) << "the robot's default gains";
  LeggedScene huge = NaoScene(1);
  huge.robots[0].motors.position_kp = 1e300;
  EXPECT_FALSE(ValidateLeggedScene(huge).empty());
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

// What MuJoCo 2.2.2 takes as it comes is refused before it sees it: a huge texture crashed it, a big composite
// took minutes, an include reads another file.
TEST(LeggedMjcfTest, RefusesIncludesGeneratorsAndSizedAssets) {
  const std::string body =
      "<worldbody><body name=\"torso\"><freejoint name=\"root\"/><geom name=\"g\" type=\"sphere\" "
      "size=\"0.1\"/>{}</body></worldbody>";
  for (const auto& [asset, inside, element] :
       {std::tuple<std::string, std::string, std::string>{
            "<texture name=\"t\" builtin=\"checker\" width=\"60000\" height=\"60000\"/>", "", "texture"},
        {"<hfield name=\"h\" nrow=\"50000\" ncol=\"50000\" size=\"1 1 1 0.1\"/>", "", "hfield"},
        {"",
         "<body name=\"c\"><composite type=\"grid\" count=\"400 400 1\" spacing=\"0.01\"><geom "
         "size=\"0.005\"/></composite></body>",
         "composite"},
        {"", "<include file=\"/dev/zero\"/>", "include"}}) {
    LeggedScene s = NaoScene(1);
    std::string world = body;
    world.replace(world.find("{}"), 2, inside);
    s.robots[0].model_xml =
        "<mujoco model=\"x\"><compiler angle=\"radian\"/><asset>" + asset + "</asset>" + world + "</mujoco>";
    const LeggedMjcf m = ComposeLeggedMjcf(s);
    ASSERT_FALSE(m.errors.empty()) << element;
    EXPECT_NE(m.errors[0].find("<" + element + "> is not supported"), std::string::npos) << m.errors[0];
  }
}

}  // namespace
}  // namespace turf
