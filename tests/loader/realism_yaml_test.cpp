#include "loader/realism_yaml.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "loader/legged_scene_yaml.h"
#include "loader/scene_yaml.h"
#include "tests/loader/test_util.h"

namespace turf {
namespace {

using test::ReadText;

bool Mentions(const std::vector<std::string>& errors, const std::string& text) {
  for (const std::string& e : errors)
    if (e.find(text) != std::string::npos) return true;
  return false;
}

TEST(RealismYaml, ShippedPresetsLoad) {
  for (const char* name : {"ideal", "realistic", "harsh"}) {
    const RealismLoadResult r = LoadRealism(name);
    EXPECT_TRUE(r.realism.has_value()) << name << ": " << (r.errors.empty() ? "" : r.errors[0]);
  }
  const SensorRealism ideal = *LoadRealism("ideal").realism;
  EXPECT_EQ(ideal.camera.robot_position_stddev, 0.0);
  EXPECT_EQ(ideal.camera.link.latency, 0.0);
  EXPECT_FALSE(ideal.command.burst.enabled);
  const SensorRealism realistic = *LoadRealism("realistic").realism;
  EXPECT_GT(realistic.camera.robot_position_stddev, 0.0);
  EXPECT_TRUE(realistic.camera.ball_occlusion);
  EXPECT_TRUE(realistic.command.burst.enabled);
  const SensorRealism harsh = *LoadRealism("harsh").realism;
  EXPECT_GT(harsh.camera.robot_position_stddev, realistic.camera.robot_position_stddev);
  EXPECT_EQ(harsh.camera.link.jitter_kind, JitterKind::kExponential);
}

TEST(RealismYaml, InlineTextAndEveryKey) {
  const RealismLoadResult r = LoadRealism(
      "camera: {robot_position_stddev: 0.01, ball_vanish: 0.5, ball_occlusion: true, processing_delay: 0.02,"
      " link: {latency: 0.003, jitter: 0.001, jitter_kind: uniform, loss: 0.1}}\n"
      "command: {latency: 0.01, burst: {p_good_to_bad: 0.1, p_bad_to_good: 0.5, loss_good: 0, loss_bad: 1}}\n"
      "encoder: {resolution: 0.001}\nimu: {gyro_noise_stddev: 0.1}");
  ASSERT_TRUE(r.realism.has_value()) << r.errors[0];
  EXPECT_DOUBLE_EQ(r.realism->camera.robot_position_stddev, 0.01);
  EXPECT_DOUBLE_EQ(r.realism->camera.ball_vanish, 0.5);
  EXPECT_EQ(r.realism->camera.link.jitter_kind, JitterKind::kUniform);
  EXPECT_DOUBLE_EQ(r.realism->camera.link.loss, 0.1);
  EXPECT_TRUE(r.realism->command.burst.enabled);
  EXPECT_DOUBLE_EQ(r.realism->command.burst.p_bad_to_good, 0.5);
  EXPECT_DOUBLE_EQ(r.realism->encoder.resolution, 0.001);
  EXPECT_DOUBLE_EQ(r.realism->imu.gyro_noise_stddev, 0.1);
}

TEST(RealismYaml, TextChangesOnlyWhatItNames) {
  const SensorRealism base = *LoadRealism("realistic").realism;
  const RealismLoadResult r = LoadRealism("camera: {ball_vanish: 0.5}", DefaultRealismDir(), false, base);
  ASSERT_TRUE(r.realism.has_value());
  EXPECT_DOUBLE_EQ(r.realism->camera.ball_vanish, 0.5);
  EXPECT_DOUBLE_EQ(r.realism->camera.robot_position_stddev, base.camera.robot_position_stddev);
  EXPECT_TRUE(r.realism->command.burst.enabled);
  // A preset replaces everything.
  const RealismLoadResult ideal = LoadRealism("ideal", DefaultRealismDir(), false, base);
  EXPECT_EQ(ideal.realism->camera.robot_position_stddev, 0.0);
}

TEST(RealismYaml, BadInputIsRefusedWithTheKey) {
  struct Case {
    const char* text;
    const char* error;
  };
  for (const Case& c :
       {Case{"camera: {robot_position_stdev: 0.1}", "camera.robot_position_stdev"},
        Case{"camera: {link: {jitter_kind: pink}}", "jitter_kind"}, Case{"command: {loss: 1.5}", "probability"},
        Case{"command: {latency: .nan}", "command.latency"}, Case{"camera: {robot_vanish: -0.1}", "vanish"},
        Case{"command: {burst: {p_bad_to_good: 0}}", "bursts must end"}, Case{"camera: [1, 2", "malformed"},
        Case{"- 1\n- 2", "expected a map"},
        // One document, as a scene file: a second one (or garbage after its end) was ignored, and "," read as ideal.
        Case{"camera: {robot_vanish: 0.1}\n---\ncamera: {robot_vanish: 5}\n", "one YAML document"},
        Case{"camera: {robot_vanish: 0.1}\n...\ngarbage: [\n", "malformed"}, Case{",", "malformed"}}) {
    const RealismLoadResult r = ParseRealismYaml(c.text);
    EXPECT_FALSE(r.realism.has_value()) << c.text;
    EXPECT_TRUE(Mentions(r.errors, c.error)) << c.text << " -> " << (r.errors.empty() ? "no error" : r.errors[0]);
  }
}

TEST(RealismYaml, ATextOfOnlyCommentsChangesNothing) {
  for (const char* text : {"", "\n  \n", "# nothing\n  # here\n"}) {
    const RealismLoadResult r = ParseRealismYaml(text);
    EXPECT_TRUE(r.realism.has_value()) << "'" << text << "': " << (r.errors.empty() ? "" : r.errors[0]);
  }
}

TEST(RealismYaml, PresetNamesAreNamesAndPathsCanBeRefused) {
  EXPECT_TRUE(Mentions(LoadRealism("nonexistent").errors, "no realism preset \"nonexistent\" (presets: "));
  EXPECT_TRUE(Mentions(LoadRealism("Bad Name!").errors, "not a realism preset name"));
  const RealismLoadResult r = LoadRealism("/etc/passwd", DefaultRealismDir(), /*allow_paths=*/false);
  EXPECT_FALSE(r.realism.has_value());
  EXPECT_TRUE(Mentions(r.errors, "not accepted"));
}

TEST(RealismYaml, ScenesNameAPresetOrSetValues) {
  const SceneLoadResult named = ParseSceneYaml("realism: realistic");
  ASSERT_TRUE(named.scene.has_value()) << named.errors[0];
  EXPECT_GT(named.scene->realism.camera.robot_position_stddev, 0.0);
  const SceneLoadResult inline_map = ParseSceneYaml("realism: {camera: {ball_vanish: 0.25}}");
  ASSERT_TRUE(inline_map.scene.has_value()) << inline_map.errors[0];
  EXPECT_DOUBLE_EQ(inline_map.scene->realism.camera.ball_vanish, 0.25);
  const SceneLoadResult typo = ParseSceneYaml("realism: {camera: {ball_vanishing: 0.25}}");
  EXPECT_FALSE(typo.scene.has_value());
  EXPECT_TRUE(Mentions(typo.errors, "realism.camera.ball_vanishing"));
  const SceneLoadResult missing = ParseSceneYaml("realism: nosuchpreset");
  EXPECT_FALSE(missing.scene.has_value());
  EXPECT_TRUE(Mentions(missing.errors, "realism"));
  // An unknown preset is told what there is.
  EXPECT_TRUE(Mentions(missing.errors, "presets: harsh, ideal, realistic")) << missing.errors[0];
  EXPECT_EQ(RealismPresets(), (std::vector<std::string>{"harsh", "ideal", "realistic"}));
}

TEST(RealismYaml, AFileIsRelativeToWhatNamesIt) {
  EXPECT_EQ(RealismSpecFrom("sub/r.yaml", "/a/b"), "/a/b/sub/r.yaml");
  EXPECT_EQ(RealismSpecFrom("../r.yaml", "/a/b"), "/a/r.yaml");
  EXPECT_EQ(RealismSpecFrom("/abs/r.yaml", "/a/b"), "/abs/r.yaml");
  EXPECT_EQ(RealismSpecFrom("sub/r.yaml", ""), "sub/r.yaml");
  EXPECT_EQ(RealismSpecFrom("harsh", "/a/b"), "harsh");                                                // a preset
  EXPECT_EQ(RealismSpecFrom("{camera: {ball_vanish: 0.5}}", "/a/b"), "{camera: {ball_vanish: 0.5}}");  // text
}

// A scene's `realism: <file>` is read next to the scene, whatever the current directory (it was read relative to
// the current one: the same scene loaded from elsewhere failed, or read another file).
TEST(RealismYaml, AScenesRealismFileIsReadNextToTheScene) {
  const std::string scenes = std::string(TURF_SOURCE_DIR) + "/configs/scenes";
  const SceneLoadResult ssl = ParseSceneYaml("realism: ../realism/harsh.yaml", scenes);
  ASSERT_TRUE(ssl.scene.has_value()) << (ssl.errors.empty() ? "" : ssl.errors[0]);
  EXPECT_DOUBLE_EQ(ssl.scene->realism.camera.ball_vanish, LoadRealism("harsh").realism->camera.ball_vanish);
  EXPECT_GT(ssl.scene->realism.camera.ball_vanish, 0.0);

  const std::string legged_text = ReadText(scenes + "/t1_stand.yaml") + "\nrealism: ../realism/harsh.yaml\n";
  const LeggedSceneLoadResult legged = ParseLeggedSceneYaml(legged_text, scenes);
  ASSERT_TRUE(legged.scene.has_value()) << (legged.errors.empty() ? "" : legged.errors[0]);
  EXPECT_DOUBLE_EQ(legged.scene->realism.imu.gyro_noise_stddev, LoadRealism("harsh").realism->imu.gyro_noise_stddev);
  EXPECT_GT(legged.scene->realism.imu.gyro_noise_stddev, 0.0);

  // From a file: its own directory, not the test's.
  const std::string dir = ::testing::TempDir() + "/scene_realism_test";
  std::filesystem::create_directories(dir + "/noise");
  std::ofstream(dir + "/noise/mine.yaml") << "camera: {ball_vanish: 0.375}\n";
  std::ofstream(dir + "/scene.yaml") << "realism: noise/mine.yaml\n";
  const SceneLoadResult from_file = LoadSceneFile(dir + "/scene.yaml");
  ASSERT_TRUE(from_file.scene.has_value()) << (from_file.errors.empty() ? "" : from_file.errors[0]);
  EXPECT_DOUBLE_EQ(from_file.scene->realism.camera.ball_vanish, 0.375);
  EXPECT_FALSE(ParseSceneYaml("realism: noise/mine.yaml").scene.has_value());  // the current directory has none
}

}  // namespace
}  // namespace turf
