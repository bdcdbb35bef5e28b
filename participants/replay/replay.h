// turf-replay: plays a recording's outputs (turf-record's MCAP file) back onto a DDS domain, so the viewer and
// team software see the match again.
//
// Publishes the messages of the channels whose topic is one of the table's published topics (world_state, clock,
// cameras, feedback, stats, the legged streams; dds/topics.h) and whose schema names the table's DDS type, under
// this participant's --prefix (the recording's own prefix is dropped): each message's CDR is deserialized with the
// generated PubSubType and written with the topic's QoS profile. Inputs (commands, control) are never published.
// Paced by the recorded receive times at --speed (1: real time; N; max). A message whose CDR does not
// deserialize is refused and counted; a damaged file is played up to the damage, which is logged.
// --start S begins S seconds (of recorded receive time) after the first message: earlier messages are skipped,
// except those of latched topics (the field), which are published at once so a viewer has them.
// --end S stops S seconds (of recorded receive time) after the first message.
// Control while playing (replay_control.h: turf-sim's control topics, so the viewer's pause button works here):
// - pause and resume (also a toggle of `paused()`; turf-replay: SIGUSR1): while paused nothing is published and the
//   pacing clock stands still; playing resumes where it stopped;
// - speed (OP_SET_TIME_MODE): from the last published message on;
// - seek (OP_SEEK, simulation time): playing goes on from the first output whose simulation time is at or after the
//   target (latched topics are always published). Forward, the file is read on without publishing; back, it is
//   read again from its start (a seek back in a long recording takes the time of reading up to the target). The
//   reply comes when the target is reached, or is refused (CONTROL_OUT_OF_RANGE) if the file ends first.
// - the same from the standard input with `stdin_commands` (replay_keys.h: pause, resume, seek S, speed X).
// The recorded control replies are not replayed: they answered the recorded match's clients.
// Re-simulation (--resimulate) is resimulate.h.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "participants/common/participant_options.h"

namespace turf {

struct ReplayOptions : ParticipantOptions {
  ReplayOptions() { name = "turf-replay"; }
  std::string file;
  double speed = 1.0;            // 0: as fast as possible
  double start_s = 0;            // skip this much recorded time from the first message
  double end_s = 0;              // stop this much recorded time after the first message; 0: at the end of the file
  std::function<bool()> paused;  // while it answers true, playing waits (null: never)
  // Before the first message: wait (up to 30 s) until a reader of some replayed topic is matched.
  bool wait_for_reader = false;
  bool stdin_commands = false;  // read terminal commands (replay_keys.h) from the standard input
  double progress_interval_s = 10.0;
};

struct ReplayTotals {
  uint64_t published = 0;
  uint64_t skipped = 0;       // inputs and channels of no known topic
  uint64_t refused = 0;       // CDR that did not deserialize
  uint64_t before_start = 0;  // skipped by --start
  uint64_t seeks = 0;         // OP_SEEK requests carried out
  bool reached_end = false;   // stopped by --end
};

// Plays the file until its end or `stop()`; throws std::invalid_argument (exit status 2) if it cannot be opened or
// is no MCAP file this build reads.
ReplayTotals Replay(const ReplayOptions& options, const std::function<bool()>& stop);

}  // namespace turf
