#include "dds/topics.h"

namespace turf::dds {

const TopicInfo& Info(Topic topic) {
  for (const TopicInfo& info : kTopics)
    if (info.topic == topic) return info;
  return kTopics[0];  // unreachable: every enumerator has a row (tested)
}

std::string TopicName(const std::string& prefix, Topic topic) {
  return prefix.empty() ? Info(topic).suffix : prefix + "/" + Info(topic).suffix;
}

}  // namespace turf::dds
