// The IMUs' accelerometers read in turf's pass (core/legged/root_accelerometers.h): the same bits as MuJoCo's own
// reading, step after step, on a model with a floating base that lands on the floor (contacts), a root with a slide
// and a hinge, and the sensors turf must leave to MuJoCo (one in a child body, one with a cutoff).
#include "core/legged/root_accelerometers.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "core/legged/legged_mjcf.h"
#include "core/mj_state.h"

namespace turf {
namespace {

constexpr const char* kModel = R"(<mujoco>
  <option integrator="Euler"/>
  <worldbody>
    <geom type="plane" size="5 5 0.1"/>
    <body name="base" pos="0 0 0.3" euler="10 20 30">
      <freejoint/>
      <geom type="box" size="0.1 0.15 0.2" mass="3"/>
      <site name="imu" pos="0.03 -0.02 0.05" euler="5 0 -7" size="0.01"/>
      <site name="foot" type="box" pos="0 0 -0.2" size="0.2 0.25 0.1"/>
      <body name="arm" pos="0 0.15 0.12">
        <joint type="hinge" axis="1 0 0" damping="0.1"/>
        <geom type="capsule" fromto="0 0 0 0 0.25 0" size="0.025" mass="0.3"/>
        <site name="hand" pos="0 0.25 0" size="0.01"/>
      </body>
    </body>
    <body name="post" pos="-1 0.5 0.4" euler="0 15 0">
      <joint type="hinge" axis="0 0 1" damping="0.05"/>
      <joint type="slide" axis="1 0 0"/>
      <geom type="cylinder" size="0.04 0.25" mass="1.2"/>
      <site name="tag" pos="0.01 0.02 0.25" euler="0 0 40" size="0.01"/>
    </body>
  </worldbody>
  <sensor>
    <accelerometer name="imu" site="imu"/>
    <touch name="foot" site="foot"/>
    <accelerometer name="hand" site="hand"/>
    <accelerometer name="tag" site="tag"/>
    <accelerometer name="clipped" site="imu" cutoff="5"/>
  </sensor>
</mujoco>)";

struct Pair {
  Pair() : mujoco(CompileLeggedMjcf(kModel)), turf(CompileLeggedMjcf(kModel)) {
    taken = TakeRootAccelerometers(turf.get());
    a.reset(mj_makeData(mujoco.get()));
    b.reset(mj_makeData(turf.get()));
  }
  MjModelPtr mujoco, turf;
  MjDataPtr a, b;
  std::vector<RootAccelerometer> taken;
};

bool SameBits(const mjtNum* x, const mjtNum* y, int n) { return std::memcmp(x, y, sizeof(mjtNum) * n) == 0; }

TEST(RootAccelerometers, TakesOnlyThoseInABodyOfTheWorldWithoutCutoff) {
  Pair p;
  ASSERT_EQ(p.taken.size(), 2u);
  EXPECT_EQ(p.taken[0].site, mj_name2id(p.turf.get(), mjOBJ_SITE, "imu"));
  EXPECT_EQ(p.taken[1].site, mj_name2id(p.turf.get(), mjOBJ_SITE, "tag"));
  EXPECT_EQ(p.turf->sensor_type[0], mjSENS_ACCELEROMETER);  // still an accelerometer
  EXPECT_EQ(p.turf->sensor_needstage[0], mjSTAGE_NONE);     // but not in MuJoCo's stages
  EXPECT_EQ(p.turf->sensor_needstage[2], mjSTAGE_ACC);      // in a child body: MuJoCo's
  EXPECT_EQ(p.turf->sensor_needstage[4], mjSTAGE_ACC);      // with a cutoff: MuJoCo's
  p.mujoco->opt.integrator = mjINT_IMPLICIT;
  EXPECT_TRUE(TakeRootAccelerometers(p.mujoco.get()).empty());
}

TEST(RootAccelerometers, ForwardReadsMujocosBits) {
  Pair p;
  mj_forward(p.mujoco.get(), p.a.get());
  mj_forward(p.turf.get(), p.b.get());
  SenseRootAccelerometers(p.turf.get(), p.b.get(), p.taken);
  EXPECT_TRUE(SameBits(p.a->sensordata, p.b->sensordata, p.mujoco->nsensordata));
  EXPECT_LT(mju_norm3(p.b->sensordata), 1e-9);  // the base falls freely: no reading
}

// With the IMUs alone, MuJoCo's whole-model pass (body accelerations and internal forces) is skipped: what the
// readings cost is gone.
TEST(RootAccelerometers, WithOnlyRootAccelerometersMujocosPassIsSkipped) {
  std::string xml = kModel;
  for (const char* sensor :
       {"<accelerometer name=\"hand\" site=\"hand\"/>", "<accelerometer name=\"clipped\" site=\"imu\" cutoff=\"5\"/>"})
    xml.erase(xml.find(sensor), std::strlen(sensor));
  MjModelPtr m(CompileLeggedMjcf(xml));
  MjDataPtr d(mj_makeData(m.get()));
  const std::vector<RootAccelerometer> taken = TakeRootAccelerometers(m.get());
  ASSERT_EQ(taken.size(), 2u);
  std::fill(d->cfrc_int, d->cfrc_int + 6 * m->nbody, NAN);
  for (int step = 0; step < 10; ++step) {
    mj_step1(m.get(), d.get());
    Step2(m.get(), d.get(), taken);
  }
  EXPECT_TRUE(std::isnan(d->cfrc_int[6])) << "mj_rnePostConstraint ran";
  EXPECT_GT(mju_norm3(d->sensordata), 0.0);
}

TEST(RootAccelerometers, StepsReadMujocosBitsThroughContactsAndPushes) {
  Pair p;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  int touching = 0;
  for (int step = 0; step < 600; ++step) {
    for (int i = 0; i < p.mujoco->nv; ++i) p.a->qfrc_applied[i] = p.b->qfrc_applied[i] = u(rng);
    mj_step(p.mujoco.get(), p.a.get());
    mj_step1(p.turf.get(), p.b.get());
    Step2(p.turf.get(), p.b.get(), p.taken);
    ASSERT_TRUE(SameBits(p.a->qpos, p.b->qpos, p.mujoco->nq)) << "step " << step;
    ASSERT_TRUE(SameBits(p.a->qvel, p.b->qvel, p.mujoco->nv)) << "step " << step;
    ASSERT_TRUE(SameBits(p.a->sensordata, p.b->sensordata, p.mujoco->nsensordata)) << "step " << step;
    touching += p.a->sensordata[3] > 0 ? 1 : 0;
  }
  EXPECT_GT(touching, 100);                            // the base landed: contact forces were in the readings
  EXPECT_NEAR(mju_norm3(p.b->sensordata), 9.81, 2.0);  // and rests on the floor: gravity's opposite, about
}

}  // namespace
}  // namespace turf
