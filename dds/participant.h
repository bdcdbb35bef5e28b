// A DDS participant of turf: the Fast DDS implementation of dds::Bus (bus.h). One DomainParticipant with one
// publisher and one subscriber, QoS from the profiles file (each topic's profile in topics.h), and typed
// writers and readers for the topics in topics.h. RAII throughout: a Writer or Reader deletes its entity; the
// Participant must outlive them (declare it first).
//
// Fast DDS headers are heavy (~10 s a file): they stay in participant.cpp; this header declares only the
// entities it keeps.
#pragma once

#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "dds/bus.h"

namespace eprosima::fastdds::dds {
class DomainParticipant;
class Publisher;
class Subscriber;
class Topic;
}  // namespace eprosima::fastdds::dds

namespace turf::dds {

struct ParticipantOptions {
  int domain = 0;
  std::string name = "turf";
  std::string prefix = "turf";  // topic names: <prefix>/<suffix>
  std::string qos_file;         // Fast DDS XML profiles; empty: built-in defaults
};

// The QoS profiles file shipped with turf, found next to the executable's
// install or source tree; empty if none is found.
std::string DefaultQosFile();

class Participant final : public Bus {
 public:
  // Throws std::runtime_error if the participant cannot be created.
  explicit Participant(const ParticipantOptions& options);
  ~Participant() override;

  const ParticipantOptions& options() const { return options_; }
  std::string Describe() const override;

 protected:
  std::unique_ptr<WriterEndpoint> OpenWriter(Topic topic, const SampleOps& ops) override;
  std::unique_ptr<ReaderEndpoint> OpenReader(Topic topic, const SampleOps& ops, SampleSink& sink) override;

 private:
  eprosima::fastdds::dds::Topic* GetTopic(Topic topic);
  [[noreturn]] void Fail(const char* what, Topic topic) const;

  ParticipantOptions options_;
  eprosima::fastdds::dds::DomainParticipant* participant_ = nullptr;
  eprosima::fastdds::dds::Publisher* publisher_ = nullptr;
  eprosima::fastdds::dds::Subscriber* subscriber_ = nullptr;
  std::mutex topics_mutex_;
  std::map<std::string, eprosima::fastdds::dds::Topic*> topics_;
};

}  // namespace turf::dds
