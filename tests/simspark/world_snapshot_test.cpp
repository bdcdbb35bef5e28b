// What the SimSpark referee reads of turf-sim's robots/state sample: robots touching each other, each torso's
// velocity and each robot's last touch of the ball, from the legged world through the published sample
// (participants/sim/legged_convert.h) into the league's world (participants/simspark_bridge/world_snapshot.h).
#include "participants/simspark_bridge/world_snapshot.h"

#include <gtest/gtest.h>

#include "core/legged/legged_world.h"
#include "participants/sim/legged_convert.h"
#include "tests/core/legged/nao_fixture.h"

namespace turf {
namespace {

TEST(SimSparkWorldSnapshot, CarriesRobotContactsByNameAndTorsoVelocities) {
  LeggedWorld w(testing::NaoScene(3));
  RobotPlacement touching;
  touching.position = {-1.85, 0.0, 0.385};  // nao_2 overlapping nao_1
  ASSERT_EQ(w.PlaceRobot(1, touching), PlacementError::kOk);
  RobotPlacement falling;
  falling.position = {0.0, 0.0, 2.0};  // nao_3 in the air
  ASSERT_EQ(w.PlaceRobot(2, falling), PlacementError::kOk);
  for (int i = 0; i < 10; ++i) w.Step();
  const LeggedWorldState state = w.State();
  ASSERT_EQ(state.robot_contacts.size(), 1u);
  idl::LeggedState sample;
  FillState(state, &sample);
  const simspark::WorldSnapshot world = SimSparkWorld::SnapshotOf(sample);
  ASSERT_EQ(world.robot_contacts.size(), 1u);
  EXPECT_EQ(world.robot_contacts[0].robot_a, "nao_1");
  EXPECT_EQ(world.robot_contacts[0].robot_b, "nao_2");
  for (int k = 0; k < 3; ++k) EXPECT_EQ(world.robot_contacts[0].point[k], state.robot_contacts[0].point[k]);
  const simspark::RobotSnapshot* nao_3 = world.Find("nao_3");
  ASSERT_NE(nao_3, nullptr);
  EXPECT_LT(nao_3->velocity.z(), -0.1) << "falling";
  EXPECT_EQ(nao_3->velocity.z(), state.robots[2].base_velocity[2]);
}

TEST(SimSparkWorldSnapshot, CarriesEachRobotsLastBallTouchInSeconds) {
  LeggedWorld w(testing::NaoScene(2, /*field=*/true));
  ASSERT_EQ(w.PlaceBall({-2.0, -0.3, 0.042}, {0.0, 1.0, 0.0}), PlacementError::kOk);  // into nao_1's feet
  int steps = 0;
  for (; steps < 500 && w.State().robots[0].ball_touch_ns < 0; ++steps) w.Step();
  const LeggedWorldState state = w.State();
  ASSERT_GE(state.robots[0].ball_touch_ns, 0);
  ASSERT_EQ(state.robots[1].ball_touch_ns, -1);
  idl::LeggedState sample;
  FillState(state, &sample);
  ASSERT_EQ(sample.ball_touches().size(), 1u) << "only robots that touched it";
  const simspark::WorldSnapshot world = SimSparkWorld::SnapshotOf(sample);
  EXPECT_DOUBLE_EQ(world.Find("nao_1")->ball_touch_time, static_cast<double>(state.robots[0].ball_touch_ns) * 1e-9);
  EXPECT_EQ(world.Find("nao_2")->ball_touch_time, -1.0);
}

}  // namespace
}  // namespace turf
