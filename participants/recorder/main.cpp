// turf-record: every turf topic of a match (or --topics) into an MCAP file; see recorder.h.
#include <CLI/CLI.hpp>

#include <stdexcept>
#include <string>

#include "participants/common/participant_main.h"
#include "participants/common/process.h"
#include "participants/recorder/recorder.h"

int main(int argc, char** argv) {
  turf::ParticipantMain participant(
      "turf-record: records a match's DDS topics (turf-sim's outputs and every input) into an MCAP file that "
      "Foxglove and `turf log info` open");
  turf::RecorderOptions options;
  std::string compression = "zstd";
  CLI::App& app = participant.app();
  app.add_option("file", options.file, "the MCAP file to write (replaced if it exists)")->required();
  app.add_option("--topics", options.topics,
                 "record only these topics (names without prefix, e.g. world_state,clock); default: all")
      ->delimiter(',');
  app.add_option("--compression", compression, "chunk compression: zstd, lz4 or none")
      ->check(CLI::IsMember({"zstd", "lz4", "none"}))
      ->capture_default_str();
  app.add_option("--chunk-size", options.chunk_size, "bytes (uncompressed) at which a chunk is closed")
      ->check(CLI::Range(size_t{4096}, size_t{256} << 20))
      ->capture_default_str();
  app.add_option("--chunk-interval", options.chunk_interval_s,
                 "seconds after which a chunk is closed and written even if not full: what a crash can lose")
      ->check(CLI::Range(0.01, 3600.0))
      ->capture_default_str();
  participant.AddCommonFlags(options);
  return participant.Run(argc, argv, [&] {
    if (const std::string e = turf::CheckTopicNames(options.topics); !e.empty()) throw std::invalid_argument(e);
    options.compression = *turf::mcap::CompressionFromWord(compression);
    turf::Recorder recorder(options);
    recorder.Run(turf::StopRequested);
    return turf::kExitClean;
  });
}
