#include "codecs/hlvs/robots.h"

namespace turf::hlvs {

namespace {

// The sample robot's 20 motors on the Booster joints that do the same; T1 and K1 differ in the shoulder pitch
// joints' names (the K1's start with "A") and the T1's waist.
std::vector<MotorEntry> BoosterMotors(const char* left_shoulder_pitch, const char* right_shoulder_pitch) {
  return {
      {"Neck", "AAHead_yaw"},
      {"Head", "Head_pitch"},
      {"ShoulderR", right_shoulder_pitch},
      {"ShoulderL", left_shoulder_pitch},
      {"ArmUpperR", "Right_Shoulder_Roll"},
      {"ArmUpperL", "Left_Shoulder_Roll"},
      {"ArmLowerR", "Right_Elbow_Pitch"},
      {"ArmLowerL", "Left_Elbow_Pitch"},
      {"Right_Elbow_Yaw", "Right_Elbow_Yaw"},
      {"Left_Elbow_Yaw", "Left_Elbow_Yaw"},
      {"PelvYR", "Right_Hip_Yaw"},
      {"PelvYL", "Left_Hip_Yaw"},
      {"PelvR", "Right_Hip_Roll"},
      {"PelvL", "Left_Hip_Roll"},
      {"LegUpperR", "Right_Hip_Pitch"},
      {"LegUpperL", "Left_Hip_Pitch"},
      {"LegLowerR", "Right_Knee_Pitch"},
      {"LegLowerL", "Left_Knee_Pitch"},
      {"AnkleR", "Right_Ankle_Pitch"},
      {"AnkleL", "Left_Ankle_Pitch"},
      {"FootR", "Right_Ankle_Roll"},
      {"FootL", "Left_Ankle_Roll"},
  };
}

// Sole touch sensors lf / rf of configs/robots/{t1,k1}.xml (normal force, N), and the head camera at the sample
// robot's 320 x 240.
std::vector<TouchEntry> BoosterTouch() { return {{"lf", "lf", TouchKind::kForce}, {"rf", "rf", TouchKind::kForce}}; }
std::vector<CameraEntry> BoosterCameras() { return {{"Camera", "camera", 320, 240}}; }

RobotModel K1() {
  return {"K1", BoosterMotors("ALeft_Shoulder_Pitch", "ARight_Shoulder_Pitch"), BoosterTouch(), BoosterCameras(), 20.0};
}

RobotModel T1() {
  RobotModel m{"T1", BoosterMotors("Left_Shoulder_Pitch", "Right_Shoulder_Pitch"), BoosterTouch(), BoosterCameras(),
               20.0};
  m.motors.push_back({"Waist", "Waist"});
  return m;
}

}  // namespace

const std::vector<RobotModel>& Models() {
  static const std::vector<RobotModel> models = {K1(), T1()};
  return models;
}

const RobotModel* FindModel(std::string_view name) {
  for (const RobotModel& m : Models())
    if (name == m.name) return &m;
  return nullptr;
}

std::string PositionSensorName(const MotorEntry& motor) { return std::string(motor.motor) + "S"; }

}  // namespace turf::hlvs
