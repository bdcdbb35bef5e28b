// One HLVS client's robot (shared/protocols/hlvs.md), as pure state: the ActuatorRequests it sent (motor commands
// that persist, sensor time steps), the Webots motor semantics turned into turf joint commands, and which sensors
// are due in each SensorMeasurements. Time arrives as values: the bridge calls, every 8 ms step of simulated time,
// Apply (each request of this step, in arrival order), Measure (the step's message), then Commands (for the next
// step). No sockets, clocks or DDS.
//
// Motors (Webots semantics; every motor starts in the scene's own mode and is taken over at its first command):
//   position (default P 10, I 0, D 0): each step the joint gets the velocity target P e + I sum(e dt) + D de/dt
//     (e = target - measured angle, target clamped into the joint's range), limited by the velocity command
//     (default: the model's max_velocity) and, by turf-sim's motor, by the joint's effort limit: turf's
//     JOINT_VELOCITY motor, which is Webots' (ODE's) velocity motor with bounded torque.
//   position +-infinity: velocity control at the commanded velocity.
//   torque / force: JOINT_TORQUE, clamped to the joint's effort limit, until the next position command.
// Sensors: position sensors (motor + "S"), Accelerometer, Gyro, the touch sensors and cameras of the model table
// (robots.h). Enabled with period T (a multiple of 8 ms; >= 8, cameras >= 16), first reported T ms after the step
// that enabled it, then every T ms; 0 disables. Violations answer with the reference's warning texts, at most
// kMaxWarnings a message (then one line saying how many more). A camera source hears a camera's period once a step,
// when it changed (a client switching a camera on and off within a step costs nothing).
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "codecs/hlvs/camera_source.h"
#include "codecs/hlvs/robots.h"
#include "codecs/hlvs/wire.h"

namespace turf::hlvs {

inline constexpr uint32_t kBasicStepMs = 8;  // Webots' basicTimeStep in the HLVS world
inline constexpr uint32_t kMinCameraStepMs = 16;
inline constexpr size_t kMaxWarnings = 64;  // warnings listed in one SensorMeasurements

// What the bridge read of the robot after a step, in the model table's order.
struct RobotReading {
  std::vector<double> position;  // per motor, rad
  Vec3 accelerometer;            // m/s^2
  Vec3 gyro;                     // rad/s
  struct Touch {
    double force = 0;  // N, normal
    Vec3 force3d;      // N
    bool contact = false;
  };
  std::vector<Touch> touch;  // per touch entry
};

// One joint's command for turf-sim (the adapter to idl::JointTarget lives in the bridge).
struct JointOutput {
  enum class Mode { kVelocity, kTorque };
  std::string joint;
  Mode mode = Mode::kVelocity;
  double value = 0;
};

struct JointLimits {
  double lo = -1e9, hi = 1e9;  // rad
  double effort = 1e9;         // N.m
};

struct SessionOptions {
  std::string robot;  // the scene's robot name (for camera requests)
  const RobotModel* model = nullptr;
  std::vector<JointLimits> limits;  // per motor; missing: unlimited
  int team_players = 4;             // the rendering quota's share: 350 MB/s / team_players
  CameraSource* cameras = nullptr;  // may be null: no images
};

class Session {
 public:
  explicit Session(SessionOptions options);

  // One request, processed in the reference's order, at the step whose measurement has time `now_ms`. Warnings go
  // into the next Measure.
  void Apply(const ActuatorRequests& requests, uint32_t now_ms);
  // The step's message: time, real time, the pending warnings and every sensor due at `now_ms`.
  SensorMeasurements Measure(const RobotReading& reading, uint32_t now_ms, uint64_t real_time_ms);
  // Commands for the next step, for the motors a client commanded (the others keep the scene's own).
  std::vector<JointOutput> Commands(const RobotReading& reading);
  // The client left: every sensor off (the camera source told at once), pending warnings dropped, camera exposures
  // forgotten, so the next client starts as a new connection does. Motors keep their commands, modes and PID gains
  // (the robot does not go limp between clients).
  void ClientLeft();

  // True once an enabled camera was due and no image could be sent (the bridge logs it once).
  bool camera_unavailable() const { return camera_unavailable_; }
  // Enabled sensors and their periods, ms (tests, status lines).
  std::map<std::string, uint32_t> SensorPeriods() const;

 private:
  struct Motor {
    bool commanded = false;
    bool torque_control = false;
    double target = 0;     // rad, may be +-infinity; NaN: where the joint is at the next Commands
    double velocity = -1;  // the velocity command's magnitude, rad/s (< 0: never set: the default limit)
    double torque = 0;     // N.m
    Vec3 pid{10, 0, 0};    // Webots' default
    double integral = 0;   // sum e dt
    double last_error = 0;
    bool has_last_error = false;
  };
  struct Sensor {
    uint32_t period = 0;  // ms; 0: disabled
    uint32_t next = 0;    // ms of the next report
    double exposure = 0;  // cameras
  };
  enum class Device { kNone, kMotor, kPosition, kAccel, kGyroscope, kTouch, kCamera };

  void Warn(std::string text);
  Motor* FindMotor(const std::string& name, const char* what);
  Device Classify(const std::string& name) const;
  void SetTimeStep(const NamedStep& step, uint32_t now_ms);
  bool CameraQuotaAllows(const std::string& name, uint32_t period);
  bool Due(const std::string& name, uint32_t now_ms);
  void MeasureCameras(uint32_t now_ms, SensorMeasurements* out);
  void TellCameras();  // each camera whose period changed since the source last heard it
  JointOutput MotorCommand(size_t i, double position);

  SessionOptions options_;
  std::vector<Motor> motors_;
  std::map<std::string, Sensor> sensors_;
  std::vector<TextMessage> pending_;
  size_t unlisted_warnings_ = 0;          // beyond kMaxWarnings since the last Measure
  std::map<std::string, uint32_t> told_;  // camera name -> the period its source last heard
  bool camera_unavailable_ = false;
};

// The reference's network quota (per robot: 350 MB/s / team players): the sizes sent in the last second of real
// time. Pure: the time comes in.
class NetworkQuota {
 public:
  explicit NetworkQuota(int team_players);
  // True when `bytes` sent at `now_ms` keep the last 1000 ms within the quota (then they are counted).
  bool Admit(size_t bytes, uint64_t now_ms);
  // The reference's error text ("87.500000 MB/s quota exceeded.").
  std::string ExceededText() const;

 private:
  double quota_mb_;
  std::deque<std::pair<uint64_t, size_t>> sent_;
  size_t total_ = 0;
};

}  // namespace turf::hlvs
