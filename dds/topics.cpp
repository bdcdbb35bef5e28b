#include "dds/topics.h"

#include <cstddef>
#include <iterator>

#include "dds/camera_topics.h"

namespace turf::dds {

std::string TopicName(const std::string& prefix, Topic topic) {
  return prefix.empty() ? topic.info().suffix : prefix + "/" + topic.info().suffix;
}

const char* DirectionName(Direction direction) {
  // By Direction's value.
  static constexpr const char* kNames[] = {"published", "published, latched", "subscribed"};
  const auto i = static_cast<size_t>(direction);
  return i < std::size(kNames) ? kNames[i] : "?";
}

std::string EndpointLine(const std::string& prefix, Topic topic, Endpoint endpoint) {
  const TopicInfo& info = topic.info();
  return std::string(endpoint == Endpoint::kWriter ? "writes " : "reads ") + TopicName(prefix, topic) + " (" +
         info.dds_type + ", QoS profile " + info.profile + ")";
}

std::string TopicsMarkdown() {
  std::string out =
      "| topic | type | direction | QoS profile | when, what |\n"
      "| --- | --- | --- | --- | --- |\n";
  for (const TopicInfo& info : kTopics) {
    out += std::string("| `") + info.suffix + "` | `" + info.type + "` | " + DirectionName(info.direction) + " | `" +
           info.profile + "` | " + info.what + " |\n";
  }
  // The camera topics: one set per camera, written by turf-render (camera_topics.h).
  for (const CameraTopicInfo& info : kCameraTopics) {
    out += std::string("| `rt/<prefix>/<robot>/<camera>/") + info.kind + "` | `" + info.dds_type +
           "` | published by turf-render | " + kCameraTopicQos + " | " + info.what + " |\n";
  }
  out += std::string("| `<prefix>/") + kCameraControlSuffix + "` | `" + kCameraControlType +
         "` | read by turf-render | " + kCameraTopicQos + " | " + kCameraControlWhat + " |\n";
  return out;
}

}  // namespace turf::dds
