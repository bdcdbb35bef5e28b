// turf-replay: a recording's outputs back onto a DDS domain; see replay.h.
#include <CLI/CLI.hpp>

#include <string>

#include "participants/common/participant_main.h"
#include "participants/common/process.h"
#include "participants/replay/replay.h"

int main(int argc, char** argv) {
  turf::ParticipantMain participant(
      "turf-replay",
      "turf-replay: plays the outputs of a turf-record MCAP file (world state, clock, cameras, ...) back onto a DDS "
      "domain, for the viewer and team software");
  turf::ReplayOptions options;
  std::string speed = "1";
  CLI::App& app = participant.app();
  app.add_option("file", options.file, "the MCAP file (turf-record's)")->required()->check(CLI::ExistingFile);
  app.add_option("--speed", speed, "a multiple of the recorded pace (e.g. 1, 4, 0.5), or max")
      ->check([](const std::string& s) -> std::string {
        if (s == "max") return "";
        try {
          const double v = std::stod(s);
          return v > 0 && v <= 1e6 ? "" : "--speed: a number in (0, 1e6] or max";
        } catch (...) {
          return "--speed: a number in (0, 1e6] or max";
        }
      })
      ->capture_default_str();
  app.add_option("--start", options.start_s,
                 "begin this many seconds (of recorded time) after the first message; latched topics (the field) "
                 "are still published first")
      ->check(CLI::Range(0.0, 1e9))
      ->capture_default_str();
  app.add_flag("--wait-for-reader", options.wait_for_reader,
               "before the first message, wait (up to 30 s) until a reader of a replayed topic is matched");
  participant.AddCommonFlags(options, {"DDS domain id to replay onto", "topic name prefix to replay under"});
  return participant.Run(argc, argv, [&] {
    options.speed = speed == "max" ? 0.0 : std::stod(speed);
    turf::Replay(options, turf::StopRequested);
    return turf::kExitClean;
  });
}
