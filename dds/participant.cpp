#include "dds/participant.h"

#include <fastrtps/xmlparser/XMLProfileManager.h>
#include <spdlog/spdlog.h>
#include <turf/idl/ClockPubSubTypes.h>
#include <turf/idl/JointsPubSubTypes.h>
#include <turf/idl/SensorStatsPubSubTypes.h>
#include <turf/idl/SimControlPubSubTypes.h>
#include <turf/idl/SimRecordPubSubTypes.h>
#include <turf/idl/SslRobotPubSubTypes.h>
#include <turf/idl/SslVisionPubSubTypes.h>
#include <turf/idl/WorldStatePubSubTypes.h>
#include <unistd.h>
#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastdds/dds/domain/DomainParticipantListener.hpp>
#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/DataReaderListener.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/topic/Topic.hpp>
#include <fastdds/dds/topic/TypeSupport.hpp>

#include <algorithm>
#include <condition_variable>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <sstream>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include "dds/authentication_watch.h"
#include "dds/fastdds_endpoint.h"
#include "dds/fastdds_peers.h"
#include "dds/held_samples.h"

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

// The held samples of a writer that may hold them (held_samples.h): a topic turf-sim publishes again and again
// (not a latched one), durable, keeping the last few (per instance if keyed). A keyed hold computes instance keys
// with a type support of its own (the generated getKey writes into a buffer of its object), under its lock.
template <class PubSub>
std::unique_ptr<HeldSamples> MakeHeldOf(size_t depth, const fdds::DataWriterQos& qos) {
  using Sample = typename PubSub::type;
  if (!PubSub().m_isGetKeyDefined) return std::make_unique<HeldSamplesOf<Sample>>(depth);
  const int32_t limit = qos.resource_limits().max_instances;
  const size_t max_instances = limit > 0 ? static_cast<size_t>(limit) : 256;
  auto type = std::make_shared<PubSub>();
  return std::make_unique<KeyedHeldSamplesOf<Sample>>(depth, max_instances, [type](const Sample& sample) {
    eprosima::fastrtps::rtps::InstanceHandle_t handle;
    type->getKey(const_cast<Sample*>(&sample), &handle, false);
    typename KeyedHeldSamplesOf<Sample>::Key key{};
    const auto& value = std::as_const(handle.value);
    for (size_t i = 0; i < key.size(); ++i) key[i] = value[i];
    return key;
  });
}

std::unique_ptr<HeldSamples> MakeHeld(Topic topic, const fdds::DataWriterQos& qos) {
  if (topic.info().direction != Direction::kPublished) return nullptr;
  if (qos.durability().kind != fdds::TRANSIENT_LOCAL_DURABILITY_QOS) return nullptr;
  if (qos.history().kind != fdds::KEEP_LAST_HISTORY_QOS || qos.history().depth <= 0) return nullptr;
  const auto depth = static_cast<size_t>(qos.history().depth);
  switch (topic.id()) {
#define TURF_TOPIC_HELD_CASE(constant, type, ...) \
  case TopicId::constant:                         \
    return MakeHeldOf<idl::type##PubSubType>(depth, qos);
    TURF_DDS_TOPICS(TURF_TOPIC_HELD_CASE)
#undef TURF_TOPIC_HELD_CASE
  }
  return nullptr;
}

// The QoS a writer offers: its profile's, except that a RELIABLE VOLATILE writer offers TRANSIENT_LOCAL. Fast DDS
// 2.9 (Debian 12) deadlocks a reliable volatile writer when one of its readers leaves while a sample of the writer
// waits for the participant's flow-controller thread (a resend): StatefulWriter::matched_reader_remove holds the
// writer's locator selector and, removing the samples all remaining readers acknowledged (what a volatile writer
// does), waits for the flow controller's mutex; that thread holds the mutex and waits for the same selector to
// flush. The test watchdog caught turf-sim's step thread blocked behind it for good, a viewer's readers having just
// left. A TRANSIENT_LOCAL writer keeps its KEEP_LAST history instead of removing acknowledged samples, so the
// removal never happens there. Its readers, VOLATILE as the profile says, still get nothing written before they
// matched: a volatile reader is sent no history. What turf does with the topic (no write without a reader, no
// held samples) follows the profile's VOLATILE.
fdds::DataWriterQos Offered(fdds::DataWriterQos qos) {
  if (qos.reliability().kind == fdds::RELIABLE_RELIABILITY_QOS &&
      qos.durability().kind == fdds::VOLATILE_DURABILITY_QOS)
    qos.durability().kind = fdds::TRANSIENT_LOCAL_DURABILITY_QOS;
  return qos;
}

