// SSL-Vision detections: golden bytes of a small frame, decoding back with the
// generated proto, the pixel model, and the refusal of untrusted frames.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "codecs/proto/ssl_vision.pb.h"
#include "codecs/ssl_vision/calibration.h"
#include "codecs/ssl_vision/detection.h"
#include "tests/support/idl_values.h"

namespace turf::vision {
namespace {

using test::V2;
using test::V3;

idl::DetectedRobot Robot(idl::Team team, int id, double x, double y, double orientation, float confidence) {
  idl::DetectedRobot r;
  r.team(team);
  r.id(static_cast<uint8_t>(id));
  r.position(V2(x, y));
  r.orientation(orientation);
  r.height(0.15);
  r.confidence(confidence);
  return r;
}

// A camera 4 m above the robots' tops (4.15 m above the floor) at (1, 1), so
// that every pixel below is a round number.
idl::CameraInfo GoldenCamera() {
  idl::CameraInfo c;
  c.id(1);
  c.position(V3(1.0, 1.0, 4.15));
  c.focal_length(400.0);
  c.image_width(800);
  c.image_height(600);
  return c;
}

// One ball (in the air at 0.15 m), one blue and one yellow robot (blue first:
// the wire lists yellow before blue, by field number).
idl::CameraFrame GoldenFrame() {
  idl::CameraFrame f;
  f.camera_id(1);
  f.frame_number(7);
  f.capture_time_ns(1'000'000'000);
  f.sent_time_ns(1'500'000'000);
  idl::DetectedBall ball;
  ball.position(V3(2.0, -1.0, 0.15));
  ball.confidence(1.0f);
  f.balls().push_back(ball);
  f.robots().push_back(Robot(idl::TEAM_BLUE, 3, 0.5, 1.5, 0.5, 0.75f));
  f.robots().push_back(Robot(idl::TEAM_YELLOW, 10, -1.0, 0.0, -1.5, 1.0f));
  return f;
}

// clang-format off
const std::vector<uint8_t> kGoldenDetection = {
    0x0A, 0x7F,                                      // SSL_WrapperPacket.detection (1, LEN), 127 bytes
    0x08, 0x07,                                      //   frame_number (1, varint) = 7
    0x11, 0, 0, 0, 0, 0, 0, 0xF0, 0x3F,              //   t_capture (2, fixed64) = 1.0
    0x19, 0, 0, 0, 0, 0, 0, 0xF8, 0x3F,              //   t_sent (3, fixed64) = 1.5
    0x20, 0x01,                                      //   camera_id (4, varint) = 1
    0x2A, 0x19,                                      //   balls (5, LEN), 25 bytes
    0x0D, 0x00, 0x00, 0x80, 0x3F,                    //     confidence (1, fixed32) = 1.0f
    0x1D, 0x00, 0x00, 0xFA, 0x44,                    //     x (3) = 2000 mm
    0x25, 0x00, 0x00, 0x7A, 0xC4,                    //     y (4) = -1000 mm
                                                     //     no z (5), as SSL-Vision: x, y on the carpet plane
    0x35, 0x00, 0x00, 0xFA, 0x43,                    //     pixel_x (6) = 500 = 400 + 400 * 1 m / 4 m
    0x3D, 0x00, 0x00, 0xFA, 0x43,                    //     pixel_y (7) = 500 = 300 - 400 * -2 m / 4 m
    0x32, 0x25,                                      //   robots_yellow (6, LEN), 37 bytes
    0x0D, 0x00, 0x00, 0x80, 0x3F,                    //     confidence (1) = 1.0f
    0x10, 0x0A,                                      //     robot_id (2, varint) = 10
    0x1D, 0x00, 0x00, 0x7A, 0xC4,                    //     x (3) = -1000 mm
    0x25, 0x00, 0x00, 0x00, 0x00,                    //     y (4) = 0 mm
    0x2D, 0x00, 0x00, 0xC0, 0xBF,                    //     orientation (5) = -1.5 rad
    0x35, 0x00, 0x00, 0x48, 0x43,                    //     pixel_x (6) = 200
    0x3D, 0x00, 0x00, 0xC8, 0x43,                    //     pixel_y (7) = 400
    0x45, 0x00, 0x00, 0x16, 0x43,                    //     height (8) = 150 mm
    0x3A, 0x25,                                      //   robots_blue (7, LEN), 37 bytes
    0x0D, 0x00, 0x00, 0x40, 0x3F,                    //     confidence (1) = 0.75f
    0x10, 0x03,                                      //     robot_id (2) = 3
    0x1D, 0x00, 0x00, 0xFA, 0x43,                    //     x (3) = 500 mm
    0x25, 0x00, 0x80, 0xBB, 0x44,                    //     y (4) = 1500 mm
    0x2D, 0x00, 0x00, 0x00, 0x3F,                    //     orientation (5) = 0.5 rad
    0x35, 0x00, 0x00, 0xAF, 0x43,                    //     pixel_x (6) = 350
    0x3D, 0x00, 0x00, 0x7A, 0x43,                    //     pixel_y (7) = 250
    0x45, 0x00, 0x00, 0x16, 0x43,                    //     height (8) = 150 mm
    0x18, 0x01,                                      // source (3, varint) = SSL_SOURCE_OTHER
};
// clang-format on

TEST(SslVisionDetection, GoldenBytes) {
  const idl::CameraInfo camera = GoldenCamera();
  const idl::CameraFrame frame = GoldenFrame();
  ASSERT_EQ(CheckCameraFrame(frame), VisionError::kOk);
  EXPECT_EQ(EncodeDetection(frame, {1.0, 1.5}, &camera), kGoldenDetection);
}

TEST(SslVisionDetection, DecodesBackToMillimetresAndRadians) {
  const idl::CameraInfo camera = GoldenCamera();
  const std::vector<uint8_t> bytes = EncodeDetection(GoldenFrame(), {1.0, 1.5}, &camera);
  wire::vision::SSL_WrapperPacket packet;
  ASSERT_TRUE(packet.ParseFromArray(bytes.data(), static_cast<int>(bytes.size())));
  ASSERT_TRUE(packet.IsInitialized());
  EXPECT_EQ(packet.source(), wire::vision::SSL_SOURCE_OTHER);
  EXPECT_FALSE(packet.has_geometry());
  const wire::vision::SSL_DetectionFrame& d = packet.detection();
  EXPECT_EQ(d.frame_number(), 7u);
  EXPECT_EQ(d.camera_id(), 1u);
  EXPECT_DOUBLE_EQ(d.t_capture(), 1.0);
  EXPECT_DOUBLE_EQ(d.t_sent(), 1.5);
  EXPECT_FALSE(d.has_t_capture_camera());
  ASSERT_EQ(d.balls_size(), 1);
  EXPECT_FLOAT_EQ(d.balls(0).x(), 2000.0f);
  EXPECT_FLOAT_EQ(d.balls(0).y(), -1000.0f);
  EXPECT_FALSE(d.balls(0).has_z());  // SSL-Vision never sends it: x and y are projected onto the carpet plane
  ASSERT_EQ(d.robots_blue_size(), 1);
  ASSERT_EQ(d.robots_yellow_size(), 1);
  const wire::vision::SSL_DetectionRobot& blue = d.robots_blue(0);
  EXPECT_EQ(blue.robot_id(), 3u);
  EXPECT_FLOAT_EQ(blue.x(), 500.0f);
  EXPECT_FLOAT_EQ(blue.y(), 1500.0f);
  EXPECT_FLOAT_EQ(blue.orientation(), 0.5f);
  EXPECT_FLOAT_EQ(blue.confidence(), 0.75f);
  EXPECT_FLOAT_EQ(blue.height(), 150.0f);
  const wire::vision::SSL_DetectionRobot& yellow = d.robots_yellow(0);
  EXPECT_EQ(yellow.robot_id(), 10u);
  EXPECT_FLOAT_EQ(yellow.x(), -1000.0f);
  EXPECT_FLOAT_EQ(yellow.orientation(), -1.5f);
}

TEST(SslVisionDetection, WithoutCameraPixelsAreZeroAndEmptyFrameEncodes) {
  idl::CameraFrame frame = GoldenFrame();
  wire::vision::SSL_DetectionFrame d;
  FillDetectionFrame(frame, {1.0, 1.0}, nullptr, &d);
  EXPECT_EQ(d.balls(0).pixel_x(), 0.0f);
  EXPECT_EQ(d.robots_blue(0).pixel_y(), 0.0f);
  frame.balls().clear();
  frame.robots().clear();
  FillDetectionFrame(frame, {1.0, 1.0}, nullptr, &d);  // clears what was there
  EXPECT_EQ(d.balls_size() + d.robots_blue_size() + d.robots_yellow_size(), 0);
  EXPECT_TRUE(d.IsInitialized());
}

TEST(SslVisionDetection, OrientationIsWrappedAndFrameNumberWraps) {
  idl::CameraFrame frame = GoldenFrame();
  frame.robots()[0].orientation(0.5 + 4 * M_PI);
  frame.frame_number((uint64_t{1} << 32) + 5);
  wire::vision::SSL_DetectionFrame d;
  FillDetectionFrame(frame, {1.0, 1.0}, nullptr, &d);
  EXPECT_NEAR(d.robots_blue(0).orientation(), 0.5f, 1e-5);
  EXPECT_EQ(d.frame_number(), 5u);
}

TEST(SslVisionDetection, PixelModelPutsTheNadirAtThePrincipalPoint) {
  const idl::CameraInfo camera = GoldenCamera();
  double px = 0, py = 0;
  ASSERT_TRUE(ProjectToPixel(camera, 1.0, 1.0, 0.0, &px, &py));
  EXPECT_DOUBLE_EQ(px, 400.0);
  EXPECT_DOUBLE_EQ(py, 300.0);
  // +x to the image's right, +y to the image's top.
  ASSERT_TRUE(ProjectToPixel(camera, 1.1, 1.1, 0.0, &px, &py));
  EXPECT_GT(px, 400.0);
  EXPECT_LT(py, 300.0);
  // Nothing at or above the camera projects.
  EXPECT_FALSE(ProjectToPixel(camera, 1.0, 1.0, 4.15, &px, &py));
  EXPECT_FALSE(ProjectToPixel(camera, 1.0, 1.0, 9.0, &px, &py));
}

TEST(SslVisionDetection, RefusesUntrustedFrames) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  auto with = [](auto change) {
    idl::CameraFrame f = GoldenFrame();
    change(f);
    return CheckCameraFrame(f);
  };
  EXPECT_EQ(with([&](idl::CameraFrame& f) { f.balls()[0].position().x(nan); }), VisionError::kNotFinite);
  EXPECT_EQ(with([&](idl::CameraFrame& f) { f.balls()[0].position().z(inf); }), VisionError::kNotFinite);
  EXPECT_EQ(with([&](idl::CameraFrame& f) { f.robots()[0].orientation(nan); }), VisionError::kNotFinite);
  EXPECT_EQ(with([&](idl::CameraFrame& f) { f.robots()[1].height(-inf); }), VisionError::kNotFinite);
  EXPECT_EQ(with([&](idl::CameraFrame& f) { f.robots()[1].confidence(NAN); }), VisionError::kNotFinite);
  EXPECT_EQ(with([&](idl::CameraFrame& f) { f.robots()[1].confidence(1.5f); }), VisionError::kOutOfRange);
  EXPECT_EQ(with([&](idl::CameraFrame& f) { f.robots()[0].position().y(1e30); }), VisionError::kOutOfRange);
  EXPECT_EQ(with([&](idl::CameraFrame& f) { f.robots()[0].id(16); }), VisionError::kBadRobotId);
  EXPECT_EQ(with([&](idl::CameraFrame& f) { f.robots()[0].id(15); }), VisionError::kOk);
  EXPECT_EQ(with([&](idl::CameraFrame& f) { f.robots()[0].team(static_cast<idl::Team>(7)); }),
            VisionError::kUnknownTeam);
  EXPECT_EQ(with([&](idl::CameraFrame& f) { f.robots().resize(kMaxDetections + 1, f.robots()[0]); }),
            VisionError::kTooMany);
}

TEST(SslVisionDetection, ErrorsHaveNames) {
  EXPECT_STREQ(VisionErrorName(VisionError::kNotFinite), "not_finite");
  EXPECT_STREQ(VisionErrorName(VisionError::kBadRobotId), "bad_robot_id");
  EXPECT_STREQ(VisionErrorName(VisionError::kTimeOrder), "time_order");
  // A value past turf's taxonomy (core/errors.h) has no name.
  EXPECT_STREQ(VisionErrorName(static_cast<VisionError>(200)), "?");
}

TEST(SslVisionDetection, FindsCamerasById) {
  idl::SslField field;
  field.cameras().push_back(GoldenCamera());
  EXPECT_EQ(FindCamera(field, 1), &field.cameras()[0]);
  EXPECT_EQ(FindCamera(field, 0), nullptr);
}

}  // namespace
}  // namespace turf::vision
