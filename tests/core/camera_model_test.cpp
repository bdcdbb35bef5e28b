// The pinhole camera model and the frame schedule (core/camera/camera_model.h).
#include "core/camera/camera_model.h"

#include <gtest/gtest.h>

#include <cmath>

namespace turf {
namespace {

TEST(CameraModel, IntrinsicsOfAHorizontalFieldOfView) {
  const Intrinsics k = IntrinsicsOf(320, 240, M_PI / 2);  // 90 deg: f = half the width
  EXPECT_DOUBLE_EQ(k.fx, 160.0);
  EXPECT_DOUBLE_EQ(k.fy, 160.0);
  EXPECT_DOUBLE_EQ(k.cx, 159.5);
  EXPECT_DOUBLE_EQ(k.cy, 119.5);
  EXPECT_NEAR(VerticalFov(320, 240, M_PI / 2), 2 * std::atan(0.75), 1e-12);
  EXPECT_NEAR(HorizontalFov(320, 240, VerticalFov(320, 240, 1.0)), 1.0, 1e-12);
}

TEST(CameraModel, ProjectsThePrincipalRayToTheCentreAndEdgesToTheBorder) {
  const Intrinsics k = IntrinsicsOf(320, 240, M_PI / 2);
  auto c = ProjectOptical(k, {0, 0, 2});
  ASSERT_TRUE(c);
  EXPECT_DOUBLE_EQ((*c)[0], 159.5);
  EXPECT_DOUBLE_EQ((*c)[1], 119.5);
  auto right = ProjectOptical(k, {1, 0, 1});  // 45 deg right: the image's right edge (pixel 319's outer side)
  ASSERT_TRUE(right);
  EXPECT_DOUBLE_EQ((*right)[0], 319.5);
  auto below = ProjectOptical(k, {0, 0.5, 1});  // optical y is down
  ASSERT_TRUE(below);
  EXPECT_DOUBLE_EQ((*below)[1], 119.5 + 80.0);
  EXPECT_FALSE(ProjectOptical(k, {0, 0, -1}));
  EXPECT_FALSE(ProjectOptical(k, {0, 0, 0}));
}

TEST(CameraModel, WorldPoseOfAHeadCameraLookingAlongTheBodysX) {
  // A T1-like head camera: xyaxes "0 -1 0 0 0 1" (image right = body -y, image up = body z): looks along body +x.
  CameraSpec cam;
  cam.pos = {0.05, 0, 0.12};
  cam.quat = {0.5, 0.5, -0.5, -0.5};
  Pose body;
  body.position = {1, 2, 1};
  body.orientation = {std::cos(M_PI / 4), 0, 0, std::sin(M_PI / 4)};  // yawed 90 deg: body x = world y
  const Pose p = CameraWorldPose(body, cam);
  EXPECT_NEAR(p.position[0], 1.0, 1e-12);
  EXPECT_NEAR(p.position[1], 2.05, 1e-12);
  EXPECT_NEAR(p.position[2], 1.12, 1e-12);
  const auto f = CameraForward(p);
  EXPECT_NEAR(f[1], 1.0, 1e-12);
  const auto u = CameraUp(p);
  EXPECT_NEAR(u[2], 1.0, 1e-12);
  // 1 m ahead, 0.1 m to the image's left (world -x here) and 0.1 m up.
  const auto o = WorldToOptical(p, {0.9, 3.05, 1.22});
  EXPECT_NEAR(o[0], -0.1, 1e-12);
  EXPECT_NEAR(o[1], -0.1, 1e-12);
  EXPECT_NEAR(o[2], 1.0, 1e-12);
}

TEST(CameraModel, EncodingNames) {
  EXPECT_EQ(EncodingFromName("yuv422"), ImageEncoding::kYuv422);
  EXPECT_EQ(EncodingFromName("jpeg"), ImageEncoding::kJpeg);
  EXPECT_FALSE(EncodingFromName("bgr8"));
  EXPECT_STREQ(RosEncoding(ImageEncoding::kYuv422), "yuv422_yuy2");
}

TEST(FrameSchedule, RendersOneStatePerPeriodAndCountsMissedFrames) {
  FrameSchedule s(50.0);  // 20 ms
  EXPECT_TRUE(s.Offer(0));
  EXPECT_FALSE(s.Offer(10'000'000));
  EXPECT_TRUE(s.Offer(20'000'000));
  EXPECT_FALSE(s.Offer(25'000'000));
  EXPECT_EQ(s.dropped(), 0u);
  // The renderer was busy: the next state it sees is at 95 ms. Frames were due at 40, 60 and 80 ms: the state at
  // 95 ms is rendered for the last of them, the other two are dropped.
  EXPECT_TRUE(s.Offer(95'000'000));
  EXPECT_EQ(s.dropped(), 2u);
  EXPECT_FALSE(s.Offer(99'000'000));
  EXPECT_TRUE(s.Offer(100'000'000));
  EXPECT_EQ(s.rendered(), 4u);
}

TEST(FrameSchedule, StatesSlowerThanTheRateRenderEveryStateAndCountTheRest) {
  FrameSchedule s(100.0);  // camera at 100 Hz, states at 50 Hz
  for (int i = 0; i <= 10; ++i) EXPECT_TRUE(s.Offer(i * 20'000'000LL));
  EXPECT_EQ(s.rendered(), 11u);
  EXPECT_EQ(s.dropped(), 10u);
}

// A rate below the minimum (1e-10 Hz overflowed 1e9 / rate: a period of 1 ns, every state rendered) is at worst the
// slowest schedule, never the fastest.
TEST(FrameSchedule, ATinyRateIsTheSlowestScheduleNotTheFastest) {
  FrameSchedule s(1e-10);
  EXPECT_TRUE(s.Offer(0));
  for (int i = 1; i <= 100; ++i) EXPECT_FALSE(s.Offer(i * 10'000'000LL)) << i;
  EXPECT_EQ(s.dropped(), 0u);
}

TEST(FrameSchedule, StartsOverWhenTimeGoesBack) {
  FrameSchedule s(10.0);
  EXPECT_TRUE(s.Offer(5'000'000'000LL));
  EXPECT_FALSE(s.Offer(5'050'000'000LL));
  EXPECT_TRUE(s.Offer(0));  // a reset
  EXPECT_FALSE(s.Offer(50'000'000));
  EXPECT_TRUE(s.Offer(100'000'000));
  EXPECT_EQ(s.dropped(), 0u);
}

}  // namespace
}  // namespace turf

namespace turf {
namespace {

TEST(PixelNoise, IsSeededByTheFrameAndHasTheStatedSpread) {
  CameraSpec cam;
  cam.robot = "t1";
  cam.name = "camera";
  std::vector<uint8_t> a(30000, 128), b(30000, 128), c(30000, 128);
  AddPixelNoise(&a, 4.0, 7, cam, 1'000'000);
  AddPixelNoise(&b, 4.0, 7, cam, 1'000'000);
  AddPixelNoise(&c, 4.0, 7, cam, 2'000'000);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  double sum = 0, sq = 0;
  for (uint8_t v : a) {
    sum += v - 128.0;
    sq += (v - 128.0) * (v - 128.0);
  }
  const double mean = sum / a.size();
  EXPECT_NEAR(mean, 0.0, 0.1);
  EXPECT_NEAR(std::sqrt(sq / a.size() - mean * mean), 4.0, 0.15);  // rounding adds 1/12 of a step's variance
  std::vector<uint8_t> quiet(10, 9);
  AddPixelNoise(&quiet, 0.0, 7, cam, 1);
  EXPECT_EQ(quiet, std::vector<uint8_t>(10, 9));
}

}  // namespace
}  // namespace turf
