// rcssserver3d's contact law in MuJoCo (core/legged/ode_contacts.h): a box resting on the ground and pushed
// sideways obeys ODE's spring-damper and force-dependent slip with the mixed parameters, measured in simulation.
#include "core/legged/ode_contacts.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/legged/legged_world.h"
#include "tests/core/legged/nao_fixture.h"

namespace turf {
namespace {

// A 4 kg box, 0.2 x 0.2 x 0.1 m, on two slide joints (x, z; it cannot tip): it rests on its 4 bottom corners
// (MuJoCo's box-plane contacts, as ODE's), and its x joint's motor in torque mode pushes it with a known force.
constexpr double kMass = 4.0;
constexpr double kHalfHeight = 0.05;

LeggedScene BoxScene(double step) {
  LeggedScene s;
  s.name = "ode-box";
  s.physics.step = step;
  LeggedRobot box;
  box.name = "box";
  box.model = "box";
  box.model_xml = R"(<mujoco><compiler angle="radian"/><worldbody><body name="base" pos="0 0 0.0495">
    <joint name="x" type="slide" axis="1 0 0"/><joint name="z" type="slide" axis="0 0 1"/>
    <geom type="box" size="0.1 0.1 0.05" mass="4" condim="3"/></body></worldbody></mujoco>)";
  s.robots.push_back(box);
  s.contacts.enabled = true;
  s.contacts.robot = {0.6, 1e-4, 5e-3};  // the Nao's surfaces on rcssserver3d
  s.contacts.ground = {0.2, -1, 5e-3};   // its field: ERP and slip set, CFM not
  return s;
}

// The box's joints free (torque mode, no force) but x pushed with `push` N.
LeggedWorld& Release(LeggedWorld& w, double push = 0.0) {
  EXPECT_EQ(w.SetJointCommand(0, {"x", JointMode::kTorque, push}), JointCommandError::kOk);
  EXPECT_EQ(w.SetJointCommand(0, {"z", JointMode::kTorque, 0.0}), JointCommandError::kOk);
  return w;
}

// The box centre: its model height plus the z joint.
double Height(const LeggedWorld& w) { return 0.0495 + w.State().robots[0].joint_positions[1]; }
double X(const LeggedWorld& w) { return w.State().robots[0].joint_positions[0]; }

TEST(OdeContacts, MixesParametersAsOdeDoes) {
  const OdeContactLaw law = BoxScene(0.005).contacts;
  // Both set: the mean; one set: that one; none: the world's.
  const OdeMixed robot_ground = MixOdeSurfaces(law, law.robot, law.ground);
  EXPECT_DOUBLE_EQ(robot_ground.k, 0.4 / (0.02 * 1e-4));  // ERP 0.4, CFM 1e-4 (robot's only)
  EXPECT_DOUBLE_EQ(robot_ground.c, 0.6 / 1e-4);
  EXPECT_DOUBLE_EQ(robot_ground.slip, 5e-3);
  const OdeMixed ground_ground = MixOdeSurfaces(law, law.ground, law.ground);
  EXPECT_DOUBLE_EQ(ground_ground.k, 0.2 / (0.02 * law.world_cfm));
  const OdeMixed none = MixOdeSurfaces(law, OdeSurface{}, OdeSurface{});
  EXPECT_DOUBLE_EQ(none.k, law.world_erp / (0.02 * law.world_cfm));
  EXPECT_DOUBLE_EQ(none.slip, 0.0);
  // rcssserver3d's ball on its ground: slip the mean, bounce the ball's alone.
  const OdeSurface ball{0.5, 0.05, 0.6, 0.8, 0.8};
  const OdeMixed ball_ground = MixOdeSurfaces(law, ball, law.ground);
  EXPECT_DOUBLE_EQ(ball_ground.slip, 0.5 * (0.6 + 5e-3));
  EXPECT_DOUBLE_EQ(ball_ground.bounce, 0.8);
  EXPECT_DOUBLE_EQ(ball_ground.bounce_vel, 0.8);
  EXPECT_DOUBLE_EQ(robot_ground.bounce, 0.0) << "none set: no bounce";
}

class OdeBoxTest : public ::testing::TestWithParam<double> {};

// At rest the box sinks by the surface layer plus its weight over 4 springs of k = ERP / (h CFM).
TEST_P(OdeBoxTest, RestsAtTheSpringsStaticDeflection) {
  LeggedWorld w(BoxScene(GetParam()));
  Release(w);
  while (w.time_ns() < 2'000'000'000) w.Step();
  const double k = 0.4 / (0.02 * 1e-4);  // 2e5 N/m per contact
  const double expected = kHalfHeight - 0.001 - kMass * 9.81 / (4 * k);
  EXPECT_NEAR(Height(w), expected, 5e-6);
}

// Pushed sideways with F, each of the 4 contacts carries F/4 and slides at slip F/4 (ODE's force-dependent slip:
// no Coulomb bound), so the box moves at a constant 5e-3 * F / 4 m/s.
TEST_P(OdeBoxTest, SlidesAtTheForceDependentSlipVelocity) {
  LeggedWorld w(BoxScene(GetParam()));
  Release(w);
  while (w.time_ns() < 500'000'000) w.Step();
  const double force = 8.0;
  const double x0 = X(w);
  const int64_t t0 = w.time_ns();
  Release(w, force);
  while (w.time_ns() < t0 + 1'000'000'000) w.Step();
  const double x1 = X(w);
  while (w.time_ns() < t0 + 2'000'000'000) w.Step();
  const double x2 = X(w);
  const double expected_v = 5e-3 * force / 4;  // 0.01 m/s
  EXPECT_GT(x1 - x0, 0.0);
  EXPECT_NEAR(x2 - x1, expected_v * 1.0, 0.02 * expected_v);  // steady state over the second second
}

// `law: ode_friction`: the same slip on MuJoCo's own normal contact. The box rests where MuJoCo's contact puts it
// (not at the springs' deflection) and slides at slip F / 4 under a push that MuJoCo's Coulomb friction (mu 1 against
// 39 N of weight) holds with the law off.
TEST_P(OdeBoxTest, FrictionOnlyLawSlidesOnMuJoCosNormalContact) {
  LeggedScene mujoco = BoxScene(GetParam());
  mujoco.contacts.enabled = false;
  LeggedScene friction = BoxScene(GetParam());
  friction.contacts.ode_normal = false;
  double rest[2] = {0, 0};
  double slid[2] = {0, 0};
  int i = 0;
  for (LeggedScene* scene : {&mujoco, &friction}) {
    LeggedWorld w(*scene);
    Release(w);
    while (w.time_ns() < 500'000'000) w.Step();
    rest[i] = Height(w);
    const int64_t t0 = w.time_ns();
    Release(w, 8.0);
    while (w.time_ns() < t0 + 1'000'000'000) w.Step();
    const double x1 = X(w);
    while (w.time_ns() < t0 + 2'000'000'000) w.Step();
    slid[i++] = X(w) - x1;
  }
  EXPECT_NEAR(rest[1], rest[0], 2e-5);  // MuJoCo's normal contact in both
  EXPECT_GT(std::abs(rest[1] - (kHalfHeight - 0.001 - kMass * 9.81 / (4 * 2e5))), 1e-4);  // not ODE's springs
  EXPECT_LT(slid[0], 1e-3);  // Coulomb friction holds the push (MuJoCo's soft friction creeps 0.7 mm/s)
  EXPECT_NEAR(slid[1], 5e-3 * 8.0 / 4, 0.02 * 5e-3 * 8.0 / 4);  // the reference's slip: 0.01 m/s
}

INSTANTIATE_TEST_SUITE_P(Steps, OdeBoxTest, ::testing::Values(0.002, 0.005, 0.02 / 3));

}  // namespace
}  // namespace turf
