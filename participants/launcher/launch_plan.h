// From a profile and the command line's overrides to the exact processes
// `turf launch` runs: argv and environment of each, in start order (discovery
// server, turf-sim, bridges). Pure apart from looking for executables.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "participants/launcher/launch_profile.h"
#include "participants/launcher/programs.h"

namespace turf::launch {

struct LaunchOverrides {
  std::optional<int> domain;
  std::optional<std::string> prefix;
  std::optional<std::string> realism;
  std::optional<std::string> discovery_server;  // HOST:PORT
  bool start_discovery_server = false;          // also with --only: this host runs the server
  std::vector<std::string> sets;                // "PROCESS.FLAG=VALUE" (VALUE true/false: a switch)
  std::vector<std::string> only;                // process names to run here; empty: all
  std::string bin_dir;                          // where the turf executables are; empty: next to `turf`, then PATH
  std::string security;  // DDS Security directory of `turf security init`: each process gets --security DIR/<identity>
};

struct ProcessCommand {
  std::string name;                                      // sim, grsim, ...
  std::vector<std::string> argv;                         // argv[0]: the executable's path
  std::vector<std::pair<std::string, std::string>> env;  // added to the launcher's environment
  bool stop_last = false;                                // stopped after every other process (the discovery server)
};

struct LaunchPlan {
  std::vector<ProcessCommand> commands;
  std::vector<std::string> errors;
  int domain = 0;
  std::string prefix;
  std::string discovery_server;  // empty: multicast discovery
};

// Applies the overrides to `profile` (errors name the option) and builds the
// commands. `self_dir` is the directory of the running `turf` executable.
LaunchPlan BuildPlan(LaunchProfile profile, const LaunchOverrides& overrides, const std::string& self_dir);

// Where a user looks and points team software, one line each, from the plan's own flags: the viewer's URL,
// the grSim, SSL-Vision and simulation-protocol ports, the SimSpark agent and monitor ports. The launcher
// prints them first.
std::vector<std::string> WhereToLook(const LaunchPlan& plan);

// The command as one POSIX shell line: VAR=value ... argv, quoted where needed.
std::string ShellLine(const ProcessCommand& command);

// The directory of the running executable.
std::string SelfDir();

// Where `program` is: in `bin_dir` (if given), next to `turf` (`self_dir`) and its sibling build directories,
// then on PATH. Empty if not found.
std::string FindBinary(const Program& program, const std::string& bin_dir, const std::string& self_dir);

}  // namespace turf::launch
