// What turf-render adds to a legged scene's model so that it looks like a soccer field to a vision pipeline:
// white field lines of their true width (as visual-only boxes 1 mm high: no contact, no mass, no change to the
// bodies, so the renderer's model poses exactly as turf-sim's), white goal frames, a sun light and a sky (a gradient
// skybox). The field's markings follow its size: a field of 100 m or more is the FIFA field of RCSSServerMJ (lines 0.12
// m, centre circle 9.15 m, penalty areas 16.5 x 40.32 m); a smaller one the SimSpark field (lines 0.05 m, centre circle
// 2 m, penalty areas 1.8 x 6 m). Pure text in, text out.
#pragma once

#include <string>

#include "core/legged/legged_scene.h"

namespace turf {

struct FieldMarkings {
  double line_width = 0.05;
  double centre_circle_radius = 2.0;
  double penalty_depth = 1.8;
  double penalty_width = 6.0;
};

FieldMarkings MarkingsFor(const Field3d& field);

// `mjcf` (ComposeLeggedMjcf's) with the markings, goal colours and lighting added; unchanged when the scene has
// no field but for the light.
std::string AddFieldLook(const std::string& mjcf, const Field3d& field);

}  // namespace turf