// Makes its DataWriter itself, with its listener from the start, so that no match goes unseen.
class DdsWriter final : public WriterEndpoint, private fdds::DataWriterListener {
 public:
  DdsWriter(fdds::Publisher* publisher, fdds::Topic* topic_dds, const fdds::DataWriterQos& qos, Topic topic)
      : publisher_(publisher),
        volatile_(qos.durability().kind == fdds::VOLATILE_DURABILITY_QOS),
        held_(MakeHeld(topic, qos)) {
    writer_ = held_
                  ? publisher->create_datawriter(topic_dds, Offered(qos), this, fdds::StatusMask::publication_matched())
                  : publisher->create_datawriter(topic_dds, Offered(qos));
  }
  ~DdsWriter() override {
    if (writer_ == nullptr) return;
    // No held sample is flushed from now on (a flush running now ends first), so the history DeleteWriter empties
    // stays empty.
    if (held_) {
      writer_->set_listener(nullptr);
      held_->Close();
    }
    DeleteWriter(publisher_, writer_);
  }
  bool ok() const { return writer_ != nullptr; }

  bool Write(const void* sample, std::optional<int64_t> source_ns) override {
    // A volatile sample with no reader matched reaches no one, now or later: skip serialising it. (turf-sim with
    // its front-end in process and no remote camera reader saves ~0.1 ms per sync request.) A durable sample of a
    // topic published over and over is held while no reader is matched (held_samples.h): turf-sim's world states,
    // clocks and replies cost ~15-40 us per sync request otherwise.
    if (volatile_ && Matched() == 0) return true;
    if (!held_) return WriteNow(sample, source_ns);
    bool ok = true;
    held_->Write(sample, source_ns, [&](const void* s, std::optional<int64_t> ns) { ok = WriteNow(s, ns) && ok; });
    return ok;
  }
  int Matched() const override { return MatchedReaders(writer_); }

 private:
  bool WriteNow(const void* sample, std::optional<int64_t> source_ns) {
    if (!source_ns) return writer_->write(const_cast<void*>(sample));
    return WriteStamped(writer_, sample, *source_ns);
  }
  // On Fast DDS's discovery thread: with a reader matched, the held samples go out now (a late joiner of a paused
  // simulation gets its last state without waiting for another write).
  void on_publication_matched(fdds::DataWriter* /*writer*/, const fdds::PublicationMatchedStatus& status) override {
    held_->SetMatched(status.current_count, [this](const void* s, std::optional<int64_t> ns) { WriteNow(s, ns); });
  }

  fdds::Publisher* publisher_;
  const bool volatile_;
  const std::unique_ptr<HeldSamples> held_;  // topics published over and over, durable, unkeyed
  fdds::DataWriter* writer_ = nullptr;
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

  int Matched() const override { return MatchedWriters(reader_); }
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

}  // namespace

// Fast DDS keeps loaded profiles process-wide; load each file once.
// Intraprocess delivery is switched off, process-wide, before any participant exists (and again after each file,
// in case one sets it): with it, Fast DDS 2.9 (Debian 12) hands samples and GAPs between participants of one
// process through pointers to each other's endpoints, and deleting two such participants at once can use a freed
// reader proxy (a SIGSEGV in StatefulWriter::intraprocess_gap, caught in a soak run of a test with three
// participants; eProsima/Fast-DDS#2183 is the same class). Participants of one process (a bridge and its writer
// watch, tests) then talk through shared memory or UDP like any two processes.
void LoadQosProfiles(const std::string& file) {
  static std::mutex mutex;
  static std::set<std::string> loaded;
  std::lock_guard<std::mutex> lock(mutex);
  if (loaded.count(file) != 0) return;
  if (!std::filesystem::exists(file)) throw std::runtime_error("QoS profiles file not found: " + file);
  if (fdds::DomainParticipantFactory::get_instance()->load_XML_profiles_file(file) != ReturnCode::RETCODE_OK)
    throw std::runtime_error("QoS profiles file is not valid Fast DDS XML: " + file);
  eprosima::fastrtps::LibrarySettingsAttributes library;
  library.intraprocess_delivery = eprosima::fastrtps::INTRAPROCESS_OFF;
  eprosima::fastrtps::xmlparser::XMLProfileManager::library_settings(library);
  loaded.insert(file);
}

