// The PD motor mode (JointMode::kPd: RCSSServerMJ's and the Booster SDK's
// MotorCmd) on the Booster T1: the torque law, the clamp at the joint's effort
// limit, validation, random commands and the snapshot.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "core/legged/legged_world.h"
#include "core/state_io.h"
#include "tests/core/legged/booster_fixture.h"

namespace turf {
namespace {

using testing::BoosterStandScene;
using testing::Finite;

JointCommand Pd(const std::string& joint, double q, double dq, double kp, double kd, double tau) {
  JointCommand c{joint, JointMode::kPd, q, kp, kd};
  c.dq = dq;
  c.tau = tau;
  return c;
}

// Each step's torque is kp (q* - q) + kd (dq* - q') + tau from the angle and
// velocity at the step's start, exactly, or the effort limit when beyond it.
// The state after a step reports both: the angle and velocity the step started
// from (read with MuJoCo's sensors, as RCSSServerMJ's jointpos and jointvel)
// and the torque that step applied.
TEST(BoosterPdMotorTest, TorqueIsTheLawClampedToTheEffortLimit) {
  LeggedWorld w(BoosterStandScene("t1"));
  for (int i = 0; i < 100; ++i) w.Step();
  const int knee = w.JointIndex(0, "Left_Knee_Pitch");
  const int elbow = w.JointIndex(0, "Left_Elbow_Pitch");
  ASSERT_EQ(w.SetJointCommand(0, Pd("Left_Knee_Pitch", 0.5, 0.3, 300, 4, 1.5)), JointCommandError::kOk);
  ASSERT_EQ(w.SetJointCommand(0, Pd("Left_Elbow_Pitch", 2.0, 0, 1000, 0, 0)), JointCommandError::kOk);
  for (int i = 0; i < 20; ++i) {
    if (i == 1) {
      EXPECT_DOUBLE_EQ(w.State().robots[0].joint_efforts[elbow], 18.0) << "about 2 rad away: clamped at 18 N m";
    }
    w.Step();
    const LeggedRobotState after = w.State().robots[0];
    const LeggedRobotState& before = after;  // the step's start, as its sensors saw it
    const double law = 300 * (0.5 - before.joint_positions[knee]) + 4 * (0.3 - before.joint_velocities[knee]) + 1.5;
    EXPECT_DOUBLE_EQ(after.joint_efforts[knee], std::clamp(law, -60.0, 60.0)) << i;
    const double elbow_law = 1000 * (2.0 - before.joint_positions[elbow]);
    EXPECT_DOUBLE_EQ(after.joint_efforts[elbow], std::clamp(elbow_law, -18.0, 18.0)) << i;
  }
}

// RCSSServerMJ's position actuators have no control range and its joints'
// actuatorfrcrange clamps the sum of the three actuators: a target beyond the
// joint's range pulls with the whole law, and a feed-forward tau beyond the
// effort limit is clamped only with the rest (a policy trained there, such as
// the example nn_client's, sends both; clamping the target instead made its T1
// walk with the torso 10 cm lower).
TEST(BoosterPdMotorTest, TargetsBeyondTheRangeAndTauBeyondTheLimitActAsSent) {
  LeggedWorld w(BoosterStandScene("t1"));
  for (int i = 0; i < 100; ++i) w.Step();
  const int roll = w.JointIndex(0, "Left_Hip_Roll");    // range -0.2..1.57 rad, effort limit 30 N m
  const int knee = w.JointIndex(0, "Left_Knee_Pitch");  // range 0..2.34 rad, effort limit 60 N m
  ASSERT_EQ(w.SetJointCommand(0, Pd("Left_Hip_Roll", -0.35, 0, 25, 0.6, 0)), JointCommandError::kOk);
  ASSERT_EQ(w.SetJointCommand(0, Pd("Left_Knee_Pitch", 0.4, 0, 200, 0, 90)), JointCommandError::kOk);
  for (int i = 0; i < 5; ++i) {
    w.Step();
    const LeggedRobotState after = w.State().robots[0];
    const LeggedRobotState& before = after;  // the step's start, as its sensors saw it
    const double roll_law = 25 * (-0.35 - before.joint_positions[roll]) - 0.6 * before.joint_velocities[roll];
    EXPECT_DOUBLE_EQ(after.joint_efforts[roll], std::clamp(roll_law, -30.0, 30.0)) << i;
    EXPECT_LT(after.joint_efforts[roll], 25 * (-0.2 - before.joint_positions[roll]) - 1.0)
        << "pulls harder than a target clamped into the range would";
    const double knee_law = 200 * (0.4 - before.joint_positions[knee]) + 90;
    EXPECT_DOUBLE_EQ(after.joint_efforts[knee], std::clamp(knee_law, -60.0, 60.0)) << i;
  }
}

TEST(BoosterPdMotorTest, BadCommandsAreRefusedWithTheirNames) {
  LeggedWorld w(BoosterStandScene("t1"));
  EXPECT_EQ(w.SetJointCommand(0, Pd("Left_Knee_Pitch", 0.4, NAN, 10, 1, 0)), JointCommandError::kNotFinite);
  EXPECT_EQ(w.SetJointCommand(0, Pd("Left_Knee_Pitch", 0.4, 0, 10, 1, INFINITY)), JointCommandError::kNotFinite);
  EXPECT_EQ(w.SetJointCommand(0, Pd("Left_Knee_Pitch", NAN, 0, 10, 1, 0)), JointCommandError::kNotFinite);
  EXPECT_EQ(w.SetJointCommand(0, Pd("Left_Knee_Pitch", 0.4, 0, -1, 1, 0)), JointCommandError::kOutOfRange);
  EXPECT_EQ(w.SetJointCommand(0, Pd("Left_Knee_Pitch", 0.4, 0, 10, -0.1, 0)), JointCommandError::kOutOfRange);
  EXPECT_EQ(w.SetJointCommand(0, Pd("Left_Knee_Pitch", 0.4, 0, kMaxPdKp * 2, 1, 0)), JointCommandError::kOutOfRange);
  EXPECT_EQ(w.SetJointCommand(0, Pd("Left_Knee_Pitch", 0.4, 0, 10, kMaxPdKd * 2, 0)), JointCommandError::kOutOfRange);
  EXPECT_EQ(w.SetJointCommand(0, Pd("Left_Knee_Pitch", kMaxPdTarget * 1.01, 0, 10, 1, 0)),
            JointCommandError::kOutOfRange);
  EXPECT_EQ(w.SetJointCommand(0, Pd("Left_Knee_Pitch", 0.4, 0, 10, 1, -kMaxPdTau * 1.01)),
            JointCommandError::kOutOfRange);
  EXPECT_EQ(w.SetJointCommand(0, Pd("Left_Knee_Pitch", 0.4, kMaxPdSpeed * 1.01, 10, 1, 0)),
            JointCommandError::kOutOfRange);
  EXPECT_EQ(w.SetJointCommand(0, Pd("Knee", 0.4, 0, 10, 1, 0)), JointCommandError::kUnknownJoint);
  EXPECT_EQ(w.SetJointCommand(1, Pd("Left_Knee_Pitch", 0.4, 0, 10, 1, 0)), JointCommandError::kUnknownRobot);
  // At the guards: accepted. A target beyond the joint's range (the knee's is 0..2.34 rad), a velocity above the
  // motors' max_speed and a tau above the effort limit are commands, as on RCSSServerMJ and a real servo.
  EXPECT_EQ(w.SetJointCommand(0, Pd("Left_Knee_Pitch", -kMaxPdTarget, kMaxPdSpeed, kMaxPdKp, kMaxPdKd, kMaxPdTau)),
            JointCommandError::kOk);
  EXPECT_EQ(w.SetJointCommand(0, Pd("Left_Knee_Pitch", -0.3, 60, 10, 1, 75)), JointCommandError::kOk);
  // The other modes' motors are bounded by the joint's effort limit too (the Nao's: the robot's max_torque).
  EXPECT_EQ(w.SetJointCommand(0, {"Left_Knee_Pitch", JointMode::kTorque, 59.0}), JointCommandError::kOk);
  EXPECT_EQ(w.SetJointCommand(0, {"Left_Knee_Pitch", JointMode::kTorque, 61.0}), JointCommandError::kOutOfRange);
  EXPECT_EQ(w.SetJointCommand(0, {"AAHead_yaw", JointMode::kTorque, 7.5}), JointCommandError::kOutOfRange);
  // All or none: one bad command refuses the batch.
  const std::vector<JointCommand> batch = {Pd("AAHead_yaw", 0.1, 0, 5, 0.1, 0), Pd("Head_pitch", 1e3, 0, 5, 0.1, 0)};
  EXPECT_EQ(w.CheckJointCommands(0, batch), JointCommandError::kOutOfRange);
}

// Seeded random PD commands on every joint every 20 ms for 20 s, within the
// limits a command may carry, with gains up to twice the scene's: the state
// stays finite every step. Steps the health stage had to undo are counted
// and printed (an explicit PD with a large kd on a light joint is unstable at
// 5 ms, as it is in RCSSServerMJ).
TEST(BoosterPdMotorTest, RandomCommandsNeverMakeTheStateNonFinite) {
  for (const char* robot : {"t1", "k1"}) {
    LeggedScene scene = BoosterStandScene(robot);
    std::vector<JointStart> gains = scene.robots[0].start_joints;
    LeggedWorld w(std::move(scene));
    std::mt19937_64 rng(20261126);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const int n = static_cast<int>(gains.size());
    for (int step = 0; step < 4000; ++step) {
      if (step % 4 == 0) {
        for (int j = 0; j < n; ++j) {
          const LeggedJointInfo info = w.JointInfo(0, j);
          JointCommand c =
              Pd(gains[j].joint, info.lo + unit(rng) * (info.hi - info.lo), (unit(rng) * 2 - 1) * 20,
                 unit(rng) * 2 * gains[j].kp, unit(rng) * 2 * gains[j].kd, (unit(rng) * 2 - 1) * info.effort_limit);
          ASSERT_EQ(w.SetJointCommand(0, c), JointCommandError::kOk) << gains[j].joint;
        }
      }
      w.Step();
      ASSERT_TRUE(Finite(w.State().robots[0])) << robot << " step " << step;
    }
    std::printf("%s: 20 s of random PD commands, %llu steps undone\n", robot,
                static_cast<unsigned long long>(w.health().instability_recoveries));
  }
}

std::string Bytes(const LeggedWorld& w) {
  StateWriter out;
  w.Save(out);
  return out.Take();
}

// The PD command state (q, dq, kp, kd, tau per joint) is in the snapshot: a
// restored world continues bit for bit, here and in a fresh world.
TEST(BoosterPdMotorTest, RestoreContinuesBitForBit) {
  auto drive = [](LeggedWorld& w, int steps) {
    for (int i = 0; i < steps; ++i) {
      const double t = static_cast<double>(w.frame()) * 0.005;
      if (w.frame() % 7 == 0)  // held between: the snapshot must carry the command
        w.SetJointCommand(
            0, Pd("Left_Hip_Pitch", -0.2 + 0.1 * std::sin(3 * t), 0.3 * std::cos(3 * t), 350, 7.5, 2 * std::sin(t)));
      if (w.frame() % 50 == 0) w.SetJointCommand(0, Pd("AAHead_yaw", 0.5 * std::sin(t), 0, 5, 0.1, 0.2));
      w.Step();
    }
    return Bytes(w);
  };
  LeggedWorld w(BoosterStandScene("t1"));
  drive(w, 300);
  const std::string snapshot = Bytes(w);
  const std::string first = drive(w, 500);
  StateReader in(snapshot);
  w.Restore(in);
  ASSERT_TRUE(in.ok()) << in.error();
  EXPECT_TRUE(Bytes(w) == snapshot) << "Save after Restore differs";
  EXPECT_TRUE(drive(w, 500) == first) << "continuation differs after restore";
  LeggedWorld fresh(BoosterStandScene("t1"));
  StateReader again(snapshot);
  fresh.Restore(again);
  ASSERT_TRUE(again.ok()) << again.error();
  EXPECT_TRUE(drive(fresh, 500) == first) << "continuation differs in a fresh world";
}

// Reset and PlaceRobot(reset_joints) go back to the scene's start pose, held
// by the start PD gains.
TEST(BoosterPdMotorTest, ResetReturnsToTheStartPoseAndGains) {
  LeggedWorld w(BoosterStandScene("t1"));
  const std::string start = Bytes(w);
  ASSERT_EQ(w.SetJointCommand(0, Pd("Left_Knee_Pitch", 1.2, 0, 350, 5.5, 0)), JointCommandError::kOk);
  for (int i = 0; i < 100; ++i) w.Step();
  w.Reset();
  EXPECT_TRUE(Bytes(w) == start);
  RobotPlacement p;
  p.position = {1, 0, 0.665};
  p.reset_joints = true;
  ASSERT_EQ(w.SetJointCommand(0, Pd("Left_Knee_Pitch", 1.2, 0, 350, 5.5, 0)), JointCommandError::kOk);
  for (int i = 0; i < 100; ++i) w.Step();
  ASSERT_EQ(w.PlaceRobot(0, p), PlacementError::kOk);
  const int knee = w.JointIndex(0, "Left_Knee_Pitch");
  EXPECT_DOUBLE_EQ(w.State().robots[0].joint_positions[knee], 0.4);
  for (int i = 0; i < 100; ++i) w.Step();
  EXPECT_NEAR(w.State().robots[0].joint_positions[knee], 0.4, 0.02) << "held at the start angle";
}

}  // namespace
}  // namespace turf
