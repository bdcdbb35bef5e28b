// Options and statistics shared by turf-sim's nodes (SSL and legged scenes).
#pragma once

#include <cstdint>
#include <string>

#include "participants/common/participant_options.h"
#include "participants/sim/pacer.h"

namespace turf {

struct SimNodeOptions : ParticipantOptions {
  SimNodeOptions() { name = "turf-sim"; }
  TimeMode mode = TimeMode::kRealtime;
  double speed = 1.0;  // for kScaled
  bool start_paused = false;
  double duration = 0.0;  // s of simulation time, then Run returns; 0 = until stopped
  // Resume after a crash (participants/sim/resume_file.h): a snapshot every `snapshot_every` s of simulation time
  // into this directory, and a start continues from the one there. Empty: neither.
  std::string resume_dir;
  double snapshot_every = 1.0;
};

struct SimNodeStats {
  uint64_t frame = 0;
  int64_t sim_time_ns = 0;
  uint64_t rejected = 0;  // refused samples of every kind
  double real_time_factor = 0.0;
};

}  // namespace turf
