// The robots an HLVS client can drive in turf, one table per model: the HLVS device names (what a client puts in
// ActuatorRequests and finds in SensorMeasurements) and the robot file's joints and sensors behind them. The session,
// the bridge, the tests and the README's table all read these tables; nothing repeats them.
//
// Motor names: where a joint does what a motor of HLVS's sample robot (the DARwIn-OP "RobocupRobot",
// shared/protocols/hlvs.md) does, it has that motor's name (Neck = head yaw, LegLowerR = right knee, ...), so the
// sample client's request (`Neck`, `NeckS`) works unchanged; the other joints keep the robot file's name. Only names
// are mapped: angles, signs and zero poses are the turf robot's (the K1's knee bends positive, the DARwIn-OP's
// does not have to). Position sensors: the motor's name + "S", as the sample robot's.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace turf::hlvs {

struct MotorEntry {
  const char* motor;  // HLVS motor name
  const char* joint;  // the robot file's joint
};

enum class TouchKind { kForce, kForce3d, kBumper };
struct TouchEntry {
  const char* name;    // HLVS touch sensor name
  const char* sensor;  // the robot file's touch sensor (robots/force reading)
  TouchKind kind;
};

struct CameraEntry {
  const char* name;  // HLVS camera name
  const char* mjcf;  // the robot file's MJCF camera
  uint32_t width, height;
};

struct RobotModel {
  const char* name;  // the robot file's stem, upper case ("K1" for ../robots/k1.xml)
  std::vector<MotorEntry> motors;
  std::vector<TouchEntry> touch;
  std::vector<CameraEntry> cameras;
  // rad/s: each motor's maxVelocity (Webots' default velocity limit). A legged scene for HLVS sets the robot's
  // motors.max_speed to at least this (turf-sim refuses faster velocity targets).
  double max_velocity;
};

inline constexpr const char* kAccelerometer = "Accelerometer";
inline constexpr const char* kGyro = "Gyro";

const std::vector<RobotModel>& Models();
const RobotModel* FindModel(std::string_view name);
std::string PositionSensorName(const MotorEntry& motor);  // motor + "S"

}  // namespace turf::hlvs
