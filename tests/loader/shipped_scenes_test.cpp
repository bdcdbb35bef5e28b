// The scene files in configs/scenes/: they load, have the advertised shape, and
// their robots stand in a legal kick-off formation (computed, not trusted).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "loader/scene_yaml.h"
#include "tests/loader/test_util.h"

namespace turf {
namespace {

using test::ErrorList;

constexpr double kPi = 3.14159265358979323846;
constexpr double kMinRobotDistance = 0.3;  // centre to centre

struct ShippedScene {
  const char* file;
  Division division;
  double length;
  double width;
  int on_field_per_team;
};

const std::vector<ShippedScene>& ShippedScenes() {
  static const std::vector<ShippedScene> scenes = {
      {"ssl_div_a.yaml", Division::kA, 12.0, 9.0, 11},
      {"ssl_div_b.yaml", Division::kB, 9.0, 6.0, 6},
      {"ssl_div_a_2x16.yaml", Division::kA, 12.0, 9.0, 16},
  };
  return scenes;
}

Scene LoadShipped(const ShippedScene& shipped) {
  const SceneLoadResult result = LoadSceneFile(test::ScenePath(shipped.file));
  EXPECT_TRUE(result.errors.empty()) << ErrorList(result);
  EXPECT_TRUE(result.scene.has_value());
  return result.scene.value_or(Scene{});
}

// Distance from a point to a team's defense area (0 inside). Blue's is at -x.
double DistanceToDefenseArea(const FieldParams& f, Team team, double x, double y) {
  const double own_x = team == Team::kBlue ? -x : x;  // as if defending +x
  const double dx = std::max({f.length / 2 - f.penalty_area_depth - own_x, own_x - f.length / 2, 0.0});
  const double dy = std::max(std::abs(y) - f.penalty_area_width / 2, 0.0);
  return std::hypot(dx, dy);
}

TEST(ShippedScenes, LoadWithTheAdvertisedShape) {
  for (const ShippedScene& shipped : ShippedScenes()) {
    SCOPED_TRACE(shipped.file);
    const Scene scene = LoadShipped(shipped);
    EXPECT_EQ(scene.field.division, shipped.division);
    EXPECT_DOUBLE_EQ(scene.field.length, shipped.length);
    EXPECT_DOUBLE_EQ(scene.field.width, shipped.width);
    EXPECT_EQ(scene.robots_per_team, kMaxRobotsPerTeam);
    EXPECT_DOUBLE_EQ(scene.ball_start_x, 0.0);
    EXPECT_DOUBLE_EQ(scene.ball_start_y, 0.0);
    for (Team team : {Team::kBlue, Team::kYellow}) {
      const auto on_field = std::count_if(scene.robots.begin(), scene.robots.end(),
                                          [team](const RobotSetup& r) { return r.team == team && r.on_field; });
      EXPECT_EQ(on_field, shipped.on_field_per_team) << TeamName(team);
    }
  }
}

TEST(ShippedScenes, DivisionBKeepsTheDivisionBField) {
  const Scene scene = LoadShipped(ShippedScenes()[1]);
  const FieldParams expected = FieldForDivision(Division::kB);
  EXPECT_DOUBLE_EQ(scene.field.penalty_area_depth, expected.penalty_area_depth);
  EXPECT_DOUBLE_EQ(scene.field.penalty_area_width, expected.penalty_area_width);
  EXPECT_DOUBLE_EQ(scene.field.goal_width, expected.goal_width);
}

TEST(ShippedScenes, KickOffFormationIsLegal) {
  for (const ShippedScene& shipped : ShippedScenes()) {
    SCOPED_TRACE(shipped.file);
    const Scene scene = LoadShipped(shipped);
    const FieldParams& f = scene.field;
    const double r = scene.robot.radius;
    for (const RobotSetup& robot : scene.robots) {
      const double x = robot.pose.x;
      const double y = robot.pose.y;
      SCOPED_TRACE(testing::Message() << TeamName(robot.team) << " " << robot.id << " at " << x << ", " << y);
      // Wholly inside the field lines and in its own half (blue defends -x).
      const double own_side = robot.team == Team::kBlue ? -1.0 : 1.0;
      EXPECT_GE(own_side * x, r);
      EXPECT_LE(std::abs(x), f.length / 2 - r);
      EXPECT_LE(std::abs(y), f.width / 2 - r);
      // Not touching the centre circle.
      EXPECT_GE(std::hypot(x, y), f.center_circle_radius + r);
      // Facing the opponent: blue +x, yellow -x.
      if (robot.team == Team::kBlue) {
        EXPECT_NEAR(robot.pose.theta, 0.0, 1e-9);
      } else {
        EXPECT_NEAR(std::abs(robot.pose.theta), kPi, 1e-9);
      }
      // The goalie (id 0) inside its own defense area; everyone else clear of both.
      const Team other = robot.team == Team::kBlue ? Team::kYellow : Team::kBlue;
      if (robot.id == 0) {
        EXPECT_EQ(DistanceToDefenseArea(f, robot.team, x, y), 0.0);
        EXPECT_GE(f.length / 2 - own_side * x, r) << "goalie stands in front of the goal line";
      } else {
        EXPECT_GT(DistanceToDefenseArea(f, robot.team, x, y), r);
      }
      EXPECT_GT(DistanceToDefenseArea(f, other, x, y), r);
    }
    for (size_t i = 0; i < scene.robots.size(); ++i) {
      for (size_t j = i + 1; j < scene.robots.size(); ++j) {
        const Pose2& a = scene.robots[i].pose;
        const Pose2& b = scene.robots[j].pose;
        EXPECT_GE(std::hypot(a.x - b.x, a.y - b.y), kMinRobotDistance)
            << TeamName(scene.robots[i].team) << " " << scene.robots[i].id << " and " << TeamName(scene.robots[j].team)
            << " " << scene.robots[j].id;
      }
    }
  }
}

TEST(ShippedScenes, EachTeamHasAGoalie) {
  for (const ShippedScene& shipped : ShippedScenes()) {
    SCOPED_TRACE(shipped.file);
    const Scene scene = LoadShipped(shipped);
    for (Team team : {Team::kBlue, Team::kYellow}) {
      EXPECT_TRUE(std::any_of(scene.robots.begin(), scene.robots.end(), [team](const RobotSetup& r) {
        return r.team == team && r.id == 0 && r.on_field;
      })) << TeamName(team);
    }
  }
}

// The default scene lists parameters to show what can be tuned; it must not drift from the code's defaults.
TEST(ShippedScenes, DefaultSceneKeepsTheCodeDefaults) {
  const Scene scene = LoadShipped(ShippedScenes()[0]);
  const Scene code;
  EXPECT_EQ(scene.name, "ssl-div-a");
  EXPECT_EQ(scene.seed, code.seed);
  EXPECT_DOUBLE_EQ(scene.physics.step, code.physics.step);
  EXPECT_EQ(scene.physics.solver_iterations, code.physics.solver_iterations);
  EXPECT_DOUBLE_EQ(scene.rates.world_state_hz, code.rates.world_state_hz);
  EXPECT_DOUBLE_EQ(scene.rates.command_timeout, code.rates.command_timeout);
  EXPECT_DOUBLE_EQ(scene.field.friction, code.field.friction);
  EXPECT_DOUBLE_EQ(scene.ball.radius, code.ball.radius);
  EXPECT_DOUBLE_EQ(scene.ball.mass, code.ball.mass);
  EXPECT_DOUBLE_EQ(scene.ball.acc_slide, code.ball.acc_slide);
  EXPECT_DOUBLE_EQ(scene.ball.acc_roll, code.ball.acc_roll);
  EXPECT_DOUBLE_EQ(scene.ball.k_switch, code.ball.k_switch);
  EXPECT_DOUBLE_EQ(scene.ball.floor_restitution, code.ball.floor_restitution);
  EXPECT_DOUBLE_EQ(scene.ball.wall_restitution, code.ball.wall_restitution);
  EXPECT_DOUBLE_EQ(scene.robot.radius, code.robot.radius);
  EXPECT_DOUBLE_EQ(scene.robot.height, code.robot.height);
  EXPECT_DOUBLE_EQ(scene.robot.mass, code.robot.mass);
  EXPECT_DOUBLE_EQ(scene.robot.center_to_dribbler, code.robot.center_to_dribbler);
  EXPECT_DOUBLE_EQ(scene.robot.drive.max_speed, code.robot.drive.max_speed);
  EXPECT_DOUBLE_EQ(scene.robot.drive.max_angular_speed, code.robot.drive.max_angular_speed);
  EXPECT_DOUBLE_EQ(scene.robot.drive.acc_speedup, code.robot.drive.acc_speedup);
  EXPECT_DOUBLE_EQ(scene.robot.drive.acc_brake, code.robot.drive.acc_brake);
  EXPECT_DOUBLE_EQ(scene.robot.drive.acc_angular, code.robot.drive.acc_angular);
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_NEAR(scene.robot.drive.wheel_angles[i], code.robot.drive.wheel_angles[i], 1e-12) << i;
  }
  EXPECT_DOUBLE_EQ(scene.robot.kicker.max_flat_speed, code.robot.kicker.max_flat_speed);
  EXPECT_DOUBLE_EQ(scene.robot.kicker.max_chip_speed, code.robot.kicker.max_chip_speed);
  EXPECT_NEAR(scene.robot.kicker.default_chip_angle, code.robot.kicker.default_chip_angle, 1e-12);
  EXPECT_DOUBLE_EQ(scene.robot.dribbler.max_force, code.robot.dribbler.max_force);
  EXPECT_DOUBLE_EQ(scene.cameras.rate_hz, code.cameras.rate_hz);
  EXPECT_DOUBLE_EQ(scene.cameras.height, code.cameras.height);
}

}  // namespace
}  // namespace turf
