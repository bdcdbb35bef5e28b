// Moving legged robots and the ball (SimSpark's beam and trainer commands),
// body poses for vision, and the robots' shapes for viewers.
#include <gtest/gtest.h>

#include <cmath>

#include "core/legged/legged_world.h"
#include "tests/core/legged/nao_fixture.h"
#include "tests/support/find.h"

namespace turf {
namespace {

using testing::NaoScene;

const LinkPose* Link(const LeggedRobotState& r, const std::string& name) {
  return test::FindBy(r.links, &LinkPose::name, name);
}

double Angle(const LeggedWorld& w, int robot, const std::string& joint) {
  return w.State().robots[robot].joint_positions[w.JointIndex(robot, joint)];
}

// Yaw about +z as a quaternion (w, x, y, z).
std::array<double, 4> Yaw(double a) { return {std::cos(a / 2), 0, 0, std::sin(a / 2)}; }

TEST(LeggedPlacementTest, LinksAreEveryBodyAtItsWorldPose) {
  LeggedWorld w(NaoScene());
  const LeggedRobotState r = w.State().robots[0];
  ASSERT_NE(Link(r, "torso"), nullptr);
  ASSERT_NE(Link(r, "head"), nullptr);
  ASSERT_NE(Link(r, "lfoot"), nullptr);
  EXPECT_EQ(Link(r, "torso")->position, r.base_position);
  // Zero pose: head centre 0.155 m above the torso centre, feet 0.375 m below (sole at 0.385).
  EXPECT_NEAR(Link(r, "head")->position[2] - r.base_position[2], 0.155, 1e-6);
  EXPECT_NEAR(Link(r, "rfoot")->position[2], 0.01, 1e-3);
  EXPECT_NEAR(Link(r, "rfoot")->position[0] - r.base_position[0], 0.055, 1e-6);  // right = +x in the model frame
}

TEST(LeggedPlacementTest, PlaceRobotMovesRootZeroesVelocityKeepsJoints) {
  LeggedWorld w(NaoScene());
  ASSERT_EQ(w.SetJointCommand(0, {"hj1", JointMode::kVelocity, 2.0}), JointCommandError::kOk);
  for (int i = 0; i < 100; ++i) w.Step();  // 0.2 s: hj1 turned ~0.4 rad, still turning
  const double hj1 = Angle(w, 0, "hj1");
  ASSERT_GT(hj1, 0.3);
  RobotPlacement p;
  p.position = {3.0, -2.0, 0.4};
  p.orientation = Yaw(M_PI / 2);
  ASSERT_EQ(w.PlaceRobot(0, p), PlacementError::kOk);
  LeggedRobotState r = w.State().robots[0];
  EXPECT_NEAR(r.base_position[0], 3.0, 1e-9);
  EXPECT_NEAR(r.base_position[1], -2.0, 1e-9);
  EXPECT_NEAR(r.base_position[2], 0.4, 1e-9);
  EXPECT_NEAR(Angle(w, 0, "hj1"), hj1, 1e-9);
  for (double v : r.joint_velocities) EXPECT_EQ(v, 0.0);
  // The model's forward (+y) now points to world -x (yaw +90 deg); the head is above the torso.
  const LinkPose* head = Link(r, "head");
  EXPECT_NEAR(head->position[0], 3.0, 0.05);
  // The robot lands from 1.5 cm and stands again; the command still holds (hj1 keeps turning, as SimSpark's).
  for (int i = 0; i < 500; ++i) w.Step();
  r = w.State().robots[0];
  EXPECT_NEAR(r.base_position[0], 3.0, 0.02);
  EXPECT_NEAR(r.base_position[2], 0.385, 0.01);
  EXPECT_GT(Angle(w, 0, "hj1"), hj1 + 0.5);
}

TEST(LeggedPlacementTest, PlaceRobotWithResetJointsRestoresZeroPoseHolding) {
  LeggedWorld w(NaoScene());
  ASSERT_EQ(w.SetJointCommand(0, {"rlj4", JointMode::kVelocity, -1.0}), JointCommandError::kOk);
  for (int i = 0; i < 200; ++i) w.Step();
  ASSERT_LT(Angle(w, 0, "rlj4"), -0.3);
  RobotPlacement p;
  p.position = {0, 0, 0.385};
  p.reset_joints = true;
  ASSERT_EQ(w.PlaceRobot(0, p), PlacementError::kOk);
  EXPECT_EQ(Angle(w, 0, "rlj4"), 0.0);
  for (int i = 0; i < 500; ++i) w.Step();
  EXPECT_NEAR(Angle(w, 0, "rlj4"), 0.0, 0.01);  // the old command is gone: it holds
}

TEST(LeggedPlacementTest, RefusesBadPlacements) {
  LeggedWorld w(NaoScene(1, /*field=*/true));
  const LeggedRobotState before = w.State().robots[0];
  RobotPlacement p;
  p.position = {NAN, 0, 0.4};
  EXPECT_EQ(w.PlaceRobot(0, p), PlacementError::kNotFinite);
  p.position = {0, 0, 0.4};
  p.orientation = {0, 0, 0, 0};
  EXPECT_EQ(w.PlaceRobot(0, p), PlacementError::kNotFinite);
  EXPECT_EQ(w.PlaceRobot(5, RobotPlacement{}), PlacementError::kUnknownRobot);
  EXPECT_EQ(w.PlaceRobot(-1, RobotPlacement{}), PlacementError::kUnknownRobot);
  EXPECT_EQ(w.State().robots[0].base_position, before.base_position);
  EXPECT_EQ(w.PlaceBall({0, 0, INFINITY}, {0, 0, 0}), PlacementError::kNotFinite);
  LeggedWorld no_field(NaoScene());
  EXPECT_EQ(no_field.PlaceBall({0, 0, 1}, {0, 0, 0}), PlacementError::kNoBall);
}

// Any finite quaternion is a rotation, however long: 1e200's squares were infinite and gave a zero quaternion.
TEST(LeggedPlacementTest, AHugeQuaternionIsNormalizedWithoutOverflow) {
  LeggedWorld w(NaoScene(1, /*field=*/true));
  RobotPlacement p;
  p.position = {0, 0, 0.4};
  p.orientation = {1e200, 0, 0, 1e200};  // 90 degrees about z
  ASSERT_EQ(w.PlaceRobot(0, p), PlacementError::kOk);
  const std::array<double, 4> q = w.State().robots[0].base_orientation;
  EXPECT_NEAR(q[0], M_SQRT1_2, 1e-12);
  EXPECT_NEAR(q[3], M_SQRT1_2, 1e-12);
  EXPECT_EQ(q[1], 0.0);
  EXPECT_EQ(q[2], 0.0);
}

TEST(LeggedPlacementTest, PlaceBallSetsPositionAndVelocity) {
  LeggedWorld w(NaoScene(1, /*field=*/true));
  ASSERT_EQ(w.PlaceBall({5.0, 1.0, 0.042}, {2.0, 0.0, 0.0}), PlacementError::kOk);
  LeggedWorldState s = w.State();
  EXPECT_NEAR(s.ball_position[0], 5.0, 1e-9);
  EXPECT_NEAR(s.ball_velocity[0], 2.0, 1e-9);
  for (int i = 0; i < 250; ++i) w.Step();  // 0.5 s rolling
  s = w.State();
  const double travelled = s.ball_position[0] - 5.0;
  std::printf("ball at 2 m/s: %.3f m in 0.5 s\n", travelled);
  EXPECT_GT(travelled, 0.6);
  EXPECT_LT(travelled, 1.01);
}

// Each robot's last touch of the ball (for referees): the end of the physics step whose contacts had one of its
// bodies against the ball; a ball rolling past 0.3 m away never touches.
TEST(LeggedPlacementTest, BallTouchIsTheLastStepARobotTouchedTheBall) {
  for (const double x : {-2.0, -1.7}) {  // at the feet (x = -2 -+ 0.055), beside them
    LeggedWorld w(NaoScene(1, /*field=*/true));
    ASSERT_EQ(w.PlaceBall({x, -1.0, 0.042}, {0.0, 1.5, 0.0}), PlacementError::kOk);
    int64_t first = -1;
    double distance_at_first = 0.0;
    for (int i = 0; i < 1000 && first < 0; ++i) {  // 2 s
      w.Step();
      const LeggedWorldState s = w.State();
      first = s.robots[0].ball_touch_ns;
      if (first >= 0) {
        EXPECT_EQ(first, s.time_ns) << "the step just made";
        const LinkPose* foot = Link(s.robots[0], "lfoot");
        ASSERT_NE(foot, nullptr);
        distance_at_first = std::hypot(s.ball_position[0] - foot->position[0], s.ball_position[1] - foot->position[1]);
      }
    }
    if (x == -2.0) {
      ASSERT_GE(first, 0) << "rolled into the feet";
      EXPECT_GT(first, 400'000'000) << "not before it got there (1 m at 1.5 m/s, slowing)";
      EXPECT_LT(distance_at_first, 0.2);
      const int64_t touched = first;
      for (int i = 0; i < 10; ++i) w.Step();
      EXPECT_GE(w.State().robots[0].ball_touch_ns, touched) << "kept (or later) after the touch";
    } else {
      EXPECT_EQ(first, -1) << "rolled past";
    }
  }
}

TEST(LeggedPlacementTest, GeomsDescribeTheNaosShapes) {
  LeggedWorld w(NaoScene());
  const std::vector<LeggedGeom> geoms = w.RobotGeoms(0);
  bool torso = false;
  bool head = false;
  for (const LeggedGeom& g : geoms) {
    if (g.body == "torso" && g.shape == LeggedGeom::Shape::kBox) {
      torso = true;
      EXPECT_NEAR(g.size[0], 0.05, 1e-9);
      EXPECT_NEAR(g.size[2], 0.09, 1e-9);
    }
    if (g.body == "head" && g.shape == LeggedGeom::Shape::kSphere) {
      head = true;
      EXPECT_NEAR(g.size[0], 0.065, 1e-9);
    }
  }
  EXPECT_TRUE(torso);
  EXPECT_TRUE(head);
  EXPECT_TRUE(w.RobotGeoms(3).empty());
}

// Robots touching (a referee's input): one entry per pair, robots in scene order, the mean contact point between them.
TEST(LeggedPlacementTest, TwoRobotsTouchingAreOnePairWithTheMeanContactPoint) {
  LeggedWorld w(NaoScene(3));
  w.Step();
  EXPECT_TRUE(w.State().robot_contacts.empty()) << "standing 1 m apart";
  RobotPlacement p;
  p.position = {-1.85, 0.0, 0.385};  // nao_2 0.15 m to nao_1's right: arms and legs overlap
  ASSERT_EQ(w.PlaceRobot(1, p), PlacementError::kOk);
  w.Step();
  const LeggedWorldState s = w.State();
  ASSERT_EQ(s.robot_contacts.size(), 1u);
  const RobotContact& c = s.robot_contacts[0];
  EXPECT_EQ(c.robot_a, 0);
  EXPECT_EQ(c.robot_b, 1);
  EXPECT_GT(c.points, 0);
  EXPECT_GT(c.point[0], -2.0) << "between the two";
  EXPECT_LT(c.point[0], -1.85);
  EXPECT_GT(c.point[2], 0.0);
  EXPECT_LT(c.point[2], 0.6);
}

// The root body's velocity, world frame: falling freely from 1 m it gains g per second downwards.
TEST(LeggedPlacementTest, BaseVelocityIsTheRootBodysInTheWorldFrame) {
  LeggedWorld w(NaoScene());
  RobotPlacement p;
  p.position = {0.0, 0.0, 1.5};
  ASSERT_EQ(w.PlaceRobot(0, p), PlacementError::kOk);
  const int64_t start = w.time_ns();
  std::array<double, 3> before{};
  while (w.time_ns() - start < 200'000'000) {
    before = w.State().robots[0].base_position;
    w.Step();
  }
  const LeggedRobotState r = w.State().robots[0];
  const double t = (w.time_ns() - start) * 1e-9;
  EXPECT_NEAR(r.base_velocity[2], -9.81 * t, 0.02 * 9.81 * t);
  EXPECT_NEAR(r.base_velocity[0], 0.0, 1e-6);
  EXPECT_NEAR(r.base_velocity[1], 0.0, 1e-6);
  const double dt = w.scene().physics.step;
  EXPECT_NEAR((r.base_position[2] - before[2]) / dt, r.base_velocity[2], 1.01 * 9.81 * dt)
      << "the position's rate of change, within one step's change of velocity";
}

}  // namespace
}  // namespace turf
