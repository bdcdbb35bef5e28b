// Where an HLVS robot's devices are in turf's data (the adapter between codecs/hlvs and turf's DDS types): each
// motor's joint and each touch sensor in the robot's robots/state entries, the joint limits the session clamps to
// (the T1/K1 tables of codecs/rcssservermj/robots.cpp), and the session's joint outputs as turf joint targets.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "codecs/hlvs/session.h"

namespace turf::idl {
class JointTarget;
class LeggedState;
}  // namespace turf::idl

namespace turf {

struct RobotBinding {
  std::string robot;             // the scene's name
  std::vector<int> joint_index;  // per motor of the model, in the robot's JointState (-1: missing)
  std::vector<int> touch_index;  // per touch entry, in its ForceState (-1: missing)
};

// nullopt, with `error`, when the robot is not in `state` or lacks a joint of the model.
std::optional<RobotBinding> BindRobot(const idl::LeggedState& state, const std::string& robot,
                                      const hlvs::RobotModel& model, std::string* error);
// The robot's devices after the step `state` shows (zeros when the robot is missing from it).
hlvs::RobotReading ReadRobot(const idl::LeggedState& state, const RobotBinding& binding);
// Range and effort limit of each motor's joint, from the 3D league's T1/K1 tables (unlimited when absent).
std::vector<hlvs::JointLimits> JointLimitsOf(const hlvs::RobotModel& model);
idl::JointTarget ToJointTarget(const hlvs::JointOutput& output);

}  // namespace turf
