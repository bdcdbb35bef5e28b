// The SimSpark session's world (codecs/simspark/session.h) in turf-sim's legged terms (read through LeggedLockstep,
// participants/common/legged_lockstep.h): where each robot parks, the world after a cycle (joints, IMU, foot force
// sensors, link poses, ball), a joint velocity command as turf's joint target, a ball placement. The SimSpark
// bridge's engine inherits these (league_front_end.h's SnapshotOf, Target, Ball).
#pragma once

#include <vector>

#include "codecs/simspark/session.h"
#include "participants/common/legged_lockstep.h"
#include "participants/lockstep_front_end/lockstep_world.h"

namespace turf {

struct SimSparkWorld {
  // Each robot's torso pose now, in the scene's order: where it waits while no agent drives it.
  static std::vector<simspark::RobotMove> ParkPoses(const LeggedLockstep& link);
  static simspark::WorldSnapshot SnapshotOf(const idl::LeggedState& state);
  static idl::JointTarget Target(const simspark::JointVelocity& command);
  static BallMotion Ball(const simspark::BallMove& ball) { return {ball.position, ball.velocity}; }
};

}  // namespace turf
