// Forces that act on bodies as wrenches at their centres of mass (rcssserver3d's drag, MuJoCo's inertia-box air),
// turned into generalized forces in one pass over the bodies: O(bodies + dofs). MuJoCo's own way (mj_applyFT for
// each body, behind xfrc_applied and opt.density / opt.viscosity) multiplies a dense Jacobian per body,
// O(bodies x dofs): with 22 T1 (644 dofs) its air alone took 1.2 ms of a 2.8 ms step.
#pragma once

#include <mujoco/mujoco.h>

#include <array>
#include <vector>

namespace turf {

// A still or moving medium around every body (MuJoCo's <option density viscosity wind>).
struct Fluid {
  double density = 0.0;                    // kg/m^3
  double viscosity = 0.0;                  // Pa s
  std::array<double, 3> wind = {0, 0, 0};  // m/s, world frame
  bool enabled() const { return density > 0.0 || viscosity > 0.0; }
};

// The model's fluid (its options), which MuJoCo would apply in mj_passive.
Fluid FluidOf(const mjModel* m);

// MuJoCo's inertia-box fluid model for one body: its drag and viscous force and torque from the body's velocity
// relative to the wind, in the frame of its equivalent inertia box, added to `wrench` (torque, then force; world
// frame; at the body's centre of mass). Needs the velocity stage (cvel). Bodies without mass feel nothing.
void AddInertiaBoxFluid(const mjModel* m, const mjData* d, const Fluid& fluid, int body, mjtNum wrench[6]);

// One wrench per body (6 x nbody: torque, then force; world frame; at the body's centre of mass, xipos) as
// generalized forces added to qfrc, what mj_applyFT gives body by body. Needs the position stage (cdof,
// subtree_com). `scratch` is resized to 6 x nbody.
void AddBodyWrenches(const mjModel* m, const mjData* d, const std::vector<mjtNum>& wrenches,
                     std::vector<mjtNum>* scratch, mjtNum* qfrc);

}  // namespace turf
