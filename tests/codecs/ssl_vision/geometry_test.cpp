// SSL-Vision geometry from the SslField turf-sim publishes: sizes, the named
// and typed field lines of divisions A and B, the ball models, one plausible
// calibration per camera, and refusal of impossible fields.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <string>

#include "codecs/proto/ssl_vision.pb.h"
#include "codecs/ssl_vision/calibration.h"
#include "codecs/ssl_vision/geometry.h"
#include "core/ssl_cameras.h"
#include "participants/sim/convert.h"

namespace turf::vision {
namespace {

using wire::vision::SSL_FieldShapeType;

// The SslField turf-sim publishes for a division's default scene.
idl::SslField PublishedField(Division division) {
  Scene scene;
  scene.field = FieldForDivision(division);
  return FieldToIdl(scene, CameraLayout(scene));
}

wire::vision::SSL_GeometryData Decode(const idl::SslField& field) {
  std::vector<uint8_t> bytes;
  EXPECT_EQ(EncodeGeometry(field, &bytes), VisionError::kOk);
  wire::vision::SSL_WrapperPacket packet;
  EXPECT_TRUE(packet.ParseFromArray(bytes.data(), static_cast<int>(bytes.size())));
  EXPECT_TRUE(packet.IsInitialized());
  EXPECT_FALSE(packet.has_detection());
  EXPECT_EQ(packet.source(), wire::vision::SSL_SOURCE_OTHER);
  return packet.geometry();
}

struct Line {
  SSL_FieldShapeType type;
  float x1, y1, x2, y2;  // mm
};

// The 12 lines SSL-Vision's field.cpp draws (x along the length, "Left" = -x,
// "Top" = +y), for a field of half length `l` and half width `w` whose penalty
// areas reach from the goal lines to |x| = `px`, `pw` to each side of the x axis.
std::map<std::string, Line> StandardLines(float l, float w, float px, float pw) {
  namespace v = wire::vision;
  return {
      {"TopTouchLine", {v::TopTouchLine, -l, w, l, w}},
      {"BottomTouchLine", {v::BottomTouchLine, -l, -w, l, -w}},
      {"LeftGoalLine", {v::LeftGoalLine, -l, -w, -l, w}},
      {"RightGoalLine", {v::RightGoalLine, l, -w, l, w}},
      {"HalfwayLine", {v::HalfwayLine, 0, -w, 0, w}},
      {"CenterLine", {v::CenterLine, -l, 0, l, 0}},
      {"LeftPenaltyStretch", {v::LeftPenaltyStretch, -px, -pw, -px, pw}},
      {"RightPenaltyStretch", {v::RightPenaltyStretch, px, -pw, px, pw}},
      {"LeftFieldLeftPenaltyStretch", {v::LeftFieldLeftPenaltyStretch, -l, -pw, -px, -pw}},
      {"LeftFieldRightPenaltyStretch", {v::LeftFieldRightPenaltyStretch, -l, pw, -px, pw}},
      {"RightFieldRightPenaltyStretch", {v::RightFieldRightPenaltyStretch, l, -pw, px, -pw}},
      {"RightFieldLeftPenaltyStretch", {v::RightFieldLeftPenaltyStretch, l, pw, px, pw}},
  };
}

void ExpectLines(const wire::vision::SSL_GeometryFieldSize& field, const std::map<std::string, Line>& expected) {
  ASSERT_EQ(field.field_lines_size(), 12);
  std::map<std::string, int> seen;
  for (const auto& l : field.field_lines()) {
    ++seen[l.name()];
    auto it = expected.find(l.name());
    ASSERT_NE(it, expected.end()) << "unexpected line " << l.name();
    const Line& e = it->second;
    EXPECT_EQ(l.type(), e.type) << l.name();
    EXPECT_FLOAT_EQ(l.p1().x(), e.x1) << l.name();
    EXPECT_FLOAT_EQ(l.p1().y(), e.y1) << l.name();
    EXPECT_FLOAT_EQ(l.p2().x(), e.x2) << l.name();
    EXPECT_FLOAT_EQ(l.p2().y(), e.y2) << l.name();
    EXPECT_FLOAT_EQ(l.thickness(), 10.0f) << l.name();
  }
  for (const auto& [name, line] : expected) EXPECT_EQ(seen[name], 1) << name;
  ASSERT_EQ(field.field_arcs_size(), 1);
  const auto& arc = field.field_arcs(0);
  EXPECT_EQ(arc.name(), "CenterCircle");
  EXPECT_EQ(arc.type(), wire::vision::CenterCircle);
  EXPECT_EQ(arc.center().x(), 0.0f);
  EXPECT_EQ(arc.center().y(), 0.0f);
  EXPECT_FLOAT_EQ(arc.radius(), 500.0f);
  EXPECT_FLOAT_EQ(arc.a1(), 0.0f);
  EXPECT_FLOAT_EQ(arc.a2(), static_cast<float>(2 * M_PI));
  EXPECT_FLOAT_EQ(arc.thickness(), 10.0f);
}

// A division's sizes, mm (the SSL rules).
struct FieldFacts {
  int length, width, goal_width, boundary_width, boundary_width_goal_line;
  int penalty_area_depth, penalty_area_width, goal_center_to_penalty_mark;
};

// The field's sizes, and its lines drawn from them.
void ExpectSizesAndLines(const wire::vision::SSL_GeometryFieldSize& f, const FieldFacts& e) {
  EXPECT_EQ(f.field_length(), e.length);
  EXPECT_EQ(f.field_width(), e.width);
  EXPECT_EQ(f.goal_width(), e.goal_width);
  EXPECT_EQ(f.boundary_width(), e.boundary_width);
  EXPECT_EQ(f.boundary_width_goal_line(), e.boundary_width_goal_line);
  EXPECT_EQ(f.penalty_area_depth(), e.penalty_area_depth);
  EXPECT_EQ(f.penalty_area_width(), e.penalty_area_width);
  EXPECT_EQ(f.goal_center_to_penalty_mark(), e.goal_center_to_penalty_mark);
  const float l = e.length / 2.0f, w = e.width / 2.0f;
  ExpectLines(f, StandardLines(l, w, l - e.penalty_area_depth, e.penalty_area_width / 2.0f));
}

TEST(SslVisionGeometry, DivisionASizesAndLines) {
  const wire::vision::SSL_GeometryData g = Decode(PublishedField(Division::kA));
  const auto& f = g.field();
  ExpectSizesAndLines(f, {12000, 9000, 1800, 300, 600, 1800, 3600, 8000});
  EXPECT_EQ(f.goal_depth(), 180);
  EXPECT_EQ(f.center_circle_radius(), 500);
  EXPECT_EQ(f.line_thickness(), 10);
  EXPECT_EQ(f.goal_height(), 160);
  EXPECT_FLOAT_EQ(f.ball_radius(), 21.5f);
  EXPECT_FLOAT_EQ(f.max_robot_radius(), 90.0f);
  EXPECT_FALSE(f.has_goal_substitution_area_width());
}

TEST(SslVisionGeometry, DivisionBSizesAndLines) {
  const wire::vision::SSL_GeometryData g = Decode(PublishedField(Division::kB));
  ExpectSizesAndLines(g.field(), {9000, 6000, 1000, 300, 300, 1000, 2000, 6000});
  EXPECT_EQ(g.calib_size(), 2);
}

TEST(SslVisionGeometry, BallModels) {
  const wire::vision::SSL_GeometryData g = Decode(PublishedField(Division::kA));
  ASSERT_TRUE(g.has_models());
  const auto& straight = g.models().straight_two_phase();
  EXPECT_DOUBLE_EQ(straight.acc_slide(), -3.0);  // m/s^2, negative: SSL convention
  EXPECT_DOUBLE_EQ(straight.acc_roll(), -0.4);
  EXPECT_DOUBLE_EQ(straight.k_switch(), 0.7);
  const auto& chip = g.models().chip_fixed_loss();
  EXPECT_DOUBLE_EQ(chip.damping_xy_first_hop(), 0.68);
  EXPECT_DOUBLE_EQ(chip.damping_xy_other_hops(), 0.95);
  EXPECT_DOUBLE_EQ(chip.damping_z(), 0.5);
}

// SSL-Vision's field2image, written from its description: p_c = R(q) p_f + t
// with (q0, q1, q2) the vector part and q3 the scalar part, then a pinhole.
void SslVisionProject(const wire::vision::SSL_GeometryCameraCalibration& c, double x, double y, double z, double* px,
                      double* py) {
  const double qx = c.q0(), qy = c.q1(), qz = c.q2(), qw = c.q3();
  // v' = v + 2 w (u x v) + 2 u x (u x v)
  const double ux = qy * z - qz * y, uy = qz * x - qx * z, uz = qx * y - qy * x;
  const double vx = qy * uz - qz * uy, vy = qz * ux - qx * uz, vz = qx * uy - qy * ux;
  const double cx = x + 2 * qw * ux + 2 * vx + c.tx();
  const double cy = y + 2 * qw * uy + 2 * vy + c.ty();
  const double cz = z + 2 * qw * uz + 2 * vz + c.tz();
  *px = c.focal_length() * cx / cz + c.principal_point_x();
  *py = c.focal_length() * cy / cz + c.principal_point_y();
}

TEST(SslVisionGeometry, CalibrationsMatchTheCamerasAndThePixelsWeSend) {
  const idl::SslField field = PublishedField(Division::kA);
  const wire::vision::SSL_GeometryData g = Decode(field);
  ASSERT_EQ(g.calib_size(), 4);
  for (int i = 0; i < 4; ++i) {
    const auto& c = g.calib(i);
    const idl::CameraInfo& cam = field.cameras()[i];
    EXPECT_EQ(c.camera_id(), cam.id());
    EXPECT_FLOAT_EQ(c.focal_length(), 390.0f);
    EXPECT_EQ(c.pixel_image_width(), 780u);
    EXPECT_EQ(c.pixel_image_height(), 580u);
    EXPECT_FLOAT_EQ(c.principal_point_x(), 390.0f);
    EXPECT_FLOAT_EQ(c.principal_point_y(), 290.0f);
    EXPECT_EQ(c.distortion(), 0.0f);
    EXPECT_NEAR(c.q0() * c.q0() + c.q1() * c.q1() + c.q2() * c.q2() + c.q3() * c.q3(), 1.0, 1e-6);
    EXPECT_FLOAT_EQ(c.derived_camera_world_tx(), static_cast<float>(cam.position().x() * 1000));
    EXPECT_FLOAT_EQ(c.derived_camera_world_ty(), static_cast<float>(cam.position().y() * 1000));
    EXPECT_FLOAT_EQ(c.derived_camera_world_tz(), 4000.0f);
    EXPECT_GT(c.tz(), 0.0f);  // the field is in front of the camera
    // Division A quadrants: camera 0 at (+,+), 1 (-,+), 2 (-,-), 3 (+,-).
    const double sx[] = {1, -1, -1, 1}, sy[] = {1, 1, -1, -1};
    EXPECT_GT(c.derived_camera_world_tx() * sx[i], 0.0f);
    EXPECT_GT(c.derived_camera_world_ty() * sy[i], 0.0f);
    // SSL-Vision's projection of the calibration agrees with the pixels we send.
    for (const auto& p : {std::array<double, 3>{0.0, 0.0, 0.0}, {2.5, -1.0, 0.15}, {-4.0, 3.0, 0.0215}}) {
      double ours_x = 0, ours_y = 0, theirs_x = 0, theirs_y = 0;
      ASSERT_TRUE(ProjectToPixel(cam, p[0], p[1], p[2], &ours_x, &ours_y));
      SslVisionProject(c, p[0] * 1000, p[1] * 1000, p[2] * 1000, &theirs_x, &theirs_y);
      EXPECT_NEAR(ours_x, theirs_x, 1e-3);
      EXPECT_NEAR(ours_y, theirs_y, 1e-3);
    }
    // The point below the camera is the image centre.
    double px = 0, py = 0;
    SslVisionProject(c, c.derived_camera_world_tx(), c.derived_camera_world_ty(), 0.0, &px, &py);
    EXPECT_NEAR(px, 390.0, 1e-3);
    EXPECT_NEAR(py, 290.0, 1e-3);
  }
}

TEST(SslVisionGeometry, RefusesImpossibleFields) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto with = [](auto change) {
    idl::SslField f = PublishedField(Division::kA);
    change(f);
    std::vector<uint8_t> bytes{1, 2, 3};
    const VisionError e = EncodeGeometry(f, &bytes);
    if (e != VisionError::kOk) {
      EXPECT_TRUE(bytes.empty());
    }
    return e;
  };
  EXPECT_EQ(with([](idl::SslField&) {}), VisionError::kOk);
  EXPECT_EQ(with([&](idl::SslField& f) { f.field_length(nan); }), VisionError::kNotFinite);
  EXPECT_EQ(with([](idl::SslField& f) { f.field_width(INFINITY); }), VisionError::kNotFinite);
  EXPECT_EQ(with([](idl::SslField& f) { f.field_length(0.0); }), VisionError::kNonPositiveSize);
  EXPECT_EQ(with([](idl::SslField& f) { f.goal_width(-1.8); }), VisionError::kNonPositiveSize);
  EXPECT_EQ(with([](idl::SslField& f) { f.ball_radius(0.0); }), VisionError::kNonPositiveSize);
  EXPECT_EQ(with([](idl::SslField& f) { f.line_thickness(-0.01); }), VisionError::kNonPositiveSize);
  EXPECT_EQ(with([](idl::SslField& f) { f.boundary_width(-0.3); }), VisionError::kNonPositiveSize);
  EXPECT_EQ(with([](idl::SslField& f) { f.boundary_width(0.0); }), VisionError::kOk);
  EXPECT_EQ(with([](idl::SslField& f) { f.field_length(3e6); }), VisionError::kOutOfRange);  // beyond int32 mm
  EXPECT_EQ(with([](idl::SslField& f) { f.penalty_area_depth(7.0); }), VisionError::kOutOfRange);
  EXPECT_EQ(with([](idl::SslField& f) { f.ball_acc_slide(3.0); }), VisionError::kOutOfRange);
  EXPECT_EQ(with([](idl::SslField& f) { f.ball_k_switch(1.5); }), VisionError::kOutOfRange);
  EXPECT_EQ(with([&](idl::SslField& f) { f.chip_damping_z(nan); }), VisionError::kNotFinite);
  EXPECT_EQ(with([](idl::SslField& f) { f.cameras()[1].position().z(0.0); }), VisionError::kNonPositiveSize);
  EXPECT_EQ(with([](idl::SslField& f) { f.cameras()[1].focal_length(-390.0); }), VisionError::kNonPositiveSize);
  EXPECT_EQ(with([](idl::SslField& f) { f.cameras()[2].image_width(0); }), VisionError::kNonPositiveSize);
  EXPECT_EQ(with([&](idl::SslField& f) { f.cameras()[3].position().x(nan); }), VisionError::kNotFinite);
  EXPECT_EQ(with([](idl::SslField& f) { f.cameras().resize(kMaxCameras + 1, f.cameras()[0]); }), VisionError::kTooMany);
  // No cameras at all is a valid (if unhelpful) field.
  EXPECT_EQ(with([](idl::SslField& f) { f.cameras().clear(); }), VisionError::kOk);
}

}  // namespace
}  // namespace turf::vision