namespace {

template <class T>
std::string Printed(const T& value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

}  // namespace

std::string PeerInfo::Describe() const {
  if (pid == 0 && host.empty())
    return "participant '" + name + "' (guid prefix " + guid_prefix + "; not a turf participant, no host or pid)";
  // The participant's name too where it says more than the program's (a test's participants, a bridge's watch).
  const std::string who = program.empty() || program == name ? name : program + " '" + name + "'";
  return who + " (pid " + std::to_string(pid) + " on host " + host + ")";
}

// Fast DDS's participant listener: keeps the other participants it discovered (by GUID prefix) and their writers of
// topics under the prefix, and tells the writer listeners. Fast DDS calls it from its own threads (receive threads
// for discovery data, the event thread for expired leases): `events_mutex_` serialises the calls and the listeners'
// deliveries, so a listener sees events one at a time and in order; `mutex_` guards the lists for readers.
class Participant::Discovery final : public fdds::DomainParticipantListener {
 public:
  explicit Discovery(std::string topic_prefix) : topic_prefix_(std::move(topic_prefix) + "/") {}

  // With security: the watch told of every participant discovered and every authentication that ends. Set before
  // the DomainParticipant is made.
  void Watch(AuthenticationWatch* watch) { watch_ = watch; }

  // This participant's GUID prefix: its own writers are not others'.
  void SetOwn(const std::string& guid_prefix) {
    std::lock_guard<std::mutex> lock(mutex_);
    own_prefix_ = guid_prefix;
  }

  std::vector<RemoteWriter> Writers(const std::string& topic) const {
    std::lock_guard<std::mutex> lock(mutex_);
    return WritersLocked(topic);
  }

  std::vector<RemoteWriter> Wait(const std::string& topic,
                                 const std::function<bool(const std::vector<RemoteWriter>&)>& done,
                                 std::chrono::steady_clock::time_point deadline) const {
    std::unique_lock<std::mutex> lock(mutex_);
    std::vector<RemoteWriter> writers = WritersLocked(topic);
    while (!done(writers)) {
      if (changed_.wait_until(lock, deadline) == std::cv_status::timeout) return WritersLocked(topic);
      writers = WritersLocked(topic);
    }
    return writers;
  }

  uint64_t Seen() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return seen_;
  }

  uint64_t AddListener(WriterListener listener) {
    std::lock_guard<std::mutex> lock(events_mutex_);
    listeners_[++last_listener_] = std::move(listener);
    return last_listener_;
  }
  void RemoveListener(uint64_t id) {
    std::lock_guard<std::mutex> lock(events_mutex_);
    listeners_.erase(id);
  }

 private:
  using Events = std::vector<std::pair<WriterEvent, RemoteWriter>>;

  void on_participant_discovery(fdds::DomainParticipant* /*participant*/,
                                eprosima::fastrtps::rtps::ParticipantDiscoveryInfo&& info) override {
    using Status = eprosima::fastrtps::rtps::ParticipantDiscoveryInfo;
    std::lock_guard<std::mutex> events_lock(events_mutex_);
    const PeerInfo peer = PeerOf(info.info);
    if (watch_ != nullptr) WatchDiscovery(*watch_, info, peer);
    Events events;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (info.status == Status::DISCOVERED_PARTICIPANT || info.status == Status::CHANGED_QOS_PARTICIPANT) {
        peers_[peer.guid_prefix] = peer;
        for (RemoteWriter& w : writers_)
          if (w.participant.guid_prefix == peer.guid_prefix) w.participant = peer;
        return;
      }
      // Removed or dropped (its lease expired): its writers go with it, whether or not Fast DDS tells of each.
      peers_.erase(peer.guid_prefix);
      for (auto it = writers_.begin(); it != writers_.end();) {
        if (it->participant.guid_prefix != peer.guid_prefix) {
          ++it;
          continue;
        }
        events.emplace_back(WriterEvent::kGone, *it);
        it = writers_.erase(it);
      }
    }
    Deliver(events);
  }

#if HAVE_SECURITY
  void onParticipantAuthentication(fdds::DomainParticipant* /*participant*/,
                                   eprosima::fastrtps::rtps::ParticipantAuthenticationInfo&& info) override {
    if (watch_ != nullptr) WatchAuthentication(*watch_, info);
  }
