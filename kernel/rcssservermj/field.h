// The RCSSServerMJ fields (shared/protocols/rcssservermj.md, "Fields") and the
// world markers its ideal vision reports, computed from a field's sizes as the
// reference does (goalie- and penalty-area markers use the full area width as
// their y offset, as coded there).
#pragma once

#include <Eigen/Core>
#include <string>
#include <string_view>
#include <vector>

namespace turf::rcssservermj {

struct MjField {
  const char* name;
  double length, width, border;                // m
  double goal_depth, goal_width, goal_height;  // m
  double goalie_depth, goalie_width;           // m (goalie area depth x width)
  double penalty_depth, penalty_width;         // m; 0: no penalty area
  double spot;                                 // penalty mark distance from the goal line, m
  double circle_radius;                        // m
  double half_length() const { return length / 2; }
  double half_width() const { return width / 2; }
};

// fifa, sim3d_7vs7, hl_adult_2020 (also as hl_adult), hl_adult_2019, hl_adult_2014; nullptr for others.
const MjField* FindField(std::string_view name);

struct FieldMarker {
  std::string name;  // l_luf, t_cuf, x_cuc, p_lpm, g_lup, l_luga, t_luga, l_lupa, t_lupa, ...
  Eigen::Vector3d position;
};

// Every marker of the field, in the facts' table order.
std::vector<FieldMarker> FieldMarkers(const MjField& field);

}  // namespace turf::rcssservermj
