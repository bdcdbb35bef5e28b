#include "dds/participant.h"

#include <spdlog/spdlog.h>
#include <turf/idl/ClockPubSubTypes.h>
#include <turf/idl/JointsPubSubTypes.h>
#include <turf/idl/SensorStatsPubSubTypes.h>
#include <turf/idl/SimControlPubSubTypes.h>
#include <turf/idl/SslRobotPubSubTypes.h>
#include <turf/idl/SslVisionPubSubTypes.h>
#include <turf/idl/WorldStatePubSubTypes.h>
#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/DataReaderListener.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/topic/Topic.hpp>
#include <fastdds/dds/topic/TypeSupport.hpp>

#include <cstdlib>
#include <filesystem>
#include <set>
#include <stdexcept>
#include <type_traits>

namespace turf::dds {

namespace fdds = eprosima::fastdds::dds;
using ReturnCode = eprosima::fastrtps::types::ReturnCode_t;

// topics.h pairs each PubSubType with its sample type without Fast DDS; here both are known.
#define TURF_TOPIC_CHECK_SAMPLE(constant, sample, ...)                                            \
  static_assert(std::is_same_v<SampleOf<idl::sample##PubSubType>, idl::sample##PubSubType::type>, \
                "SampleOf<" #sample "PubSubType> is not its type");
TURF_DDS_TOPICS(TURF_TOPIC_CHECK_SAMPLE)
#undef TURF_TOPIC_CHECK_SAMPLE

namespace {

// The DDS type of a topic (its row in topics.h).
fdds::TypeSupport TypeOf(Topic topic) {
  switch (topic.id()) {
#define TURF_TOPIC_TYPE_CASE(constant, type, ...) \
  case TopicId::constant:                         \
    return fdds::TypeSupport(new idl::type##PubSubType());
    TURF_DDS_TOPICS(TURF_TOPIC_TYPE_CASE)
#undef TURF_TOPIC_TYPE_CASE
  }
  throw std::logic_error("topic without a type");
}

class DdsWriter final : public WriterEndpoint {
 public:
  DdsWriter(fdds::Publisher* publisher, fdds::DataWriter* writer)
      : publisher_(publisher),
        writer_(writer),
        volatile_(writer->get_qos().durability().kind == fdds::VOLATILE_DURABILITY_QOS) {}
  ~DdsWriter() override { publisher_->delete_datawriter(writer_); }

  bool Write(const void* sample, std::optional<int64_t> source_ns) override {
    // A volatile sample with no reader matched reaches no one, now or later: skip serialising it. (turf-sim with
    // its front-end in process and no remote camera reader saves ~0.1 ms per sync request.) Samples of durable
    // topics are written regardless: a reader that matches later gets the last of them.
    if (volatile_ && Matched() == 0) return true;
    void* data = const_cast<void*>(sample);
    if (!source_ns) return writer_->write(data);
    eprosima::fastrtps::Time_t t(static_cast<int32_t>(*source_ns / 1000000000),
                                 static_cast<uint32_t>(*source_ns % 1000000000));
    return writer_->write_w_timestamp(data, fdds::HANDLE_NIL, t) == ReturnCode::RETCODE_OK;
  }
  int Matched() const override {
    fdds::PublicationMatchedStatus status;
    writer_->get_publication_matched_status(status);
    return status.current_count;
  }

 private:
  fdds::Publisher* publisher_;
  fdds::DataWriter* writer_;
  const bool volatile_;
};

// Takes samples on Fast DDS's thread into a buffer of the topic's type and hands them to the typed queue.
class DdsReader final : public ReaderEndpoint, private fdds::DataReaderListener {
 public:
  DdsReader(fdds::Subscriber* subscriber, fdds::TypeSupport type, SampleSink& sink)
      : subscriber_(subscriber), type_(std::move(type)), sink_(sink) {}
  ~DdsReader() override {
    if (reader_ != nullptr) subscriber_->delete_datareader(reader_);
  }
  fdds::DataReaderListener* listener() { return this; }
  void Attach(fdds::DataReader* reader) { reader_ = reader; }

  int Matched() const override {
    fdds::SubscriptionMatchedStatus status;
    reader_->get_subscription_matched_status(status);
    return status.current_count;
  }
  int DeadlinesMissed() const override {
    fdds::RequestedDeadlineMissedStatus status;
    reader_->get_requested_deadline_missed_status(status);
    return status.total_count;
  }

 private:
  void on_data_available(fdds::DataReader* reader) override {
    // One buffer a call: Fast DDS may call this from more than one of its threads.
    void* sample = type_.create_data();
    fdds::SampleInfo info;
    bool any = false;
    while (reader->take_next_sample(sample, &info) == ReturnCode::RETCODE_OK) {
      if (!info.valid_data) continue;
      any = sink_.Push(sample) || any;
    }
    type_.delete_data(sample);
    if (any) sink_.Notify();
  }

  fdds::Subscriber* subscriber_;
  fdds::TypeSupport type_;
  SampleSink& sink_;
  fdds::DataReader* reader_ = nullptr;
};

constexpr const char* kParticipantProfile = "turf.participant";

// Fast DDS keeps loaded profiles process-wide; load each file once.
void LoadProfiles(const std::string& file) {
  static std::mutex mutex;
  static std::set<std::string> loaded;
  std::lock_guard<std::mutex> lock(mutex);
  if (loaded.count(file) != 0) return;
  if (!std::filesystem::exists(file)) throw std::runtime_error("QoS profiles file not found: " + file);
  if (fdds::DomainParticipantFactory::get_instance()->load_XML_profiles_file(file) != ReturnCode::RETCODE_OK)
    throw std::runtime_error("QoS profiles file is not valid Fast DDS XML: " + file);
  loaded.insert(file);
}

}  // namespace

std::string DefaultQosFile() {
  if (const char* env = std::getenv("TURF_QOS_FILE"); env != nullptr && *env != '\0') return env;
  return TURF_DEFAULT_QOS_FILE;
}

Participant::Participant(const ParticipantOptions& options) : Bus(options.prefix), options_(options) {
  if (options_.qos_file.empty()) options_.qos_file = DefaultQosFile();
  LoadProfiles(options_.qos_file);
  auto* factory = fdds::DomainParticipantFactory::get_instance();
  fdds::DomainParticipantQos qos = factory->get_default_participant_qos();
  if (factory->get_participant_qos_from_profile(kParticipantProfile, qos) != ReturnCode::RETCODE_OK)
    spdlog::warn("QoS file {} has no participant profile '{}'; using Fast DDS defaults", options_.qos_file,
                 kParticipantProfile);
  qos.name(options_.name);
  participant_ = factory->create_participant(options_.domain, qos);
  if (participant_ == nullptr)
    throw std::runtime_error("cannot create a DDS participant on domain " + std::to_string(options_.domain));
  publisher_ = participant_->create_publisher(fdds::PUBLISHER_QOS_DEFAULT);
  subscriber_ = participant_->create_subscriber(fdds::SUBSCRIBER_QOS_DEFAULT);
  if (publisher_ == nullptr || subscriber_ == nullptr) {
    factory->delete_participant(participant_);
    throw std::runtime_error("cannot create a DDS publisher/subscriber");
  }
}

Participant::~Participant() {
  // Writers and readers are owned (and deleted) by their holders, which the
  // owner destroys first; delete whatever is left, then the participant.
  participant_->delete_contained_entities();
  fdds::DomainParticipantFactory::get_instance()->delete_participant(participant_);
}

std::string Participant::Describe() const {
  return "DDS domain " + std::to_string(options_.domain) + ", QoS profiles " + options_.qos_file;
}

fdds::Topic* Participant::GetTopic(Topic topic) {
  const std::string name = TopicName(topic);
  std::lock_guard<std::mutex> lock(topics_mutex_);
  auto it = topics_.find(name);
  if (it != topics_.end()) return it->second;
  fdds::TypeSupport type = TypeOf(topic);
  type.register_type(participant_);
  fdds::Topic* t = participant_->create_topic(name, type.get_type_name(), fdds::TOPIC_QOS_DEFAULT);
  if (t == nullptr) Fail("topic", topic);
  topics_[name] = t;
  return t;
}

std::unique_ptr<WriterEndpoint> Participant::OpenWriter(Topic topic, const SampleOps& /*ops*/) {
  fdds::Topic* t = GetTopic(topic);
  fdds::DataWriterQos qos = fdds::DATAWRITER_QOS_DEFAULT;
  if (publisher_->get_datawriter_qos_from_profile(topic.info().profile, qos) != ReturnCode::RETCODE_OK)
    spdlog::warn("QoS file has no data_writer profile '{}'; using Fast DDS defaults", topic.info().profile);
  fdds::DataWriter* w = publisher_->create_datawriter(t, qos);
  if (w == nullptr) Fail("data writer", topic);
  return std::make_unique<DdsWriter>(publisher_, w);
}

// Samples are buffers of the topic's DDS type (TypeOf), which the sink copies: `ops` is not needed here.
std::unique_ptr<ReaderEndpoint> Participant::OpenReader(Topic topic, const SampleOps& /*ops*/, SampleSink& sink) {
  fdds::Topic* t = GetTopic(topic);
  fdds::DataReaderQos qos = fdds::DATAREADER_QOS_DEFAULT;
  if (subscriber_->get_datareader_qos_from_profile(topic.info().profile, qos) != ReturnCode::RETCODE_OK)
    spdlog::warn("QoS file has no data_reader profile '{}'; using Fast DDS defaults", topic.info().profile);
  auto reader = std::make_unique<DdsReader>(subscriber_, TypeOf(topic), sink);
  fdds::DataReader* r = subscriber_->create_datareader(t, qos, reader->listener(), fdds::StatusMask::data_available());
  if (r == nullptr) Fail("data reader", topic);
  reader->Attach(r);
  return reader;
}

void Participant::Fail(const char* what, Topic topic) const {
  throw std::runtime_error(std::string("cannot create DDS ") + what + " for " + TopicName(topic));
}

}  // namespace turf::dds
