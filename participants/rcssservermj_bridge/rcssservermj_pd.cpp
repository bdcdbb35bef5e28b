// The adapter seam between the RCSSServerMJ session's per-joint PD commands and turf's joint-command type.
// Before the legged world had a PD mode (JOINT_PD: q, dq, kp, kd, tau), this was JOINT_POSITION with q, kp, kd
// (dq and tau dropped); only this function changes with the world's motor modes.
#include <turf/idl/JointsPubSubTypes.h>

#include "participants/rcssservermj_bridge/legged_link.h"

namespace turf {

idl::JointTarget ToJointTarget(const rcssservermj::PdCommand& c) {
  idl::JointTarget t;
  t.name(c.joint);
  t.mode(idl::JOINT_POSITION);
  t.value(c.q);
  t.kp(c.kp);
  t.kd(c.kd);
  return t;
}

}  // namespace turf
