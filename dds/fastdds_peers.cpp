#include "dds/fastdds_peers.h"

#include <errno.h>  // program_invocation_short_name (glibc)
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <chrono>
#include <exception>
#include <sstream>

namespace turf::dds {
namespace {

// The properties a turf participant announces (propagated with its discovery data), so a peer can name the process.
constexpr const char* kHostProperty = "turf.host";
constexpr const char* kPidProperty = "turf.pid";
constexpr const char* kProgramProperty = "turf.program";
constexpr const char* kStartedProperty = "turf.started_ns";

std::string HostName() {
  char name[256] = {};
  if (gethostname(name, sizeof(name) - 1) != 0) return "unknown";
  return name;
}

// The executable's name: what `ps` shows, the same for every participant of the process.
std::string ProgramName() {
  const char* name = program_invocation_short_name;  // glibc
  return name != nullptr ? name : "";
}

int64_t ToInt(const std::string& text) {
  try {
    return std::stoll(text);
  } catch (const std::exception&) {
    return 0;  // a malformed value from another implementation: as if it said nothing
  }
}

}  // namespace

PeerInfo AnnounceSelf(const std::string& name, eprosima::fastdds::dds::DomainParticipantQos& qos) {
  PeerInfo self;
  self.name = name;
  self.host = HostName();
  self.pid = getpid();
  self.program = ProgramName();
  self.started_unix_ns =
      std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch()).count();
  auto& properties = qos.properties().properties();
  properties.emplace_back(kHostProperty, self.host, /*propagate=*/true);
  properties.emplace_back(kPidProperty, std::to_string(self.pid), true);
  properties.emplace_back(kProgramProperty, self.program, true);
  properties.emplace_back(kStartedProperty, std::to_string(self.started_unix_ns), true);
  return self;
}

PeerInfo PeerOf(const eprosima::fastrtps::rtps::ParticipantProxyData& data) {
  PeerInfo peer;
  peer.name = data.m_participantName.to_string();
  peer.guid_prefix = PrefixText(data.m_guid.guidPrefix);
  for (auto it = data.m_properties.begin(); it != data.m_properties.end(); ++it) {
    const std::string key = it->first();
    if (key == kHostProperty) peer.host = it->second();
    if (key == kPidProperty) peer.pid = ToInt(it->second());
    if (key == kProgramProperty) peer.program = it->second();
    if (key == kStartedProperty) peer.started_unix_ns = ToInt(it->second());
  }
  return peer;
}

std::string PrefixText(const eprosima::fastrtps::rtps::GuidPrefix_t& prefix) {
  std::ostringstream out;
  out << prefix;
  return out.str();
}

void WatchDiscovery(AuthenticationWatch& watch, const eprosima::fastrtps::rtps::ParticipantDiscoveryInfo& info,
                    const PeerInfo& peer) {
  using Status = eprosima::fastrtps::rtps::ParticipantDiscoveryInfo;
  if (info.status == Status::DISCOVERED_PARTICIPANT)
    watch.Discovered(peer, AuthenticationWatch::Clock::now());
  else if (info.status != Status::CHANGED_QOS_PARTICIPANT)
    watch.Gone(peer.guid_prefix);  // removed, or dropped for its lease
}

#if HAVE_SECURITY
// A refusal is a peer without an identity, of another CA, or whose identity does not verify.
void WatchAuthentication(AuthenticationWatch& watch,
                         const eprosima::fastrtps::rtps::ParticipantAuthenticationInfo& info) {
  using Status = eprosima::fastrtps::rtps::ParticipantAuthenticationInfo;
  const std::string prefix = PrefixText(info.guid.guidPrefix);
  const std::optional<PeerInfo> peer = watch.Ended(prefix);
  if (info.status != Status::UNAUTHORIZED_PARTICIPANT) return;
  spdlog::warn(
      "DDS security: {} failed to authenticate (no identity, one of another CA, or one that does not verify): it "
      "meets no topic of this participant",
      peer ? peer->Describe() : "participant with guid prefix " + prefix);
}
#endif

}  // namespace turf::dds
