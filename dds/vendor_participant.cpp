#include "dds/vendor_participant.h"

#include <spdlog/spdlog.h>

#include <fastdds/rtps/transport/UDPv4TransportDescriptor.h>
#include <fastdds/rtps/transport/shared_mem/SharedMemTransportDescriptor.h>
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
#include <fastdds/rtps/flowcontrol/FlowControllerDescriptor.hpp>
#include <map>
#include <mutex>
#include <stdexcept>

#include "dds/authentication_watch.h"
#include "dds/fastdds_endpoint.h"
#include "dds/fastdds_peers.h"
#include "dds/participant.h"

namespace turf::dds {

namespace fdds = eprosima::fastdds::dds;
using ReturnCode = eprosima::fastrtps::types::ReturnCode_t;

namespace {

// Under DDS Security: Fast DDS's participant listener tells the watch of discoveries and authentications.
class AuthenticationListener final : public fdds::DomainParticipantListener {
 public:
  explicit AuthenticationListener(AuthenticationWatch& watch) : watch_(watch) {}

 private:
  void on_participant_discovery(fdds::DomainParticipant* /*participant*/,
                                eprosima::fastrtps::rtps::ParticipantDiscoveryInfo&& info) override {
    WatchDiscovery(watch_, info, PeerOf(info.info));
  }
#if HAVE_SECURITY
  void onParticipantAuthentication(fdds::DomainParticipant* /*participant*/,
                                   eprosima::fastrtps::rtps::ParticipantAuthenticationInfo&& info) override {
    WatchAuthentication(watch_, info);
  }
#endif

  AuthenticationWatch& watch_;
};

}  // namespace

struct VendorParticipant::Impl {
  // With security and a timeout (as Participant's): made before and deleted after the DomainParticipant, which
  // calls the listener until it is deleted; the timer stops first.
  std::unique_ptr<AuthenticationWatch> watch;
  std::unique_ptr<AuthenticationListener> listener;
  std::unique_ptr<AuthenticationTimer> timer;
  fdds::DomainParticipant* participant = nullptr;
  fdds::Publisher* publisher = nullptr;
  fdds::Subscriber* subscriber = nullptr;
  std::mutex mutex;
  std::map<std::string, fdds::Topic*> topics;

  // One topic per name, registering its type on first use; a second type for one name is refused.
  fdds::Topic* TopicOf(const std::string& name, fdds::TypeSupport type) {
    std::lock_guard<std::mutex> lock(mutex);
    auto it = topics.find(name);
    if (it != topics.end()) {
      if (it->second->get_type_name() != type.get_type_name())
        throw std::runtime_error("topic " + name + " is already of type " + it->second->get_type_name());
      return it->second;
    }
    if (type.register_type(participant) != ReturnCode::RETCODE_OK)
      throw std::runtime_error("cannot register DDS type " + type.get_type_name());
    fdds::Topic* topic = participant->create_topic(name, type.get_type_name(), fdds::TOPIC_QOS_DEFAULT);
    if (topic == nullptr) throw std::runtime_error("cannot create DDS topic " + name);
    topics.emplace(name, topic);
    return topic;
  }
};

namespace {

constexpr const char* kLargeSampleController = "turf.large_samples";
constexpr uint32_t kLargeSampleSocketBuffer = 4 * 1024 * 1024;

// The vendor SDKs' default: best effort, volatile, keep last (a few samples for commands arriving together).
fdds::DataWriterQos WriterQos(fdds::Publisher* publisher, bool large_samples) {
  fdds::DataWriterQos qos = publisher->get_default_datawriter_qos();
  qos.reliability().kind = fdds::BEST_EFFORT_RELIABILITY_QOS;
  qos.durability().kind = fdds::VOLATILE_DURABILITY_QOS;
  qos.history().kind = fdds::KEEP_LAST_HISTORY_QOS;
  qos.history().depth = 1;
  if (large_samples) {
    qos.publish_mode().kind = fdds::ASYNCHRONOUS_PUBLISH_MODE;
    qos.publish_mode().flow_controller_name = kLargeSampleController;
  }
  return qos;
}

// A best-effort reader matches best-effort and reliable writers alike. Keyed topics (turf's camera switch: one
// instance per camera) hold up to kMaxInstances live instances: Fast DDS's default of 10 let a live writer of ten
// other cameras' keys make every further switch vanish unread (a scene of more than ten cameras could not switch
// the eleventh).
constexpr int32_t kReaderDepth = 8;
constexpr int32_t kMaxInstances = 1024;
fdds::DataReaderQos ReaderQos(fdds::Subscriber* subscriber) {
  fdds::DataReaderQos qos = subscriber->get_default_datareader_qos();
  qos.reliability().kind = fdds::BEST_EFFORT_RELIABILITY_QOS;
  qos.durability().kind = fdds::VOLATILE_DURABILITY_QOS;
  qos.history().kind = fdds::KEEP_LAST_HISTORY_QOS;
  qos.history().depth = kReaderDepth;
  qos.resource_limits().max_instances = kMaxInstances;
  qos.resource_limits().max_samples_per_instance = kReaderDepth;
  qos.resource_limits().max_samples = kMaxInstances * kReaderDepth;
  qos.resource_limits().allocated_samples = kReaderDepth;
  return qos;
}

class DdsVendorWriter final : public VendorParticipant::RawWriter {
 public:
  DdsVendorWriter(fdds::Publisher* publisher, fdds::DataWriter* writer) : publisher_(publisher), writer_(writer) {}
  ~DdsVendorWriter() override { DeleteWriter(publisher_, writer_); }
  bool Write(const void* sample) override { return writer_->write(const_cast<void*>(sample)); }
  bool Write(const void* sample, int64_t source_ns) override { return WriteStamped(writer_, sample, source_ns); }
  int Matched() const override { return MatchedReaders(writer_); }

