#include "codecs/ssl_vision/geometry.h"

#include <cmath>
#include <initializer_list>

#include "codecs/ssl_vision/calibration.h"

namespace turf::vision {

namespace {

using wire::vision::SSL_FieldShapeType;
constexpr double kMm = 1000.0;
constexpr double kMaxSize = 1000.0;         // m; keeps every size well inside int32 mm
constexpr double kMaxAcceleration = 100.0;  // m/s^2
constexpr double kTwoPi = 6.283185307179586;

int32_t MmInt(double metres) { return static_cast<int32_t>(std::lround(metres * kMm)); }
float Mm(double metres) { return static_cast<float>(metres * kMm); }

// A size must be finite, inside (0, kMaxSize] (or [0, kMaxSize] if it may be 0).
VisionError CheckSize(double v, bool may_be_zero) {
  if (!std::isfinite(v)) return VisionError::kNotFinite;
  if (v < 0.0 || (v == 0.0 && !may_be_zero)) return VisionError::kNonPositiveSize;
  return v <= kMaxSize ? VisionError::kOk : VisionError::kOutOfRange;
}

VisionError CheckBetween(double v, double lo, double hi) {
  if (!std::isfinite(v)) return VisionError::kNotFinite;
  return v >= lo && v <= hi ? VisionError::kOk : VisionError::kOutOfRange;
}

VisionError First(std::initializer_list<VisionError> errors) {
  for (VisionError e : errors)
    if (e != VisionError::kOk) return e;
  return VisionError::kOk;
}

void AddLine(const char* name, SSL_FieldShapeType type, double x1, double y1, double x2, double y2, double thickness,
             wire::vision::SSL_GeometryFieldSize* field) {
  wire::vision::SSL_FieldLineSegment* line = field->add_field_lines();
  line->set_name(name);
  line->mutable_p1()->set_x(Mm(x1));
  line->mutable_p1()->set_y(Mm(y1));
  line->mutable_p2()->set_x(Mm(x2));
  line->mutable_p2()->set_y(Mm(y2));
  line->set_thickness(Mm(thickness));
  line->set_type(type);
}

void FillFieldSize(const idl::SslField& f, wire::vision::SSL_GeometryFieldSize* out) {
  out->set_field_length(MmInt(f.field_length()));
  out->set_field_width(MmInt(f.field_width()));
  out->set_goal_width(MmInt(f.goal_width()));
  out->set_goal_depth(MmInt(f.goal_depth()));
  out->set_boundary_width(MmInt(f.boundary_width()));
  out->set_penalty_area_depth(MmInt(f.penalty_area_depth()));
  out->set_penalty_area_width(MmInt(f.penalty_area_width()));
  out->set_center_circle_radius(MmInt(f.center_circle_radius()));
  out->set_line_thickness(MmInt(f.line_thickness()));
  out->set_goal_center_to_penalty_mark(MmInt(f.goal_center_to_penalty_mark()));
  out->set_goal_height(MmInt(f.goal_height()));
  out->set_ball_radius(Mm(f.ball_radius()));
  out->set_max_robot_radius(Mm(f.max_robot_radius()));
  out->set_boundary_width_goal_line(MmInt(f.boundary_width_goal_line()));

  // The lines as SSL-Vision's field.cpp lays them out.
  const double hl = f.field_length() / 2;
  const double hw = f.field_width() / 2;
  const double pen_x = hl - f.penalty_area_depth();
  const double pen_y = f.penalty_area_width() / 2;
  const double t = f.line_thickness();
  AddLine("TopTouchLine", wire::vision::TopTouchLine, -hl, hw, hl, hw, t, out);
  AddLine("BottomTouchLine", wire::vision::BottomTouchLine, -hl, -hw, hl, -hw, t, out);
  AddLine("LeftGoalLine", wire::vision::LeftGoalLine, -hl, -hw, -hl, hw, t, out);
  AddLine("RightGoalLine", wire::vision::RightGoalLine, hl, -hw, hl, hw, t, out);
  AddLine("HalfwayLine", wire::vision::HalfwayLine, 0.0, -hw, 0.0, hw, t, out);
  AddLine("CenterLine", wire::vision::CenterLine, -hl, 0.0, hl, 0.0, t, out);
  AddLine("LeftPenaltyStretch", wire::vision::LeftPenaltyStretch, -pen_x, -pen_y, -pen_x, pen_y, t, out);
  AddLine("RightPenaltyStretch", wire::vision::RightPenaltyStretch, pen_x, -pen_y, pen_x, pen_y, t, out);
  AddLine("LeftFieldLeftPenaltyStretch", wire::vision::LeftFieldLeftPenaltyStretch, -hl, -pen_y, -pen_x, -pen_y, t,
          out);
  AddLine("LeftFieldRightPenaltyStretch", wire::vision::LeftFieldRightPenaltyStretch, -hl, pen_y, -pen_x, pen_y, t,
          out);
  AddLine("RightFieldRightPenaltyStretch", wire::vision::RightFieldRightPenaltyStretch, hl, -pen_y, pen_x, -pen_y, t,
          out);
  AddLine("RightFieldLeftPenaltyStretch", wire::vision::RightFieldLeftPenaltyStretch, hl, pen_y, pen_x, pen_y, t, out);

  wire::vision::SSL_FieldCircularArc* arc = out->add_field_arcs();
  arc->set_name("CenterCircle");
  arc->mutable_center()->set_x(0.0f);
  arc->mutable_center()->set_y(0.0f);
  arc->set_radius(Mm(f.center_circle_radius()));
  arc->set_a1(0.0f);
  arc->set_a2(static_cast<float>(kTwoPi));
  arc->set_thickness(Mm(t));
  arc->set_type(wire::vision::CenterCircle);
}

}  // namespace

VisionError CheckField(const idl::SslField& f) {
  const VisionError sizes = First({
      CheckSize(f.field_length(), false),
      CheckSize(f.field_width(), false),
      CheckSize(f.boundary_width(), true),
      CheckSize(f.boundary_width_goal_line(), true),
      CheckSize(f.goal_width(), false),
      CheckSize(f.goal_depth(), false),
      CheckSize(f.goal_height(), false),
      CheckSize(f.penalty_area_depth(), false),
      CheckSize(f.penalty_area_width(), false),
      CheckSize(f.center_circle_radius(), false),
      CheckSize(f.line_thickness(), false),
      CheckSize(f.goal_center_to_penalty_mark(), true),
      CheckSize(f.ball_radius(), false),
      CheckSize(f.max_robot_radius(), false),
      CheckBetween(f.ball_acc_slide(), -kMaxAcceleration, 0.0),
      CheckBetween(f.ball_acc_roll(), -kMaxAcceleration, 0.0),
      CheckBetween(f.ball_k_switch(), 0.0, 1.0),
      CheckBetween(f.chip_damping_xy_first_hop(), 0.0, 1.0),
      CheckBetween(f.chip_damping_xy_other_hops(), 0.0, 1.0),
      CheckBetween(f.chip_damping_z(), 0.0, 1.0),
  });
  if (sizes != VisionError::kOk) return sizes;
  if (f.penalty_area_depth() > f.field_length() / 2 || f.penalty_area_width() > f.field_width() ||
      f.goal_width() > f.field_width())
    return VisionError::kOutOfRange;
  if (f.cameras().size() > kMaxCameras) return VisionError::kTooMany;
  for (const idl::CameraInfo& c : f.cameras()) {
    const VisionError e = CheckCamera(c);
    if (e != VisionError::kOk) return e;
  }
  return VisionError::kOk;
}

void FillGeometry(const idl::SslField& field, wire::vision::SSL_GeometryData* out) {
  out->Clear();
  FillFieldSize(field, out->mutable_field());
  for (const idl::CameraInfo& c : field.cameras()) FillCalibration(c, out->add_calib());
  wire::vision::SSL_BallModelStraightTwoPhase* straight = out->mutable_models()->mutable_straight_two_phase();
  straight->set_acc_slide(field.ball_acc_slide());
  straight->set_acc_roll(field.ball_acc_roll());
  straight->set_k_switch(field.ball_k_switch());
  wire::vision::SSL_BallModelChipFixedLoss* chip = out->mutable_models()->mutable_chip_fixed_loss();
  chip->set_damping_xy_first_hop(field.chip_damping_xy_first_hop());
  chip->set_damping_xy_other_hops(field.chip_damping_xy_other_hops());
  chip->set_damping_z(field.chip_damping_z());
}

VisionError EncodeGeometry(const idl::SslField& field, std::vector<uint8_t>* out) {
  out->clear();
  const VisionError e = CheckField(field);
  if (e != VisionError::kOk) return e;
  wire::vision::SSL_WrapperPacket packet;
  FillGeometry(field, packet.mutable_geometry());
  packet.set_source(wire::vision::SSL_SOURCE_OTHER);
  out->resize(packet.ByteSizeLong());
  packet.SerializeToArray(out->data(), static_cast<int>(out->size()));
  return VisionError::kOk;
}

}  // namespace turf::vision