#endif

  void on_publisher_discovery(fdds::DomainParticipant* /*participant*/,
                              eprosima::fastrtps::rtps::WriterDiscoveryInfo&& info) override {
    using Status = eprosima::fastrtps::rtps::WriterDiscoveryInfo;
    const std::string topic = info.info.topicName().to_string();
    if (topic.compare(0, topic_prefix_.size(), topic_prefix_) != 0) return;  // another prefix's, or not turf's
    std::lock_guard<std::mutex> events_lock(events_mutex_);
    const std::string participant = Printed(info.info.guid().guidPrefix);
    const std::string guid = Printed(info.info.guid());
    Events events;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (participant == own_prefix_) return;
      auto it = std::find_if(writers_.begin(), writers_.end(), [&](const RemoteWriter& w) { return w.guid == guid; });
      if (info.status == Status::DISCOVERED_WRITER && it == writers_.end()) {
        RemoteWriter writer{topic, guid, {}};
        auto peer = peers_.find(participant);
        writer.participant = peer != peers_.end() ? peer->second : PeerInfo{"", "", 0, "", 0, participant};
        writers_.push_back(writer);
        ++seen_;
        events.emplace_back(WriterEvent::kAppeared, std::move(writer));
      } else if (info.status == Status::REMOVED_WRITER && it != writers_.end()) {
        events.emplace_back(WriterEvent::kGone, *it);
        writers_.erase(it);
      }
    }
    Deliver(events);
  }

  // Under events_mutex_ (not mutex_: a listener may read the lists).
  void Deliver(const Events& events) {
    if (events.empty()) return;
    changed_.notify_all();
    for (const auto& [event, writer] : events)
      for (const auto& [id, listener] : listeners_) listener(event, writer);
  }

  std::vector<RemoteWriter> WritersLocked(const std::string& topic) const {
    std::vector<RemoteWriter> out;
    for (const RemoteWriter& w : writers_)
      if (w.topic == topic) out.push_back(w);
    return out;
  }

  const std::string topic_prefix_;  // "<prefix>/"
  std::mutex events_mutex_;
  std::map<uint64_t, WriterListener> listeners_;  // under events_mutex_
  uint64_t last_listener_ = 0;
  mutable std::mutex mutex_;
  mutable std::condition_variable changed_;
  std::string own_prefix_;
  std::map<std::string, PeerInfo> peers_;  // by GUID prefix
  std::vector<RemoteWriter> writers_;      // in discovery order
  AuthenticationWatch* watch_ = nullptr;
  uint64_t seen_ = 0;
};

std::string DefaultQosFile() {
  if (const char* env = std::getenv("TURF_QOS_FILE"); env != nullptr && *env != '\0') return env;
  return TURF_DEFAULT_QOS_FILE;
}

Participant::Participant(const ParticipantOptions& options)
    : Bus(options.prefix), options_(options), discovery_(std::make_unique<Discovery>(options.prefix)) {
  if (options_.qos_file.empty()) options_.qos_file = DefaultQosFile();
  LoadQosProfiles(options_.qos_file);
  auto* factory = fdds::DomainParticipantFactory::get_instance();
  fdds::DomainParticipantQos qos = factory->get_default_participant_qos();
  if (factory->get_participant_qos_from_profile(kParticipantProfile, qos) != ReturnCode::RETCODE_OK)
    spdlog::warn("QoS file {} has no participant profile '{}'; using Fast DDS defaults", options_.qos_file,
                 kParticipantProfile);
  qos.name(options_.name);
  AnnounceSelf(qos);
  if (!options_.security.empty()) {
    EnableSecurity(qos);
    if (options_.authentication_timeout.count() > 0) {
      authentication_ = std::make_unique<AuthenticationWatch>(options_.authentication_timeout);
      discovery_->Watch(authentication_.get());
    }
  }
  // The listener from the start: a peer discovered while the participant is being made is not missed. Discovery
  // callbacks are not masked by status; no status callback is wanted here (the readers have their own).
  participant_ = factory->create_participant(options_.domain, qos, discovery_.get(), fdds::StatusMask::none());
  if (participant_ == nullptr && !options_.security.empty())
    throw std::invalid_argument("DDS Security refused the identity in " + options_.security +
                                ": its certificate, permissions or governance do not verify against its ca.pem "
                                "(tampered with, expired, or signed by another CA; Fast DDS's error above says "
                                "which)");
  if (participant_ == nullptr)
    throw std::runtime_error("cannot create a DDS participant on domain " + std::to_string(options_.domain));
  self_.guid_prefix = Printed(participant_->guid().guidPrefix);
  discovery_->SetOwn(self_.guid_prefix);
  publisher_ = participant_->create_publisher(fdds::PUBLISHER_QOS_DEFAULT);
  subscriber_ = participant_->create_subscriber(fdds::SUBSCRIBER_QOS_DEFAULT);
  if (publisher_ == nullptr || subscriber_ == nullptr) {
    factory->delete_participant(participant_);
    throw std::runtime_error("cannot create a DDS publisher/subscriber");
  }
  if (authentication_) authentication_timer_ = std::make_unique<AuthenticationTimer>(*authentication_);
}

