#include "codecs/rcssservermj/robots.h"

namespace turf::rcssservermj {

namespace {

// Facts: shared/protocols/rcssservermj.md, "Robot models" (T1 table; right
// rows mirror the listed ranges).
MjRobotModel T1() {
  MjRobotModel m{"T1",
                 {},
                 0.6735,
                 {"H2", {0.05, 0, 0.12}},
                 {"H2", {0.01, 0, 0.11}},
                 {"left_foot_link", {0, 0, 0}},
                 {"right_foot_link", {0, 0, 0}}};
  m.joints = {
      {"he1", "q_hj1", "AAHead_yaw", -90, 90, 7},
      {"he2", "q_hj2", "Head_pitch", -20.1, 69.9, 7},
      {"lae1", "q_laj1", "Left_Shoulder_Pitch", -189.6, 69.9, 18},
      {"lae2", "q_laj2", "Left_Shoulder_Roll", -99.7, 90, 18},
      {"lae3", "q_laj3", "Left_Elbow_Pitch", -130.1, 130.1, 18},
      {"lae4", "q_laj4", "Left_Elbow_Yaw", -139.8, 0, 18},
      {"rae1", "q_raj1", "Right_Shoulder_Pitch", -189.6, 69.9, 18},
      {"rae2", "q_raj2", "Right_Shoulder_Roll", -90, 99.7, 18},
      {"rae3", "q_raj3", "Right_Elbow_Pitch", -130.1, 130.1, 18},
      {"rae4", "q_raj4", "Right_Elbow_Yaw", 0, 139.8, 18},
      {"te1", "q_tj1", "Waist", -90, 90, 30},
      {"lle1", "q_llj1", "Left_Hip_Pitch", -103.1, 90, 45},
      {"lle2", "q_llj2", "Left_Hip_Roll", -11.5, 90, 30},
      {"lle3", "q_llj3", "Left_Hip_Yaw", -57.3, 57.3, 30},
      {"lle4", "q_llj4", "Left_Knee_Pitch", 0, 134.1, 60},
      {"lle5", "q_llj5", "Left_Ankle_Pitch", -49.8, 20.1, 20},
      {"lle6", "q_llj6", "Left_Ankle_Roll", -25.2, 25.2, 15},
      {"rle1", "q_rlj1", "Right_Hip_Pitch", -103.1, 90, 45},
      {"rle2", "q_rlj2", "Right_Hip_Roll", -90, 11.5, 30},
      {"rle3", "q_rlj3", "Right_Hip_Yaw", -57.3, 57.3, 30},
      {"rle4", "q_rlj4", "Right_Knee_Pitch", 0, 134.1, 60},
      {"rle5", "q_rlj5", "Right_Ankle_Pitch", -49.8, 20.1, 20},
      {"rle6", "q_rlj6", "Right_Ankle_Roll", -25.2, 25.2, 15},
  };
  return m;
}

// K1: the T1's names without te1 / q_tj1; its own MJCF joints, ranges and torques.
MjRobotModel K1() {
  MjRobotModel m{"K1",
                 {},
                 1.0,
                 {"Head_2", {0.06, 0, 0.08}},
                 {"Head_2", {0, 0, 0.08}},
                 {"left_foot_link", {0, 0, 0}},
                 {"right_foot_link", {0, 0, 0}}};
  m.joints = {
      {"he1", "q_hj1", "AAHead_yaw", -57.3, 57.3, 6},
      {"he2", "q_hj2", "Head_pitch", -20.0, 49.0, 6},
      {"lae1", "q_laj1", "ALeft_Shoulder_Pitch", -190.0, 69.9, 14},
      {"lae2", "q_laj2", "Left_Shoulder_Roll", -99.7, 90, 14},
      {"lae3", "q_laj3", "Left_Elbow_Pitch", -130.1, 130.1, 14},
      {"lae4", "q_laj4", "Left_Elbow_Yaw", -139.8, 0, 14},
      {"rae1", "q_raj1", "ARight_Shoulder_Pitch", -190.0, 69.9, 14},
      {"rae2", "q_raj2", "Right_Shoulder_Roll", -90, 99.7, 14},
      {"rae3", "q_raj3", "Right_Elbow_Pitch", -130.1, 130.1, 14},
      {"rae4", "q_raj4", "Right_Elbow_Yaw", 0, 139.8, 14},
      {"lle1", "q_llj1", "Left_Hip_Pitch", -171.9, 126.6, 30},
      {"lle2", "q_llj2", "Left_Hip_Roll", -22.9, 90, 35},
      {"lle3", "q_llj3", "Left_Hip_Yaw", -57.3, 57.3, 20},
      {"lle4", "q_llj4", "Left_Knee_Pitch", 0, 127.8, 40},
      {"lle5", "q_llj5", "Left_Ankle_Pitch", -49.8, 19.8, 20},
      {"lle6", "q_llj6", "Left_Ankle_Roll", -19.8, 19.8, 20},
      {"rle1", "q_rlj1", "Right_Hip_Pitch", -171.9, 126.6, 30},
      {"rle2", "q_rlj2", "Right_Hip_Roll", -90, 22.9, 35},
      {"rle3", "q_rlj3", "Right_Hip_Yaw", -57.3, 57.3, 20},
      {"rle4", "q_rlj4", "Right_Knee_Pitch", 0, 127.8, 40},
      {"rle5", "q_rlj5", "Right_Ankle_Pitch", -49.8, 19.8, 20},
      {"rle6", "q_rlj6", "Right_Ankle_Roll", -19.8, 19.8, 20},
  };
  return m;
}

}  // namespace

const std::vector<MjRobotModel>& Models() {
  static const std::vector<MjRobotModel> models = {T1(), K1()};
  return models;
}

const MjRobotModel* FindModel(std::string_view name) {
  for (const MjRobotModel& m : Models())
    if (name == m.name) return &m;
  return nullptr;
}

int EffectorIndex(const MjRobotModel& model, std::string_view effector) {
  for (size_t i = 0; i < model.joints.size(); ++i)
    if (effector == model.joints[i].effector) return static_cast<int>(i);
  return -1;
}

}  // namespace turf::rcssservermj
