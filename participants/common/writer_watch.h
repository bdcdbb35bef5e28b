// Two simulators on one DDS domain and prefix fight silently: readers get both worlds' samples interleaved (a robot
// jumps metres between two vision packets) and both obey every command (issue 20). DDS discovery tells who writes a
// topic (dds::Participant::OtherWriters, with each writer's host, pid and program); these are the checks on it that
// turf-sim and the bridges share:
//  - turf-sim at start-up: FindEarlierWriter, then RefusalLine and exit 2;
//  - turf-sim while running, and every bridge: WriterWatch, an error line (rate-limited) naming the writers whenever
//    a topic has more than one; a bridge runs it on a participant of its own (BridgeWriterWatch), since its main()
//    does not reach the bridge's participant.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "core/pinned.h"
#include "dds/participant.h"
#include "participants/common/participant_options.h"

namespace turf {

// Whether a writer's process is known to have exited: it runs on this host under a pid that no longer exists.
// Fast DDS keeps a crashed participant's writers until its lease expires (5 s with turf's QoS): without this, a
// turf-sim restarted at once after a crash would refuse to start because of its dead predecessor.
bool WriterProcessGone(const dds::RemoteWriter& writer, const dds::PeerInfo& self);

// Other participants' writers of `topic` whose process may still run (WriterProcessGone filtered out).
std::vector<dds::RemoteWriter> LiveOtherWriters(const dds::Participant& participant, dds::Topic topic);

// Whether `other` was on the domain before `self`: made earlier, or at the same nanosecond with the smaller GUID
// prefix. A participant that does not say when it started (not turf) counts as earlier. Two turf-sims started
// together thus agree on which one gives way.
bool StartedEarlier(const dds::PeerInfo& other, const dds::PeerInfo& self);

// turf-sim's start-up check, once its writers exist: waits until discovery shows a live writer of `topic` that
// StartedEarlier than this participant, or `window` passes (the whole window when there is none: discovery has no
// "that was everyone"). The writer, or nullopt.
std::optional<dds::RemoteWriter> FindEarlierWriter(const dds::Participant& participant, dds::Topic topic,
                                                   std::chrono::milliseconds window);

// The line turf-sim refuses to start with, naming the other writer's program, pid and host.
std::string RefusalLine(const dds::Participant& participant, dds::Topic topic, const dds::RemoteWriter& other);

// While it lives, logs an error whenever one of `topics` has more than one writer on the participant's domain and
// prefix, naming each (at most one line per topic every `interval`; lines left out are counted in the next), and an
// info line once the topic is back to one writer. Runs on Fast DDS's discovery thread; thread-safe.
class WriterWatch : Pinned {
 public:
  struct Options {
    std::vector<dds::Topic> topics;
    // The participant writes these topics itself (turf-sim): one other writer is one too many. False for a
    // participant that only watches (a bridge's): two others are.
    bool own_writer = false;
    std::chrono::seconds interval{10};
  };

  WriterWatch(dds::Participant& participant, Options options);
  ~WriterWatch();

  // Writers that appeared while their topic already had one (each counted once).
  uint64_t Conflicts() const;
  // Waits until Conflicts() >= n or `timeout` passes; Conflicts() then.
  uint64_t WaitForConflicts(uint64_t n, std::chrono::milliseconds timeout) const;

 private:
  // Compares the topic's live writers with what it last saw; counts and reports a change. Under mutex_.
  void Evaluate(dds::Topic topic);
  std::string ConflictLine(dds::Topic topic, const std::vector<dds::RemoteWriter>& others) const;

  dds::Participant& participant_;
  const Options options_;
  struct TopicState {
    int writers = 0;  // live writers when last evaluated, this participant's own included
    std::chrono::steady_clock::time_point last_line{};
    bool logged = false;    // an error line was logged since the topic last had one writer
    uint64_t left_out = 0;  // conflicts not logged because of the interval
  };
  mutable std::mutex mutex_;
  mutable std::condition_variable conflicted_;
  std::map<std::string, TopicState> state_;  // by full topic name
  uint64_t conflicts_ = 0;
  uint64_t listener_ = 0;
};

// A bridge's watch over turf-sim's output topics (world_state and ssl/camera): a DDS participant of its own on the
// bridge's domain and prefix (it writes and reads nothing; discovery is all it takes part in), with a WriterWatch
// that reports a second writer of either topic: two simulators feeding the bridge.
class BridgeWriterWatch : Pinned {
 public:
  // Throws std::runtime_error if the participant cannot be created.
  explicit BridgeWriterWatch(const ParticipantOptions& options);
  const WriterWatch& watch() const { return watch_; }
  dds::Participant& participant() { return participant_; }

 private:
  dds::Participant participant_;
  WriterWatch watch_;
};

}  // namespace turf
