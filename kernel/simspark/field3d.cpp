#include "kernel/simspark/field3d.h"

#include <cmath>

namespace turf::simspark {

Field3dGeometry Field3dFromDimensions(Field3dGeometry dims) {
  const double hl = dims.length / 2.0;
  const double hw = dims.width / 2.0;
  const double gw = dims.goal_width / 2.0;
  const double gh = dims.goal_height;

  dims.flags = {{"F1L", {-hl, hw, 0.0}}, {"F2L", {-hl, -hw, 0.0}}, {"F1R", {hl, hw, 0.0}}, {"F2R", {hl, -hw, 0.0}}};
  dims.goal_posts = {{"G1L", {-hl, gw, gh}}, {"G2L", {-hl, -gw, gh}}, {"G1R", {hl, gw, gh}}, {"G2R", {hl, -gw, gh}}};

  auto& lines = dims.lines;
  lines.clear();
  const auto ground = [](double x, double y) { return Eigen::Vector3d(x, y, 0.0); };
  lines.push_back({ground(0.0, -hw), ground(0.0, hw)});  // halfway line
  lines.push_back({ground(-hl, -hw), ground(-hl, hw)});  // left goal line
  lines.push_back({ground(hl, -hw), ground(hl, hw)});    // right goal line
  lines.push_back({ground(-hl, hw), ground(hl, hw)});    // touch line, +y
  lines.push_back({ground(-hl, -hw), ground(hl, -hw)});  // touch line, -y
  const double px = hl - dims.penalty_depth;
  const double py = dims.penalty_width / 2.0;
  for (const double sign : {-1.0, 1.0}) {  // penalty areas: front line and the two side lines
    lines.push_back({ground(sign * px, -py), ground(sign * px, py)});
    lines.push_back({ground(sign * px, py), ground(sign * hl, py)});
    lines.push_back({ground(sign * px, -py), ground(sign * hl, -py)});
  }
  const double step = 2.0 * M_PI / kCentreCircleSegments;
  const double r = dims.circle_radius;
  for (int i = 0; i < kCentreCircleSegments; ++i) {
    const double a0 = i * step;
    const double a1 = (i + 1) * step;
    lines.push_back({ground(r * std::cos(a0), r * std::sin(a0)), ground(r * std::cos(a1), r * std::sin(a1))});
  }
  return dims;
}

Field3dGeometry StandardField3d() { return Field3dFromDimensions(Field3dGeometry{}); }

}  // namespace turf::simspark
