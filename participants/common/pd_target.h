// One PD joint target as turf's joint-command type carries it (JOINT_PD: the legged world's torque =
// kp (q - θ) + kd (dq - θ') + tau, core/legged/legged_world.h): what the Booster SDK bridge and the RCSSServerMJ
// front-end send for each joint. Header-only.
#pragma once

#include <turf/idl/Joints.h>

#include <string>

namespace turf {

inline idl::JointTarget PdTarget(const std::string& joint, double q, double dq, double kp, double kd, double tau) {
  idl::JointTarget t;
  t.name(joint);
  t.mode(idl::JOINT_PD);
  t.value(q);
  t.dq(dq);
  t.kp(kp);
  t.kd(kd);
  t.tau(tau);
  return t;
}

}  // namespace turf
