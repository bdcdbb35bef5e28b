// `turf record ...` and `turf replay ...`: the recorder and the replayer are participants of their own
// (turf-record, turf-replay; participants/recorder, participants/replay); these subcommands run them with the
// arguments as given (--help included), found as `turf launch` finds its programs.
#pragma once

#include <CLI/CLI.hpp>

#include <string>

#include "core/pinned.h"

namespace turf::launch {

class ForwardCommand : Pinned {
 public:
  // Adds subcommand `name` to `app`, which runs `binary` (built in participants/<build_dir>).
  ForwardCommand(CLI::App& app, const std::string& name, const std::string& binary, const std::string& build_dir,
                 const std::string& description);
  bool Chosen() const { return command_->parsed(); }
  // Replaces this process with the program; 2 (printed on stderr) if it cannot be found or run.
  int Run();

 private:
  CLI::App* command_ = nullptr;
  std::string binary_;
  std::string build_dir_;
};

}  // namespace turf::launch
