#include "kernel/rcssservermj/field.h"

#include <array>

namespace turf::rcssservermj {

namespace {

// Facts' table "Fields": length x width, border, goal depth x width x height,
// goalie area, penalty area (0 = none), spot, circle radius.
constexpr std::array<MjField, 5> kFields = {{
    {"fifa", 105, 68, 3.0, 1.6, 7.32, 2.44, 5.5, 18.32, 16.5, 40.32, 11, 9.15},
    {"sim3d_7vs7", 55, 36, 3.0, 1.0, 3.66, 1.83, 4, 7.3, 9, 16.5, 7.32, 5.5},
    {"hl_adult_2020", 14, 9, 2, 0.6, 2.6, 1.8, 1, 4.0, 3, 6.0, 2.1, 1.5},
    {"hl_adult_2019", 14, 9, 2, 0.6, 2.6, 1.8, 1, 5.0, 0, 0, 2.1, 1.5},
    {"hl_adult_2014", 9, 6, 2, 0.6, 2.6, 1.8, 1, 5.0, 0, 0, 2.1, 0.75},
}};

// The four markers of an area's corners on the field: l_<s><u|l><feature> at
// the area's front edge, t_... on the goal line.
void AreaMarkers(double hx, double depth, double width, const char* feature, std::vector<FieldMarker>* out) {
  for (const char* kind : {"l", "t"}) {
    const double x = kind[0] == 'l' ? hx - depth : hx;
    out->push_back({std::string(kind) + "_lu" + feature, {-x, width, 0}});
    out->push_back({std::string(kind) + "_ll" + feature, {-x, -width, 0}});
    out->push_back({std::string(kind) + "_ru" + feature, {x, width, 0}});
    out->push_back({std::string(kind) + "_rl" + feature, {x, -width, 0}});
  }
}

}  // namespace

const MjField* FindField(std::string_view name) {
  if (name == "hl_adult") name = "hl_adult_2020";
  for (const MjField& f : kFields)
    if (name == f.name) return &f;
  return nullptr;
}

std::vector<FieldMarker> FieldMarkers(const MjField& f) {
  const double hx = f.half_length(), hy = f.half_width();
  const double gy = f.goal_width / 2, gz = f.goal_height, r = f.circle_radius, spot = hx - f.spot;
  std::vector<FieldMarker> out = {
      {"l_luf", {-hx, hy, 0}},  {"l_llf", {-hx, -hy, 0}}, {"l_ruf", {hx, hy, 0}},   {"l_rlf", {hx, -hy, 0}},
      {"t_cuf", {0, hy, 0}},    {"t_clf", {0, -hy, 0}},   {"x_cuc", {0, r, 0}},     {"x_clc", {0, -r, 0}},
      {"p_lpm", {-spot, 0, 0}}, {"p_rpm", {spot, 0, 0}},  {"g_lup", {-hx, gy, gz}}, {"g_llp", {-hx, -gy, gz}},
      {"g_rup", {hx, gy, gz}},  {"g_rlp", {hx, -gy, gz}},
  };
  AreaMarkers(hx, f.goalie_depth, f.goalie_width, "ga", &out);
  if (f.penalty_depth > 0) AreaMarkers(hx, f.penalty_depth, f.penalty_width, "pa", &out);
  return out;
}

}  // namespace turf::rcssservermj
