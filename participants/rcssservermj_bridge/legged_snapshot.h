// The RCSSServerMJ session's world (codecs/rcssservermj/session.h) in turf-sim's legged terms (read through
// LeggedLockstep, participants/common/legged_lockstep.h): the scene's robots with their models and where they park,
// the world after a cycle (joints, IMU, link poses, ball), a PD command as turf's joint target, a ball placement (at
// rest). The RCSSServerMJ front-end's engine inherits these (league_front_end.h's SnapshotOf, Target, Ball).
#pragma once

#include <string>
#include <vector>

#include "codecs/rcssservermj/session.h"
#include "participants/common/legged_lockstep.h"
#include "participants/lockstep_front_end/lockstep_world.h"

namespace turf {

// "T1" for a robot file label "../robots/t1.xml" (its file name's stem, upper case).
std::string ModelOfLabel(const std::string& label);

struct RcssServerMjWorld {
  // The scene's robots in its order, each with its model and its torso pose now (its park).
  static std::vector<rcssservermj::SceneRobot> SceneRobots(const LeggedLockstep& link);
  static rcssservermj::MjWorldSnapshot SnapshotOf(const idl::LeggedState& state);
  // One PD command as turf's joint-command type carries it: the adapter seam between the session and the legged
  // world's motor mode (rcssservermj_pd.cpp).
  static idl::JointTarget Target(const rcssservermj::PdCommand& command);
  static BallMotion Ball(const Eigen::Vector3d& at_rest) { return {at_rest, Eigen::Vector3d::Zero()}; }
};

}  // namespace turf
