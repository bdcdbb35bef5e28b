// The skeleton of every turf participant's main(): the flags all of them share
// (-d/--domain, -p/--prefix, --qos, --security, --log-level; --help), log setup, stop
// signals, one exception boundary and the exit codes. A main declares its own
// flags on app(), puts the common ones where its --help shows them, and hands
// its body to Run():
//
//   turf::ParticipantMain participant("turf-viewer: a live web view ...");
//   turf::ViewerOptions options;
//   participant.app().add_option("--port", options.port, "...");
//   participant.AddCommonFlags(options);
//   return participant.Run(argc, argv, [&] {
//     turf::ViewerNode(options).Run(turf::StopRequested);
//     return turf::kExitClean;
//   });
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <functional>
#include <string>

#include "participants/common/participant_options.h"

namespace turf {

// Exit status of every turf participant (and what the launcher sees).
enum ExitCode : int {
  kExitClean = 0,      // stopped on request (SIGINT, SIGTERM, --duration reached, a trainer's killsim), or --help
  kExitFailure = 1,    // runtime failure: DDS, a socket that cannot be bound, any exception but the one below
  kExitBadConfig = 2,  // bad arguments or configuration: a flag CLI11 refuses (e.g. --domain 300), an unknown
                       // log level, a scene or realism file that does not load, std::invalid_argument from the body
};

// Help text of --domain and --prefix. The defaults suit a bridge, which joins
// turf-sim's domain and prefix; turf-sim says what its own are for.
struct CommonFlagHelp {
  std::string domain = "DDS domain id of turf-sim";
  std::string prefix = "topic name prefix of turf-sim";
};

class ParticipantMain {
 public:
  // `process_name` tags every log line; `description` heads --help.
  ParticipantMain(std::string process_name, const std::string& description);
  // The same, the process name being the description's first word: "turf-viewer: a live web view ...".
  explicit ParticipantMain(const std::string& description);

  // The participant's own flags go here, in the order --help lists them.
  CLI::App& app() { return app_; }

  // Adds -d/--domain (checked: 0..232), -p/--prefix, --qos, --security and --authentication-timeout, parsed into
  // `options` (which must outlive Run), at this point of --help.
  void AddCommonFlags(ParticipantOptions& options, const CommonFlagHelp& help = {});

  // A port flag: 0..65535 (1..65535 unless `zero_allowed`), refused with the range it must be in
  // ("--port: Value 99999 not in range [1 - 65535]") rather than a bare conversion error. `port` must outlive Run.
  CLI::Option* AddPort(const std::string& name, uint16_t& port, const std::string& help, bool zero_allowed = false);

  // Adds --log-level (the last flag of --help) and parses argv: --help prints
  // and returns kExitClean, a refused flag prints why and returns
  // kExitBadConfig, both without running `body`. Then sets up logging, installs
  // the stop signals (StopRequested(), process.h) and runs `body`, whose result
  // is the exit code; an escaping std::invalid_argument is logged as an error
  // and gives kExitBadConfig, any other exception is logged as critical and
  // gives kExitFailure. Logs "stopped cleanly" when the result is kExitClean.
  // If the body asked for a restart (RequestRestart, process.h) and returned
  // kExitClean, runs the same program again in this process (execv, same pid
  // and arguments) instead of returning. Call it once.
  int Run(int argc, const char* const* argv, const std::function<int()>& body);

 private:
  int Restart(const char* const* argv);

  std::string process_name_;
  std::string log_level_ = "info";
  CLI::App app_;
};

}  // namespace turf
