// A DDS participant of turf: the Fast DDS implementation of dds::Bus (bus.h). One DomainParticipant with one
// publisher and one subscriber, QoS from the profiles file (each topic's profile in topics.h), and typed
// writers and readers for the topics in topics.h. RAII throughout: a Writer or Reader deletes its entity; the
// Participant must outlive them (declare it first).
//
// Fast DDS headers are heavy (~10 s a file): they stay in participant.cpp; this header declares only the
// entities it keeps.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "dds/bus.h"

namespace eprosima::fastdds::dds {
class DomainParticipant;
class DomainParticipantQos;
class Publisher;
class Subscriber;
class Topic;
}  // namespace eprosima::fastdds::dds

namespace turf::dds {

class AuthenticationWatch;
class AuthenticationTimer;

struct ParticipantOptions {
  int domain = 0;
  std::string name = "turf";
  std::string prefix = "turf";  // topic names: <prefix>/<suffix>
  std::string qos_file;         // Fast DDS XML profiles; empty: built-in defaults
  // DDS Security: an identity's directory made by `turf security init` (ca.pem, cert.pem, key.pem, governance.p7s,
  // permissions.p7s: participants/launcher/security_init.h); empty: security off. The participant then authenticates
  // with that identity's certificate, may publish and subscribe only what its signed permissions allow, and meets only
  // participants of the same CA.
  std::string security;
  // With security: a participant discovered that has not finished authenticating after this long is named in a
  // warning, once (Fast DDS 2.9.1 sometimes never finishes a handshake; README, Access control). 0: no watch.
  std::chrono::milliseconds authentication_timeout{20000};
};

// With DDS Security: the other participants discovered whose authentication has not ended (pending), those whose
// authentication ended after they were discovered (authorized or refused), and those warned of as still pending after
// ParticipantOptions::authentication_timeout (stalled). All zero without security.
struct Authentications {
  size_t pending = 0;
  uint64_t ended = 0;
  uint64_t stalled = 0;
};

// Who a participant is, as its discovery data tells: a turf participant announces its host, process id, program
// and start time (as propagated participant properties, "turf.host" and so on), so that a peer can name the
// process behind a writer. Another DDS application's participant says none of that: empty strings and zeros.
struct PeerInfo {
  std::string name;             // the participant's DDS name (e.g. "turf-sim")
  std::string host;             // host name; "" if it did not say
  int64_t pid = 0;              // process id on that host; 0 if it did not say
  std::string program;          // the executable's name (e.g. "turf-sim"); "" if it did not say
  int64_t started_unix_ns = 0;  // when the participant was made (wall clock); 0 if it did not say
  std::string guid_prefix;      // the participant's GUID prefix, as Fast DDS prints it: unique per participant

  // "turf-sim (pid 4242 on host lab-3)", "my_test 'sim-b' (pid 4242 on host lab-3)" where the participant's name is
  // not the program's, or "participant 'x' (guid prefix ...; not a turf participant, no host or pid)".
  std::string Describe() const;
};

// Another participant's writer of one of this participant's topics (<prefix>/...), as discovery tells it.
struct RemoteWriter {
  std::string topic;  // full name
  std::string guid;   // the writer's GUID, as Fast DDS prints it
  PeerInfo participant;
};

// What a writer listener is told: a writer of another participant appeared (discovered) or is gone (removed by its
// participant, or its participant left or stopped answering for its lease, 5 s with turf's QoS).
enum class WriterEvent { kAppeared, kGone };
using WriterListener = std::function<void(WriterEvent event, const RemoteWriter& writer)>;

// Loads a Fast DDS QoS profiles file (once per process; Fast DDS keeps profiles process-wide). Throws
// std::runtime_error if it is missing or not valid.
void LoadQosProfiles(const std::string& file);
// Puts DDS Security's builtin plugins with the identity in `dir` (made by `turf security init`) into `qos`; throws
// std::invalid_argument naming a missing file. Participant does this for --security; VendorParticipant too.
void AddSecurityProperties(const std::string& dir, eprosima::fastdds::dds::DomainParticipantQos& qos);

// The participant profile every turf participant takes from it (transports: UDP only).
inline constexpr const char* kParticipantProfile = "turf.participant";

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

  // --- Discovery of other participants' writers (two simulators on one domain and prefix, issue 20) ---
  // Thread-safe; Fast DDS's discovery threads keep the list. Only writers of topics under this participant's prefix
  // are kept, and never this participant's own.

  // What this participant announces about itself.
  const PeerInfo& Self() const { return self_; }
  // Other participants' writers of `topic` known now, in discovery order.
  std::vector<RemoteWriter> OtherWriters(Topic topic) const;
  // Waits until `done(OtherWriters(topic))` holds or `deadline` passes (checked at once and at each discovery event,
  // under the participant's discovery lock: `done` must not call the participant); OtherWriters(topic) then.
  std::vector<RemoteWriter> WaitForOtherWriters(Topic topic,
                                                const std::function<bool(const std::vector<RemoteWriter>&)>& done,
                                                std::chrono::steady_clock::time_point deadline) const;
  // Other participants' writers discovered so far (every topic under the prefix), gone ones included.
  uint64_t OtherWritersSeen() const;
  // `listener` is called for every writer that appears or goes from now on, one event at a time, in order, on a
  // Fast DDS thread; it must not add or remove listeners. Returns the id for RemoveWriterListener, after which no
  // call runs or starts.
  uint64_t AddWriterListener(WriterListener listener);
  void RemoveWriterListener(uint64_t id);

  // --- DDS Security ---
  Authentications AuthenticationsNow() const;

 protected:
  std::unique_ptr<WriterEndpoint> OpenWriter(Topic topic, const SampleOps& ops) override;
  std::unique_ptr<ReaderEndpoint> OpenReader(Topic topic, const SampleOps& ops, SampleSink& sink) override;

 private:
  eprosima::fastdds::dds::Topic* GetTopic(Topic topic);
  [[noreturn]] void Fail(const char* what, Topic topic) const;
  // Fills self_ and puts it in the participant's QoS as propagated properties (PeerInfo).
  void EnableSecurity(eprosima::fastdds::dds::DomainParticipantQos& qos) const;
  void AnnounceSelf(eprosima::fastdds::dds::DomainParticipantQos& qos);

  ParticipantOptions options_;
  PeerInfo self_;
  // Fast DDS's listener and the writers it learnt of (participant.cpp); made before and deleted after the
  // DomainParticipant, which calls it until it is deleted.
  class Discovery;
  // With security and a timeout: made before and deleted after the DomainParticipant, whose listener (discovery_)
  // tells the watch; the timer stops first.
  std::unique_ptr<AuthenticationWatch> authentication_;
  std::unique_ptr<AuthenticationTimer> authentication_timer_;
  std::unique_ptr<Discovery> discovery_;
  eprosima::fastdds::dds::DomainParticipant* participant_ = nullptr;
  eprosima::fastdds::dds::Publisher* publisher_ = nullptr;
  eprosima::fastdds::dds::Subscriber* subscriber_ = nullptr;
  std::mutex topics_mutex_;
  std::map<std::string, eprosima::fastdds::dds::Topic*> topics_;
};

}  // namespace turf::dds