 private:
  fdds::Publisher* publisher_;
  fdds::DataWriter* writer_;
};

class DdsVendorReader final : public VendorParticipant::RawReader, public fdds::DataReaderListener {
 public:
  DdsVendorReader(fdds::Subscriber* subscriber, fdds::TypeSupport type,
                  std::function<void(const void*, int64_t)> on_sample)
      : subscriber_(subscriber), type_(std::move(type)), on_sample_(std::move(on_sample)) {}
  ~DdsVendorReader() override {
    if (reader_ != nullptr) subscriber_->delete_datareader(reader_);
  }
  void Attach(fdds::DataReader* reader) { reader_ = reader; }
  int Matched() const override { return MatchedWriters(reader_); }

 private:
  void on_data_available(fdds::DataReader* reader) override {
    void* sample = type_.create_data();
    fdds::SampleInfo info;
    while (reader->take_next_sample(sample, &info) == ReturnCode::RETCODE_OK) {
      if (!info.valid_data) continue;
      const auto& t = info.source_timestamp;
      on_sample_(sample, static_cast<int64_t>(t.seconds()) * 1'000'000'000 + t.nanosec());
    }
    type_.delete_data(sample);
  }

  fdds::Subscriber* subscriber_;
  fdds::TypeSupport type_;
  std::function<void(const void*, int64_t)> on_sample_;
  fdds::DataReader* reader_ = nullptr;
};

// Shared memory and UDPv4, with socket buffers large enough for a few images, and the flow controller that paces
// large samples.
void UseLargeSampleTransports(fdds::DomainParticipantQos& qos) {
  auto udp = std::make_shared<eprosima::fastdds::rtps::UDPv4TransportDescriptor>();
  udp->sendBufferSize = kLargeSampleSocketBuffer;
  udp->receiveBufferSize = kLargeSampleSocketBuffer;
  auto shm = std::make_shared<eprosima::fastdds::rtps::SharedMemTransportDescriptor>();
  shm->segment_size(4 * kLargeSampleSocketBuffer);
  qos.transport().user_transports.clear();
  qos.transport().user_transports.push_back(shm);
  qos.transport().user_transports.push_back(udp);
  qos.transport().use_builtin_transports = false;
  qos.transport().send_socket_buffer_size = kLargeSampleSocketBuffer;
  qos.transport().listen_socket_buffer_size = kLargeSampleSocketBuffer;
  auto controller = std::make_shared<eprosima::fastdds::rtps::FlowControllerDescriptor>();
  controller->name = kLargeSampleController;
  controller->max_bytes_per_period = kLargeSampleBytesPerMs;
  controller->period_ms = 1;
  qos.flow_controllers().push_back(controller);
}

}  // namespace

VendorParticipant::VendorParticipant(int domain, const std::string& name)
    : VendorParticipant(VendorOptions{domain, name, "", false}) {}

VendorParticipant::VendorParticipant(const VendorOptions& options)
    : domain_(options.domain), large_samples_(options.large_samples), impl_(std::make_unique<Impl>()) {
  auto* factory = fdds::DomainParticipantFactory::get_instance();
  fdds::DomainParticipantQos qos = factory->get_default_participant_qos();
  const std::string profiles = DefaultQosFile();
  if (!profiles.empty()) {
    LoadQosProfiles(profiles);
    if (factory->get_participant_qos_from_profile(kParticipantProfile, qos) != ReturnCode::RETCODE_OK)
      spdlog::warn("QoS file {} has no participant profile '{}'; using Fast DDS defaults", profiles,
                   kParticipantProfile);
  }
  qos.name(options.name);
  if (options.large_samples) UseLargeSampleTransports(qos);
  AnnounceSelf(options.name, qos);
  if (!options.security.empty()) {
    AddSecurityProperties(options.security, qos);
    if (options.authentication_timeout.count() > 0) {
      impl_->watch = std::make_unique<AuthenticationWatch>(options.authentication_timeout);
      impl_->listener = std::make_unique<AuthenticationListener>(*impl_->watch);
    }
  }
  impl_->participant =
      factory->create_participant(options.domain, qos, impl_->listener.get(), fdds::StatusMask::none());
  if (impl_->participant == nullptr && !options.security.empty())
    throw std::invalid_argument("DDS Security refused the identity in " + options.security);
  if (impl_->participant == nullptr)
    throw std::runtime_error("cannot create a DDS participant on domain " + std::to_string(options.domain));
  impl_->publisher = impl_->participant->create_publisher(fdds::PUBLISHER_QOS_DEFAULT);
  impl_->subscriber = impl_->participant->create_subscriber(fdds::SUBSCRIBER_QOS_DEFAULT);
  if (impl_->publisher == nullptr || impl_->subscriber == nullptr)
    throw std::runtime_error("cannot create a DDS publisher/subscriber");
  if (impl_->watch) impl_->timer = std::make_unique<AuthenticationTimer>(*impl_->watch);
}

Authentications VendorParticipant::AuthenticationsNow() const {
  if (!impl_->watch) return {};
  return {impl_->watch->Pending(), impl_->watch->Ended(), impl_->watch->Stalled()};
}

VendorParticipant::~VendorParticipant() {
  if (impl_->participant == nullptr) return;
  impl_->timer.reset();
  impl_->participant->delete_contained_entities();
  fdds::DomainParticipantFactory::get_instance()->delete_participant(impl_->participant);
}

std::unique_ptr<VendorParticipant::RawWriter> VendorParticipant::OpenWriter(const std::string& topic,
                                                                            fdds::TopicDataType* type) {
  fdds::TypeSupport support(type);
  fdds::Topic* t = impl_->TopicOf(topic, support);
  fdds::DataWriter* w = impl_->publisher->create_datawriter(t, WriterQos(impl_->publisher, large_samples_));
  if (w == nullptr) throw std::runtime_error("cannot create a DDS writer for " + topic);
  return std::make_unique<DdsVendorWriter>(impl_->publisher, w);
}

std::unique_ptr<VendorParticipant::RawReader> VendorParticipant::OpenReader(
    const std::string& topic, fdds::TopicDataType* type, std::function<void(const void*, int64_t)> on_sample) {
  fdds::TypeSupport support(type);
  fdds::Topic* t = impl_->TopicOf(topic, support);
  auto reader = std::make_unique<DdsVendorReader>(impl_->subscriber, support, std::move(on_sample));
  fdds::DataReader* r = impl_->subscriber->create_datareader(t, ReaderQos(impl_->subscriber), reader.get(),
                                                             fdds::StatusMask::data_available());
  if (r == nullptr) throw std::runtime_error("cannot create a DDS reader for " + topic);
  reader->Attach(r);
  return reader;
}

}  // namespace turf::dds
