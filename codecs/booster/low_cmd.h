// rt/joint_ctrl into turf's joint commands (shared/protocols/booster-sdk-dds.md). Each MotorCmd becomes a PD
// command (JointMode::kPd: torque = kp (q - q_measured) + kd (dq - dq_measured) + tau, clamped to the joint's
// effort limit each physics step) for the joint of the same SDK index. This decoder checks what only the message
// can tell (the cmd_type, one entry per joint, finite numbers, weight in 0..1); the ranges of q, dq, tau and the
// gains are the world's one validator's (LeggedWorld::CheckJointCommands), which refuses the whole message.
// Semantics taken from the facts:
//  - SERIAL is joint space and exact. PARALLEL (the ankles' crank motors) is taken as SERIAL, flagged: no
//    published model has the crank linkage;
//  - weight is not a blend: the robot is in Custom mode, where the real robot applies the command regardless;
//  - MotorCmd.mode is ignored (undocumented).
#pragma once

#include <string>
#include <vector>

#include "codecs/booster/robots.h"
#include "core/errors.h"
#include "core/legged/legged_world.h"
#include "turf/idl/BoosterLowLevel.h"

namespace turf::booster {

struct LowCmdDecode {
  Error error = Error::kOk;  // kUnknownEnum, kMalformed (not one entry per joint), kNotFinite, kOutOfRange (weight)
  std::string detail;        // which entry and field, when refused
  std::vector<JointCommand> commands;  // one per joint, SDK order, when kOk
  bool parallel = false;               // PARALLEL, taken as SERIAL
};

LowCmdDecode DecodeLowCmd(const booster_interface::msg::dds_::LowCmd_& cmd, BoosterModel model);

}  // namespace turf::booster
