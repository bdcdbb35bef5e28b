#include "participants/render/field_look.h"

#include <fmt/format.h>

#include <cmath>

namespace turf {

namespace {

constexpr double kLineHalfHeight = 0.0005;  // m: 1 mm high, on the ground
constexpr int kCircleSegments = 64;

// A white visual-only box centred at (x, y) on the ground, `length` along its own x turned by `yaw`.
std::string LineBox(const std::string& name, double x, double y, double length, double width, double yaw) {
  return fmt::format(R"(    <geom name="{}" type="box" pos="{:.6g} {:.6g} {:.6g}" size="{:.6g} {:.6g} {:.6g}" )"
                     R"(euler="0 0 {:.9g}" contype="0" conaffinity="0" mass="0" rgba="1 1 1 1"/>)"
                     "\n",
                     name, x, y, kLineHalfHeight, length / 2, width / 2, kLineHalfHeight, yaw);
}

std::string Markings(const Field3d& f) {
  const FieldMarkings m = MarkingsFor(f);
  const double hx = f.length / 2, hy = f.width / 2, w = m.line_width;
  std::string x;
  // Outer lines: their outer edges on the field's boundary.
  x += LineBox("line_touch_pos", 0, hy - w / 2, f.length, w, 0);
  x += LineBox("line_touch_neg", 0, -hy + w / 2, f.length, w, 0);
  x += LineBox("line_goal_pos", hx - w / 2, 0, f.width, w, M_PI / 2);
  x += LineBox("line_goal_neg", -hx + w / 2, 0, f.width, w, M_PI / 2);
  x += LineBox("line_halfway", 0, 0, f.width, w, M_PI / 2);
  for (int side : {-1, 1}) {
    const char* n = side < 0 ? "neg" : "pos";
    const double front = side * (hx - m.penalty_depth);
    x += LineBox(fmt::format("line_penalty_front_{}", n), front, 0, m.penalty_width, w, M_PI / 2);
    for (int edge : {-1, 1})
      x += LineBox(fmt::format("line_penalty_side_{}_{}", n, edge < 0 ? "neg" : "pos"),
                   side * (hx - m.penalty_depth / 2), edge * (m.penalty_width / 2 - w / 2), m.penalty_depth, w, 0);
  }
  const double r = m.centre_circle_radius - w / 2;  // the line's centre
  const double chord = 2 * r * std::sin(M_PI / kCircleSegments) * 1.02;
  for (int i = 0; i < kCircleSegments; ++i) {
    const double a = 2 * M_PI * (i + 0.5) / kCircleSegments;
    x += LineBox(fmt::format("line_circle_{}", i), r * std::cos(a), r * std::sin(a), chord, w, a + M_PI / 2);
  }
  return x;
}

}  // namespace

FieldMarkings MarkingsFor(const Field3d& field) {
  if (field.length >= 100.0) return FieldMarkings{0.12, 9.15, 16.5, 40.32};
  return FieldMarkings{};
}

std::string AddFieldLook(const std::string& mjcf, const Field3d& field) {
  std::string out = mjcf;
  std::string add =
      "    <light name=\"sun\" directional=\"true\" pos=\"0 0 20\" dir=\"0.3 0.2 -1\" diffuse=\"0.7 0.7 0.7\" "
      "castshadow=\"false\"/>\n";
  if (field.enabled) add += Markings(field);
  const size_t end = out.find("</worldbody>");
  if (end == std::string::npos) return out;
  out.insert(end, add);
  // A sky: a light blue gradient, brighter at the horizon.
  const std::string sky =
      "<texture name=\"turf_sky\" type=\"skybox\" builtin=\"gradient\" rgb1=\"0.75 0.85 0.95\" "
      "rgb2=\"0.35 0.5 0.75\" width=\"64\" height=\"64\"/>";
  const size_t empty = out.find("<asset/>");
  const size_t open = out.find("<asset>");
  if (empty != std::string::npos)
    out.replace(empty, 8, "<asset>" + sky + "</asset>");
  else if (open != std::string::npos)
    out.insert(open + 7, sky);
  return out;
}

}  // namespace turf
