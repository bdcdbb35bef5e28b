// turf-record: records turf's topics into an MCAP file.
//
// Reads every topic of the table in dds/topics.h (turf-sim's outputs and its inputs: commands, joint commands,
// control requests and replies), or those named by --topics, each with its QoS profile. Each sample is
// serialized to CDR as on the wire (the generated PubSubType, with its encapsulation header) and written as an
// MCAP message on the topic's channel: log_time is the wall-clock time (Unix ns) the recorder took it from its
// reader, publish_time the sample's simulation time (sim_time_ns, or a camera frame's capture_time_ns; 0 for types
// without one). Channels: topic "<prefix>/<name>", message encoding "cdr", metadata dds_type, qos_profile and
// direction; schema: the DDS type name ("turf::idl::Clock") with the IDL text (encoding "omgidl").
//
// Memory stays bounded: each reader's queue (dds::Reader::kMaxQueued; overflow is counted), one open chunk
// (--chunk-size) and one chunk index per chunk. A chunk is closed at least every --chunk-interval seconds and
// handed to the kernel at once, so kill -9 loses at most that much; SIGINT/SIGTERM close a complete file.
// A progress line every 10 s: samples, MB in the file, simulation time reached, samples dropped.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "codecs/mcap/compression.h"
#include "core/pinned.h"
#include "participants/common/participant_options.h"

namespace turf {

namespace dds {
class Bus;
}  // namespace dds

struct RecorderOptions : ParticipantOptions {
  RecorderOptions() { name = "turf-record"; }
  std::string file;
  std::vector<std::string> topics;  // topic names without prefix ("world_state"); empty: all
  mcap::Compression compression = mcap::Compression::kZstd;
  size_t chunk_size = 1024 * 1024;
  double chunk_interval_s = 1.0;
  double progress_interval_s = 10.0;
};

// Names of the table's topics (without prefix) for --topics; an error sentence for an unknown one, else empty.
std::string CheckTopicNames(const std::vector<std::string>& names);

struct RecorderTotals {
  uint64_t samples = 0;
  uint64_t dropped = 0;  // reader queue overflows and samples that did not serialize
  uint64_t file_bytes = 0;
  int64_t sim_time_ns = 0;  // the newest simulation time seen
};

class Recorder : Pinned {
 public:
  // Opens the file and subscribes; throws std::invalid_argument (exit status 2) if the file cannot be made.
  explicit Recorder(const RecorderOptions& options);
  // On `bus` (a dds::MemoryBus: turf-sim's node in the same process, in tests), which must outlive the recorder.
  Recorder(const RecorderOptions& options, dds::Bus& bus);
  ~Recorder();
  // Records until `stop()`, then closes the file (a valid MCAP file with its summary).
  void Run(const std::function<bool()>& stop);
  RecorderTotals totals() const;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace turf
