#include "codecs/booster/low_cmd.h"

#include <fmt/format.h>

#include <cmath>

namespace turf::booster {

namespace bi = booster_interface::msg::dds_;

namespace {

LowCmdDecode Refuse(Error error, std::string detail) {
  LowCmdDecode d;
  d.error = error;
  d.detail = std::move(detail);
  return d;
}

}  // namespace

LowCmdDecode DecodeLowCmd(const bi::LowCmd_& cmd, BoosterModel model) {
  const uint32_t type = static_cast<uint32_t>(cmd.cmd_type());
  if (type != bi::PARALLEL && type != bi::SERIAL) return Refuse(Error::kUnknownEnum, fmt::format("cmd_type {}", type));
  const std::vector<std::string>& joints = SdkJoints(model);
  const std::vector<bi::MotorCmd_>& motors = cmd.motor_cmd();
  if (motors.size() != joints.size())
    return Refuse(Error::kMalformed, fmt::format("{} motor commands; the {} has {} joints", motors.size(),
                                                 ModelName(model), joints.size()));
  LowCmdDecode d;
  d.parallel = type == bi::PARALLEL;
  d.commands.reserve(motors.size());
  for (size_t i = 0; i < motors.size(); ++i) {
    const bi::MotorCmd_& m = motors[i];
    const float values[] = {m.q(), m.dq(), m.tau(), m.kp(), m.kd(), m.weight()};
    const char* names[] = {"q", "dq", "tau", "kp", "kd", "weight"};
    for (int k = 0; k < 6; ++k) {
      if (!std::isfinite(values[k])) return Refuse(Error::kNotFinite, fmt::format("motor_cmd[{}].{}", i, names[k]));
    }
    if (m.weight() < 0.0f || m.weight() > 1.0f)
      return Refuse(Error::kOutOfRange, fmt::format("motor_cmd[{}].weight {} (0..1)", i, m.weight()));
    JointCommand c;
    c.joint = joints[i];
    c.mode = JointMode::kPd;
    c.value = m.q();
    c.dq = m.dq();
    c.tau = m.tau();
    c.kp = m.kp();
    c.kd = m.kd();
    d.commands.push_back(std::move(c));
  }
  return d;
}

}  // namespace turf::booster
