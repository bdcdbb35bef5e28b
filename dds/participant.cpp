#include "dds/participant.h"

#include <spdlog/spdlog.h>
#include <fastdds/dds/domain/DomainParticipantFactory.hpp>

#include <cstdlib>
#include <filesystem>
#include <set>
#include <stdexcept>

namespace turf::dds {

namespace {

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

Participant::Participant(const ParticipantOptions& options) : options_(options) {
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

fdds::Topic* Participant::GetTopic(Topic topic, fdds::TypeSupport type) {
  const std::string name = TopicName(topic);
  auto it = topics_.find(name);
  if (it != topics_.end()) return it->second;
  type.register_type(participant_);
  fdds::Topic* t = participant_->create_topic(name, type.get_type_name(), fdds::TOPIC_QOS_DEFAULT);
  if (t == nullptr) Fail("topic", topic);
  topics_[name] = t;
  return t;
}

fdds::DataWriterQos Participant::WriterQos(Topic topic) const {
  fdds::DataWriterQos qos = fdds::DATAWRITER_QOS_DEFAULT;
  if (publisher_->get_datawriter_qos_from_profile(topic.info().profile, qos) != ReturnCode::RETCODE_OK)
    spdlog::warn("QoS file has no data_writer profile '{}'; using Fast DDS defaults", topic.info().profile);
  return qos;
}

fdds::DataReaderQos Participant::ReaderQos(Topic topic) const {
  fdds::DataReaderQos qos = fdds::DATAREADER_QOS_DEFAULT;
  if (subscriber_->get_datareader_qos_from_profile(topic.info().profile, qos) != ReturnCode::RETCODE_OK)
    spdlog::warn("QoS file has no data_reader profile '{}'; using Fast DDS defaults", topic.info().profile);
  return qos;
}

void Participant::Created(Endpoint endpoint, Topic topic) {
  spdlog::debug("{}", EndpointLine(options_.prefix, topic, endpoint));
  std::lock_guard<std::mutex> lock(endpoints_mutex_);
  const std::pair<Endpoint, Topic> entry(endpoint, topic);
  for (const auto& e : endpoints_)
    if (e == entry) return;
  endpoints_.push_back(entry);
}

std::vector<std::pair<Endpoint, Topic>> Participant::Endpoints() const {
  std::lock_guard<std::mutex> lock(endpoints_mutex_);
  return endpoints_;
}

std::vector<std::string> Participant::TopicLines() const {
  std::vector<std::string> lines;
  for (const auto& [endpoint, topic] : Endpoints()) lines.push_back(EndpointLine(options_.prefix, topic, endpoint));
  return lines;
}

void Participant::LogTopics() const {
  for (const std::string& line : TopicLines()) spdlog::info("{}", line);
}

void Participant::Fail(const char* what, Topic topic) const {
  throw std::runtime_error(std::string("cannot create DDS ") + what + " for " + TopicName(topic));
}

}  // namespace turf::dds
