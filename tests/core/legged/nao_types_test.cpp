// The 3D league's Nao robot types 0..4 (core/legged/nao_types.h) against the facts (shared/protocols/simspark.md,
// "Robot types" and "Nao physical model"): the expected numbers below are the facts', not the code's table.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <string>

#include "core/legged/legged_world.h"
#include "core/legged/nao_types.h"
#include "kernel/simspark/self_collision.h"
#include "loader/legged_scene_yaml.h"
#include "tests/core/legged/nao_fixture.h"

namespace turf {
namespace {

struct TypeFacts {
  int type;
  double sole_below_torso;  // m, zero pose
  double hip_x;             // H
  double thigh_z;           // T
  double ankle_z;           // A
  double elbow_y;           // E
  size_t joints;
};

constexpr TypeFacts kFacts[] = {
    {0, 0.385, 0.055, -0.04, -0.055, 0.07, 22}, {1, 0.42164, 0.055, -0.05832, -0.07332, 0.10664, 22},
    {2, 0.385, 0.055, -0.04, -0.055, 0.07, 22}, {3, 0.440737, 0.072954143, -0.067868424, -0.082868424, 0.125736848, 22},
    {4, 0.385, 0.055, -0.04, -0.055, 0.07, 24},
};

void PrintTo(const TypeFacts& f, std::ostream* os) { *os << "type " << f.type; }

LeggedScene TypedScene(int type) {
  LeggedScene s = testing::NaoScene(1);
  s.physics.step = 0.02 / 3;
  NaoTypeModel typed = NaoTypeMjcf(s.robots[0].model_xml, type);
  if (!typed.error.empty()) throw std::runtime_error(typed.error);
  s.robots[0].model_xml = typed.xml;
  s.robots[0].robot_type = type;
  return s;
}

// A body's centre relative to the torso's, at the start (zero pose, yaw 0: model axes are world axes).
std::array<double, 3> Offset(const LeggedRobotState& r, const std::string& body) {
  auto find = [&](const std::string& name) {
    auto it = std::find_if(r.links.begin(), r.links.end(), [&](const LinkPose& l) { return l.name == name; });
    if (it == r.links.end()) throw std::runtime_error("no body " + name);
    return it->position;
  };
  const auto b = find(body);
  const auto t = find("torso");
  return {b[0] - t[0], b[1] - t[1], b[2] - t[2]};
}

class NaoTypesTest : public ::testing::TestWithParam<TypeFacts> {};

TEST_P(NaoTypesTest, BodyAsTheFactsDefineIt) {
  const TypeFacts f = GetParam();
  LeggedWorld w(TypedScene(f.type));
  EXPECT_NEAR(w.RobotMass(0), 4.6071, 1e-6) << "every type weighs the same";
  const LeggedRobotState r = w.State().robots[0];
  EXPECT_EQ(r.joint_names.size(), f.joints);
  EXPECT_NEAR(r.base_position[2], f.sole_below_torso, 1e-6) << "standing height: sole on the ground";
  for (const char* side : {"r", "l"}) {
    const double s = side[0] == 'r' ? 1.0 : -1.0;
    const std::string p = side;
    const auto hip = Offset(r, p + "hip1");
    EXPECT_NEAR(hip[0], s * f.hip_x, 1e-9) << p;
    EXPECT_NEAR(hip[2], -0.115, 1e-9) << p;
    EXPECT_NEAR(Offset(r, p + "thigh")[2], -0.115 + f.thigh_z, 1e-9) << p;
    EXPECT_NEAR(Offset(r, p + "shank")[2], -0.24 + f.thigh_z, 1e-9) << p;
    EXPECT_NEAR(Offset(r, p + "ankle")[2], -0.24 + f.thigh_z + f.ankle_z, 1e-9) << p;
    EXPECT_NEAR(Offset(r, p + "elbow")[1], 0.02 + f.elbow_y, 1e-9) << p;
    EXPECT_NEAR(Offset(r, p + "lowerarm")[1], 0.07 + f.elbow_y, 1e-9) << p;
  }
}

// Zero joint velocities for 5 s: every type stands where it was put, on both feet.
TEST_P(NaoTypesTest, StandsWithZeroCommands) {
  const TypeFacts f = GetParam();
  LeggedWorld w(TypedScene(f.type));
  double max_tilt = 0.0;
  double min_z = 1.0;
  for (int i = 0; i < 750; ++i) {
    w.Step();
    const LeggedRobotState s = w.State().robots[0];
    const auto& q = s.base_orientation;
    max_tilt = std::max(max_tilt, std::acos(std::clamp(1 - 2 * (q[1] * q[1] + q[2] * q[2]), -1.0, 1.0)));
    min_z = std::min(min_z, s.base_position[2]);
  }
  EXPECT_LT(max_tilt, 0.05);
  EXPECT_NEAR(min_z, f.sole_below_torso, 0.01);
  const LeggedRobotState s = w.State().robots[0];
  double load = 0.0;
  for (const ForceReading& r : s.forces) load += r.values[0];
  EXPECT_NEAR(load, 4.6071 * 9.81, 0.1 * 4.6071 * 9.81) << "the feet (and toes) carry the weight";
}

// The SimSpark referee's self-collision boxes (kernel/simspark/self_collision.h, the reference's colliders) are the
// model's own: a box geom of that size at each link's origin, along its axes.
TEST_P(NaoTypesTest, SelfCollisionBoxesAreTheModelsGeoms) {
  const TypeFacts f = GetParam();
  LeggedWorld w(TypedScene(f.type));
  const std::vector<LeggedGeom> geoms = w.RobotGeoms(0);
  for (const simspark::NaoBox& box : simspark::NaoBoxes(f.type)) {
    const auto g = std::find_if(geoms.begin(), geoms.end(), [&](const LeggedGeom& g) {
      return g.body == box.link && g.shape == LeggedGeom::Shape::kBox;
    });
    ASSERT_NE(g, geoms.end()) << box.link;
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(g->size[k], box.half[k], 1e-9) << box.link;
      EXPECT_NEAR(g->position[k], 0.0, 1e-9) << box.link;
    }
    EXPECT_NEAR(std::abs(g->orientation[0]), 1.0, 1e-9) << box.link;
  }
}

INSTANTIATE_TEST_SUITE_P(Types, NaoTypesTest, ::testing::ValuesIn(kFacts),
                         [](const auto& info) { return "Type" + std::to_string(info.param.type); });

// Type 4: a toe hinge on each foot, -1..70 degrees, at the sole under the foot's front edge, with touch sensors
// lf1 and rf1 (FRP); the foot is shorter by the toe's length.
TEST(NaoType4, ToesHingeAtTheFrontEdgeOfTheSole) {
  LeggedWorld w(TypedScene(4));
  const LeggedRobotState r = w.State().robots[0];
  for (const char* toe : {"llj7", "rlj7"}) {
    const int j = w.JointIndex(0, toe);
    ASSERT_GE(j, 0) << toe;
    const LeggedJointInfo info = w.JointInfo(0, j);
    EXPECT_TRUE(info.limited);
    EXPECT_NEAR(info.lo * 180 / M_PI, -1.0, 1e-6);
    EXPECT_NEAR(info.hi * 180 / M_PI, 70.0, 1e-6);
  }
  std::vector<std::string> sensors;
  for (const ForceReading& f : r.forces) sensors.push_back(f.name);
  for (const char* name : {"lf", "rf", "lf1", "rf1"})
    EXPECT_NE(std::find(sensors.begin(), sensors.end(), name), sensors.end()) << name;
  // Toe centre: ankle + (0, 0.0122412 + 0.080, -0.045); the facts' toe <- foot anchor (+-0.055, 0.0695, -0.385).
  const auto toe = Offset(r, "rtoe");
  const auto ankle = Offset(r, "rankle");
  EXPECT_NEAR(toe[1] - ankle[1], 0.0922412, 1e-6);
  EXPECT_NEAR(toe[2] - ankle[2], -0.045, 1e-9);
  EXPECT_NEAR(toe[1] - 0.035517656 / 2, 0.0695, 1e-3) << "the hinge at the toe's rear edge";
}

TEST(NaoType4, ToeFollowsAVelocityCommand) {
  LeggedWorld w(TypedScene(4));
  const int j = w.JointIndex(0, "rlj7");
  ASSERT_GE(j, 0);
  JointCommand up;
  up.joint = "rlj7";
  up.value = 1.0;  // rad/s, toe up
  ASSERT_EQ(w.SetJointCommand(0, up), JointCommandError::kOk);
  for (int i = 0; i < 60; ++i) w.Step();  // 0.4 s
  EXPECT_NEAR(w.State().robots[0].joint_positions[j], 0.4, 0.05);
}

// rcssserver3d's toe motor (ODE, joint CFM 1e-8) holds an uncommanded toe at exactly 0 through every push-off of
// UT Austin Villa's walk (its HJ reads 0.00). In the match scene's physics: ankles pressing the toes into the ground
// load each toe hinge with several N m, and the toes stay within 0.05 deg (a relative compliance alone, 12.6 for the
// 22 g toe, bent them 0.8 deg in one step).
TEST(NaoType4, ToesHoldUnderLoadAsTheReferencesMotor) {
  LeggedScene s = TypedScene(4);
  LeggedSceneLoadResult match = LoadLeggedSceneFile(TURF_SOURCE_DIR "/configs/scenes/simspark_match.yaml");
  ASSERT_TRUE(match.scene.has_value()) << match.errors.front();
  s.physics = match.scene->physics;
  s.contacts = match.scene->contacts;
  s.joint_stops = match.scene->joint_stops;
  LeggedWorld w(s);
  for (const char* ankle : {"rlj5", "llj5"})
    ASSERT_EQ(w.SetJointCommand(0, {ankle, JointMode::kVelocity, -1.0}), JointCommandError::kOk);
  double max_load = 0.0;
  double max_bend = 0.0;
  for (int i = 0; i < 15; ++i) {  // 0.3 s
    w.Step();
    const LeggedRobotState r = w.State().robots[0];
    for (const char* toe : {"rlj7", "llj7"}) {
      const int j = w.JointIndex(0, toe);
      ASSERT_GE(j, 0) << toe;
      max_load = std::max(max_load, std::abs(r.joint_efforts[j]));
      max_bend = std::max(max_bend, std::abs(r.joint_positions[j]));
    }
  }
  EXPECT_GT(max_load, 1.0) << "the toes carry a load (N m)";
  EXPECT_LT(max_bend * 180 / M_PI, 0.05) << "max load " << max_load << " N m";
}

TEST(NaoTypes, RefusesWhatIsNotATypeOrNotANao) {
  const std::string nao = testing::ReadNaoXml();
  EXPECT_FALSE(NaoTypeMjcf(nao, 5).error.empty());
  EXPECT_FALSE(NaoTypeMjcf(nao, -1).error.empty());
  EXPECT_FALSE(NaoTypeMjcf("<mujoco/>", 1).error.empty());
  EXPECT_FALSE(NaoTypeMjcf("not xml <", 1).error.empty());
  EXPECT_NE(NaoTypeMjcf("<mujoco/>", 1).error.find("body 'torso'"), std::string::npos);
}

// The scene key: `nao_type: k` builds the robot file as type k and says so; anything else is refused by name.
TEST(NaoTypes, SceneKeyBuildsTheType) {
  const std::string robots = std::string(TURF_SOURCE_DIR) + "/configs/robots";
  auto scene = [&](const std::string& type) {
    return ParseLeggedSceneYaml(
        "kind: legged\nname: t\nrobots:\n  - {name: a, model: nao.xml, nao_type: " + type + "}\n", robots);
  };
  LeggedSceneLoadResult three = scene("3");
  ASSERT_TRUE(three.scene.has_value()) << (three.errors.empty() ? "" : three.errors.front());
  EXPECT_EQ(three.scene->robots[0].robot_type, 3);
  EXPECT_EQ(three.scene->robots[0].model, "nao.xml (type 3)");
  EXPECT_EQ(three.scene->robots[0].model_xml, NaoTypeMjcf(testing::ReadNaoXml(), 3).xml);
  for (const char* bad : {"5", "-1", "two"}) {
    LeggedSceneLoadResult r = scene(bad);
    EXPECT_FALSE(r.scene.has_value()) << bad;
    ASSERT_FALSE(r.errors.empty()) << bad;
    EXPECT_NE(r.errors.front().find("nao_type"), std::string::npos) << r.errors.front();
  }
}

}  // namespace
}  // namespace turf
