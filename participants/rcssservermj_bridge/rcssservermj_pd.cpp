// The adapter seam between the RCSSServerMJ session's per-joint PD commands and turf's joint-command type: the
// legged world's PD mode (JOINT_PD, core/legged/legged_world.h JointMode::kPd), evaluated every physics step,
// torque = kp (q - θ) + kd (dq - θ') + tau clamped to the joint's effort limit, as RCSSServerMJ's actuators.
#include <turf/idl/JointsPubSubTypes.h>

#include "participants/common/pd_target.h"
#include "participants/rcssservermj_bridge/legged_snapshot.h"

namespace turf {

idl::JointTarget RcssServerMjWorld::Target(const rcssservermj::PdCommand& c) {
  return PdTarget(c.joint, c.q, c.dq, c.kp, c.kd, c.tau);
}

}  // namespace turf
