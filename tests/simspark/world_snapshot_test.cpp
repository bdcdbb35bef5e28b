// What the SimSpark referee reads of turf-sim's robots/state sample: robots touching each other and each torso's
// velocity, from the legged world through the published sample (participants/sim/legged_convert.h) into the
// league's world (participants/simspark_bridge/world_snapshot.h).
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

}  // namespace
}  // namespace turf
