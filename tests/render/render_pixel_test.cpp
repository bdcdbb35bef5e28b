// turf-render's GL part without DDS: a known scene rendered offscreen through EGL (Mesa's llvmpipe here, a GPU
// where there is one). Skips cleanly, saying why, where no EGL display can be made.
#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>

#include "codecs/image/image_codec.h"
#include "core/legged/legged_cameras.h"
#include "core/legged/legged_mjcf.h"
#include "core/mj_state.h"
#include "loader/legged_scene_yaml.h"
#include "participants/render/egl_context.h"
#include "participants/render/field_look.h"
#include "participants/render/scene_renderer.h"
#include "participants/render/team_colours.h"

namespace turf {
namespace {

const std::string kScenes = std::string(TURF_SOURCE_DIR) + "/configs/scenes/";

struct Loaded {
  LeggedScene scene;
  std::vector<CameraSpec> cameras;
};

Loaded Load(const std::string& yaml) {
  LeggedSceneLoadResult r = ParseLeggedSceneYaml(yaml, kScenes);
  if (!r.scene) throw std::runtime_error(r.errors.front());
  const LeggedMjcf mjcf = ComposeLeggedMjcf(*r.scene);
  MjModelPtr model(CompileLeggedMjcf(mjcf.xml));
  LeggedCameras c = ResolveLeggedCameras(*r.scene, model.get());
  if (!c.errors.empty()) throw std::runtime_error(c.errors.front());
  return {std::move(*r.scene), std::move(c.cameras)};
}

std::unique_ptr<EglContext> MakeContextOrNull(std::string* why) {
  try {
    return std::make_unique<EglContext>();
  } catch (const std::exception& e) {
    *why = e.what();
    return nullptr;
  }
}

// Saves the image as build/tests/render/artifacts/<name>.jpg, to look at.
void SaveArtifact(const std::string& name, const std::vector<uint8_t>& rgb, int w, int h) {
  const std::string dir = std::string(TURF_BINARY_DIR) + "/tests/render/artifacts";
  std::filesystem::create_directories(dir);
  const image::Encoded jpeg = image::EncodeJpeg(rgb, w, h, 90);
  std::ofstream(dir + "/" + name + ".jpg", std::ios::binary)
      .write(reinterpret_cast<const char*>(jpeg.bytes.data()), static_cast<std::streamsize>(jpeg.bytes.size()));
}

bool Orange(const uint8_t* p) { return p[0] > 90 && p[1] > 0.3 * p[0] && p[1] < 0.75 * p[0] && p[2] < 0.3 * p[0]; }

// The centroid of the orange pixels, if any.
std::optional<std::array<double, 2>> OrangeCentroid(const std::vector<uint8_t>& rgb, int w, int h, int* count) {
  double su = 0, sv = 0;
  *count = 0;
  for (int v = 0; v < h; ++v)
    for (int u = 0; u < w; ++u)
      if (Orange(&rgb[3 * (static_cast<size_t>(v) * w + u)])) {
        su += u;
        sv += v;
        ++*count;
      }
  if (*count == 0) return std::nullopt;
  return std::array<double, 2>{su / *count, sv / *count};
}

// Each GL test skips, saying why, where no EGL display can be made.
class WithEgl : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string why;
    egl_ = MakeContextOrNull(&why);
    if (!egl_) GTEST_SKIP() << "no EGL display: " << why;
  }

 private:
  std::unique_ptr<EglContext> egl_;
};

class RenderPixel : public WithEgl {
 protected:
  // A T1 at x = -5 with one head camera of 320 x 240 pixels.
  static Loaded HeadCamera(int hfov_deg) {
    return Load(
        "kind: legged\nfield: {}\nrobots:\n  - name: t1\n    model: ../robots/t1.xml\n    x: -5\n    cameras:\n"
        "      - {name: camera, width: 320, height: 240, hfov_deg: " +
        std::to_string(hfov_deg) + "}\n");
  }
};

