// The ball on the carpet. MuJoCo supplies the normal force; the carpet's
// tangential forces are applied here:
//  - sliding: Coulomb friction at the contact point, mu = -acc_slide / g. It
//    slows the ball and spins it up until the contact point stops slipping,
//    which happens at k_switch of the start speed (set by the ball's inertia).
//  - rolling: a resistance that slows speed and spin together at acc_roll.
#pragma once

#include "core/ball_handling.h"
#include "core/scene.h"
#include "core/types.h"

namespace turf {

struct Wrench {
  Vec3 force;
  Vec3 torque;
};

// Speed of the ball's contact point over the carpet (0 when rolling cleanly).
double BallSlipSpeed(const BallState& ball, double radius);

// Coulomb friction of the carpet on a ball pressed down with `normal_force`
// (N): opposes the contact point's slip, never reverses it within one step.
Wrench CarpetFriction(const BallState& ball, double normal_force, const BallParams& params, double inertia, double dt);

// Force and torque that slow a rolling ball at acc_roll without making it slip:
// both the linear and the angular speed drop together, in proportion to the
// load (acc_roll at normal_force = m g). Zero while the ball slides, flies or
// rests.
Wrench RollingResistance(const BallState& ball, double normal_force, const BallParams& params, double inertia,
                         double dt);

}  // namespace turf
