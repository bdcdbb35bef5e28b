// Where a legged scene's robots and ball may be put. Past these a placement is nonsense: turf-sim refuses it
// (kernel/legged_kernel.h), and so does every legged protocol's codec first (RCSSServerMJ beams and monitor
// placements, the SimSpark trainer), so a refusal is named and counted where the message arrives rather than
// passed on to turf-sim. Header only: the codecs use it without linking the physics.
#pragma once

namespace turf {

inline constexpr double kMaxLeggedPlacement = 100.0;  // m from the origin, any axis
inline constexpr double kMaxLeggedBallSpeed = 50.0;   // m/s

}  // namespace turf
