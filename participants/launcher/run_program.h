// Runs a program to its end and keeps what it printed: the launcher's preflight (`<program> --help`) and
// `turf security init` (openssl). No shell: arguments are passed as they are.
#pragma once

#include <string>
#include <vector>

namespace turf::launch {

struct ProgramResult {
  int exit_status = -1;  // the program's exit status; -1 if it could not be run or was killed by a signal
  std::string output;    // stdout and stderr, interleaved
};

ProgramResult RunProgram(const std::vector<std::string>& argv);

}  // namespace turf::launch
