// turf replay --resimulate FILE: re-runs a recorded match from its recorded inputs alone and checks that every
// recorded output comes out again byte for byte.
//
// What the file must hold (turf-record records both from turf-sim, dds/topics.h):
//   sim/run             the scene file's text and directory, the realism flag and the seed (latched);
//   sim/applied_inputs  every poll of turf-sim's inputs that took any: the samples (CDR) in the order applied and
//                       the step count at which they were applied (participants/sim/applied_inputs.h).
// The re-simulation builds the scene from sim/run, runs turf-sim's node (the same SimNode as turf-sim) in this
// process on a dds::MemoryBus, free-running, and has its control loop apply each recorded AppliedInputs record at
// its step (ControlLoop::TakeScheduled: the same HandleControl and node command path as in the original run), until
// the records are used up and the simulation time passed the last recorded output by a second (or the world cannot
// step any more: a lockstep or paused run). Nothing comes from the input topics' own channels: those show what was
// sent, the applied-inputs record what turf-sim took and when.
//
// Comparison: each output the node publishes is serialized as turf-record does and matched against the recorded
// messages of its topic at the same simulation time (MCAP publish_time); a recorded message is reproduced when a
// re-simulated one of that topic and time has exactly its bytes. Skipped: the clock (it carries the run's wall-clock
// epoch, measured speed and the time mode turf-sim was started in) and sim/run; topics in `skip` too. Re-simulated
// samples the recording lacks (the recorder's reader dropped one, or it stopped earlier) are counted, not failed.
// The first recorded message (by simulation time, then file order) not reproduced is the first difference: topic,
// its index among that topic's messages, simulation time, sizes and the first differing byte offset against the
// closest re-simulated sample of that topic and time.
//
// Refused (std::invalid_argument, exit status 2): no MCAP file, no sim/run (or an empty scene text), a run that
// resumed from a snapshot, a gap in the applied-inputs sequence (the recording lost one), a scene that does not load.
// A damaged file is re-simulated up to the damage (logged). Memory: the recording's outputs are held in memory.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace turf {

struct ResimulateOptions {
  std::string file;
  std::vector<std::string> skip = {"clock"};  // topic names without prefix, not compared
};

struct ResimulateResult {
  bool identical = false;
  std::string verdict;         // one line: what was reproduced, or the first difference
  uint64_t recorded = 0;       // recorded outputs compared
  uint64_t reproduced = 0;     // of them, re-simulated byte for byte
  uint64_t unrecorded = 0;     // re-simulated outputs the recording lacks
  uint64_t input_records = 0;  // AppliedInputs records applied
  int64_t sim_time_ns = 0;     // where the re-simulation stopped
  // The first difference (identical: empty topic).
  std::string topic;
  uint64_t index = 0;  // among the recorded messages of `topic`, from 0
  int64_t diff_sim_time_ns = 0;
};

ResimulateResult Resimulate(const ResimulateOptions& options, const std::function<bool()>& stop);

}  // namespace turf
