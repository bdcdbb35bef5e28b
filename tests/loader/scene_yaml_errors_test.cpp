// ParseSceneYaml and LoadSceneFile on bad input: every problem is an error
// naming its key path, there is no scene, and nothing throws or crashes.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "loader/scene_yaml.h"
#include "tests/loader/test_util.h"

namespace turf {
namespace {

using test::ErrorList;
using test::HasErrorContaining;

struct BadCase {
  const char* what;
  std::string yaml;
  std::string expected_error;  // a part of one of the errors
};

// teams.blue with one more robot than a team can have.
std::string SeventeenBlueRobots() {
  std::string list;
  for (int id = 0; id < 17; ++id) list += fmt::format("{}{{id: {}, on_field: false}}", id ? ", " : "", id);
  return "teams: {blue: [" + list + "]}";
}

TEST(SceneYamlErrors, EachProblemIsNamedAndGivesNoScene) {
  const std::vector<BadCase> cases = {
      // Unknown keys at every level, with a hint for near misses.
      {"typo in field", "field: {lenght: 10}", "field.lenght: unknown key (did you mean length?)"},
      {"unknown top-level key", "balls: {radius: 0.02}", "balls: unknown key (did you mean ball?)"},
      {"unknown nested key", "robot: {drive: {max_sped: 2}}", "robot.drive.max_sped: unknown key"},
      {"radians key instead of degrees", "robot: {kicker: {default_chip_angle: 0.5}}",
       "robot.kicker.default_chip_angle: unknown key (did you mean default_chip_angle_deg?)"},
      {"unknown robot key", "teams: {blue: [{id: 0, x: 0, y: 1, theta: 0}]}", "teams.blue[0].theta: unknown key"},
      {"no hint for a far-fetched match", "teams: {blue: [{id: 0, x: 0, y: 1, z: 0}]}",
       "teams.blue[0].z: unknown key (line 1)"},
      {"unknown team", "teams: {green: []}", "teams.green: unknown key"},
      {"duplicate key", "seed: 1\nseed: 2\n", "seed: duplicate key (line 2)"},
      // Wrong types.
      {"text for a number", "robot:\n  drive:\n    max_speed: fast\n",
       "robot.drive.max_speed: expected a number, got \"fast\" (line 3)"},
      {"quoted number", "ball: {radius: \"0.02\"}", "ball.radius: expected a number, got the quoted text \"0.02\""},
      {"list for a number", "ball: {mass: [1]}", "ball.mass: expected a number, got a list"},
      {"map for a number", "physics: {step: {value: 1}}", "physics.step: expected a number, got a map"},
      {"no value", "ball:\n  mass:\n", "ball.mass: no value given (line 2)"},
      {"number for a section", "field: 12", "field: expected a map, got \"12\""},
      {"fraction for an integer", "physics: {solver_iterations: 2.5}",
       "physics.solver_iterations: expected an integer, got \"2.5\""},
      {"huge integer", "robots_per_team: 99999999999999999999",
       "robots_per_team: \"99999999999999999999\" is out of range"},
      {"negative seed", "seed: -1", "seed: expected a non-negative integer, got \"-1\""},
      {"yes for a bool", "teams: {blue: [{id: 0, on_field: maybe}]}",
       "teams.blue[0].on_field: expected true or false, got \"maybe\""},
      {"list for a name", "name: [a, b]", "name: expected text, got a list"},
      {"division C", "field: {division: C}", "field.division: expected A or B, got \"C\""},
      {"three wheels", "robot: {drive: {wheel_angles_deg: [1, 2, 3]}}",
       "robot.drive.wheel_angles_deg: expected a list of 4 numbers, got a list of 3"},
      {"bad wheel", "robot: {drive: {wheel_angles_deg: [1, 2, x, 4]}}",
       "robot.drive.wheel_angles_deg[2]: expected a number, got \"x\""},
      {"bad ball start", "ball: {start: [0, .nan]}", "ball.start[1]: expected a finite number, got \".nan\""},
      // Not finite.
      {"NaN", "ball: {mass: .nan}", "ball.mass: expected a finite number, got \".nan\""},
      {"NaN spelled out", "ball: {mass: nan}", "ball.mass: expected a finite number"},
      {"minus infinity", "physics: {step: -.inf}", "physics.step: expected a finite number"},
      {"overflowing number", "robot: {mass: 1e999}", "robot.mass: expected a finite number"},
      {"NaN angle", "teams: {blue: [{id: 0, x: 0, y: 1, theta_deg: .NaN}]}",
       "teams.blue[0].theta_deg: expected a finite"},
      // Out of range (ValidateScene).
      {"ball too big", "ball: {radius: 5}", "ball.radius must be in"},
      {"negative step", "physics: {step: -0.002}", "physics.step must be in"},
      {"too many ids", "robots_per_team: 17", "robots_per_team must be in"},
      {"ball outside", "ball: {start: [7, 0]}", "ball start must be finite and inside the walls"},
      // Robots.
      {"duplicate id", "teams: {blue: [{id: 3, x: -1, y: 0}, {id: 3, x: -2, y: 0}]}",
       "teams.blue[1].id: robot blue 3 is already listed at teams.blue[0]"},
      {"id too large", "robots_per_team: 4\nteams: {yellow: [{id: 4, x: 1, y: 0}]}",
       "teams.yellow[0].id: must be in [0, robots_per_team = 4), got 4"},
      {"negative id", "teams: {blue: [{id: -1, x: 1, y: 0}]}", "teams.blue[0].id: must be in [0"},
      {"missing id", "teams: {blue: [{x: 1, y: 0}]}", "teams.blue[0].id: required (line 1)"},
      {"missing y", "teams: {blue: [{id: 0, x: 1}]}", "teams.blue[0].y: required for a robot on the field"},
      {"outside the walls", "teams: {blue: [{id: 0, x: -1, y: 0}, {id: 1, x: -6.6, y: 0}]}",
       "teams.blue[1]: robot blue 1: start pose must be finite and inside the walls"},
      {"robot not a map", "teams: {blue: [3]}", "teams.blue[0]: expected a map, got \"3\""},
      {"team not a list", "teams: {blue: 5}", "teams.blue: expected a list of robots"},
      {"too many robots", SeventeenBlueRobots(), "teams.blue: at most 16 robots, got 17"},
      // Not a scene at all.
      {"malformed: unbalanced bracket", "teams: {blue: [{id: 0, x: 1, y: 0}", "malformed YAML at line 1"},
      {"malformed: bad indentation", "field:\n  length: 10\n width: 8\n", "malformed YAML"},
      {"malformed: unknown alias", "field: *nowhere", "malformed YAML"},
      {"empty text", "", "expected a map of scene settings at the top level"},
      {"only a comment", "# nothing\n", "expected a map of scene settings"},
      {"a list", "- 1\n- 2\n", "expected a map of scene settings"},
      {"a scalar", "hello", "expected a map of scene settings"},
      {"two documents", "seed: 1\n---\nseed: 2\n", "expected one YAML document, got 2"},
      // yaml-cpp's LoadAll never returns on these (a document starting with ','); the reader does not use it.
      {"a document starting with ','", ", seed: 1\n", "malformed YAML at line 1, column 1: no document can start here"},
      {"a second document starting with ','", "seed: 1\n---\n, seed: 2\n", "malformed YAML at line 3, column 1"},
      {"a list, then ','", "- 1\n, x\n", "malformed YAML at line 2, column 1"},
      {"non-scalar key", "? [a, b]\n: 1\n", "expected a name as key, got a list"},
  };
  for (const BadCase& c : cases) {
    SCOPED_TRACE(fmt::format("{}:\n{}", c.what, c.yaml));
    const SceneLoadResult result = ParseSceneYaml(c.yaml);
    EXPECT_FALSE(result.scene.has_value());
    EXPECT_TRUE(HasErrorContaining(result, c.expected_error)) << "want: " << c.expected_error << "\n"
                                                              << ErrorList(result);
  }
}

TEST(SceneYamlErrors, AllProblemsAreReportedAtOnce) {
  const SceneLoadResult result = ParseSceneYaml(R"(
field: {lenght: 10}
ball: {mass: heavy, radius: 3}
robot: {drive: {max_speed: .inf}}
)");
  EXPECT_FALSE(result.scene.has_value());
  EXPECT_EQ(result.errors.size(), 4u) << ErrorList(result);
  EXPECT_TRUE(HasErrorContaining(result, "field.lenght: unknown key"));
  EXPECT_TRUE(HasErrorContaining(result, "ball.mass: expected a number"));
  EXPECT_TRUE(HasErrorContaining(result, "ball.radius must be in"));
  EXPECT_TRUE(HasErrorContaining(result, "robot.drive.max_speed: expected a finite number"));
}

TEST(SceneYamlErrors, HostileInputNeverCrashes) {
  const std::vector<std::string> inputs = {
      std::string(100000, '['),  // deeper than yaml-cpp's recursion guard
      std::string(5000, '{'),
      "teams: &a {blue: *a}",
      "a: &x [*x, *x]\nteams: {blue: [*x]}",
      std::string("\0\xff\xfe field", 9),
      "field: !!binary aGVsbG8=",
      "\t\tfield: 1",
      "teams: {blue: [{id: 0, x: 1, y: 2}], blue: []}",
  };
  for (const std::string& input : inputs) {
    SCOPED_TRACE(input.substr(0, 40));
    SceneLoadResult result;
    EXPECT_NO_THROW(result = ParseSceneYaml(input));
    EXPECT_FALSE(result.scene.has_value());
    EXPECT_FALSE(result.errors.empty());
  }
}

TEST(SceneYamlErrors, EveryTruncationOfTheDefaultSceneIsHandled) {
  // Cut the file anywhere: each prefix gives a scene or errors, never both, never a crash.
  const std::string text = test::ReadText(test::ScenePath("ssl_div_a.yaml"));
  ASSERT_FALSE(text.empty());
  for (size_t length = 0; length <= text.size(); length += 3) {
    const SceneLoadResult result = ParseSceneYaml(text.substr(0, length));
    EXPECT_NE(result.scene.has_value(), !result.errors.empty()) << length;
  }
}

TEST(SceneYamlErrors, MissingFileIsAnErrorNamingThePath) {
  const std::string path = test::ScenePath("no_such_scene.yaml");
  const SceneLoadResult result = LoadSceneFile(path);
  EXPECT_FALSE(result.scene.has_value());
  ASSERT_EQ(result.errors.size(), 1u) << ErrorList(result);
  EXPECT_EQ(result.errors[0], path + ": no such file");
}

TEST(SceneYamlErrors, DirectoryIsNotASceneFile) {
  const SceneLoadResult result = LoadSceneFile(test::ScenePath(""));
  EXPECT_FALSE(result.scene.has_value());
  EXPECT_TRUE(HasErrorContaining(result, "not a regular file")) << ErrorList(result);
}

}  // namespace
}  // namespace turf
