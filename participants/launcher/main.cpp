// turf: the launcher. `turf launch <profile>` starts a league profile's
// processes (configs/launch/*.yaml; schema in launch_profile.h), supervises
// them (supervisor.h) and stops them all on Ctrl-C; `--print` shows the
// command of each instead, to run them on separate hosts by hand.
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include <cstdio>
#include <string>
#include <vector>

#include "participants/common/process.h"
#include "participants/launcher/launch_plan.h"
#include "participants/launcher/launch_profile.h"
#include "participants/launcher/programs.h"
#include "participants/launcher/supervisor.h"

namespace {

int Fail(const std::vector<std::string>& errors) {
  for (const std::string& e : errors) std::fprintf(stderr, "turf launch: %s\n", e.c_str());
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"turf: runs a match's processes (turf-sim and its bridges) from a league profile"};
  app.require_subcommand(1);
  CLI::App* launch = app.add_subcommand(
      "launch",
      "start a profile's processes, restart any that crashes, stop them all on Ctrl-C; or --print their commands");
  std::string profile_arg;
  std::string profile_dir = turf::launch::DefaultProfileDir();
  bool print = false;
  int domain = 0;
  std::string prefix, realism, discovery_server, log_level = "info";
  double grace = 0;
  turf::launch::LaunchOverrides overrides;
  launch
      ->add_option("profile", profile_arg,
                   "profile name (ssl_div_a, ssl_div_b, simspark: configs/launch/<name>.yaml) or file")
      ->required();
  launch->add_flag("--print", print,
                   "print one shell command line per process and exit (run them on separate hosts by hand)");
  auto* domain_opt = launch->add_option("-d,--domain", domain, "DDS domain of every process (overrides the profile)");
  auto* prefix_opt = launch->add_option("-p,--prefix", prefix, "topic prefix of every process (overrides the profile)");
  auto* realism_opt = launch->add_option("--realism", realism, "turf-sim's sensor realism preset or file");
  auto* server_opt = launch->add_option(
      "--discovery-server", discovery_server,
      "HOST:PORT of a Fast DDS discovery server: every process gets ROS_DISCOVERY_SERVER (no multicast needed)");
  launch->add_flag("--start-discovery-server", overrides.start_discovery_server,
                   "also run fast-discovery-server on the --discovery-server address (on the host that has it; "
                   "even with --only)");
  std::string program_names;
  for (const turf::launch::Program& p : turf::launch::kPrograms)
    program_names += (program_names.empty() ? "" : ", ") + std::string(p.name);
  launch->add_option("--only", overrides.only, "run only these processes (" + program_names + ")")->delimiter(',');
  launch->add_option("--set", overrides.sets, "PROCESS.FLAG=VALUE: change one process's flag (repeatable)");
  launch->add_option("--bin-dir", overrides.bin_dir,
                     "where the turf executables are (default: next to turf in the build tree, then PATH)");
  launch->add_option("--profile-dir", profile_dir, "where profile names are looked up")->capture_default_str();
  auto* grace_opt =
      launch->add_option("--grace", grace, "s from SIGTERM to SIGKILL when stopping (overrides the profile)")
          ->check(CLI::PositiveNumber);
  launch->add_option("--log-level", log_level, "the launcher's own messages: trace, debug, info, warn, error")
      ->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  if (domain_opt->count() > 0) overrides.domain = domain;
  if (prefix_opt->count() > 0) overrides.prefix = prefix;
  if (realism_opt->count() > 0) overrides.realism = realism;
  if (server_opt->count() > 0) overrides.discovery_server = discovery_server;

  const turf::launch::ProfileLoadResult loaded = turf::launch::LoadLaunchProfile(profile_arg, profile_dir);
  if (!loaded.profile) return Fail(loaded.errors);
  const turf::launch::LaunchProfile& profile = *loaded.profile;
  const turf::launch::LaunchPlan plan = turf::launch::BuildPlan(profile, overrides, turf::launch::SelfDir());
  if (!plan.errors.empty()) return Fail(plan.errors);

  if (print) {
    for (const auto& command : plan.commands) std::printf("%s\n", turf::launch::ShellLine(command).c_str());
    return 0;
  }
  if (!turf::SetupLogging("turf", log_level)) return 2;
  spdlog::info("profile {} ({}): {} processes, DDS domain {}, prefix '{}', discovery {}", profile.name, profile.path,
               plan.commands.size(), plan.domain, plan.prefix,
               plan.discovery_server.empty() ? "multicast" : "server " + plan.discovery_server);
  turf::launch::SupervisorOptions options;
  options.restart = profile.restart;
  const double grace_s = grace_opt->count() > 0 ? grace : profile.stop_grace;
  options.grace = std::chrono::milliseconds(static_cast<int64_t>(grace_s * 1000));
  return turf::launch::Supervise(plan.commands, options);
}
