#include "participants/hlvs_bridge/robot_binding.h"

#include <turf/idl/JointsPubSubTypes.h>

#include <fmt/format.h>

#include <cmath>

#include "codecs/rcssservermj/robots.h"

namespace turf {

namespace {

int RobotIndex(const idl::LeggedState& state, const std::string& robot) {
  for (size_t i = 0; i < state.joints().size(); ++i)
    if (state.joints()[i].robot() == robot) return static_cast<int>(i);
  return -1;
}

hlvs::Vec3 V(const idl::Vec3& v) { return {v.x(), v.y(), v.z()}; }

}  // namespace

std::optional<RobotBinding> BindRobot(const idl::LeggedState& state, const std::string& robot,
                                      const hlvs::RobotModel& model, std::string* error) {
  const int r = RobotIndex(state, robot);
  if (r < 0) {
    *error = fmt::format("robot '{}' is not in turf-sim's state", robot);
    return std::nullopt;
  }
  RobotBinding b{robot, {}, {}};
  const auto& names = state.joints()[r].name();
  for (const hlvs::MotorEntry& m : model.motors) {
    int index = -1;
    for (size_t j = 0; j < names.size(); ++j)
      if (names[j] == m.joint) index = static_cast<int>(j);
    if (index < 0) {
      *error =
          fmt::format("robot '{}' has no joint '{}' (HLVS motor {} of the {})", robot, m.joint, m.motor, model.name);
      return std::nullopt;
    }
    b.joint_index.push_back(index);
  }
  const auto& sensors =
      r < static_cast<int>(state.force().size()) ? state.force()[r].sensors() : std::vector<idl::ForceReading>{};
  for (const hlvs::TouchEntry& t : model.touch) {
    int index = -1;
    for (size_t j = 0; j < sensors.size(); ++j)
      if (sensors[j].name() == t.sensor) index = static_cast<int>(j);
    b.touch_index.push_back(index);
  }
  return b;
}

hlvs::RobotReading ReadRobot(const idl::LeggedState& state, const RobotBinding& b) {
  hlvs::RobotReading out;
  out.position.assign(b.joint_index.size(), 0.0);
  out.touch.resize(b.touch_index.size());
  const int r = RobotIndex(state, b.robot);
  if (r < 0) return out;
  const auto& q = state.joints()[r].position();
  for (size_t i = 0; i < b.joint_index.size(); ++i)
    if (b.joint_index[i] >= 0 && b.joint_index[i] < static_cast<int>(q.size())) out.position[i] = q[b.joint_index[i]];
  if (r < static_cast<int>(state.imu().size())) {
    out.accelerometer = V(state.imu()[r].linear_acceleration());
    out.gyro = V(state.imu()[r].angular_velocity());
  }
  if (r >= static_cast<int>(state.force().size())) return out;
  const auto& sensors = state.force()[r].sensors();
  for (size_t i = 0; i < b.touch_index.size(); ++i) {
    const int j = b.touch_index[i];
    if (j < 0 || j >= static_cast<int>(sensors.size())) continue;
    const idl::ForceReading& f = sensors[j];
    out.touch[i].force = f.values().empty() ? 0.0 : f.values()[0];
    out.touch[i].force3d = V(f.force());
    out.touch[i].contact = f.contact();
  }
  return out;
}

std::vector<hlvs::JointLimits> JointLimitsOf(const hlvs::RobotModel& model) {
  std::vector<hlvs::JointLimits> out(model.motors.size());
  const rcssservermj::MjRobotModel* table = rcssservermj::FindModel(model.name);
  if (table == nullptr) return out;
  for (size_t i = 0; i < model.motors.size(); ++i) {
    for (const rcssservermj::MjJoint& j : table->joints) {
      if (std::string(j.joint) != model.motors[i].joint) continue;
      out[i] = {j.lo_deg * M_PI / 180.0, j.hi_deg * M_PI / 180.0, j.torque};
    }
  }
  return out;
}

idl::JointTarget ToJointTarget(const hlvs::JointOutput& o) {
  idl::JointTarget t;
  t.name(o.joint);
  t.mode(o.mode == hlvs::JointOutput::Mode::kTorque ? idl::JOINT_TORQUE : idl::JOINT_VELOCITY);
  t.value(o.value);
  t.kp(-1);
  t.kd(-1);
  return t;
}

}  // namespace turf
