#include "dds/camera_topics.h"

namespace turf::dds {

const CameraTopicInfo& Info(CameraTopic topic) { return kCameraTopics[static_cast<std::size_t>(topic)]; }

std::string CameraTopicName(const std::string& prefix, const std::string& robot, const std::string& camera,
                            CameraTopic topic) {
  return "rt/" + (prefix.empty() ? std::string() : prefix + "/") + robot + "/" + camera + "/" + Info(topic).kind;
}

std::string CameraTopicPattern(const std::string& prefix, CameraTopic topic) {
  return CameraTopicName(prefix, "*", "*", topic);
}

std::string CameraControlTopicName(const std::string& prefix) {
  return (prefix.empty() ? std::string() : prefix + "/") + kCameraControlSuffix;
}

}  // namespace turf::dds
