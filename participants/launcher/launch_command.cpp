#include "participants/launcher/launch_command.h"

#include <spdlog/spdlog.h>

#include <stdlib.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include "participants/common/cli_checks.h"
#include "participants/common/process.h"
#include "participants/launcher/launch_profile.h"
#include "participants/launcher/preflight.h"
#include "participants/launcher/programs.h"
#include "participants/launcher/security_init.h"
#include "participants/launcher/supervisor.h"

namespace turf::launch {
namespace {

int Fail(const std::vector<std::string>& errors) {
  for (const std::string& e : errors) std::fprintf(stderr, "turf launch: %s\n", e.c_str());
  return 2;
}

// A directory of this launch's own for turf-sim's resume file (turf-sim --resume-dir): a turf-sim the supervisor
// restarts after a crash continues the match where its last snapshot was; a new launch starts a new match.
// Removed, with what is in it, when the launch ends. A profile that sets sim's resume-dir keeps its own.
class ResumeDirectory {
 public:
  explicit ResumeDirectory(std::vector<ProcessCommand>* commands) {
    auto sim =
        std::find_if(commands->begin(), commands->end(), [](const ProcessCommand& c) { return c.name == "sim"; });
    if (sim == commands->end() || std::find(sim->argv.begin(), sim->argv.end(), "--resume-dir") != sim->argv.end())
      return;
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp != nullptr && *tmp != '\0' ? tmp : "/tmp") + "/turf-launch-XXXXXX";
    if (mkdtemp(pattern.data()) == nullptr) {
      spdlog::warn("no directory for turf-sim's snapshots ({}): a crashed turf-sim restarts from the scene's start",
                   std::strerror(errno));
      return;
    }
    path_ = pattern;
    sim->argv.insert(sim->argv.end(), {"--resume-dir", path_});
  }
  ~ResumeDirectory() {
    if (path_.empty()) return;
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ResumeDirectory(const ResumeDirectory&) = delete;
  ResumeDirectory& operator=(const ResumeDirectory&) = delete;

 private:
  std::string path_;
};

}  // namespace

LaunchCommand::LaunchCommand(CLI::App& app) : profile_dir_(DefaultProfileDir()) {
  CLI::App* launch = app.add_subcommand(
      "launch",
      "start a profile's processes, restart any that crashes, stop them all on Ctrl-C; or --print their commands");
  launch
      ->add_option("profile", profile_arg_,
                   "profile name (ssl_div_a, ssl_div_b, simspark: configs/launch/<name>.yaml) or file")
      ->required();
  launch->add_flag("--print", print_,
                   "print one shell command line per process and exit (run them on separate hosts by hand)");
  domain_opt_ = launch->add_option("-d,--domain", domain_, "DDS domain of every process (overrides the profile)");
  prefix_opt_ = launch->add_option("-p,--prefix", prefix_, "topic prefix of every process (overrides the profile)");
  realism_opt_ = launch->add_option("--realism", realism_, "turf-sim's sensor realism preset or file");
  launch->add_option("--scene", scene_,
                     "scene file instead of the profile's (of the same kind: SSL or legged, as the profile's bridges "
                     "need), e.g. configs/scenes/rcssservermj_fifa_1v1.yaml");
  server_opt_ = launch->add_option(
      "--discovery-server", discovery_server_,
      "HOST:PORT of a Fast DDS discovery server: every process gets ROS_DISCOVERY_SERVER (no multicast needed)");
  launch->add_flag("--start-discovery-server", overrides_.start_discovery_server,
                   "also run fast-discovery-server on the --discovery-server address (on the host that has it; "
                   "even with --only)");
  std::string program_names;
  for (const Program& p : kPrograms) program_names += (program_names.empty() ? "" : ", ") + std::string(p.name);
  launch->add_option("--only", overrides_.only, "run only these processes (" + program_names + ")")->delimiter(',');
  launch->add_option("--set", overrides_.sets, "PROCESS.FLAG=VALUE: change one process's flag (repeatable)");
  launch->add_option("--bin-dir", overrides_.bin_dir,
                     "where the turf executables are (default: next to turf in the build tree, then PATH)");
  launch
      ->add_option("--security", overrides_.security,
                   "DDS Security: every process runs as DIR/<identity> (sim, the bridges, the viewer as operator); "
                   "a DIR without a CA is made first (`turf security init DIR`, lab profile, this prefix)")
      ->type_name("DIR");
  launch->add_option("--profile-dir", profile_dir_, "where profile names are looked up")->capture_default_str();
  grace_opt_ = launch->add_option("--grace", grace_, "s from SIGTERM to SIGKILL when stopping (overrides the profile)")
                   ->check(FiniteAtLeastZero(/*zero_allowed=*/false))
                   ->check(CLI::Range(0.0, kMaxLaunchSeconds));
  launch->add_option("--log-level", log_level_, "the launcher's own messages: trace, debug, info, warn, error")
      ->capture_default_str();
}

int LaunchCommand::Run() {
  if (domain_opt_->count() > 0) overrides_.domain = domain_;
  if (prefix_opt_->count() > 0) overrides_.prefix = prefix_;
  if (realism_opt_->count() > 0) overrides_.realism = realism_;
  if (server_opt_->count() > 0) overrides_.discovery_server = discovery_server_;

  const ProfileLoadResult loaded = LoadLaunchProfile(profile_arg_, profile_dir_, scene_);
  if (!loaded.profile) return Fail(loaded.errors);
  const LaunchProfile& profile = *loaded.profile;
  const LaunchPlan plan = BuildPlan(profile, overrides_, SelfDir());
  if (!plan.errors.empty()) return Fail(plan.errors);
  if (!print_ && !overrides_.security.empty() && !std::filesystem::exists(overrides_.security + "/ca.pem")) {
    SecurityInitOptions init;
    init.dir = overrides_.security;
    init.prefix = plan.prefix;
    if (const std::vector<std::string> errors = InitSecurity(init); !errors.empty()) return Fail(errors);
    std::printf("turf launch: made a CA and identities in %s (turf security init)\n", init.dir.c_str());
  }

  // Checked before --print too: a printed line is one that would start (it printed `--nosuch 1` and exited 0).
  if (const std::vector<std::string> unknown = UnknownFlags(plan); !unknown.empty()) return Fail(unknown);
  if (!SetupLogging("turf", log_level_)) return 2;
  if (print_) {
    for (const auto& command : plan.commands) std::printf("%s\n", ShellLine(command).c_str());
    return 0;
  }
  spdlog::info("profile {} ({}): {} processes, DDS domain {}, prefix '{}', discovery {}", profile.name, profile.path,
               plan.commands.size(), plan.domain, plan.prefix,
               plan.discovery_server.empty() ? "multicast" : "server " + plan.discovery_server);
  for (const std::string& line : WhereToLook(plan)) spdlog::info("{}", line);
  SupervisorOptions options;
  options.restart = profile.restart;
  const double grace_s = grace_opt_->count() > 0 ? grace_ : profile.stop_grace;
  options.grace = std::chrono::milliseconds(static_cast<int64_t>(grace_s * 1000));
  std::vector<ProcessCommand> commands = plan.commands;
  const ResumeDirectory resume(&commands);
  return Supervise(commands, options);
}

}  // namespace turf::launch
