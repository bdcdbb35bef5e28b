// The RoboCup 3D league's Nao robot types 0..4 (SimSpark's nao_hetero; shared/protocols/simspark.md, "Robot
// types" and "Nao physical model"): one body, five variants. Types 1 and 3 have longer legs and arms (type 3 also
// a wider hip), type 2 the standard body with other ankle speeds (the SimSpark front-end's per-type speed limits,
// codecs/simspark/nao_joints.h), type 4 a toe on each foot: a hinge llj7/rlj7 (-1..70 deg) between a shorter
// foot and a toe box, with its own touch sensor (lf1, rf1). Sizes and masses are the same for every type
// (4.6071 kg), only offsets differ.
//
// NaoTypeMjcf turns turf's type 0 model (configs/robots/nao.xml) into a type's: it moves the hips, thighs, ankles
// and elbows by the type's offsets, the torso to the type's standing height (sole 0.385, 0.42164, 0.385,
// 0.440737, 0.385 m below the torso centre), and for type 4 splits each foot. Pure text in, text out.
#pragma once

#include <string>

namespace turf {

inline constexpr int kNaoRobotTypes = 5;

// The offsets that differ between the types (m), from the facts' robot-type table.
struct NaoTypeOffsets {
  double hip_x;    // H: |x| of the hips from the torso centre
  double thigh_z;  // T: the thigh's centre below the hip's
  double ankle_z;  // A: the ankle's centre below the shank's
  double elbow_y;  // E: the elbow ahead of the upper arm's centre
  bool toes;       // type 4
  double SoleBelowTorso() const { return 0.29 - thigh_z - ankle_z; }
};

// The type's offsets; type must be 0..4.
const NaoTypeOffsets& NaoType(int type);

struct NaoTypeModel {
  std::string xml;    // empty on error
  std::string error;  // names what the model lacks
};

// `type0_xml`: a Nao model with the bodies, joints, geoms and sites of configs/robots/nao.xml (names as there).
NaoTypeModel NaoTypeMjcf(const std::string& type0_xml, int type);

}  // namespace turf