// A T1's head camera, its head placed 1.5 m above the field looking along world +x (yawed), and the ball put 1 m
// in front of the camera, off the optical axis: the ball's pixels are centred where the pinhole model projects the
// ball's centre, within 2 px.
TEST_F(RenderPixel, TheBallAppearsWhereThePinholeModelPutsIt) {
  Loaded l = HeadCamera(70);
  SceneRenderer renderer(l.scene, l.cameras);
  const double yaw = 0.3;
  ASSERT_TRUE(renderer.SetBodyPose("t1", "H2", Pose{{2.0, 1.0, 1.5}, {std::cos(yaw / 2), 0, 0, std::sin(yaw / 2)}}));
  renderer.UpdateFrames();
  const Pose cam = renderer.CameraPose(0);
  const auto f = CameraForward(cam);
  const auto up = CameraUp(cam);
  // 1 m ahead, 0.15 m up and a little to the side (left of the axis: forward x up).
  const std::array<double, 3> left{up[1] * f[2] - up[2] * f[1], up[2] * f[0] - up[0] * f[2],
                                   up[0] * f[1] - up[1] * f[0]};
  std::array<double, 3> ball;
  for (int i = 0; i < 3; ++i) ball[i] = cam.position[i] + f[i] + 0.15 * up[i] - 0.2 * left[i];
  ASSERT_TRUE(renderer.SetBallPosition(ball));
  renderer.UpdateFrames();
  std::vector<uint8_t> rgb;
  renderer.Render(0, &rgb);
  const CameraSpec& c = l.cameras[0];
  ASSERT_EQ(rgb.size(), static_cast<size_t>(c.width * c.height * 3));
  SaveArtifact("ball_1m", rgb, c.width, c.height);
  const auto predicted = ProjectOptical(IntrinsicsOf(c.width, c.height, c.hfov), WorldToOptical(cam, ball));
  ASSERT_TRUE(predicted);
  int count = 0;
  const auto centroid = OrangeCentroid(rgb, c.width, c.height, &count);
  ASSERT_TRUE(centroid) << "no orange pixel in the image";
  // The ball (radius 0.042 m at 1 m) covers about pi * (f * 0.042)^2 pixels.
  const double f_px = IntrinsicsOf(c.width, c.height, c.hfov).fx;
  EXPECT_GT(count, 0.5 * M_PI * std::pow(f_px * 0.042, 2));
  EXPECT_NEAR((*centroid)[0], (*predicted)[0], 2.0) << "predicted u " << (*predicted)[0];
  EXPECT_NEAR((*centroid)[1], (*predicted)[1], 2.0) << "predicted v " << (*predicted)[1];
  // The pixel the model predicts is the ball's colour.
  const int u = static_cast<int>(std::lround((*predicted)[0]));
  const int v = static_cast<int>(std::lround((*predicted)[1]));
  EXPECT_TRUE(Orange(&rgb[3 * (static_cast<size_t>(v) * c.width + u)]));
}

// Culling keeps what a camera partly sees: a ball whose centre lies just past the image's right edge still shows
// its left part there.
TEST_F(RenderPixel, ABallHalfOutOfViewIsStillDrawnAtTheEdge) {
  Loaded l = HeadCamera(70);
  SceneRenderer renderer(l.scene, l.cameras);
  ASSERT_TRUE(renderer.SetBodyPose("t1", "H2", Pose{{2.0, 1.0, 1.5}, {1, 0, 0, 0}}));
  renderer.UpdateFrames();
  const Pose cam = renderer.CameraPose(0);
  // 1 m ahead (+x), the centre 0.01 m beyond the right edge of the view (image right = world -y), level.
  const double edge = std::tan(35.0 * M_PI / 180.0);
  ASSERT_TRUE(renderer.SetBallPosition({cam.position[0] + 1.0, cam.position[1] - edge - 0.01, cam.position[2]}));
  renderer.UpdateFrames();
  std::vector<uint8_t> rgb;
  renderer.Render(0, &rgb);
  int count = 0;
  const auto centroid = OrangeCentroid(rgb, 320, 240, &count);
  ASSERT_TRUE(centroid) << "the ball was culled";
  EXPECT_GT((*centroid)[0], 310.0);
  // Level with the camera: around the middle row (a sliver's shaded lower part reads darker than "orange", so its
  // centroid sits a few pixels high).
  EXPECT_NEAR((*centroid)[1], 119.5, 6.0);
}

// Looking down at the field from above the halfway line: green grass and the white line, as wide as the field's
// markings say (SimSpark field: 0.05 m).
TEST_F(RenderPixel, TheFieldIsGreenWithWhiteLinesOfTheirWidth) {
  Loaded l = HeadCamera(60);
  SceneRenderer renderer(l.scene, l.cameras);
  // The head 2 m above (0, 1): pitched down 90 deg, the camera (looking along the head's +x) looks straight down,
  // image up = world +x, so the halfway line (x = 0) runs across the image's middle row.
  const double s = std::sqrt(0.5);
  ASSERT_TRUE(renderer.SetBodyPose("t1", "H2", Pose{{-0.12, 1.0, 2.05}, {s, 0, s, 0}}));
  renderer.UpdateFrames();
  const Pose cam = renderer.CameraPose(0);
  ASSERT_NEAR(cam.position[2], 2.0, 1e-9);
  std::vector<uint8_t> rgb;
  renderer.Render(0, &rgb);
  const CameraSpec& c = l.cameras[0];
  SaveArtifact("halfway_line_from_2m", rgb, c.width, c.height);
  const Intrinsics k = IntrinsicsOf(c.width, c.height, c.hfov);
  const int u = c.width / 2;
  int white_rows = 0;
  for (int v = 0; v < c.height; ++v) {
    const uint8_t* p = &rgb[3 * (static_cast<size_t>(v) * c.width + u)];
    if (p[0] > 150 && p[1] > 150 && p[2] > 150) ++white_rows;
  }
  // 0.05 m at 2 m: f * 0.025 px.
  EXPECT_NEAR(white_rows, k.fy * 0.05 / 2.0, 1.5);
  const uint8_t* grass = &rgb[3 * (static_cast<size_t>(20) * c.width + u)];
  EXPECT_GT(grass[1], grass[0] + 20);
  EXPECT_GT(grass[1], grass[2] + 20);
}

