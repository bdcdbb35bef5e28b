// Options and statistics shared by turf-sim's nodes (SSL and legged scenes).
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "participants/common/participant_options.h"
#include "participants/sim/pacer.h"

namespace turf {

class InputSchedule;

// The match as turf-sim loaded it, published latched on sim/run so a recording can be re-simulated from the file
// alone (participants/replay/resimulate.h). Filled by turf-sim's start-up; empty in a node made without a file.
struct SceneSource {
  std::string kind;     // "ssl" or "legged"
  std::string name;     // the scene's name
  std::string path;     // the scene file as given
  std::string dir;      // its absolute directory: relative paths in it (robot models) resolve against it
  std::string yaml;     // the file's text
  std::string realism;  // --realism as given (a preset or a file); empty: the scene's own
  uint64_t seed = 0;
};

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
  SceneSource scene_source;
  // Re-simulation (turf replay --resimulate): the node takes its inputs from this recorded schedule at the steps it
  // names instead of from its readers, never paces, and Run returns when the world cannot step any more.
  std::shared_ptr<InputSchedule> resimulate;
};

struct SimNodeStats {
  uint64_t frame = 0;
  int64_t sim_time_ns = 0;
  uint64_t rejected = 0;  // refused samples of every kind
  double real_time_factor = 0.0;
};

}  // namespace turf