Participant::~Participant() {
  // Writers and readers are owned (and deleted) by their holders, which the
  // owner destroys first; delete whatever is left, then the participant.
  authentication_timer_.reset();
  participant_->delete_contained_entities();
  fdds::DomainParticipantFactory::get_instance()->delete_participant(participant_);
}

// The builtin plugins of DDS Security with the identity's files; a missing file is a configuration error.
void Participant::EnableSecurity(fdds::DomainParticipantQos& qos) const {
  AddSecurityProperties(options_.security, qos);
}

// Security needs multicast discovery or initial peers (a --qos file): a discovery server named by the environment
// would be an unauthenticated participant (`turf launch` refuses its own --discovery-server with --security; a
// participant started by hand with ROS_DISCOVERY_SERVER set ran, then aborted in Fast DDS's SecurityManager).
void AddSecurityProperties(const std::string& dir, fdds::DomainParticipantQos& qos) {
  if (const char* server = std::getenv("ROS_DISCOVERY_SERVER"); server != nullptr && *server != '\0')
    throw std::invalid_argument(std::string("--security with ROS_DISCOVERY_SERVER=") + server +
                                ": the discovery server would be an unauthenticated participant; use multicast "
                                "discovery or initial peers in a --qos file, and unset ROS_DISCOVERY_SERVER");
  auto file = [&](const std::string& name) {
    const std::string path = dir + "/" + name;
    if (access(path.c_str(), R_OK) != 0)
      throw std::invalid_argument("--security " + dir + ": no readable " + name +
                                  " (make the directory with `turf security init`)");
    return "file://" + std::filesystem::absolute(path).string();  // Fast DDS's form: file:// and the path
  };
  auto& properties = qos.properties().properties();
  const std::string auth = "dds.sec.auth.builtin.PKI-DH.";
  const std::string access_control = "dds.sec.access.builtin.Access-Permissions.";
  properties.emplace_back("dds.sec.auth.plugin", "builtin.PKI-DH");
  properties.emplace_back(auth + "identity_ca", file("ca.pem"));
  properties.emplace_back(auth + "identity_certificate", file("cert.pem"));
  properties.emplace_back(auth + "private_key", file("key.pem"));
  properties.emplace_back("dds.sec.access.plugin", "builtin.Access-Permissions");
  properties.emplace_back(access_control + "permissions_ca", file("ca.pem"));
  properties.emplace_back(access_control + "governance", file("governance.p7s"));
  properties.emplace_back(access_control + "permissions", file("permissions.p7s"));
  properties.emplace_back("dds.sec.crypto.plugin", "builtin.AES-GCM-GMAC");
}

void Participant::AnnounceSelf(fdds::DomainParticipantQos& qos) { self_ = dds::AnnounceSelf(options_.name, qos); }

std::vector<RemoteWriter> Participant::OtherWriters(Topic topic) const { return discovery_->Writers(TopicName(topic)); }

std::vector<RemoteWriter> Participant::WaitForOtherWriters(
    Topic topic, const std::function<bool(const std::vector<RemoteWriter>&)>& done,
    std::chrono::steady_clock::time_point deadline) const {
  return discovery_->Wait(TopicName(topic), done, deadline);
}

Authentications Participant::AuthenticationsNow() const {
  if (!authentication_) return {};
  return {authentication_->Pending(), authentication_->Ended(), authentication_->Stalled()};
}

uint64_t Participant::OtherWritersSeen() const { return discovery_->Seen(); }

uint64_t Participant::AddWriterListener(WriterListener listener) {
  return discovery_->AddListener(std::move(listener));
}

void Participant::RemoveWriterListener(uint64_t id) { discovery_->RemoveListener(id); }

std::string Participant::Describe() const {
  return "DDS domain " + std::to_string(options_.domain) + ", QoS profiles " + options_.qos_file +
         (options_.security.empty() ? "" : ", DDS Security as " + options_.security);
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
  auto writer = std::make_unique<DdsWriter>(publisher_, t, qos, topic);
  if (!writer->ok()) Fail("data writer", topic);
  return writer;
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
