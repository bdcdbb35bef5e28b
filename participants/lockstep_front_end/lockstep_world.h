// What the lockstep front-ends do with turf-sim's legged scene through LeggedLockstep
// (participants/common/legged_lockstep.h), whatever their league's types: the link on a DDS participant of its own
// or on a given bus, turf's IDL vectors and quaternions as Eigen values, a robot's torso pose (where it parks), the
// league's moves and one step with its joint commands (each league converts its own command type into a
// JointTarget).
#pragma once

#include <turf/idl/JointsPubSubTypes.h>
#include <turf/idl/SimControlPubSubTypes.h>

#include <Eigen/Geometry>
#include <array>
#include <chrono>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "dds/bus_fwd.h"
#include "participants/common/legged_lockstep.h"
#include "participants/common/participant_options.h"

namespace turf {

// On `bus` (it outlives the link), or (null) on a DDS participant of its own made from `options` and named `client`;
// `client` goes into every control request. With `need_force` a frame is whole only with the force sensors too.
std::unique_ptr<LeggedLockstep> MakeLockstep(const ParticipantOptions& options, dds::Bus* bus, const char* client,
                                             bool need_force);

// Where the ball goes and how fast it moves then.
struct BallMotion {
  Eigen::Vector3d position;
  Eigen::Vector3d velocity;
};

inline Eigen::Vector3d ToEigen(const idl::Vec3& v) { return {v.x(), v.y(), v.z()}; }
inline std::array<double, 3> ToArray(const idl::Vec3& v) { return {v.x(), v.y(), v.z()}; }
inline Eigen::Quaterniond ToEigen(const idl::Quat& q) { return Eigen::Quaterniond(q.w(), q.x(), q.y(), q.z()); }

// A robot's torso (its first link) as a league's move (robot, position, orientation, reset_joints): where a robot
// nobody drives is parked.
template <class Move>
Move TorsoMove(const std::string& robot, const idl::LinkState& links, bool reset_joints) {
  const idl::LinkPose& torso = links.links().at(0);
  Move m;
  m.robot = robot;
  m.position = ToEigen(torso.position());
  m.orientation = ToEigen(torso.orientation());
  m.reset_joints = reset_joints;
  return m;
}

// A robot's link poses (idl::LinkState) as a league's links, each {name, position, orientation}.
template <class Link>
std::vector<Link> LinkPoses(const idl::LinkState& links) {
  std::vector<Link> poses;
  for (const idl::LinkPose& l : links.links())
    poses.push_back({l.name(), ToEigen(l.position()), ToEigen(l.orientation())});
  return poses;
}

// The world a league's session reads after a step (time in s, ball, robots), each robot of the frame converted by
// `robot_of(state, i)` (i: its index in the frame's joints, IMU, force and links).
template <class World, class RobotOf>
World WorldOf(const idl::LeggedState& state, RobotOf robot_of) {
  World w;
  w.time = static_cast<double>(state.sim_time_ns()) * 1e-9;
  w.ball = ToEigen(state.ball_position());
  for (size_t i = 0; i < state.joints().size(); ++i) w.robots.push_back(robot_of(state, i));
  return w;
}

// The league's moves (each with robot, position, orientation, reset_joints), answered before the next step.
template <class Move>
void SendMoves(LeggedLockstep& link, const std::vector<Move>& moves, std::chrono::milliseconds timeout) {
  for (const Move& m : moves) link.SendMove(m.robot, m.position, m.orientation, m.reset_joints, timeout);
}

// OP_STEP of `steps` physics steps with every robot's joint commands, each converted by `to_target`.
template <class Command, class ToTarget>
idl::SimControl StepWith(uint32_t steps, const std::map<std::string, std::vector<Command>>& joints,
                         ToTarget to_target) {
  idl::SimControl step;
  step.op(idl::OP_STEP);
  step.step_count(steps);
  for (const auto& [robot, targets] : joints) {
    idl::JointCommand c;
    c.robot(robot);
    for (const Command& t : targets) c.joints().push_back(to_target(t));
    step.joint_commands().push_back(std::move(c));
  }
  return step;
}

}  // namespace turf
