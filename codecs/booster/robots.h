// The Booster SDK's joint order (b1_api_const.hpp's JointIndex; shared/protocols/booster-sdk-dds.md) for the T1 and
// the K1, as the joint names of turf's robot files (configs/robots/t1.xml, k1.xml: RCSSServerMJ's MJCF names, in
// the same order). One table per robot drives the codec and its tests.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace turf::booster {

enum class BoosterModel { kT1, kK1 };

std::string_view ModelName(BoosterModel model);  // "T1", "K1"
// Index i = the SDK's JointIndex i.
const std::vector<std::string>& SdkJoints(BoosterModel model);
// Which Booster robot has exactly these hinge joints in this order (a robot's joint_names), if any.
std::optional<BoosterModel> IdentifyRobot(const std::vector<std::string>& joint_names);

}  // namespace turf::booster
