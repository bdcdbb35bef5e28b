// The Nao model and its motors against rcssserver3d's facts
// (shared/protocols/simspark.md; rsg/agent/nao/*.rsg, hingejoint.rsg,
// HingeEffector): body masses and inertias of uniform solid shapes, no rotor
// inertia, and ODE's hinge motor: a velocity constraint with at most FMax
// (10 N m) that reaches its target within one step when the torque allows,
// holds a zero velocity against gravity, and hard joint stops.
#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <vector>

#include "core/legged/legged_world.h"
#include "tests/core/legged/nao_fixture.h"

namespace turf {
namespace {

using testing::NaoScene;

struct ModelDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
};

// The composed model, compiled again for inspection.
std::unique_ptr<mjModel, ModelDeleter> Compile(const std::string& xml) {
  auto vfs = std::make_unique<mjVFS>();
  mj_defaultVFS(vfs.get());
  mj_makeEmptyFileVFS(vfs.get(), "nao.xml", static_cast<int>(xml.size()));
  std::copy(xml.begin(), xml.end(), static_cast<char*>(vfs->filedata[vfs->nfile - 1]));
  char error[1000] = {0};
  mjModel* m = mj_loadXML("nao.xml", vfs.get(), error, sizeof(error));
  mj_deleteVFS(vfs.get());
  EXPECT_NE(m, nullptr) << error;
  return std::unique_ptr<mjModel, ModelDeleter>(m);
}

// Body masses (kg) of type 0 from the reference's RSG files.
const std::map<std::string, double> kMasses = {
    {"torso", 1.2171}, {"neck", 0.05},     {"head", 0.35},  {"rshoulder", 0.07}, {"rupperarm", 0.15},
    {"relbow", 0.035}, {"rlowerarm", 0.2}, {"rhip1", 0.09}, {"rhip2", 0.125},    {"rthigh", 0.275},
    {"rshank", 0.225}, {"rankle", 0.125},  {"rfoot", 0.2},  {"lshoulder", 0.07}, {"lupperarm", 0.15},
    {"lelbow", 0.035}, {"llowerarm", 0.2}, {"lhip1", 0.09}, {"lhip2", 0.125},    {"lthigh", 0.275},
    {"lshank", 0.225}, {"lankle", 0.125},  {"lfoot", 0.2}};

TEST(NaoModelTest, MassesInertiasAndJointsAreTheReferences) {
  LeggedWorld w(NaoScene());
  auto m = Compile(w.mjcf());
  ASSERT_NE(m, nullptr);
  double total = 0.0;
  for (const auto& [name, mass] : kMasses) {
    const int b = mj_name2id(m.get(), mjOBJ_BODY, ("nao_1/" + name).c_str());
    ASSERT_GE(b, 0) << name;
    EXPECT_NEAR(m->body_mass[b], mass, 1e-9) << name;
    total += m->body_mass[b];
  }
  EXPECT_NEAR(total, 4.6071, 1e-9);
  // ODE's dMassSetBoxTotal: I = m/12 (b^2 + c^2); torso box 0.1 x 0.1 x 0.18.
  const int torso = mj_name2id(m.get(), mjOBJ_BODY, "nao_1/torso");
  const double i_xx = 1.2171 / 12 * (0.1 * 0.1 + 0.18 * 0.18);
  const double i_zz = 1.2171 / 12 * (0.1 * 0.1 + 0.1 * 0.1);
  EXPECT_NEAR(m->body_inertia[3 * torso + 0], i_xx, 1e-9);
  EXPECT_NEAR(m->body_inertia[3 * torso + 2], i_zz, 1e-9);
  // ODE's dMassSetSphereTotal: I = 2/5 m r^2 (elbow: r 0.01, 0.035 kg).
  const int elbow = mj_name2id(m.get(), mjOBJ_BODY, "nao_1/relbow");
  EXPECT_NEAR(m->body_inertia[3 * elbow], 0.4 * 0.035 * 1e-4, 1e-12);
  // ODE hinges have no rotor inertia and no viscous friction.
  int hinges = 0;
  for (int j = 0; j < m->njnt; ++j) {
    if (m->jnt_type[j] != mjJNT_HINGE) continue;
    ++hinges;
    EXPECT_EQ(m->dof_armature[m->jnt_dofadr[j]], 0.0) << mj_id2name(m.get(), mjOBJ_JOINT, j);
    EXPECT_EQ(m->dof_damping[m->jnt_dofadr[j]], 0.0) << mj_id2name(m.get(), mjOBJ_JOINT, j);
  }
  EXPECT_EQ(hinges, 22);
}

class NaoMotorTest : public ::testing::TestWithParam<double> {
 protected:
  int steps_per_second() const { return static_cast<int>(std::lround(1.0 / GetParam())); }
  LeggedScene Scene() const {
    LeggedScene s = NaoScene();
    s.physics.step = GetParam();
    return s;
  }
};

double Angle(const LeggedWorld& w, const std::string& joint) {
  return w.State().robots[0].joint_positions[w.JointIndex(0, joint)];
}
double Speed(const LeggedWorld& w, const std::string& joint) {
  return w.State().robots[0].joint_velocities[w.JointIndex(0, joint)];
}
double Effort(const LeggedWorld& w, const std::string& joint) {
  return w.State().robots[0].joint_efforts[w.JointIndex(0, joint)];
}

// ODE's motor is a constraint row solved with the rest of the step: a target
// the torque limit allows is reached at the end of the first step, for a
// 0.035 kg elbow, the arm and the head alike. A stance leg's joint is in a
// closed chain (both feet on the ground, the other joints held): it can move
// only as fast as the feet tip, so it gets one 20 ms cycle, and 3 % because
// the motor then makes up the first step's lag (its reference angle).
TEST_P(NaoMotorTest, VelocityReachedWithinOneStep) {
  struct Case {
    const char* joint;
    double v;
    bool closed_chain;
  };
  for (const Case& c :
       {Case{"raj1", -3.0, false}, Case{"raj3", 6.0, false}, Case{"raj4", 3.0, false}, Case{"laj2", 2.0, false},
        Case{"hj1", 1.0, false}, Case{"hj2", -2.0, false}, Case{"rlj4", -1.0, true}, Case{"llj3", 1.0, true}}) {
    LeggedWorld w(Scene());
    for (int i = 0; i < steps_per_second() / 2; ++i) w.Step();  // settle
    ASSERT_EQ(w.SetJointCommand(0, {c.joint, JointMode::kVelocity, c.v}), JointCommandError::kOk);
    w.Step();
    const double after_one = Speed(w, c.joint);
    for (int i = 1; i < steps_per_second() / 50; ++i) w.Step();  // rest of one 20 ms cycle
    const double after_cycle = Speed(w, c.joint);
    std::printf("%s commanded %.2f rad/s: %.4f after one step, %.4f after 20 ms (effort %.3f N m)\n", c.joint, c.v,
                after_one, after_cycle, Effort(w, c.joint));
    if (!c.closed_chain) {
      EXPECT_NEAR(after_one, c.v, 0.01 * std::abs(c.v)) << c.joint;
    }
    EXPECT_NEAR(after_cycle, c.v, (c.closed_chain ? 0.03 : 0.01) * std::abs(c.v)) << c.joint;
  }
}

// Velocity 0 holds a joint still against gravity (no servo sag): the arms
// held forward (shoulder torque ~0.34 N m) and a crouched robot's knees.
TEST_P(NaoMotorTest, ZeroVelocityHoldsAgainstGravity) {
  LeggedWorld w(Scene());
  // Crouch: hips and ankles pitch, knees bend, for 0.25 s; then hold.
  const std::map<std::string, double> crouch = {{"rlj3", 2.0},  {"llj3", 2.0}, {"rlj4", -4.0},
                                                {"llj4", -4.0}, {"rlj5", 2.0}, {"llj5", 2.0}};
  for (const auto& [j, v] : crouch)
    ASSERT_EQ(w.SetJointCommand(0, {j, JointMode::kVelocity, v}), JointCommandError::kOk);
  for (int i = 0; i < steps_per_second() / 4; ++i) w.Step();
  for (const auto& [j, v] : crouch)
    ASSERT_EQ(w.SetJointCommand(0, {j, JointMode::kVelocity, 0.0}), JointCommandError::kOk);
  for (int i = 0; i < steps_per_second() / 5; ++i) w.Step();
  const double knee = Angle(w, "rlj4");
  const double shoulder = Angle(w, "raj1");
  for (int i = 0; i < steps_per_second(); ++i) w.Step();
  const double knee_drift = std::abs(Angle(w, "rlj4") - knee);
  const double shoulder_drift = std::abs(Angle(w, "raj1") - shoulder);
  std::printf("held 1 s: knee %.4f rad drifts %.2e rad (effort %.3f N m), shoulder drifts %.2e rad (effort %.3f N m)\n",
              knee, knee_drift, Effort(w, "rlj4"), shoulder_drift, Effort(w, "raj1"));
  EXPECT_NEAR(knee, -1.0, 0.02);  // 0.25 s at -4 rad/s
  EXPECT_LT(knee_drift, 1e-3);
  EXPECT_LT(shoulder_drift, 1e-3);
  EXPECT_GT(std::abs(Effort(w, "rlj4")), 0.3);  // the knee carries the body
  EXPECT_LE(std::abs(Effort(w, "rlj4")), 10.0);
}

// The torque limit: a motor never gives more than FMax (10 N m), so a load
// beyond it moves the joint. An ankle pitch pressing the toes into the
// ground against the whole robot's weight saturates.
TEST_P(NaoMotorTest, TorqueNeverExceedsFMax) {
  LeggedWorld w(Scene());
  double max_effort = 0.0;
  for (const char* j : {"rlj5", "llj5"})
    ASSERT_EQ(w.SetJointCommand(0, {j, JointMode::kVelocity, -6.0}), JointCommandError::kOk);
  for (int i = 0; i < steps_per_second() / 10; ++i) {
    w.Step();
    const LeggedWorldState s = w.State();
    for (double e : s.robots[0].joint_efforts) max_effort = std::max(max_effort, std::abs(e));
  }
  std::printf("ankles pushing toes down at 6 rad/s: max |effort| %.3f N m, rlj5 at %.3f rad/s\n", max_effort,
              Speed(w, "rlj5"));
  EXPECT_LE(max_effort, 10.0 + 1e-9);
  EXPECT_GT(max_effort, 9.0);
}

// With an impulse window (physics.motor_impulse_window, the reference's 20 ms
// step) a motor's bound holds for its impulse since the window began: FMax x
// the time elapsed in the window, so a load that comes after lighter steps of
// the same window meets what they left unspent (ODE bounds the force of its
// whole step). Ankles pressing the toes down load up within each window: more
// than FMax in some physics step, never more impulse than the bound allows.
TEST_P(NaoMotorTest, ImpulseWindowBoundsEachMotorsImpulseSinceTheWindowBegan) {
  LeggedScene scene = Scene();
  scene.physics.motor_impulse_window = 0.02;
  const int per_window = static_cast<int>(std::lround(0.02 / GetParam()));
  const double dt = GetParam();
  LeggedWorld w(scene);
  for (const char* j : {"rlj5", "llj5"})
    ASSERT_EQ(w.SetJointCommand(0, {j, JointMode::kVelocity, -6.0}), JointCommandError::kOk);
  const size_t joints = w.State().robots[0].joint_efforts.size();
  std::vector<double> spent(joints, 0.0);
  double max_effort = 0.0;
  double max_window = 0.0;
  double max_prefix_excess = -1.0;  // the largest (impulse since the window began) - FMax x elapsed
  for (int i = 0; i < 10 * per_window; ++i) {
    w.Step();
    const int k = i % per_window;
    const LeggedWorldState s = w.State();
    for (size_t j = 0; j < joints; ++j) {
      if (k == 0) spent[j] = 0.0;
      const double e = std::abs(s.robots[0].joint_efforts[j]);
      spent[j] += e * dt;
      max_effort = std::max(max_effort, e);
      max_prefix_excess = std::max(max_prefix_excess, spent[j] - 10.0 * (k + 1) * dt);
      max_window = std::max(max_window, spent[j]);
    }
  }
  std::printf(
      "ankles pressing, %d steps per window: max |effort| %.3f N m, max impulse per window %.5f N m s, "
      "beyond the bound %.2e N m s\n",
      per_window, max_effort, max_window, max_prefix_excess);
  EXPECT_LE(max_prefix_excess, 1e-9);
  EXPECT_LE(max_window, 10.0 * 0.02 + 1e-9);
  EXPECT_GT(max_window, 10.0 * 0.02 * 0.9);
  EXPECT_GT(max_effort, 10.0 * std::min(per_window, 2));
}

// ODE stops (stop ERP 0.8, stop CFM 1e-8): a joint passes its stop by at
// most one 20 ms step's travel before the stop acts (0.12 rad at 6 rad/s), and
// a motor pushing into it with its full 10 N m does not press it in.
TEST_P(NaoMotorTest, JointStopsAreHard) {
  LeggedWorld w(Scene());
  ASSERT_EQ(w.SetJointCommand(0, {"raj4", JointMode::kVelocity, 6.0}), JointCommandError::kOk);
  ASSERT_EQ(w.SetJointCommand(0, {"laj4", JointMode::kVelocity, -6.0}), JointCommandError::kOk);
  double transient = 0.0;
  double pressed = 0.0;
  // 0.26 s to the stop from the zero pose, then pressed in for 0.74 s.
  for (int i = 0; i < steps_per_second(); ++i) {
    w.Step();
    const double beyond = std::max(Angle(w, "raj4") - M_PI / 2, -M_PI / 2 - Angle(w, "laj4"));
    transient = std::max(transient, beyond);
    if (i > steps_per_second() / 2) pressed = std::max(pressed, beyond);
  }
  std::printf("elbows driven into their 90 deg stops: overshoot %.4f rad, pressed in %.5f rad (effort %.2f N m)\n",
              transient, pressed, Effort(w, "raj4"));
  EXPECT_LT(transient, 6.0 * 0.02);
  EXPECT_LT(pressed, 0.005);
  EXPECT_NEAR(Effort(w, "raj4"), 10.0, 1e-6);
}

INSTANTIATE_TEST_SUITE_P(Steps, NaoMotorTest, ::testing::Values(0.002, 0.005, 0.02 / 3),
                         [](const ::testing::TestParamInfo<double>& p) {
                           return std::to_string(static_cast<int>(std::lround(p.param * 1e6))) + "us";
                         });

}  // namespace
}  // namespace turf
