// Body wrenches as generalized forces in one pass (core/legged/body_forces.h): the same as MuJoCo's own
// mj_applyFT body by body, and MuJoCo's inertia-box air the same as mj_passive's, on a model with every kind of
// joint, two trees, a moving state and a wind.
#include "core/legged/body_forces.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "core/legged/legged_mjcf.h"
#include "core/mj_state.h"

namespace turf {
namespace {

// Two trees: a free box carrying a hinge-jointed capsule and a ball-jointed box on a slide; a hinge pendulum with
// a slide and a massless site body. Density, viscosity and wind as RCSSServerMJ's air, with a breeze.
constexpr const char* kModel = R"(<mujoco>
  <option density="1.2" viscosity="2e-5" wind="0.7 -0.4 0.2" integrator="Euler"/>
  <worldbody>
    <body name="base" pos="0 0 1">
      <freejoint/>
      <geom type="box" size="0.1 0.15 0.2" mass="3"/>
      <body name="arm" pos="0.1 0 0.1">
        <joint type="hinge" axis="0 1 0"/>
        <geom type="capsule" fromto="0 0 0 0.3 0 0" size="0.03" mass="0.4"/>
        <body name="hand" pos="0.3 0 0">
          <joint type="slide" axis="1 0 0"/>
          <joint type="ball"/>
          <geom type="box" size="0.02 0.05 0.01" mass="0.05"/>
        </body>
      </body>
    </body>
    <body name="post" pos="1 1 0.5">
      <joint type="slide" axis="0 0 1"/>
      <joint type="hinge" axis="1 1 0"/>
      <geom type="box" size="0.05 0.05 0.3" mass="1.5"/>
      <body name="tag" pos="0 0 0.3"><site size="0.01"/></body>
    </body>
  </worldbody>
</mujoco>)";

struct Model {
  Model() : m(CompileLeggedMjcf(kModel)) {
    d.reset(mj_makeData(m.get()));
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < m->nq; ++i) d->qpos[i] += 0.3 * u(rng);
    mju_normalize4(d->qpos + 3);                  // the free joint's quaternion
    mju_normalize4(d->qpos + m->jnt_qposadr[3]);  // the ball joint's
    for (int i = 0; i < m->nv; ++i) d->qvel[i] = 3.0 * u(rng);
  }
  MjModelPtr m;
  MjDataPtr d;
};

// MuJoCo's passive forces with the model's fluid on, less those with it off: the air alone.
std::vector<mjtNum> MujocoAir(Model& x) {
  mj_forward(x.m.get(), x.d.get());
  std::vector<mjtNum> with(x.d->qfrc_passive, x.d->qfrc_passive + x.m->nv);
  const mjOption saved = x.m->opt;
  x.m->opt.density = 0;
  x.m->opt.viscosity = 0;
  mj_forward(x.m.get(), x.d.get());
  x.m->opt = saved;
  for (int i = 0; i < x.m->nv; ++i) with[i] -= x.d->qfrc_passive[i];
  return with;
}

void ExpectSameForces(const std::vector<mjtNum>& expected, const std::vector<mjtNum>& got) {
  ASSERT_EQ(expected.size(), got.size());
  double scale = 0.0;
  for (double v : expected) scale = std::max(scale, std::abs(v));
  ASSERT_GT(scale, 0.0);
  for (size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR(got[i], expected[i], 1e-10 * scale) << "dof " << i;
}

TEST(BodyForces, WrenchesBecomeTheGeneralizedForcesOfMujocosApplyFT) {
  Model x;
  mj_forward(x.m.get(), x.d.get());
  const int nb = x.m->nbody, nv = x.m->nv;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-5.0, 5.0);
  std::vector<mjtNum> wrenches(6 * nb, 0.0), expected(nv, 0.0), got(nv, 0.0), scratch;
  for (int b = 1; b < nb; ++b) {
    for (int k = 0; k < 6; ++k) wrenches[6 * b + k] = u(rng);
    mj_applyFT(x.m.get(), x.d.get(), &wrenches[6 * b + 3], &wrenches[6 * b], x.d->xipos + 3 * b, b, expected.data());
  }
  AddBodyWrenches(x.m.get(), x.d.get(), wrenches, &scratch, got.data());
  ExpectSameForces(expected, got);
}

TEST(BodyForces, InertiaBoxAirIsMujocosOwnWithWind) {
  Model x;
  const std::vector<mjtNum> expected = MujocoAir(x);
  mj_forward(x.m.get(), x.d.get());
  const Fluid air = FluidOf(x.m.get());
  ASSERT_TRUE(air.enabled());
  std::vector<mjtNum> wrenches(6 * x.m->nbody, 0.0), got(x.m->nv, 0.0), scratch;
  for (int b = 1; b < x.m->nbody; ++b) AddInertiaBoxFluid(x.m.get(), x.d.get(), air, b, &wrenches[6 * b]);
  AddBodyWrenches(x.m.get(), x.d.get(), wrenches, &scratch, got.data());
  ExpectSameForces(expected, got);
}

// Each half of the model on its own: viscosity alone (no density), density alone, and still air.
TEST(BodyForces, ViscosityAndDensityEachAsMujocos) {
  for (int part = 0; part < 3; ++part) {
    Model x;
    if (part == 0) x.m->opt.density = 0;
    if (part == 1) x.m->opt.viscosity = 0;
    if (part == 2) mju_zero3(x.m->opt.wind);
    const std::vector<mjtNum> expected = MujocoAir(x);
    mj_forward(x.m.get(), x.d.get());
    std::vector<mjtNum> wrenches(6 * x.m->nbody, 0.0), got(x.m->nv, 0.0), scratch;
    for (int b = 1; b < x.m->nbody; ++b)
      AddInertiaBoxFluid(x.m.get(), x.d.get(), FluidOf(x.m.get()), b, &wrenches[6 * b]);
    AddBodyWrenches(x.m.get(), x.d.get(), wrenches, &scratch, got.data());
    SCOPED_TRACE(part);
    ExpectSameForces(expected, got);
  }
}

}  // namespace
}  // namespace turf