TEST(TeamColours, TheNameSaysTheTeam) {
  ASSERT_TRUE(TeamColour("red_1").has_value());
  EXPECT_TRUE(TeamColour("Blue-3").has_value());
  EXPECT_TRUE(TeamColour("yellow2").has_value());
  EXPECT_TRUE(TeamColour("blue").has_value());
  ASSERT_TRUE(TeamColour("blue_1").has_value());
  EXPECT_FALSE(TeamColour("redshirt").has_value());
  EXPECT_FALSE(TeamColour("nao_1").has_value());
  EXPECT_FALSE(TeamColour("").has_value());
  EXPECT_GT((*TeamColour("red_1"))[0], 0.8f);
  EXPECT_GT((*TeamColour("blue_1"))[2], 0.8f);
}

// red_1's head camera 1.2 m in front of blue_1, level: blue_1's trunk is blue in the image (and not with
// --no-team-colours); with the lights at half brightness the grass below the horizon is darker.
class TeamLook : public WithEgl {
 protected:
  std::vector<uint8_t> Render(const RenderLook& look) {
    Loaded l = Load(
        "kind: legged\nfield: {}\nrobots:\n  - name: red_1\n    model: ../robots/t1.xml\n    x: -5\n    cameras:\n"
        "      - {name: camera, width: 160, height: 120, hfov_deg: 60}\n"
        "  - name: blue_1\n    model: ../robots/t1.xml\n    x: 0\n    yaw_deg: 180\n");
    SceneRenderer renderer(l.scene, l.cameras, look);
    EXPECT_TRUE(renderer.SetBodyPose("red_1", "H2", Pose{{-1.2, 0.0, 0.75}, {1, 0, 0, 0}}));
    renderer.UpdateFrames();
    std::vector<uint8_t> rgb;
    renderer.Render(0, &rgb);
    return rgb;
  }
  static int Blue(const std::vector<uint8_t>& rgb) {
    int n = 0;
    for (size_t i = 0; i + 2 < rgb.size(); i += 3)
      n += rgb[i + 2] > 120 && rgb[i + 2] > rgb[i] + 60 && rgb[i + 2] > rgb[i + 1] + 50;
    return n;
  }
  // The mean green of the bottom quarter (grass).
  static double Grass(const std::vector<uint8_t>& rgb) {
    double sum = 0;
    int n = 0;
    for (size_t i = rgb.size() * 3 / 4 / 3 * 3; i + 2 < rgb.size(); i += 3, ++n) sum += rgb[i + 1];
    return sum / n;
  }
};

TEST_F(TeamLook, ATeamRobotWearsItsColourAndTheLightsDim) {
  const std::vector<uint8_t> team = Render(RenderLook{});
  SaveArtifact("blue_1_from_red_1", team, 160, 120);
  const std::vector<uint8_t> plain = Render(RenderLook{false, 1.0});
  SaveArtifact("blue_1_no_team_colours", plain, 160, 120);
  const std::vector<uint8_t> dim = Render(RenderLook{true, 0.5});
  SaveArtifact("blue_1_half_light", dim, 160, 120);
  EXPECT_GT(Blue(team), 150) << "blue_1's trunk, about 17 x 23 px at 1.2 m";
  EXPECT_LT(Blue(plain), 10);
  EXPECT_LT(Grass(dim), 0.8 * Grass(team)) << Grass(dim) << " vs " << Grass(team);
  EXPECT_GT(Grass(dim), 0.2 * Grass(team)) << "dimmer, not black";
}

TEST(FieldLook, MarkingsFollowTheFieldSize) {
  Field3d simspark;
  EXPECT_DOUBLE_EQ(MarkingsFor(simspark).line_width, 0.05);
  Field3d fifa;
  fifa.length = 105;
  EXPECT_DOUBLE_EQ(MarkingsFor(fifa).line_width, 0.12);
  EXPECT_DOUBLE_EQ(MarkingsFor(fifa).centre_circle_radius, 9.15);
  const std::string xml = "<mujoco><worldbody>\n</worldbody></mujoco>";
  fifa.enabled = true;
  const std::string with = AddFieldLook(xml, fifa);
  EXPECT_NE(with.find("name=\"line_halfway\""), std::string::npos);
  EXPECT_NE(with.find("contype=\"0\" conaffinity=\"0\""), std::string::npos);
  Field3d none;
  EXPECT_EQ(AddFieldLook(xml, none).find("line_"), std::string::npos);
}

}  // namespace
}  // namespace turf
