// Camera declarations of legged scenes (core/legged/legged_cameras.h): the robot files' MJCF cameras, the
// scene's overrides and new cameras, each refusal naming the robot and camera.
#include "core/legged/legged_cameras.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/legged/legged_mjcf.h"
#include "core/mj_state.h"
#include "loader/legged_scene_yaml.h"

namespace turf {
namespace {

const std::string kScenes = std::string(TURF_SOURCE_DIR) + "/configs/scenes/";

LeggedCameras Resolve(const std::string& yaml) {
  LeggedSceneLoadResult r = ParseLeggedSceneYaml(yaml, kScenes);
  EXPECT_TRUE(r.scene) << (r.errors.empty() ? "" : r.errors.front());
  if (!r.scene) return {};
  const LeggedMjcf mjcf = ComposeLeggedMjcf(*r.scene);
  MjModelPtr model(CompileLeggedMjcf(mjcf.xml));
  return ResolveLeggedCameras(*r.scene, model.get());
}

bool HasError(const LeggedCameras& c, const std::string& part) {
  for (const std::string& e : c.errors)
    if (e.find(part) != std::string::npos) return true;
  return false;
}

TEST(LeggedCameras, TheT1HeadCameraAndTheNaosTwoAreDeclaredByTheirRobotFiles) {
  const LeggedCameras c = Resolve(
      "kind: legged\nrobots:\n  - {name: t1, model: ../robots/t1.xml}\n  - {name: nao, model: ../robots/nao.xml, x: "
      "2}\n");
  ASSERT_TRUE(c.errors.empty()) << c.errors.front();
  ASSERT_EQ(c.cameras.size(), 3u);
  EXPECT_EQ(CameraId(c.cameras[0]), "t1/camera");
  EXPECT_EQ(c.cameras[0].body, "H2");
  EXPECT_NEAR(VerticalFov(320, 240, c.cameras[0].hfov), 63.6 * M_PI / 180, 1e-9);
  EXPECT_NEAR(c.cameras[0].pos[0], 0.05, 1e-12);
  EXPECT_EQ(CameraId(c.cameras[1]), "nao/top");
  EXPECT_EQ(CameraId(c.cameras[2]), "nao/bottom");
  EXPECT_EQ(c.cameras[2].body, "head");
  EXPECT_EQ(c.cameras[1].width, 320);
  EXPECT_EQ(c.cameras[1].encoding, ImageEncoding::kRgb8);
  EXPECT_DOUBLE_EQ(c.cameras[1].rate_hz, 30.0);
}

TEST(LeggedCameras, TheSceneOverridesAnMjcfCameraAndAddsOne) {
  const LeggedCameras c = Resolve(
      "kind: legged\nrobots:\n  - name: k1\n    model: ../robots/k1.xml\n    cameras:\n"
      "      - {name: camera, width: 640, height: 480, rate_hz: 60, encoding: yuv422}\n"
      "      - {name: chest, body: torso, pos: [0.1, 0, 0], xyaxes: [0, -1, 0, 0, 0, 1], hfov_deg: 90, "
      "encoding: jpeg, jpeg_quality: 70, noise_stddev: 2}\n");
  ASSERT_TRUE(c.errors.empty()) << c.errors.front();
  ASSERT_EQ(c.cameras.size(), 2u);
  EXPECT_EQ(c.cameras[0].width, 640);
  EXPECT_EQ(c.cameras[0].encoding, ImageEncoding::kYuv422);
  EXPECT_NEAR(VerticalFov(640, 480, c.cameras[0].hfov), 68 * M_PI / 180, 1e-9);  // the file's fovy kept
  EXPECT_EQ(c.cameras[1].body, "torso");
  EXPECT_NEAR(c.cameras[1].hfov, M_PI / 2, 1e-12);
  EXPECT_EQ(c.cameras[1].encoding, ImageEncoding::kJpeg);
  // xyaxes 0 -1 0 / 0 0 1 is the quaternion (0.5, 0.5, -0.5, -0.5): looking along the body's +x.
  EXPECT_NEAR(std::abs(c.cameras[1].quat[0]), 0.5, 1e-9);
}

TEST(LeggedCameras, BadDeclarationsAreRefusedByName) {
  const std::string head = "kind: legged\nrobots:\n  - name: t1\n    model: ../robots/t1.xml\n    cameras:\n";
  EXPECT_TRUE(HasError(Resolve(head + "      - {name: eye}\n"), "camera 'eye': the robot file has no camera"));
  EXPECT_TRUE(HasError(Resolve(head + "      - {name: eye, body: nose}\n"), "body 'nose' is not a body"));
  EXPECT_TRUE(HasError(Resolve(head + "      - {name: camera, width: 321}\n"), "width 321 must be even"));
  EXPECT_TRUE(HasError(Resolve(head + "      - {name: camera, rate_hz: 0}\n"), "rate_hz 0"));
  EXPECT_TRUE(HasError(Resolve(head + "      - {name: camera, encoding: bgr8}\n"), "encoding 'bgr8'"));
  EXPECT_TRUE(HasError(Resolve(head + "      - {name: camera, hfov_deg: 180}\n"), "hfov_deg 180"));
  EXPECT_TRUE(HasError(Resolve(head + "      - {name: camera, jpeg_quality: 0}\n"), "jpeg_quality 0"));
  EXPECT_TRUE(HasError(Resolve(head + "      - {name: camera, xyaxes: [1, 0, 0, 2, 0, 0]}\n"), "xyaxes"));
  // 1e300 squared is infinite: the axis was normalized to zero and the camera pointed anywhere.
  EXPECT_TRUE(HasError(Resolve(head + "      - {name: camera, xyaxes: [1e300, 0, 0, 0, 1, 0]}\n"), "xyaxes"));
  EXPECT_TRUE(HasError(Resolve(head + "      - {name: camera, rate_hz: 1e-10}\n"), "rate_hz 1e-10"));
  // A camera name that cannot be part of a ROS topic name.
  EXPECT_TRUE(HasError(Resolve(head + "      - {name: my-eye, body: H2}\n"), "cannot name a ROS topic"));
}

TEST(LeggedCameras, UnknownKeysInACameraAreNamed) {
  LeggedSceneLoadResult r = ParseLeggedSceneYaml(
      "kind: legged\nrobots:\n  - {name: t1, model: ../robots/t1.xml, cameras: [{name: camera, fps: 30}]}\n", kScenes);
  ASSERT_FALSE(r.scene);
  bool named = false;
  for (const std::string& e : r.errors) named = named || e.find("robots[0].cameras[0].fps") != std::string::npos;
  EXPECT_TRUE(named) << r.errors.front();
}

}  // namespace
}  // namespace turf
