// ParseSceneYaml on valid input: defaults, overrides, units, every key.
#include "loader/scene_yaml.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "tests/loader/test_util.h"

namespace turf {
namespace {

using test::ErrorList;

constexpr double kPi = 3.14159265358979323846;

Scene ParseOk(const std::string& yaml) {
  SceneLoadResult result = ParseSceneYaml(yaml);
  EXPECT_TRUE(result.errors.empty()) << ErrorList(result) << "\nfor:\n" << yaml;
  EXPECT_TRUE(result.scene.has_value());
  return result.scene.value_or(Scene{});
}

TEST(SceneYaml, EmptyMapKeepsAllDefaults) {
  const Scene scene = ParseOk("{}");
  const Scene defaults;
  EXPECT_EQ(scene.name, defaults.name);
  EXPECT_EQ(scene.seed, defaults.seed);
  EXPECT_EQ(scene.field.division, Division::kA);
  EXPECT_DOUBLE_EQ(scene.field.length, 12.0);
  EXPECT_DOUBLE_EQ(scene.ball.radius, defaults.ball.radius);
  EXPECT_DOUBLE_EQ(scene.robot.drive.max_speed, defaults.robot.drive.max_speed);
  EXPECT_EQ(scene.robots_per_team, kMaxRobotsPerTeam);
  EXPECT_TRUE(scene.robots.empty());
}

TEST(SceneYaml, EmptySectionsKeepDefaults) {
  const Scene scene = ParseOk("field:\nball:\nteams:\n  blue:\n");
  EXPECT_DOUBLE_EQ(scene.field.width, 9.0);
  EXPECT_TRUE(scene.robots.empty());
}

TEST(SceneYaml, DivisionPicksItsFieldThenOtherKeysOverride) {
  // The override is written before the division on purpose: order in the file does not matter.
  const Scene scene = ParseOk("field: {length: 10.0, division: B}");
  EXPECT_EQ(scene.field.division, Division::kB);
  EXPECT_DOUBLE_EQ(scene.field.length, 10.0);
  EXPECT_DOUBLE_EQ(scene.field.width, 6.0);
  EXPECT_DOUBLE_EQ(scene.field.goal_width, 1.0);
  EXPECT_DOUBLE_EQ(scene.field.penalty_area_depth, 1.0);
  EXPECT_DOUBLE_EQ(scene.field.penalty_area_width, 2.0);
  EXPECT_DOUBLE_EQ(scene.field.boundary_width_goal_line, 0.3);
}

TEST(SceneYaml, DegreesBecomeRadians) {
  const Scene scene = ParseOk(R"(
robot:
  drive: {wheel_angles_deg: [-30, -150, 150, 30]}
  kicker: {default_chip_angle_deg: 60}
teams:
  blue: [{id: 2, x: 1.0, y: -1.0, theta_deg: 90}]
  yellow: [{id: 0, x: 2.0, y: 0.5, theta_deg: -180}]
)");
  const std::array<double, 4> wheels = scene.robot.drive.wheel_angles;
  EXPECT_NEAR(wheels[0], -kPi / 6, 1e-12);
  EXPECT_NEAR(wheels[1], -5 * kPi / 6, 1e-12);
  EXPECT_NEAR(wheels[2], 5 * kPi / 6, 1e-12);
  EXPECT_NEAR(wheels[3], kPi / 6, 1e-12);
  EXPECT_NEAR(scene.robot.kicker.default_chip_angle, kPi / 3, 1e-12);
  ASSERT_EQ(scene.robots.size(), 2u);
  EXPECT_NEAR(scene.robots[0].pose.theta, kPi / 2, 1e-12);
  EXPECT_NEAR(scene.robots[1].pose.theta, -kPi, 1e-12);
}

TEST(SceneYaml, DefaultWheelAnglesInDegreesMatchTheCode) {
  const Scene scene = ParseOk("robot: {drive: {wheel_angles_deg: [-60, -135, 135, 60]}}");
  const Scene defaults;
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_NEAR(scene.robot.drive.wheel_angles[i], defaults.robot.drive.wheel_angles[i], 1e-12) << i;
  }
}

TEST(SceneYaml, RobotsKeepTeamIdPoseAndOnField) {
  const Scene scene = ParseOk(R"(
robots_per_team: 3
teams:
  blue:
    - {id: 2, x: -1.5, y: 0.25}
    - {id: 0, on_field: false}
  yellow:
    - {id: 1, x: 2.0, y: -3.0, theta_deg: 180, on_field: true}
)");
  EXPECT_EQ(scene.robots_per_team, 3);
  ASSERT_EQ(scene.robots.size(), 3u);
  const RobotSetup& first = scene.robots[0];
  EXPECT_EQ(first.team, Team::kBlue);
  EXPECT_EQ(first.id, 2);
  EXPECT_TRUE(first.on_field);
  EXPECT_DOUBLE_EQ(first.pose.x, -1.5);
  EXPECT_DOUBLE_EQ(first.pose.y, 0.25);
  EXPECT_DOUBLE_EQ(first.pose.theta, 0.0);
  EXPECT_EQ(scene.robots[1].team, Team::kBlue);
  EXPECT_FALSE(scene.robots[1].on_field);
  EXPECT_EQ(scene.robots[2].team, Team::kYellow);
  EXPECT_EQ(scene.robots[2].id, 1);
  EXPECT_NEAR(scene.robots[2].pose.theta, kPi, 1e-12);
}

TEST(SceneYaml, ScalarsOfEveryKind) {
  const Scene scene = ParseOk("name: my scene\nseed: 18446744073709551615\nball: {start: [+1.5, -2e0]}");
  EXPECT_EQ(scene.name, "my scene");
  EXPECT_EQ(scene.seed, 18446744073709551615ull);
  EXPECT_DOUBLE_EQ(scene.ball_start_x, 1.5);
  EXPECT_DOUBLE_EQ(scene.ball_start_y, -2.0);
}

// One row per settable number: its key path, a valid non-default value, where it lands.
struct KeyCase {
  std::string path;
  std::string value;
  double expected;
  std::function<double(const Scene&)> get;
};

// "a.b.c" = v as nested flow maps: {a: {b: {c: v}}}.
std::string NestedYaml(const std::string& path, const std::string& value) {
  std::string yaml = value;
  std::string rest = path;
  for (size_t dot = rest.rfind('.'); dot != std::string::npos; dot = rest.rfind('.')) {
    yaml = "{" + rest.substr(dot + 1) + ": " + yaml + "}";
    rest.resize(dot);
  }
  return rest + ": " + yaml;
}

TEST(SceneYaml, EveryKeyLandsInItsMember) {
  const std::vector<KeyCase> cases = {
      {"seed", "42", 42, [](const Scene& s) { return static_cast<double>(s.seed); }},
      {"robots_per_team", "11", 11, [](const Scene& s) { return s.robots_per_team; }},
      {"physics.step", "0.001", 0.001, [](const Scene& s) { return s.physics.step; }},
      {"physics.solver_iterations", "30", 30, [](const Scene& s) { return s.physics.solver_iterations; }},
      {"rates.world_state_hz", "50", 50, [](const Scene& s) { return s.rates.world_state_hz; }},
      {"rates.command_timeout", "1.0", 1.0, [](const Scene& s) { return s.rates.command_timeout; }},
      {"field.length", "11", 11, [](const Scene& s) { return s.field.length; }},
      {"field.width", "8", 8, [](const Scene& s) { return s.field.width; }},
      {"field.boundary_width", "0.4", 0.4, [](const Scene& s) { return s.field.boundary_width; }},
      {"field.boundary_width_goal_line", "0.7", 0.7, [](const Scene& s) { return s.field.boundary_width_goal_line; }},
      {"field.goal_width", "1.5", 1.5, [](const Scene& s) { return s.field.goal_width; }},
      {"field.goal_depth", "0.2", 0.2, [](const Scene& s) { return s.field.goal_depth; }},
      {"field.goal_height", "0.2", 0.2, [](const Scene& s) { return s.field.goal_height; }},
      {"field.goal_wall_thickness", "0.03", 0.03, [](const Scene& s) { return s.field.goal_wall_thickness; }},
      {"field.penalty_area_depth", "1.5", 1.5, [](const Scene& s) { return s.field.penalty_area_depth; }},
      {"field.penalty_area_width", "3.0", 3.0, [](const Scene& s) { return s.field.penalty_area_width; }},
      {"field.center_circle_radius", "0.6", 0.6, [](const Scene& s) { return s.field.center_circle_radius; }},
      {"field.line_thickness", "0.02", 0.02, [](const Scene& s) { return s.field.line_thickness; }},
      {"field.goal_center_to_penalty_mark", "7", 7, [](const Scene& s) { return s.field.goal_center_to_penalty_mark; }},
      {"field.wall_height", "0.2", 0.2, [](const Scene& s) { return s.field.wall_height; }},
      {"field.wall_thickness", "0.06", 0.06, [](const Scene& s) { return s.field.wall_thickness; }},
      {"field.friction", "0.5", 0.5, [](const Scene& s) { return s.field.friction; }},
      {"ball.start", "[1.5, 0]", 1.5, [](const Scene& s) { return s.ball_start_x; }},
      {"ball.start", "[0, -2]", -2, [](const Scene& s) { return s.ball_start_y; }},
      {"ball.radius", "0.02", 0.02, [](const Scene& s) { return s.ball.radius; }},
      {"ball.mass", "0.05", 0.05, [](const Scene& s) { return s.ball.mass; }},
      {"ball.acc_slide", "-4", -4, [](const Scene& s) { return s.ball.acc_slide; }},
      {"ball.acc_roll", "-0.5", -0.5, [](const Scene& s) { return s.ball.acc_roll; }},
      {"ball.k_switch", "0.65", 0.65, [](const Scene& s) { return s.ball.k_switch; }},
      {"ball.floor_restitution", "0.4", 0.4, [](const Scene& s) { return s.ball.floor_restitution; }},
      {"ball.wall_restitution", "0.5", 0.5, [](const Scene& s) { return s.ball.wall_restitution; }},
      {"ball.chip_damping_xy_first_hop", "0.7", 0.7, [](const Scene& s) { return s.ball.chip_damping_xy_first_hop; }},
      {"ball.chip_damping_xy_other_hops", "0.9", 0.9, [](const Scene& s) { return s.ball.chip_damping_xy_other_hops; }},
      {"robot.radius", "0.1", 0.1, [](const Scene& s) { return s.robot.radius; }},
      {"robot.height", "0.14", 0.14, [](const Scene& s) { return s.robot.height; }},
      {"robot.mass", "2", 2, [](const Scene& s) { return s.robot.mass; }},
      {"robot.center_to_dribbler", "0.07", 0.07, [](const Scene& s) { return s.robot.center_to_dribbler; }},
      {"robot.friction", "0.5", 0.5, [](const Scene& s) { return s.robot.friction; }},
      {"robot.drive.max_speed", "2.5", 2.5, [](const Scene& s) { return s.robot.drive.max_speed; }},
      {"robot.drive.max_angular_speed", "8", 8, [](const Scene& s) { return s.robot.drive.max_angular_speed; }},
      {"robot.drive.acc_speedup", "2.5", 2.5, [](const Scene& s) { return s.robot.drive.acc_speedup; }},
      {"robot.drive.acc_brake", "4", 4, [](const Scene& s) { return s.robot.drive.acc_brake; }},
      {"robot.drive.acc_angular", "30", 30, [](const Scene& s) { return s.robot.drive.acc_angular; }},
      {"robot.drive.wheel_distance", "0.07", 0.07, [](const Scene& s) { return s.robot.drive.wheel_distance; }},
      {"robot.drive.wheel_radius", "0.025", 0.025, [](const Scene& s) { return s.robot.drive.wheel_radius; }},
      {"robot.kicker.max_flat_speed", "6", 6, [](const Scene& s) { return s.robot.kicker.max_flat_speed; }},
      {"robot.kicker.max_chip_speed", "4", 4, [](const Scene& s) { return s.robot.kicker.max_chip_speed; }},
      {"robot.kicker.default_chip_angle_deg", "30", kPi / 6,
       [](const Scene& s) { return s.robot.kicker.default_chip_angle; }},
      {"robot.kicker.reach", "0.02", 0.02, [](const Scene& s) { return s.robot.kicker.reach; }},
      {"robot.dribbler.restitution", "0.3", 0.3, [](const Scene& s) { return s.robot.dribbler.restitution; }},
      {"robot.dribbler.max_force", "2", 2, [](const Scene& s) { return s.robot.dribbler.max_force; }},
      {"robot.dribbler.stiffness", "50", 50, [](const Scene& s) { return s.robot.dribbler.stiffness; }},
      {"robot.dribbler.damping", "3", 3, [](const Scene& s) { return s.robot.dribbler.damping; }},
      {"robot.dribbler.capture_distance", "0.01", 0.01,
       [](const Scene& s) { return s.robot.dribbler.capture_distance; }},
      {"cameras.rate_hz", "75", 75, [](const Scene& s) { return s.cameras.rate_hz; }},
      {"cameras.height", "5", 5, [](const Scene& s) { return s.cameras.height; }},
      {"cameras.overlap", "0.3", 0.3, [](const Scene& s) { return s.cameras.overlap; }},
      {"cameras.focal_length", "400", 400, [](const Scene& s) { return s.cameras.focal_length; }},
      {"cameras.image_width", "1024", 1024, [](const Scene& s) { return s.cameras.image_width; }},
      {"cameras.image_height", "768", 768, [](const Scene& s) { return s.cameras.image_height; }},
  };
  for (const KeyCase& c : cases) {
    const std::string yaml = NestedYaml(c.path, c.value);
    SCOPED_TRACE(yaml);
    ASSERT_NE(c.get(Scene{}), c.expected) << "pick a value other than the default";
    EXPECT_NEAR(c.get(ParseOk(yaml)), c.expected, 1e-12);
  }
}

}  // namespace
}  // namespace turf
