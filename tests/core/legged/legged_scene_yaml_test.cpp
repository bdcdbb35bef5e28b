// Legged scene files: the shipped scenes load, and bad input is refused with
// errors that name the key.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/legged/legged_mjcf.h"
#include "core/legged/legged_world.h"
#include "loader/legged_scene_yaml.h"

namespace turf {
namespace {

const std::string kScenes = std::string(TURF_SOURCE_DIR) + "/configs/scenes/";

bool HasError(const LeggedSceneLoadResult& r, const std::string& part) {
  for (const std::string& e : r.errors) {
    if (e.find(part) != std::string::npos) return true;
  }
  return false;
}

// A scene of one Nao with `settings` (YAML lines, each ending in a newline) before its robot list, read as if
// from configs/scenes.
LeggedSceneLoadResult ParseNaoScene(const std::string& settings) {
  return ParseLeggedSceneYaml("kind: legged\n" + settings + "robots:\n  - {name: a, model: ../robots/nao.xml}\n",
                              std::string(TURF_SOURCE_DIR) + "/configs/scenes");
}

// The `law` switch of an ODE block (`key`, read into scene.*block): `law: mujoco` leaves the block off, and an
// unknown law is an error naming "law".
template <class Block>
void ExpectLawSwitch(const std::string& key, Block LeggedScene::*block) {
  const LeggedSceneLoadResult r = ParseNaoScene(key + ": {law: mujoco}\n");
  ASSERT_TRUE(r.scene) << r.errors.front();
  EXPECT_FALSE(((*r.scene).*block).enabled) << key;
  EXPECT_TRUE(HasError(ParseNaoScene(key + ": {law: bullet}\n"), "law")) << key;
}

TEST(LeggedSceneYamlTest, SimSpark3dSceneLoadsAndBuilds) {
  ASSERT_TRUE(IsLeggedSceneFile(kScenes + "simspark_3d.yaml"));
  EXPECT_FALSE(IsLeggedSceneFile(kScenes + "ssl_div_a.yaml"));
  LeggedSceneLoadResult r = LoadLeggedSceneFile(kScenes + "simspark_3d.yaml");
  ASSERT_TRUE(r.scene) << r.errors.front();
  EXPECT_TRUE(r.scene->field.enabled);
  ASSERT_EQ(r.scene->robots.size(), 2u);
  EXPECT_NEAR(r.scene->robots[0].yaw, -M_PI / 2, 1e-12);
  LeggedWorld w(std::move(*r.scene));
  const LeggedWorldState s = w.State();
  EXPECT_TRUE(s.has_ball);
  EXPECT_NEAR(s.ball_position[2], 0.042, 1e-9);
  EXPECT_NEAR(s.robots[0].base_position[0], -14.2, 1e-9);
}

// RCSSServerMJ's world has no outer walls; the SimSpark scenes keep theirs.
TEST(LeggedSceneYamlTest, WallsCanBeTurnedOffAndTheRcssServerMjSceneHasNone) {
  LeggedSceneLoadResult mj = LoadLeggedSceneFile(kScenes + "rcssservermj_fifa.yaml");
  ASSERT_TRUE(mj.scene) << mj.errors.front();
  EXPECT_FALSE(mj.scene->field.walls);
  const LeggedMjcf without = ComposeLeggedMjcf(*mj.scene);
  ASSERT_TRUE(without.errors.empty()) << without.errors.front();
  EXPECT_EQ(without.xml.find("wall_"), std::string::npos);
  EXPECT_NE(without.xml.find("goal_left_back"), std::string::npos);
  LeggedSceneLoadResult ss = LoadLeggedSceneFile(kScenes + "simspark_match.yaml");
  ASSERT_TRUE(ss.scene) << ss.errors.front();
  EXPECT_TRUE(ss.scene->field.walls);
  const LeggedMjcf with = ComposeLeggedMjcf(*ss.scene);
  ASSERT_TRUE(with.errors.empty()) << with.errors.front();
  for (const char* wall : {"wall_neg_x", "wall_pos_x", "wall_neg_y", "wall_pos_y"})
    EXPECT_NE(with.xml.find(wall), std::string::npos) << wall;
}

TEST(LeggedSceneYamlTest, SimSparkMatchSceneParks22NaosOffTheField) {
  LeggedSceneLoadResult r = LoadLeggedSceneFile(kScenes + "simspark_match.yaml");
  ASSERT_TRUE(r.scene) << r.errors.front();
  ASSERT_EQ(r.scene->robots.size(), 22u);
  EXPECT_EQ(r.scene->physics.step, 0.02);  // one step per SimSpark cycle, as the reference steps ODE
  LeggedWorld w(std::move(*r.scene));
  while (w.time_ns() < 1'000'000'000) w.Step();
  const LeggedScene& scene = w.scene();
  constexpr double kSoleBelowTorso[5] = {0.385, 0.42164, 0.385, 0.440737, 0.385};  // robot types 0..4 (facts)
  int of_type[5] = {0, 0, 0, 0, 0};
  for (size_t i = 0; i < scene.robots.size(); ++i) {
    const LeggedRobotState robot = w.State().robots[i];
    const int type = scene.robots[i].robot_type;
    ASSERT_TRUE(type >= 0 && type < 5) << robot.name;
    ++of_type[type];
    EXPECT_LT(robot.base_position[1], -10.5) << robot.name;                           // outside the touch line
    EXPECT_NEAR(robot.base_position[2], kSoleBelowTorso[type], 0.005) << robot.name;  // standing
  }
  EXPECT_EQ(of_type[0], 14);
  for (int t = 1; t < 5; ++t) EXPECT_EQ(of_type[t], 2) << "type " << t;
}

// The match scene carries rcssserver3d's contact parameters with its whole law on (`law: ode`; a Nao stands on it
// at 2 ms too); `law: ode_friction` keeps MuJoCo's normal contact.
TEST(LeggedSceneYamlTest, ContactLawBlockLoadsAndIsChecked) {
  LeggedSceneLoadResult r = LoadLeggedSceneFile(kScenes + "simspark_match.yaml");
  ASSERT_TRUE(r.scene) << r.errors.front();
  const OdeContactLaw& c = r.scene->contacts;
  EXPECT_TRUE(c.enabled);
  EXPECT_TRUE(c.ode_normal);
  EXPECT_EQ(c.robot.slip, 5e-3);
  EXPECT_EQ(c.robot.erp, 0.6);
  EXPECT_EQ(c.robot.cfm, 1e-4);
  EXPECT_EQ(c.ground.cfm, -1.0);  // not set
  r = ParseNaoScene("contacts: {law: ode_friction}\n");
  ASSERT_TRUE(r.scene) << r.errors.front();
  EXPECT_TRUE(r.scene->contacts.enabled);
  EXPECT_FALSE(r.scene->contacts.ode_normal);
  r = ParseNaoScene("contacts: {law: ode, robot: {erp: 0.6, cfm: 1.0e-4, slip: 5.0e-3}}\n");
  ASSERT_TRUE(r.scene) << r.errors.front();
  EXPECT_TRUE(r.scene->contacts.enabled);
  EXPECT_TRUE(r.scene->contacts.ode_normal);
  LeggedWorld w(std::move(*r.scene));
  for (int i = 0; w.time_ns() < 2'000'000'000; ++i) w.Step();
  EXPECT_NEAR(w.State().robots[0].base_position[2], 0.385, 0.005);  // standing
  ASSERT_NO_FATAL_FAILURE(ExpectLawSwitch("contacts", &LeggedScene::contacts));
  EXPECT_TRUE(HasError(ParseNaoScene("contacts: {law: ode, robot: {erp: 2}}\n"), "contacts"));
  EXPECT_TRUE(HasError(ParseNaoScene("contacts: {law: ode, robot: {cfm: .nan}}\n"), "contacts"));
}

// The match scene reads the IMU after the step and bounds its motors per 20 ms cycle (physics block); both off
// by default, the window checked.
TEST(LeggedSceneYamlTest, PhysicsBlockCarriesSensorTimingAndTheMotorImpulseWindow) {
  LeggedSceneLoadResult r = LoadLeggedSceneFile(kScenes + "simspark_match.yaml");
  ASSERT_TRUE(r.scene) << r.errors.front();
  EXPECT_TRUE(r.scene->physics.sensors_after_step);
  EXPECT_EQ(r.scene->physics.motor_impulse_window, 0.02);
  EXPECT_EQ(r.scene->physics.body_linear_drag, 0.01);  // rsg/agent/nao/dragcontroller.rsg
  EXPECT_EQ(r.scene->physics.body_angular_drag, 0.01);
  r = ParseNaoScene("");
  ASSERT_TRUE(r.scene) << r.errors.front();
  EXPECT_FALSE(r.scene->physics.sensors_after_step);
  EXPECT_EQ(r.scene->physics.motor_impulse_window, 0.0);
  EXPECT_TRUE(HasError(ParseNaoScene("physics: {motor_impulse_window: -0.02}\n"), "motor_impulse_window"));
  EXPECT_TRUE(HasError(ParseNaoScene("physics: {motor_impulse_window: .nan}\n"), "motor_impulse_window"));
  EXPECT_EQ(r.scene->physics.body_linear_drag, 0.0);
  EXPECT_TRUE(HasError(ParseNaoScene("physics: {body_drag: [-0.01, 0.01]}\n"), "body_drag"));
  EXPECT_TRUE(HasError(ParseNaoScene("physics: {body_drag: [0.01]}\n"), "body_drag"));
}

// rcssserver3d's hinge stops (core/legged/legged_scene.h: OdeJointStops): off unless asked for (the match scene asks,
// at the reference's step with its contact law), the reference's values by default, checked.
TEST(LeggedSceneYamlTest, JointStopsBlockLoadsAndIsChecked) {
  LeggedSceneLoadResult r = LoadLeggedSceneFile(kScenes + "simspark_match.yaml");
  ASSERT_TRUE(r.scene) << r.errors.front();
  EXPECT_TRUE(r.scene->joint_stops.enabled);
  EXPECT_EQ(r.scene->joint_stops.step, r.scene->physics.step);
  r = ParseNaoScene("");
  ASSERT_TRUE(r.scene) << r.errors.front();
  EXPECT_FALSE(r.scene->joint_stops.enabled);
  r = ParseNaoScene("joint_stops: {law: ode}\n");
  ASSERT_TRUE(r.scene) << r.errors.front();
  const OdeJointStops& j = r.scene->joint_stops;
  EXPECT_TRUE(j.enabled);
  EXPECT_EQ(j.step, 0.02);
  EXPECT_EQ(j.erp, 0.8);
  EXPECT_EQ(j.bounce, 1.0);
  EXPECT_EQ(j.fudge, 1e-5);
  EXPECT_TRUE(j.hold_commands_at_stop);
  r = ParseNaoScene("joint_stops: {law: ode, step: 0.01, bounce: 0.5, hold_commands_at_stop: false}\n");
  ASSERT_TRUE(r.scene) << r.errors.front();
  EXPECT_EQ(r.scene->joint_stops.step, 0.01);
  EXPECT_EQ(r.scene->joint_stops.bounce, 0.5);
  EXPECT_FALSE(r.scene->joint_stops.hold_commands_at_stop);
  ASSERT_NO_FATAL_FAILURE(ExpectLawSwitch("joint_stops", &LeggedScene::joint_stops));
  EXPECT_TRUE(HasError(ParseNaoScene("joint_stops: {law: ode, erp: 2}\n"), "joint_stops"));
  EXPECT_TRUE(HasError(ParseNaoScene("joint_stops: {law: ode, step: .nan}\n"), "joint_stops"));
  EXPECT_TRUE(HasError(ParseNaoScene("joint_stops: {law: ode, spring: 1}\n"), "spring"));
}

TEST(LeggedSceneYamlTest, RealismPresetOrMapSetsEncodersAndImu) {
  LeggedSceneLoadResult r = ParseNaoScene("realism: realistic\n");
  ASSERT_TRUE(r.scene) << r.errors.front();
  EXPECT_GT(r.scene->realism.encoder.resolution, 0.0);
  EXPECT_GT(r.scene->realism.imu.gyro_noise_stddev, 0.0);
  r = ParseNaoScene("realism: {encoder: {noise_stddev: 0.01}}\n");
  ASSERT_TRUE(r.scene) << r.errors.front();
  EXPECT_EQ(r.scene->realism.encoder.noise_stddev, 0.01);
  EXPECT_TRUE(HasError(ParseNaoScene("realism: nosuchpreset\n"), "realism"));
}

TEST(LeggedSceneYamlTest, ExampleSceneLoads) {
  LeggedSceneLoadResult r = LoadLeggedSceneFile(kScenes + "legged_example.yaml");
  ASSERT_TRUE(r.scene) << r.errors.front();
  EXPECT_EQ(r.scene->robots[0].motors.velocity_kp, 200.0);
}

TEST(LeggedSceneYamlTest, RefusesBadInput) {
  const std::string dir = std::string(TURF_SOURCE_DIR) + "/configs/scenes";
  EXPECT_TRUE(HasError(ParseLeggedSceneYaml("kind: ssl\nrobots: []\n", dir), "kind"));
  EXPECT_TRUE(
      HasError(ParseLeggedSceneYaml("kind: legged\nrobots:\n  - {name: a, model: nope.xml}\n", dir), "nope.xml"));
  EXPECT_TRUE(HasError(ParseLeggedSceneYaml("kind: legged\nrobots:\n  - {name: a, model: ../robots/nao.xml, "
                                            "colour: red}\n",
                                            dir),
                       "colour"));
  EXPECT_TRUE(HasError(ParseLeggedSceneYaml("kind: legged\nrobots:\n  - {name: a, model: ../robots/nao.xml, "
                                            "x: .nan}\n",
                                            dir),
                       "robots[0].x"));
  EXPECT_FALSE(ParseLeggedSceneYaml("kind: legged\n", dir).errors.empty());  // no robots
  // Numbers past which MuJoCo's first steps are NaN, a step of 0 ns, more robots than any match.
  const std::string robot = "robots:\n  - {name: a, model: ../robots/nao.xml}\n";
  for (const auto& [yaml, error] : std::vector<std::pair<std::string, std::string>>{
           {"physics: {step: 1e-12}\n" + robot, "physics.step"},
           {"physics: {fluid_density: 1e12}\n" + robot, "fluid_density"},
           {"physics: {fluid_viscosity: -1}\n" + robot, "fluid_viscosity"},
           {"ground_friction: 1e300\n" + robot, "ground_friction"},
           {"field: {ball_mass: 1e300}\n" + robot, "ball_mass"},
           {"field: {length: 1e300}\n" + robot, "every size"},
           {"field: {ball_start: [1e20, 0]}\n" + robot, "ball start"},
           {"robots:\n  - {name: a, model: ../robots/nao.xml, x: 1e20}\n", "robots.a: pose"}}) {
    EXPECT_TRUE(HasError(ParseLeggedSceneYaml("kind: legged\n" + yaml, dir), error)) << yaml;
  }
  std::string many = "kind: legged\nrobots:\n";
  for (size_t i = 0; i <= kMaxLeggedRobots; ++i)
    many += "  - {name: r" + std::to_string(i) + ", model: ../robots/nao.xml, x: " + std::to_string(i) + "}\n";
  EXPECT_TRUE(HasError(ParseLeggedSceneYaml(many, dir), "at most 32 robots"));
  EXPECT_FALSE(ParseLeggedSceneYaml("[", dir).errors.empty());
}

TEST(LeggedSceneYamlTest, BoosterStandScenesLoadWithStartHeightPoseAndGains) {
  for (const char* name : {"t1_stand.yaml", "k1_stand.yaml"}) {
    LeggedSceneLoadResult r = LoadLeggedSceneFile(kScenes + name);
    ASSERT_TRUE(r.scene) << r.errors.front();
    const LeggedRobot& robot = r.scene->robots[0];
    ASSERT_TRUE(robot.z.has_value()) << name;
    EXPECT_EQ(robot.start_joints.size(), robot.model.find("t1") != std::string::npos ? 23u : 22u) << name;
    const double z = *robot.z;
    LeggedWorld w(std::move(*r.scene));
    EXPECT_NEAR(w.State().robots[0].base_position[2], z, 1e-9) << name;
  }
}

// Start joints: a list of {name, q, kp, kd}; bad values are named by the
// loader, names and ranges the model must check are named by the world.
// The 22-robot RCSSServerMJ match steps its robots in groups on two threads; one world by default; groups need
// MuJoCo's own contacts and limits (rcssserver3d's law and stops act on a whole world's rows).
TEST(LeggedSceneYamlTest, IslandThreadsAreReadAndChecked) {
  LeggedSceneLoadResult r = LoadLeggedSceneFile(kScenes + "rcssservermj_fifa.yaml");
  ASSERT_TRUE(r.scene) << r.errors.front();
  EXPECT_EQ(r.scene->physics.island_threads, 2);
  r = ParseNaoScene("");
  ASSERT_TRUE(r.scene) << r.errors.front();
  EXPECT_EQ(r.scene->physics.island_threads, 1);
  EXPECT_TRUE(HasError(ParseNaoScene("physics: {island_threads: 0}\n"), "island_threads must be 1..8"));
  EXPECT_TRUE(HasError(ParseNaoScene("physics: {island_threads: 9}\n"), "island_threads must be 1..8"));
  EXPECT_TRUE(HasError(ParseNaoScene("physics: {island_threads: 2}\ncontacts: {law: ode}\n"), "island_threads > 1"));
  r = ParseNaoScene("physics: {island_threads: 2}\n");
  ASSERT_TRUE(r.scene) << r.errors.front();
  EXPECT_EQ(r.scene->physics.island_threads, 2);
}

TEST(LeggedSceneYamlTest, RefusesBadStartJoints) {
  const std::string dir = std::string(TURF_SOURCE_DIR) + "/configs/scenes";
  const std::string head = "kind: legged\nrobots:\n  - name: a\n    model: ../robots/t1.xml\n";
  EXPECT_TRUE(HasError(ParseLeggedSceneYaml(head + "    joints: {Waist: 0}\n", dir), "robots[0].joints"));
  EXPECT_TRUE(HasError(ParseLeggedSceneYaml(head + "    joints:\n      - {name: Waist, q: 0, kq: 1}\n", dir),
                       "robots[0].joints[0].kq"));
  EXPECT_TRUE(HasError(ParseLeggedSceneYaml(head + "    joints:\n      - {q: 0}\n", dir), "robots[0].joints[0].name"));
  EXPECT_TRUE(HasError(ParseLeggedSceneYaml(head + "    joints:\n      - {name: Waist, kp: -1}\n", dir),
                       "robots.a.joints.Waist: kp and kd"));
  EXPECT_TRUE(HasError(ParseLeggedSceneYaml(head + "    joints:\n      - {name: Waist}\n      - {name: Waist}\n", dir),
                       "duplicate"));
  EXPECT_TRUE(HasError(ParseLeggedSceneYaml(head + "    z: -1\n", dir), "z must be"));
  // Parsed, but refused when the world is built from it (the model knows the joints and their ranges).
  const std::pair<std::string, std::string> refused_by_the_world[] = {
      {"    joints:\n      - {name: Knee, q: 0.4}\n", "robots.a.joints.Knee: no such joint"},
      {"    joints:\n      - {name: Left_Knee_Pitch, q: -0.5}\n", "outside the joint's range"},
  };
  for (const auto& [robot_yaml, why] : refused_by_the_world) {
    LeggedSceneLoadResult r = ParseLeggedSceneYaml(head + robot_yaml, dir);
    ASSERT_TRUE(r.scene) << robot_yaml;
    try {
      LeggedWorld w(std::move(*r.scene));
      ADD_FAILURE() << "accepted: " << robot_yaml;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace turf
