// The RCSSServerMJ robot models as the agent protocol sees them
// (shared/protocols/rcssservermj.md, "Robot models"): for each model one table
// of its joints in HJ order (effector, HJ perceptor name, MJCF joint, range,
// effort limit), and where its camera and seen markers are. The codec, the
// session and the tests all read these tables; nothing repeats them.
#pragma once

#include <Eigen/Core>
#include <string_view>
#include <vector>

namespace turf::rcssservermj {

struct MjJoint {
  const char* effector;   // motor effector on the wire ("lle4")
  const char* perceptor;  // HJ name ("q_llj4")
  const char* joint;      // MJCF joint name of the robot file ("Left_Knee_Pitch")
  double lo_deg, hi_deg;  // range
  double torque;          // effort limit, N m (the actuators' force range)
};

// A point fixed in one of the robot's bodies (a site of the reference model).
struct BodyPoint {
  const char* body;  // body name in the robot file
  Eigen::Vector3d offset;
};

struct MjRobotModel {
  const char* name;              // `init` model name ("T1")
  std::vector<MjJoint> joints;   // HJ order
  double torso_height;           // m, the torso's height in the model file (placement at activation)
  BodyPoint camera;              // the camera site (See's origin and frame)
  BodyPoint head, lfoot, rfoot;  // the seen robot part markers
};

// The models an agent may ask for in `init` (T1, K1; case sensitive). The
// reference's toy `ant` is not offered (its motor commands fail there too).
const std::vector<MjRobotModel>& Models();
const MjRobotModel* FindModel(std::string_view name);
// Index of an effector in model.joints, -1 if the model has none of that name.
int EffectorIndex(const MjRobotModel& model, std::string_view effector);

}  // namespace turf::rcssservermj
