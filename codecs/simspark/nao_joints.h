// The Nao's hinge joints as the agent protocol names them (perceptor HJ name,
// effector name) and their speed limits per robot type
// (shared/protocols/simspark.md, "The 22 (+2) joints", "Robot types").
//
// Order (turf's, stable; the protocol does not fix one and clients must not
// rely on it): head hj1 hj2, right arm raj1-4, left arm laj1-4, right leg
// rlj1-6, left leg llj1-6: 22 joints. Type 4 has the toes as each leg's 7th
// joint: ... rlj1-7, llj1-7: 24 joints.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace turf::simspark {

inline constexpr int kNaoTypes = 5;             // robot types 0..4 (scene parameter)
inline constexpr double kNaoMaxSpeed = 6.1395;  // rad/s, all joints but type 2's lj5/lj6

struct NaoJoint {
  const char* perceptor;  // "hj1", "raj1", "llj7", ...
  const char* effector;   // "he1", "rae1", "lle7", ...
};

// The joints of robot type 0..4 in the order above; empty for another type.
const std::vector<NaoJoint>& NaoJoints(int robot_type);

// The perceptor name of the joint an effector drives, nullopt when that robot type has no such effector
// (e.g. "lle7" for types 0..3, "xyz" for all).
std::optional<std::string> JointForEffector(std::string_view effector, int robot_type);

// True when `effector` is a hinge effector of any robot type (so an agent message may name it).
bool IsNaoHingeEffector(std::string_view effector);

// Maximum joint speed in rad/s: 6.1395 except type 2's llj5/rlj5 (8.80667) and llj6/rlj6 (3.47234).
// 0 for a joint the robot type does not have.
double NaoMaxSpeed(int robot_type, std::string_view perceptor_joint);

}  // namespace turf::simspark
