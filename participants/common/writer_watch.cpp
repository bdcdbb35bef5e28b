#include "participants/common/writer_watch.h"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <signal.h>
#include <algorithm>
#include <cerrno>
#include <tuple>
#include <utility>

#include "participants/common/process.h"

namespace turf {

namespace {

// A writer of a topic in a log line: "turf-sim (pid 4242 on host lab-3)".
std::string Named(const dds::RemoteWriter& writer) { return writer.participant.Describe(); }

std::string NamedList(const std::vector<dds::RemoteWriter>& writers) {
  std::string out;
  for (const dds::RemoteWriter& w : writers) out += (out.empty() ? "" : ", ") + Named(w);
  return out;
}

}  // namespace

bool WriterProcessGone(const dds::RemoteWriter& writer, const dds::PeerInfo& self) {
  const dds::PeerInfo& peer = writer.participant;
  if (peer.pid <= 0 || peer.host.empty() || peer.host != self.host) return false;  // cannot tell: assume it runs
  // ESRCH: no such process. EPERM: it exists under another user.
  return kill(static_cast<pid_t>(peer.pid), 0) != 0 && errno == ESRCH;
}

std::vector<dds::RemoteWriter> LiveOtherWriters(const dds::Participant& participant, dds::Topic topic) {
  std::vector<dds::RemoteWriter> writers = participant.OtherWriters(topic);
  writers.erase(std::remove_if(writers.begin(), writers.end(),
                               [&](const dds::RemoteWriter& w) { return WriterProcessGone(w, participant.Self()); }),
                writers.end());
  return writers;
}

bool StartedEarlier(const dds::PeerInfo& other, const dds::PeerInfo& self) {
  if (other.started_unix_ns == 0) return true;
  return std::tie(other.started_unix_ns, other.guid_prefix) < std::tie(self.started_unix_ns, self.guid_prefix);
}

std::optional<dds::RemoteWriter> FindEarlierWriter(const dds::Participant& participant, dds::Topic topic,
                                                   std::chrono::milliseconds window) {
  std::optional<dds::RemoteWriter> found;
  // Evaluated at each discovery event (and once at the start) under the participant's lock: only what it decides on
  // is kept, nothing is logged from here.
  auto earlier = [&](const std::vector<dds::RemoteWriter>& writers) {
    for (const dds::RemoteWriter& w : writers) {
      if (WriterProcessGone(w, participant.Self()) || !StartedEarlier(w.participant, participant.Self())) continue;
      found = w;
      return true;
    }
    return false;
  };
  // In slices, so a stop signal during the window is heard within 0.1 s (it waited the whole 1.5 s).
  const auto end = std::chrono::steady_clock::now() + window;
  for (auto now = std::chrono::steady_clock::now(); now < end && !found && !StopRequested();
       now = std::chrono::steady_clock::now())
    participant.WaitForOtherWriters(topic, earlier, std::min(end, now + std::chrono::milliseconds(100)));
  return found;
}

std::string RefusalLine(const dds::Participant& participant, dds::Topic topic, const dds::RemoteWriter& other) {
  return fmt::format(
      "refusing to start: {} already writes {} on DDS domain {}; two simulators on one domain and prefix would "
      "feed every reader both worlds in turn. Stop it, or give this one another --domain or --prefix (a process "
      "that has just crashed stays known for up to 5 s, its DDS lease)",
      Named(other), participant.TopicName(topic), participant.options().domain);
}

WriterWatch::WriterWatch(dds::Participant& participant, Options options)
    : participant_(participant), options_(std::move(options)) {
  // The listener first, then a look at what discovery already knows: a writer found in between is evaluated
  // twice, which changes nothing the second time.
  listener_ = participant_.AddWriterListener([this](dds::WriterEvent, const dds::RemoteWriter& writer) {
    for (dds::Topic topic : options_.topics) {
      if (participant_.TopicName(topic) != writer.topic) continue;
      std::lock_guard<std::mutex> lock(mutex_);
      Evaluate(topic);
    }
  });
  std::lock_guard<std::mutex> lock(mutex_);
  for (dds::Topic topic : options_.topics) Evaluate(topic);
}

WriterWatch::~WriterWatch() { participant_.RemoveWriterListener(listener_); }

uint64_t WriterWatch::Conflicts() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return conflicts_;
}

uint64_t WriterWatch::WaitForConflicts(uint64_t n, std::chrono::milliseconds timeout) const {
  std::unique_lock<std::mutex> lock(mutex_);
  conflicted_.wait_for(lock, timeout, [&] { return conflicts_ >= n; });
  return conflicts_;
}

void WriterWatch::Evaluate(dds::Topic topic) {
  const std::string name = participant_.TopicName(topic);
  const std::vector<dds::RemoteWriter> others = LiveOtherWriters(participant_, topic);
  const int writers = static_cast<int>(others.size()) + (options_.own_writer ? 1 : 0);
  TopicState& state = state_[name];
  const int extra_before = std::max(0, state.writers - 1);
  const int extra = std::max(0, writers - 1);
  state.writers = writers;
  if (extra == 0) {
    if (state.logged) spdlog::info("{} has one writer again", name);
    state.logged = false;
    return;
  }
  if (extra <= extra_before) return;
  conflicts_ += static_cast<uint64_t>(extra - extra_before);
  conflicted_.notify_all();
  const auto now = std::chrono::steady_clock::now();
  if (state.logged && now - state.last_line < options_.interval) {
    state.left_out += static_cast<uint64_t>(extra - extra_before);
    return;
  }
  std::string line = ConflictLine(topic, others);
  if (state.left_out > 0) line += fmt::format(" [{} more left out of the log since the last line]", state.left_out);
  spdlog::error("{}", line);
  state.logged = true;
  state.last_line = now;
  state.left_out = 0;
}

std::string WriterWatch::ConflictLine(dds::Topic topic, const std::vector<dds::RemoteWriter>& others) const {
  const std::string name = participant_.TopicName(topic);
  const int domain = participant_.options().domain;
  if (options_.own_writer)
    return fmt::format(
        "another writer of {} on DDS domain {}: {}. Two simulators on one domain and prefix: every reader gets both "
        "worlds in turn and both obey its commands; this one keeps publishing, stop one of them",
        name, domain, NamedList(others));
  return fmt::format(
      "{} writers of {} on DDS domain {}: {}. Two simulators on one domain and prefix: this bridge gets both worlds "
      "in turn until one of them stops",
      others.size(), name, domain, NamedList(others));
}

namespace {

dds::ParticipantOptions WatchParticipant(const ParticipantOptions& options) {
  // Its own name, so that a peer's log tells it from the bridge's participant.
  return DdsOptions(options, options.name + "/watch");
}

}  // namespace

BridgeWriterWatch::BridgeWriterWatch(const ParticipantOptions& options)
    : participant_(WatchParticipant(options)),
      watch_(participant_, {{dds::Topic::kWorldState, dds::Topic::kSslCamera}, /*own_writer=*/false}) {}

}  // namespace turf
