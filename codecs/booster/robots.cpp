#include "codecs/booster/robots.h"

namespace turf::booster {

std::string_view ModelName(BoosterModel model) { return model == BoosterModel::kT1 ? "T1" : "K1"; }

const std::vector<std::string>& SdkJoints(BoosterModel model) {
  // Head, left arm, right arm, (waist), left leg, right leg; in SERIAL space the crank indices are ankle pitch
  // and ankle roll.
  static const std::vector<std::string> kT1 = {"AAHead_yaw",
                                               "Head_pitch",
                                               "Left_Shoulder_Pitch",
                                               "Left_Shoulder_Roll",
                                               "Left_Elbow_Pitch",
                                               "Left_Elbow_Yaw",
                                               "Right_Shoulder_Pitch",
                                               "Right_Shoulder_Roll",
                                               "Right_Elbow_Pitch",
                                               "Right_Elbow_Yaw",
                                               "Waist",
                                               "Left_Hip_Pitch",
                                               "Left_Hip_Roll",
                                               "Left_Hip_Yaw",
                                               "Left_Knee_Pitch",
                                               "Left_Ankle_Pitch",
                                               "Left_Ankle_Roll",
                                               "Right_Hip_Pitch",
                                               "Right_Hip_Roll",
                                               "Right_Hip_Yaw",
                                               "Right_Knee_Pitch",
                                               "Right_Ankle_Pitch",
                                               "Right_Ankle_Roll"};
  static const std::vector<std::string> kK1 = {
      "AAHead_yaw",        "Head_pitch",      "ALeft_Shoulder_Pitch",  "Left_Shoulder_Roll",
      "Left_Elbow_Pitch",  "Left_Elbow_Yaw",  "ARight_Shoulder_Pitch", "Right_Shoulder_Roll",
      "Right_Elbow_Pitch", "Right_Elbow_Yaw", "Left_Hip_Pitch",        "Left_Hip_Roll",
      "Left_Hip_Yaw",      "Left_Knee_Pitch", "Left_Ankle_Pitch",      "Left_Ankle_Roll",
      "Right_Hip_Pitch",   "Right_Hip_Roll",  "Right_Hip_Yaw",         "Right_Knee_Pitch",
      "Right_Ankle_Pitch", "Right_Ankle_Roll"};
  return model == BoosterModel::kT1 ? kT1 : kK1;
}

std::optional<BoosterModel> IdentifyRobot(const std::vector<std::string>& joint_names) {
  for (BoosterModel m : {BoosterModel::kT1, BoosterModel::kK1}) {
    if (joint_names == SdkJoints(m)) return m;
  }
  return std::nullopt;
}

}  // namespace turf::booster
