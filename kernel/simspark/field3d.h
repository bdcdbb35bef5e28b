// The 3D soccer field's visible features as the restricted vision perceptor
// reports them: four corner flags, four goal-post tops and 21 field lines
// (shared/protocols/simspark.md, "3D soccer field"). Field frame: origin at
// the centre, x towards the right team's goal, y towards the F1 flags, z up.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace turf::simspark {

struct FieldPoint {
  std::string label;  // F1L, F2L, F1R, F2R, G1L, G2L, G1R, G2R
  Eigen::Vector3d position;
};

struct FieldSegment {
  Eigen::Vector3d a;
  Eigen::Vector3d b;
};

// Dimensions (m) and the features derived from them.
struct Field3dGeometry {
  double length = 30.0;
  double width = 20.0;
  double goal_width = 2.1;
  double goal_height = 0.8;
  double penalty_depth = 1.8;
  double penalty_width = 6.0;
  double circle_radius = 2.0;
  double ball_radius = 0.042;

  std::vector<FieldPoint> flags;       // on the ground at the corners
  std::vector<FieldPoint> goal_posts;  // tops of the posts
  std::vector<FieldSegment> lines;     // on the ground
};

// Number of straight segments the centre circle is seen as.
inline constexpr int kCentreCircleSegments = 10;

// Fills flags, goal posts and lines from the dimensions in `dims` (any
// features already in it are replaced). The centre circle is a regular
// decagon inscribed in the circle with a vertex at (+radius, 0).
Field3dGeometry Field3dFromDimensions(Field3dGeometry dims);

// The standard 30 x 20 m field: 4 flags, 4 posts, 21 lines.
Field3dGeometry StandardField3d();

}  // namespace turf::simspark
