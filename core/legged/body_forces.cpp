#include "core/legged/body_forces.h"

#include <algorithm>
#include <cmath>

namespace turf {

namespace {

// The sides of the uniform box with the body's mass and principal inertia: for such a box of mass m and sides s,
// I_j + I_k - I_i = m s_i^2 / 6.
void InertiaBox(const mjModel* m, int body, mjtNum box[3]) {
  const mjtNum* inertia = m->body_inertia + 3 * body;
  const mjtNum mass = m->body_mass[body];
  for (int i = 0; i < 3; ++i) {
    const mjtNum side_term = inertia[(i + 1) % 3] + inertia[(i + 2) % 3] - inertia[i];
    box[i] = std::sqrt(std::max(mjMINVAL, side_term) / mass * 6.0);
  }
}

}  // namespace

Fluid FluidOf(const mjModel* m) {
  return {m->opt.density, m->opt.viscosity, {m->opt.wind[0], m->opt.wind[1], m->opt.wind[2]}};
}

void AddInertiaBoxFluid(const mjModel* m, const mjData* d, const Fluid& fluid, int body, mjtNum wrench[6]) {
  if (m->body_mass[body] < mjMINVAL || !fluid.enabled()) return;
  mjtNum box[3];
  InertiaBox(m, body, box);
  // The body's velocity at its centre of mass, relative to the wind, in its inertial frame (cvel is about the
  // tree's centre of mass: angular, then linear).
  const mjtNum* cvel = d->cvel + 6 * body;
  const mjtNum* com = d->xipos + 3 * body;
  const mjtNum* root = d->subtree_com + 3 * m->body_rootid[body];
  const mjtNum* mat = d->ximat + 9 * body;
  mjtNum arm[3], world_lin[3], w[3], v[3];
  mju_sub3(arm, com, root);
  mju_cross(world_lin, cvel, arm);  // w x (p - c)
  mju_addTo3(world_lin, cvel + 3);
  mju_subFrom3(world_lin, fluid.wind.data());
  mju_rotVecMatT(w, cvel, mat);
  mju_rotVecMatT(v, world_lin, mat);

  mjtNum torque[3] = {0, 0, 0}, force[3] = {0, 0, 0};
  if (fluid.viscosity > 0) {
    const mjtNum diameter = (box[0] + box[1] + box[2]) / 3.0;
    for (int i = 0; i < 3; ++i) {
      torque[i] -= mjPI * diameter * diameter * diameter * fluid.viscosity * w[i];
      force[i] -= 3.0 * mjPI * diameter * fluid.viscosity * v[i];
    }
  }
  if (fluid.density > 0) {
    for (int i = 0; i < 3; ++i) {
      const mjtNum a = box[(i + 1) % 3], b = box[(i + 2) % 3];
      force[i] -= 0.5 * fluid.density * a * b * std::abs(v[i]) * v[i];
      torque[i] -= fluid.density * box[i] * (a * a * a * a + b * b * b * b) * std::abs(w[i]) * w[i] / 64.0;
    }
  }
  mjtNum world[3];
  mju_rotVecMat(world, torque, mat);
  mju_addTo3(wrench, world);
  mju_rotVecMat(world, force, mat);
  mju_addTo3(wrench + 3, world);
}

// Each body's wrench as a spatial force about its tree's centre of mass (the frame of cdof), summed over its
// subtree from the leaves up (a child's id is above its parent's), then projected on the body's own dofs.
void AddBodyWrenches(const mjModel* m, const mjData* d, const std::vector<mjtNum>& wrenches,
                     std::vector<mjtNum>* scratch, mjtNum* qfrc) {
  scratch->assign(6 * m->nbody, 0.0);
  mjtNum* s = scratch->data();
  for (int b = 1; b < m->nbody; ++b) {
    const mjtNum* w = wrenches.data() + 6 * b;
    const mjtNum* com = d->xipos + 3 * b;
    const mjtNum* root = d->subtree_com + 3 * m->body_rootid[b];
    mjtNum arm[3], moment[3];
    mju_sub3(arm, com, root);
    mju_cross(moment, arm, w + 3);
    for (int k = 0; k < 3; ++k) {
      s[6 * b + k] += w[k] + moment[k];
      s[6 * b + 3 + k] += w[3 + k];
    }
  }
  for (int b = m->nbody - 1; b > 0; --b) {
    const mjtNum* sb = s + 6 * b;
    for (int j = m->body_dofadr[b]; j < m->body_dofadr[b] + m->body_dofnum[b]; ++j)
      qfrc[j] += mju_dot(d->cdof + 6 * j, sb, 6);
    const int parent = m->body_parentid[b];
    if (parent > 0)
      for (int k = 0; k < 6; ++k) s[6 * parent + k] += sb[k];
  }
}

}  // namespace turf
