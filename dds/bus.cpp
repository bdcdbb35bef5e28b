#include "dds/bus.h"

#include <spdlog/spdlog.h>

namespace turf::dds {

void Bus::Created(Endpoint endpoint, Topic topic) {
  spdlog::debug("{}", EndpointLine(prefix_, topic, endpoint));
  std::lock_guard<std::mutex> lock(endpoints_mutex_);
  const std::pair<Endpoint, Topic> entry(endpoint, topic);
  for (const auto& e : endpoints_)
    if (e == entry) return;
  endpoints_.push_back(entry);
}

std::vector<std::pair<Endpoint, Topic>> Bus::Endpoints() const {
  std::lock_guard<std::mutex> lock(endpoints_mutex_);
  return endpoints_;
}

std::vector<std::string> Bus::TopicLines() const {
  std::vector<std::string> lines;
  for (const auto& [endpoint, topic] : Endpoints()) lines.push_back(EndpointLine(prefix_, topic, endpoint));
  return lines;
}

void Bus::LogTopics() const {
  for (const std::string& line : TopicLines()) spdlog::info("{}", line);
}

}  // namespace turf::dds
