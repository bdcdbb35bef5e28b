// A legged scene stepped as groups of robots on two threads (core/legged/legged_islands.h) against the same scene
// as one world: robots apart move as they do in one world (to the solver's tolerance), robots that come to touch
// (or meet the ball) are stepped together first, and runs, snapshots and resets stay byte for byte reproducible.
// Simulation time only, at RCSSServerMJ's 5 ms step, with T1 robots holding configs/scenes/t1_stand.yaml's pose.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/legged/legged_islands.h"
#include "core/legged/legged_world.h"
#include "tests/core/legged/booster_fixture.h"

namespace turf {
namespace {

using testing::BoosterStandScene;

// n T1 at (x_i, y), each holding the stand pose; with the 3D field and its ball at the centre if `field`.
LeggedScene Robots(const std::vector<double>& xs, double y, bool field, int threads) {
  const LeggedScene stand = BoosterStandScene("t1");
  LeggedScene s = stand;
  s.field.enabled = field;
  s.field.walls = false;
  s.field.ball_radius = 0.11;  // RCSSServerMJ's ball
  s.field.ball_mass = 0.41;
  s.physics.island_threads = threads;
  s.robots.clear();
  for (size_t i = 0; i < xs.size(); ++i) {
    LeggedRobot r = stand.robots.front();
    r.name = "t1_" + std::to_string(i + 1);
    r.id = static_cast<int>(i) + 1;
    r.x = xs[i];
    r.y = y;
    s.robots.push_back(std::move(r));
  }
  return s;
}

// Every robot's arms swing (shoulder pitch targets on a sine), the same in both worlds.
template <class World>
void Swing(World& w, int step) {
  for (int r = 0; r < w.RobotCount(); ++r) {
    JointCommand c;
    c.mode = JointMode::kPd;
    c.kp = 40;
    c.kd = 2;
    c.value = 0.6 * std::sin(0.02 * step + r);
    for (const char* joint : {"Left_Shoulder_Pitch", "Right_Shoulder_Pitch"}) {
      c.joint = joint;
      ASSERT_EQ(w.SetJointCommand(r, c), JointCommandError::kOk) << joint;
    }
  }
}

// The largest difference of any robot's base position or joint angle between two states.
double Difference(const LeggedWorldState& a, const LeggedWorldState& b) {
  double d = 0.0;
  for (size_t r = 0; r < a.robots.size(); ++r) {
    for (int k = 0; k < 3; ++k) d = std::max(d, std::abs(a.robots[r].base_position[k] - b.robots[r].base_position[k]));
    for (size_t j = 0; j < a.robots[r].joint_positions.size(); ++j)
      d = std::max(d, std::abs(a.robots[r].joint_positions[j] - b.robots[r].joint_positions[j]));
  }
  return d;
}

std::string Snapshot(const LeggedIslands& w) {
  StateWriter out;
  w.Save(out);
  return out.Take();
}

// Four robots 2 m apart: two groups of two, and 2 s of swinging arms as in one world, to 1e-6 (m, rad): both
// solve each robot's contacts to MuJoCo's tolerance, apart or together.
TEST(LeggedIslands, RobotsApartMoveAsInOneWorld) {
  const std::vector<double> xs{-3, -1, 1, 3};
  LeggedIslands islands(Robots(xs, 0, false, 2));
  LeggedWorld one(Robots(xs, 0, false, 1));
  ASSERT_EQ(islands.GroupCount(), 2);
  EXPECT_NE(islands.GroupOf(0), islands.GroupOf(3));
  double worst = 0.0;
  for (int i = 0; i < 400; ++i) {
    Swing(islands, i);
    Swing(one, i);
    islands.Step();
    one.Step();
    worst = std::max(worst, Difference(islands.State(), one.State()));
  }
  EXPECT_LT(worst, 1e-6);
  EXPECT_EQ(islands.regroups(), 1u) << "the start's grouping held";
  EXPECT_GT(Difference(islands.State(), LeggedIslands(Robots(xs, 0, false, 2)).State()), 1e-3) << "the arms moved";
  EXPECT_EQ(islands.time_ns(), one.time_ns());
}

// A robot dropped onto another's head from the other group: both step in one group from the next step on, with
// the commands they had; they touch (a robot contact), and the fall is the one world's.
TEST(LeggedIslands, RobotsThatMayTouchStepTogether) {
  const std::vector<double> xs{-3, 3};
  LeggedIslands islands(Robots(xs, 0, false, 2));
  LeggedWorld one(Robots(xs, 0, false, 1));
  ASSERT_NE(islands.GroupOf(0), islands.GroupOf(1));
  RobotPlacement above;
  above.position = {-3, 0, 2.0};
  ASSERT_EQ(islands.PlaceRobot(1, above), PlacementError::kOk);
  ASSERT_EQ(one.PlaceRobot(1, above), PlacementError::kOk);
  Swing(islands, 0);  // commands given before the regroup, held since: they move with the robot
  Swing(one, 0);
  bool touched = false;
  double worst = 0.0;
  for (int i = 0; i < 200; ++i) {
    islands.Step();
    one.Step();
    ASSERT_EQ(islands.GroupOf(0), islands.GroupOf(1)) << "step " << i;
    const LeggedWorldState a = islands.State();
    const LeggedWorldState b = one.State();
    worst = std::max(worst, Difference(a, b));
    ASSERT_EQ(a.robot_contacts.size(), b.robot_contacts.size()) << "step " << i;
    touched = touched || !a.robot_contacts.empty();
  }
  EXPECT_TRUE(touched) << "the dropped robot never landed on the other";
  EXPECT_LT(worst, 1e-6);
}

// Robots touching in both groups, then every robot in one pile: one group is left empty. Its last state's robot
// contacts were read as if it still held robots (turf-sim and `import turf` segfaulted on a 22-robot pile).
TEST(LeggedIslands, AGroupLeftEmptyReportsNothing) {
  LeggedIslands islands(Robots({-6, -2, 2, 6}, 0, false, 2));
  ASSERT_NE(islands.GroupOf(0), islands.GroupOf(3));
  auto drop = [&](int robot, double x, double z) {
    RobotPlacement p;
    p.position = {x, 0, z};
    ASSERT_EQ(islands.PlaceRobot(robot, p), PlacementError::kOk);
  };
  drop(1, -6, 1.6);  // on robot 0's head
  drop(3, 2, 1.6);   // on robot 2's head
  bool both_touch = false;
  for (int i = 0; i < 400 && !both_touch; ++i) {
    islands.Step();
    const LeggedWorldState s = islands.State();
    both_touch = s.robot_contacts.size() >= 2;
  }
  ASSERT_TRUE(both_touch) << "the dropped robots never landed";
  ASSERT_NE(islands.GroupOf(0), islands.GroupOf(2));
  for (int r = 1; r < 4; ++r) drop(r, -6, 1.0 + 0.8 * r);  // everyone on robot 0
  for (int i = 0; i < 50; ++i) {
    islands.Step();
    const LeggedWorldState s = islands.State();
    ASSERT_EQ(s.robots.size(), 4u);
    for (const RobotContact& c : s.robot_contacts) {
      EXPECT_GE(c.robot_a, 0);
      EXPECT_LT(c.robot_b, 4);
    }
  }
  EXPECT_EQ(islands.GroupOf(0), islands.GroupOf(3));
}

// The ball rolled from its own island at a robot: it joins the robot's group before it arrives, and the robot
// records the touch in the same step as in one world.
TEST(LeggedIslands, TheBallJoinsTheGroupOfTheRobotItRollsAt) {
  const std::vector<double> xs{-3, 3};
  LeggedIslands islands(Robots(xs, 0, true, 2));
  LeggedWorld one(Robots(xs, 0, true, 1));
  ASSERT_GE(islands.BallGroup(), 0);
  ASSERT_NE(islands.BallGroup(), islands.GroupOf(1)) << "the ball at the centre is an island of its own";
  const std::array<double, 3> at{1.5, 0.1, 0.11};
  const std::array<double, 3> toward{4, 0, 0};
  ASSERT_EQ(islands.PlaceBall(at, toward), PlacementError::kOk);
  ASSERT_EQ(one.PlaceBall(at, toward), PlacementError::kOk);
  for (int i = 0; i < 200; ++i) {
    islands.Step();
    one.Step();
  }
  EXPECT_EQ(islands.BallGroup(), islands.GroupOf(1));
  const LeggedWorldState a = islands.State();
  const LeggedWorldState b = one.State();
  ASSERT_GE(b.robots[1].ball_touch_ns, 0) << "the ball never reached the robot";
  EXPECT_EQ(a.robots[1].ball_touch_ns, b.robots[1].ball_touch_ns);
  EXPECT_EQ(a.robots[0].ball_touch_ns, -1);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(a.ball_position[k], b.ball_position[k], 1e-6) << k;
}

// Regroups included: the same inputs give the same bytes; a snapshot restored into a new object (whose spare
// worlds differ) continues byte for byte; a reset is the start again.
TEST(LeggedIslands, RunsSnapshotsAndResetsAreReproducible) {
  const LeggedScene scene = Robots({-3, 3, 6}, 0, true, 2);
  auto run = [&](LeggedIslands& w, int from, int to) {
    for (int i = from; i < to; ++i) {
      if (i == 10) {
        RobotPlacement above;
        above.position = {-3, 0, 2.0};
        ASSERT_EQ(w.PlaceRobot(1, above), PlacementError::kOk);
      }
      Swing(w, i);
      w.Step();
    }
  };
  LeggedIslands a(scene);
  const std::string start = Snapshot(a);
  run(a, 0, 100);
  const std::string middle = Snapshot(a);
  run(a, 100, 200);
  const std::string end = Snapshot(a);
  EXPECT_GE(a.regroups(), 2u);

  LeggedIslands b(scene);
  run(b, 0, 200);
  EXPECT_EQ(Snapshot(b), end);

  LeggedIslands c(scene);
  StateReader in(middle);
  c.Restore(in);
  ASSERT_TRUE(in.ok()) << in.error();
  EXPECT_EQ(Snapshot(c), middle);
  run(c, 100, 200);
  EXPECT_EQ(Snapshot(c), end);

  a.Reset();
  EXPECT_EQ(Snapshot(a), start);
}

// A snapshot restored into new islands (turf-sim resuming after a crash) regroups as the run it came from: the
// grouping before the next step reads the shapes' positions of the last step, which the snapshot carries. Robots 1
// and 2 are put beside robot 0 (one group of three, robot 3 alone); the new islands' worlds start with every
// group's robots at the same spots, so without those positions they regroup at once, and differently.
TEST(LeggedIslands, ARestoredSnapshotRegroupsAsTheRunItCameFrom) {
  const LeggedScene scene = Robots({-6, -2, 2, 6}, 0, false, 2);
  LeggedIslands a(scene);
  const double z = a.State().robots[0].base_position[2];
  auto run = [&](LeggedIslands& w, int from, int to) {
    for (int i = from; i < to; ++i) {
      if (i == 10) {
        RobotPlacement beside;
        beside.position = {-6, 0.5, z};
        ASSERT_EQ(w.PlaceRobot(1, beside), PlacementError::kOk);
        beside.position = {-6, -0.5, z};
        ASSERT_EQ(w.PlaceRobot(2, beside), PlacementError::kOk);
      }
      Swing(w, i);
      w.Step();
    }
  };
  run(a, 0, 100);
  const std::string middle = Snapshot(a);
  LeggedIslands c(scene);
  StateReader in(middle);
  c.Restore(in);
  ASSERT_TRUE(in.ok()) << in.error();
  const uint64_t a_regroups = a.regroups(), c_regroups = c.regroups();
  run(a, 100, 101);
  run(c, 100, 101);
  for (int r = 0; r < 4; ++r) EXPECT_EQ(c.GroupOf(r), a.GroupOf(r)) << "robot " << r;
  EXPECT_EQ(c.regroups() - c_regroups, a.regroups() - a_regroups) << "regroupings in the step after the snapshot";
  run(a, 101, 300);
  run(c, 101, 300);
  EXPECT_EQ(Snapshot(c), Snapshot(a));
}

// A snapshot whose groups name a robot twice (or none) is refused and changes nothing.
TEST(LeggedIslands, ASnapshotWithBrokenGroupsIsRefused) {
  LeggedIslands w(Robots({-3, 3}, 0, false, 2));
  std::string bytes = Snapshot(w);
  // Header: tag, frame, regroup frame, two counters (4 + 4 x 8 bytes), the group count (4); then the first group's
  // robot count (8) and robot (4).
  const size_t robot = 4 + 4 * 8 + 4 + 8;
  ASSERT_LT(robot + 4, bytes.size());
  bytes[robot] = 7;  // no such robot
  StateReader in(bytes);
  const std::string before = Snapshot(w);
  w.Restore(in);
  EXPECT_FALSE(in.ok());
  EXPECT_EQ(Snapshot(w), before);
}

}  // namespace
}  // namespace turf
