// `turf log diff A B`: do two recordings hold the same samples, byte for byte? Topics are matched by name
// without their prefix (the part up to the first '/'), so recordings of two domains or prefixes compare; within a
// topic the samples are compared in order. The report names the earliest difference by simulation time: the topic,
// the sample's index and sim time, and the first differing byte (or which file ends first). A step towards
// re-simulation (issue 17): record a lockstep run twice, or a match and its re-run, and compare.
// Memory: 24 bytes per sample (a hash, the size and the sim time); the differing pair is read again at the end.
#pragma once

#include <cstdint>
#include <set>
#include <string>

#include "codecs/mcap/reader.h"

namespace turf::launch {

struct LogDiff {
  bool same = false;
  std::string report;  // one line per finding; "same: N samples on T topics" when same
  mcap::Damage damage_a, damage_b;
};

struct DiffOptions {
  // Topic names without prefix ("clock": its run epoch and measured speed differ from run to run).
  std::set<std::string> skip;
  // Only samples up to this simulation time (ns) count (the end of a run may be cut by its last moments).
  uint64_t until_ns = UINT64_MAX;
};

LogDiff DiffRecordings(const mcap::ByteSource& a, const mcap::ByteSource& b, const DiffOptions& options);

}  // namespace turf::launch
