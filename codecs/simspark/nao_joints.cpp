#include "codecs/simspark/nao_joints.h"

namespace turf::simspark {

namespace {

// One table: the 24 joints of type 4; the other types have all but the toes (lj7).
constexpr NaoJoint kAllJoints[] = {
    {"hj1", "he1"},   {"hj2", "he2"},                                                          // head
    {"raj1", "rae1"}, {"raj2", "rae2"}, {"raj3", "rae3"}, {"raj4", "rae4"},                    // right arm
    {"laj1", "lae1"}, {"laj2", "lae2"}, {"laj3", "lae3"}, {"laj4", "lae4"},                    // left arm
    {"rlj1", "rle1"}, {"rlj2", "rle2"}, {"rlj3", "rle3"}, {"rlj4", "rle4"}, {"rlj5", "rle5"},  // right leg
    {"rlj6", "rle6"}, {"rlj7", "rle7"},                                                        //
    {"llj1", "lle1"}, {"llj2", "lle2"}, {"llj3", "lle3"}, {"llj4", "lle4"}, {"llj5", "lle5"},  // left leg
    {"llj6", "lle6"}, {"llj7", "lle7"},                                                        //
};

bool IsToe(const NaoJoint& joint) { return std::string_view(joint.perceptor).substr(1) == "lj7"; }

std::vector<NaoJoint> JointsOf(bool toes) {
  std::vector<NaoJoint> joints;
  for (const NaoJoint& joint : kAllJoints)
    if (toes || !IsToe(joint)) joints.push_back(joint);
  return joints;
}

}  // namespace

const std::vector<NaoJoint>& NaoJoints(int robot_type) {
  static const std::vector<NaoJoint> kStandard = JointsOf(false);
  static const std::vector<NaoJoint> kToes = JointsOf(true);
  static const std::vector<NaoJoint> kNone;
  if (robot_type < 0 || robot_type >= kNaoTypes) return kNone;
  return robot_type == 4 ? kToes : kStandard;
}

std::optional<std::string> JointForEffector(std::string_view effector, int robot_type) {
  for (const NaoJoint& joint : NaoJoints(robot_type))
    if (effector == joint.effector) return std::string(joint.perceptor);
  return std::nullopt;
}

bool IsNaoHingeEffector(std::string_view effector) {
  for (const NaoJoint& joint : kAllJoints)
    if (effector == joint.effector) return true;
  return false;
}

double NaoMaxSpeed(int robot_type, std::string_view perceptor_joint) {
  bool found = false;
  for (const NaoJoint& joint : NaoJoints(robot_type)) found = found || perceptor_joint == joint.perceptor;
  if (!found) return 0.0;
  if (robot_type == 2) {
    if (perceptor_joint == "llj5" || perceptor_joint == "rlj5") return 8.80667;
    if (perceptor_joint == "llj6" || perceptor_joint == "rlj6") return 3.47234;
  }
  return kNaoMaxSpeed;
}

}  // namespace turf::simspark
