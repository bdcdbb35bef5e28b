// `turf launch <profile>`: its flags on the launcher's command line and what
// it does once they are parsed (load the profile, plan, then print the
// commands or supervise the processes). main.cpp only parses.
#pragma once

#include <CLI/CLI.hpp>

#include <string>

#include "core/pinned.h"
#include "participants/launcher/launch_plan.h"

namespace turf::launch {

class LaunchCommand : Pinned {
 public:
  // Adds the `launch` subcommand and its flags to `app`, which must outlive
  // this object and be parsed before Run.
  explicit LaunchCommand(CLI::App& app);

  // The launcher's exit status: 2 for a profile or plan error (printed on
  // stderr), 0 after --print, else Supervise's (supervisor.h).
  int Run();

 private:
  std::string profile_arg_;
  std::string profile_dir_;
  bool print_ = false;
  int domain_ = 0;
  std::string prefix_, realism_, scene_, discovery_server_, log_level_ = "info";
  double grace_ = 0;
  LaunchOverrides overrides_;
  // Flags that override the profile only when given.
  CLI::Option* domain_opt_ = nullptr;
  CLI::Option* prefix_opt_ = nullptr;
  CLI::Option* realism_opt_ = nullptr;
  CLI::Option* server_opt_ = nullptr;
  CLI::Option* grace_opt_ = nullptr;
};

}  // namespace turf::launch
