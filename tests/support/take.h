// What a test client keeps of a topic's samples: the newest, or the newest of each robot.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace turf::test {

// Takes what `reader` (a dds::Reader) holds and keeps the newest sample, if any came.
template <class Reader, class Sample>
void TakeNewest(Reader& reader, std::optional<Sample>* newest) {
  std::vector<Sample> got;
  if (reader.Take(&got) && !got.empty()) *newest = std::move(got.back());
}

// Takes what `reader` holds and keeps the newest sample of each robot (the sample's robot()).
template <class Reader, class Sample>
void TakeNewestByRobot(Reader& reader, std::map<std::string, Sample>* by_robot) {
  std::vector<Sample> got;
  if (reader.Take(&got))
    for (Sample& s : got) (*by_robot)[s.robot()] = std::move(s);
}

}  // namespace turf::test
