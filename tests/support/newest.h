// A test client's view of one topic: the reader, and what Poll() keeps of its
// samples (take.h): the newest one (Newest, read as a std::optional) or the
// newest of each robot (NewestByRobot, read as a map by robot name).
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>

#include "dds/bus.h"
#include "tests/support/take.h"

namespace turf::test {

template <class PubSub>
class Newest : public std::optional<typename PubSub::type> {
 public:
  Newest(dds::Bus& bus, const dds::TopicDef<PubSub>& topic) : reader_(bus.MakeReader(topic)) {}
  void Poll() { TakeNewest(*reader_, static_cast<std::optional<typename PubSub::type>*>(this)); }

 private:
  std::unique_ptr<dds::Reader<PubSub>> reader_;
};

template <class PubSub>
class NewestByRobot : public std::map<std::string, typename PubSub::type> {
 public:
  NewestByRobot(dds::Bus& bus, const dds::TopicDef<PubSub>& topic) : reader_(bus.MakeReader(topic)) {}
  void Poll() { TakeNewestByRobot(*reader_, static_cast<std::map<std::string, typename PubSub::type>*>(this)); }

 private:
  std::unique_ptr<dds::Reader<PubSub>> reader_;
};

// Polls every one of `views`.
template <class... Views>
void PollAll(Views&... views) {
  (views.Poll(), ...);
}

}  // namespace turf::test
