// Physics of the Nao model (configs/robots/nao.xml) in a legged world:
// standing, joint servos like SimSpark's hinge motors, robustness.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/legged/legged_world.h"
#include "loader/legged_scene_yaml.h"
#include "tests/core/legged/nao_fixture.h"

namespace turf {
namespace {

using testing::NaoScene;

double JointAngle(const LeggedWorld& w, int robot, const std::string& joint) {
  return w.State().robots[robot].joint_positions[w.JointIndex(robot, joint)];
}

// Every test runs at the default 2 ms step, at 5 ms and 6.67 ms with MuJoCo's contacts, and at the SimSpark match
// scene's 20 ms step with its physics, contact law and joint stops (configs/scenes/simspark_match.yaml:
// rcssserver3d's whole ODE law and hinge stops at the reference's step).
constexpr double kMatchStep = 0.02;

class NaoPhysicsTest : public ::testing::TestWithParam<double> {
 protected:
  double step() const { return GetParam(); }
  int steps_per_second() const { return static_cast<int>(std::lround(1.0 / step())); }
  LeggedScene Scene(int robots = 1, bool field = false) const {
    LeggedScene s = NaoScene(robots, field);
    s.physics.step = step();
    if (step() == kMatchStep) {
      LeggedSceneLoadResult match = LoadLeggedSceneFile(TURF_SOURCE_DIR "/configs/scenes/simspark_match.yaml");
      if (!match.scene) throw std::runtime_error(match.errors.front());
      EXPECT_EQ(match.scene->physics.step, kMatchStep);
      s.physics = match.scene->physics;
      s.contacts = match.scene->contacts;
      s.joint_stops = match.scene->joint_stops;
    }
    return s;
  }
  struct Phase {
    JointCommand command;  // robot 0's
    int steps;             // physics steps it runs for
  };
  // One robot, from its start, runs each phase in turn: then the angle of the
  // last phase's joint, or NaN if a command is refused.
  double AngleAfter(const std::vector<Phase>& phases) const {
    LeggedWorld w(Scene());
    for (const Phase& p : phases) {
      if (w.SetJointCommand(0, p.command) != JointCommandError::kOk) return NAN;
      for (int i = 0; i < p.steps; ++i) w.Step();
    }
    return JointAngle(w, 0, phases.back().command.joint);
  }
};

TEST_P(NaoPhysicsTest, ModelHasTheSheetsJointsMassAndSensors) {
  LeggedWorld w(Scene());
  const LeggedRobotState s = w.State().robots[0];
  EXPECT_EQ(s.joint_names.size(), 22u);
  for (const char* j : {"hj1", "hj2", "raj1", "laj4", "rlj1", "llj6"}) EXPECT_GE(w.JointIndex(0, j), 0) << j;
  EXPECT_TRUE(s.has_imu);
  ASSERT_EQ(s.forces.size(), 2u);
  EXPECT_EQ(s.forces[0].name, "rf");
  EXPECT_EQ(s.forces[1].name, "lf");
  // Torso centre 0.385 m above the sole at the start.
  EXPECT_NEAR(s.base_position[2], 0.385, 1e-9);
}

// Zero joint velocities for 10 s: the Nao stays upright where it stands.
TEST_P(NaoPhysicsTest, StandsTenSecondsWithZeroCommands) {
  LeggedWorld w(Scene());
  const auto start = w.State().robots[0].base_position;
  double max_dz = 0.0;
  double max_dxy = 0.0;
  double max_tilt = 0.0;
  for (int i = 0; i < 10 * steps_per_second(); ++i) {
    w.Step();
    const LeggedRobotState s = w.State().robots[0];
    max_dz = std::max(max_dz, std::abs(s.base_position[2] - start[2]));
    max_dxy = std::max(max_dxy, std::hypot(s.base_position[0] - start[0], s.base_position[1] - start[1]));
    // Tilt: angle of the torso's z axis from the vertical.
    const auto& q = s.base_orientation;
    const double zz = 1 - 2 * (q[1] * q[1] + q[2] * q[2]);
    max_tilt = std::max(max_tilt, std::acos(std::clamp(zz, -1.0, 1.0)));
  }
  std::printf("stand 10 s: max |dz| %.4f m, max |dxy| %.4f m, max tilt %.4f rad\n", max_dz, max_dxy, max_tilt);
  EXPECT_LT(max_dz, 0.01);
  EXPECT_LT(max_dxy, 0.01);
  EXPECT_LT(max_tilt, 0.05);
  const LeggedRobotState s = w.State().robots[0];
  // Standing still: the accelerometer reads about +g up, both feet carry the weight.
  EXPECT_NEAR(s.accelerometer[2], 9.81, 0.2);
  const double weight = 4.6071 * 9.81;
  EXPECT_NEAR(s.forces[0].values[0] + s.forces[1].values[0], weight, 0.1 * weight);
  // SimSpark's FRP: force on each foot in the foot frame (+z), applied at the sole (z = -0.01).
  for (const ForceReading& f : s.forces) {
    std::printf("%s: force (%.2f %.2f %.2f) N at (%.4f %.4f %.4f) m\n", f.name.c_str(), f.force[0], f.force[1],
                f.force[2], f.point[0], f.point[1], f.point[2]);
    EXPECT_TRUE(f.contact);
    EXPECT_NEAR(f.force[2], weight / 2, 0.15 * weight);
    EXPECT_NEAR(f.point[2], -0.01, 0.002);
    EXPECT_LT(std::hypot(f.force[0], f.force[1]), 0.05 * weight);
  }
  EXPECT_EQ(w.health().instability_recoveries, 0u);
}

// The constraint solver's cap is counted: four robots standing need more than one iteration a step, and a cap the
// solver never reaches (physics.solver_iterations, configs/scenes/simspark_match.yaml) counts nothing.
TEST_P(NaoPhysicsTest, StepsWhereTheSolverStoppedAtItsCapAreCounted) {
  for (const int iterations : {1, 100}) {
    LeggedScene s = Scene(4);
    s.physics.solver_iterations = iterations;
    LeggedWorld w(s);
    for (int i = 0; i < 2 * steps_per_second(); ++i) w.Step();
    std::printf("%d iterations: %llu of %d steps capped\n", iterations,
                static_cast<unsigned long long>(w.health().solver_capped_steps), 2 * steps_per_second());
    if (iterations == 1)
      EXPECT_GT(w.health().solver_capped_steps, 0u);
    else
      EXPECT_EQ(w.health().solver_capped_steps, 0u);
  }
}

// SimSpark: (he1 1.0) for 25 cycles (0.5 s) turns hj1 by 28.65 deg (0.5 rad).
TEST_P(NaoPhysicsTest, VelocityCommandReachesExpectedAngle) {
  LeggedWorld w(Scene());
  for (int i = 0; i < steps_per_second(); ++i) w.Step();  // settle
  const double start = JointAngle(w, 0, "hj1");
  ASSERT_EQ(w.SetJointCommand(0, {"hj1", JointMode::kVelocity, 1.0}), JointCommandError::kOk);
  for (int i = 0; i < steps_per_second() / 2; ++i) w.Step();
  const double moved_at_half_second = JointAngle(w, 0, "hj1") - start;
  ASSERT_EQ(w.SetJointCommand(0, {"hj1", JointMode::kVelocity, 0.0}), JointCommandError::kOk);
  for (int i = 0; i < steps_per_second() / 5; ++i) w.Step();
  const double moved = JointAngle(w, 0, "hj1") - start;
  std::printf("hj1 at 1 rad/s: %.4f rad after 0.5 s, %.4f rad after stopping\n", moved_at_half_second, moved);
  EXPECT_NEAR(moved_at_half_second, 0.5, 0.03);
  EXPECT_NEAR(moved, 0.5, 0.02);
}

// A knee bent by a velocity command (knee bends negative) and held.
TEST_P(NaoPhysicsTest, KneeFollowsVelocityAndHolds) {
  const double knee = AngleAfter({{{"rlj4", JointMode::kVelocity, -1.0}, steps_per_second() / 5},
                                  {{"rlj4", JointMode::kVelocity, 0.0}, steps_per_second()}});
  std::printf("rlj4 at -1 rad/s for 0.2 s, held 1 s: %.4f rad\n", knee);
  EXPECT_NEAR(knee, -0.2, 0.03);
}

TEST_P(NaoPhysicsTest, PositionCommandReachesTarget) {
  const double a = AngleAfter({{{"laj1", JointMode::kPosition, -1.0}, steps_per_second()}});
  std::printf("laj1 position target -1.0 rad after 1 s: %.4f rad\n", a);
  EXPECT_NEAR(a, -1.0, 0.05);
}

// hj2's range is -45..45 deg. MuJoCo's limit holds a joint driven into it; the reference's stop (the match
// scene's) is elastic, the joint bouncing about it by a few degrees (tests/core/legged/nao_stops_test.cpp).
TEST_P(NaoPhysicsTest, JointsStopAtTheirLimits) {
  const double angle = AngleAfter({{{"hj2", JointMode::kVelocity, 6.0}, steps_per_second()}});
  std::printf("hj2 driven at 6 rad/s into its 45 deg stop for 1 s: %.2f deg\n", angle * 180 / M_PI);
  EXPECT_NEAR(angle, M_PI / 4, step() == kMatchStep ? 0.09 : 0.02);  // 20 ms: 41.3 deg at this instant
}

TEST_P(NaoPhysicsTest, RefusesBadCommands) {
  LeggedWorld w(Scene());
  EXPECT_EQ(w.SetJointCommand(1, {"hj1", JointMode::kVelocity, 0.0}), JointCommandError::kUnknownRobot);
  EXPECT_EQ(w.SetJointCommand(0, {"he1", JointMode::kVelocity, 0.0}), JointCommandError::kUnknownJoint);
  EXPECT_EQ(w.SetJointCommand(0, {"hj1", JointMode::kVelocity, NAN}), JointCommandError::kNotFinite);
  EXPECT_EQ(w.SetJointCommand(0, {"hj1", JointMode::kVelocity, 6.2}), JointCommandError::kOutOfRange);
  EXPECT_EQ(w.SetJointCommand(0, {"hj2", JointMode::kPosition, 1.0}), JointCommandError::kOutOfRange);
  EXPECT_EQ(w.SetJointCommand(0, {"hj2", JointMode::kTorque, 10.5}), JointCommandError::kOutOfRange);
  EXPECT_EQ(w.SetJointCommand(0, {"hj2", JointMode::kPosition, 0.1, -1.0, INFINITY}), JointCommandError::kNotFinite);
}

// Random commands at SimSpark's 50 Hz cycle for 10 s, two robots on the 3D
// field: velocity only (SimSpark's effectors), or velocity, position
// (anywhere in +-2 rad; out of range is refused) and torque mixed. The state
// stays finite and on the field, and no step needs an undo. Returns the
// largest joint speed seen.
double RunRandomCommands(const LeggedScene& scene, bool mixed) {
  LeggedWorld w(scene);
  const int steps_per_second = static_cast<int>(std::lround(1.0 / scene.physics.step));
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> mode(0, mixed ? 2 : 0);
  const LeggedWorldState first = w.State();
  double max_joint_speed = 0.0;
  int refused = 0;
  for (int i = 0; i < 10 * steps_per_second; ++i) {
    if (i % (steps_per_second / 50) == 0) {  // every 20 ms
      for (int r = 0; r < 2; ++r) {
        for (const std::string& j : first.robots[r].joint_names) {
          JointCommand c{j, static_cast<JointMode>(mode(rng)), 0.0};
          c.value = unit(rng) * (c.mode == JointMode::kVelocity ? 6.1395 : c.mode == JointMode::kTorque ? 10.0 : 2.0);
          refused += w.SetJointCommand(r, c) != JointCommandError::kOk;  // positions out of range are refused
        }
      }
    }
    w.Step();
    const LeggedWorldState s = w.State();
    for (const LeggedRobotState& r : s.robots) {
      for (double v : r.joint_velocities) {
        EXPECT_TRUE(std::isfinite(v));
        max_joint_speed = std::max(max_joint_speed, std::abs(v));
      }
      for (double p : r.base_position) EXPECT_TRUE(std::isfinite(p));
      EXPECT_LT(std::abs(r.base_position[0]), 5.0);
      EXPECT_LT(r.base_position[2], 1.0);
      EXPECT_GT(r.base_position[2], -0.01);
      if (::testing::Test::HasFailure()) return max_joint_speed;
    }
  }
  std::printf("random %s commands 10 s: max joint speed %.2f rad/s, %d refused, recoveries %llu\n",
              mixed ? "mixed" : "velocity", max_joint_speed, refused,
              static_cast<unsigned long long>(w.health().instability_recoveries));
  EXPECT_EQ(w.health().instability_recoveries, 0u);
  return max_joint_speed;
}

TEST_P(NaoPhysicsTest, RandomVelocityCommandsDoNotExplode) {
  // Joints move at most about the commanded 6.14 rad/s, plus impacts.
  EXPECT_LT(RunRandomCommands(Scene(2, /*field=*/true), /*mixed=*/false), 20.0);
}

TEST_P(NaoPhysicsTest, RandomMixedCommandsDoNotExplode) {
  // Torque and position modes drive a joint no faster than max_speed (the
  // motor's speed limit), but a joint under a small torque is nearly free and
  // falls and impacts whip its light links (measured 38-40 rad/s; 63-67 before
  // the motors were speed-limited constraints).
  EXPECT_LT(RunRandomCommands(Scene(2, /*field=*/true), /*mixed=*/true), 60.0);
}

// Same scene and command stream: identical state, also after a reset.
TEST_P(NaoPhysicsTest, DeterministicAndResettable) {
  auto run = [](LeggedWorld& w) {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> speed(-3.0, 3.0);
    const std::vector<std::string> joints = w.State().robots[0].joint_names;
    for (int i = 0; i < 1000; ++i) {
      if (i % 10 == 0) {
        for (const std::string& j : joints) w.SetJointCommand(0, {j, JointMode::kVelocity, speed(rng)});
      }
      w.Step();
    }
    return w.State();
  };
  LeggedWorld a(Scene());
  LeggedWorld b(Scene());
  const LeggedWorldState sa = run(a);
  const LeggedWorldState sb = run(b);
  EXPECT_EQ(sa.robots[0].joint_positions, sb.robots[0].joint_positions);
  EXPECT_EQ(sa.robots[0].base_position, sb.robots[0].base_position);
  a.Reset();
  EXPECT_EQ(a.time_ns(), 0);
  const LeggedWorldState again = run(a);
  EXPECT_EQ(again.robots[0].joint_positions, sa.robots[0].joint_positions);
}

// rcssserver3d's DragController on every body (physics.body_drag, as in the match scene): a Nao falling freely (its
// joints held, so all bodies move as one) slows as dv/dt = g - k v with k = bodies x 0.01 / 4.6071 kg; without drag
// it falls at g.
TEST(NaoDrag, AFallingNaoSlowsByEachBodysDrag) {
  const auto fall_speed = [](double linear_drag) {
    LeggedScene s = NaoScene(1, false);
    s.physics.step = 0.005;
    s.physics.body_linear_drag = linear_drag;
    s.physics.body_angular_drag = linear_drag;
    LeggedWorld w(std::move(s));
    RobotPlacement high;
    high.position = {0.0, 0.0, 20.0};
    EXPECT_EQ(w.PlaceRobot(0, high), PlacementError::kOk);
    while (w.time_ns() < 500'000'000) w.Step();
    return std::pair{-w.State().robots[0].base_velocity[2], w.State().robots[0].links.size()};
  };
  const auto [free, bodies] = fall_speed(0.0);
  const auto [dragged, same_bodies] = fall_speed(0.01);
  const double k = bodies * 0.01 / 4.6071;
  const double predicted = 9.81 / k * (1.0 - std::exp(-k * 0.5));
  std::printf("after 0.5 s of fall: %.4f m/s free, %.4f m/s with drag (predicted %.4f, %zu bodies)\n", free, dragged,
              predicted, bodies);
  EXPECT_NEAR(free, 9.81 * 0.5, 0.002);
  EXPECT_NEAR(dragged, predicted, 0.002);
  EXPECT_GT(free - dragged, 0.05);
}

INSTANTIATE_TEST_SUITE_P(Steps, NaoPhysicsTest, ::testing::Values(0.002, 0.005, 0.02 / 3, kMatchStep),
                         [](const ::testing::TestParamInfo<double>& p) {
                           return std::to_string(static_cast<int>(std::lround(p.param * 1e6))) + "us";
                         });

}  // namespace
}  // namespace turf
