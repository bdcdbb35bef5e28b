#include "participants/launcher/launch_plan.h"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <sstream>
#include <system_error>

#include "dds/topic_prefix.h"
#include "loader/realism_yaml.h"
#include "participants/launcher/programs.h"

namespace turf::launch {

namespace fs = std::filesystem;

namespace {

bool Executable(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec) && access(p.c_str(), X_OK) == 0;
}

}  // namespace

std::string FindBinary(const Program& program, const std::string& bin_dir, const std::string& self_dir) {
  std::vector<fs::path> candidates;
  const std::string binary(program.binary);
  const std::string build_dir(program.build_dir);
  for (const std::string& dir : {bin_dir, self_dir}) {
    if (dir.empty()) continue;
    candidates.push_back(fs::path(dir) / binary);
    if (!build_dir.empty()) {
      candidates.push_back(fs::path(dir) / build_dir / binary);
      candidates.push_back(fs::path(dir) / ".." / build_dir / binary);
    }
    if (dir == bin_dir) break;  // an explicit --bin-dir is not second-guessed, except for system tools
  }
  for (const fs::path& c : candidates) {
    if (Executable(c)) return c.lexically_normal().string();
  }
  if (!bin_dir.empty() && !build_dir.empty()) return "";
  std::stringstream path(std::getenv("PATH") != nullptr ? std::getenv("PATH") : "/usr/bin:/bin");
  for (std::string dir; std::getline(path, dir, ':');) {
    if (!dir.empty() && Executable(fs::path(dir) / binary)) return (fs::path(dir) / binary).string();
  }
  return "";
}

namespace {

void SetFlag(std::vector<Flag>* flags, Flag flag) {
  auto it = std::find_if(flags->begin(), flags->end(), [&flag](const Flag& f) { return f.name == flag.name; });
  if (it != flags->end()) flags->erase(it);
  if (!(flag.bare && flag.value == "false")) flags->push_back(std::move(flag));
}

// --set PROCESS.FLAG=VALUE
void ApplySet(const std::string& set, LaunchProfile* profile, std::vector<std::string>* errors) {
  const size_t dot = set.find('.');
  const size_t eq = set.find('=');
  if (dot == std::string::npos || eq == std::string::npos || dot > eq) {
    errors->push_back(fmt::format("--set {}: expected PROCESS.FLAG=VALUE (e.g. vision.port=10006)", set));
    return;
  }
  const std::string process = set.substr(0, dot);
  const std::string name = set.substr(dot + 1, eq - dot - 1);
  const std::string value = set.substr(eq + 1);
  ProcessSpec* spec = process == "sim" ? &profile->sim : nullptr;
  for (ProcessSpec& b : profile->bridges) {
    if (b.name == process) spec = &b;
  }
  if (spec == nullptr) {
    errors->push_back(fmt::format("--set {}: the profile runs no process named '{}'", set, process));
    return;
  }
  if (!ValidFlagName(name) || name == "domain" || name == "prefix" || name == "qos" ||
      ((process == "sim" || process == "render") && name == "scene") || (process == "sim" && name == "realism")) {
    errors->push_back(
        fmt::format("--set {}: '{}' is not a flag --set may change (use --domain, --prefix, --realism)", set, name));
    return;
  }
  const bool is_switch = value == "true" || value == "false";
  SetFlag(&spec->flags, Flag{name, value, is_switch});
}

void AddFlags(const std::vector<Flag>& flags, std::vector<std::string>* argv) {
  for (const Flag& f : flags) {
    argv->push_back("--" + f.name);
    if (!f.bare) argv->push_back(f.value);
  }
}

void ApplyOverrides(const LaunchOverrides& o, LaunchProfile* profile, std::vector<std::string>* errors) {
  if (o.domain) {
    if (*o.domain < 0 || *o.domain > 232) errors->push_back("--domain: must be 0..232");
    profile->domain = *o.domain;
  }
  if (o.prefix) {
    if (!dds::ValidTopicPrefix(*o.prefix)) errors->push_back(std::string("--prefix: ") + dds::kTopicPrefixRule);
    profile->prefix = *o.prefix;
  }
  if (o.realism) {
    const RealismLoadResult r = LoadRealism(*o.realism);
    if (!r.realism) {
      errors->push_back(fmt::format("--realism {}: {}", *o.realism, fmt::join(r.errors, "; ")));
    }
    profile->realism = *o.realism;
  }
  if (o.discovery_server) {
    std::string host;
    int port = 0;
    if (!ParseHostPort(*o.discovery_server, &host, &port))
      errors->push_back(fmt::format("--discovery-server {}: expected HOST:PORT", *o.discovery_server));
    profile->discovery.server = *o.discovery_server;
  }
  if (o.start_discovery_server) {
    if (profile->discovery.server.empty()) errors->push_back("--start-discovery-server needs --discovery-server");
    profile->discovery.start = true;
  }
  if (!o.security.empty() && !profile->discovery.server.empty())
    errors->push_back(
        "--security with a discovery server: the server would be an unauthenticated participant; use multicast "
        "discovery (the default) or initial peers in a --qos file");
  for (const std::string& set : o.sets) ApplySet(set, profile, errors);
}

// The processes of the profile, in start order.
std::vector<ProcessSpec> Specs(const LaunchProfile& profile) {
  std::vector<ProcessSpec> specs;
  if (profile.discovery.start) {
    std::string host;
    int port = 0;
    ParseHostPort(profile.discovery.server, &host, &port);
    specs.push_back({"discovery", {{"i", "0", false}, {"l", host, false}, {"p", std::to_string(port), false}}});
  }
  specs.push_back(profile.sim);
  specs.insert(specs.end(), profile.bridges.begin(), profile.bridges.end());
  return specs;
}

ProcessCommand MakeCommand(const ProcessSpec& spec, const LaunchProfile& profile, const std::string& binary,
                           const std::string& security) {
  ProcessCommand command{spec.name, {binary}, {}};
  if (spec.name == "discovery") {
    // Stopped last, so the others' goodbyes still reach their peers through it.
    command.stop_last = true;
    for (const Flag& f : spec.flags) command.argv.insert(command.argv.end(), {"-" + f.name, f.value});
    return command;
  }
  if (spec.name == "render") command.argv.insert(command.argv.end(), {"--scene", profile.scene});
  if (spec.name == "sim") {
    command.argv.insert(command.argv.end(), {"--scene", profile.scene});
    if (!profile.realism.empty()) command.argv.insert(command.argv.end(), {"--realism", profile.realism});
  }
  command.argv.insert(command.argv.end(), {"--domain", std::to_string(profile.domain), "--prefix", profile.prefix});
  if (!profile.qos.empty()) command.argv.insert(command.argv.end(), {"--qos", profile.qos});
  if (!security.empty())
    command.argv.insert(command.argv.end(),
                        {"--security", security + "/" + std::string(FindProgram(spec.name)->identity)});
  AddFlags(spec.flags, &command.argv);
  if (!profile.discovery.server.empty()) command.env.emplace_back("ROS_DISCOVERY_SERVER", profile.discovery.server);
  return command;
}

}  // namespace

LaunchPlan BuildPlan(LaunchProfile profile, const LaunchOverrides& o, const std::string& self_dir) {
  LaunchPlan plan;
  ApplyOverrides(o, &profile, &plan.errors);
  const std::vector<ProcessSpec> specs = Specs(profile);
  std::set<std::string> only(o.only.begin(), o.only.end());
  // Asked for on this command line: runs here, whatever --only says.
  if (o.start_discovery_server && !only.empty()) only.insert("discovery");
  for (const std::string& name : only) {
    if (std::none_of(specs.begin(), specs.end(), [&name](const ProcessSpec& s) { return s.name == name; })) {
      std::vector<std::string> names;
      for (const ProcessSpec& s : specs) names.push_back(s.name);
      plan.errors.push_back(
          fmt::format("--only {}: the profile runs no such process ({})", name, fmt::join(names, ", ")));
    }
  }
  for (const ProcessSpec& spec : specs) {
    if (!only.empty() && only.count(spec.name) == 0) continue;
    const Program* program = FindProgram(spec.name);
    std::string binary = FindBinary(*program, o.bin_dir, self_dir);
    if (binary.empty()) {
      plan.errors.push_back(fmt::format(
          "{}: cannot find {} ({})", spec.name, program->binary,
          program->build_dir.empty() ? "install it; Debian: fastdds-tools" : "build turf, or give --bin-dir"));
      binary = program->binary;
    }
    plan.commands.push_back(MakeCommand(spec, profile, binary, o.security));
  }
  plan.domain = profile.domain;
  plan.prefix = profile.prefix;
  plan.discovery_server = profile.discovery.server;
  return plan;
}

namespace {

// The value that follows `flag` in `argv`; `fallback` if the flag is not there.
std::string FlagValue(const std::vector<std::string>& argv, const std::string& flag, const std::string& fallback) {
  for (size_t i = 1; i + 1 < argv.size(); ++i)
    if (argv[i] == flag && argv[i + 1].rfind("--", 0) != 0) return argv[i + 1];
  return fallback;
}

bool HasFlag(const std::vector<std::string>& argv, const std::string& flag) {
  return std::find(argv.begin(), argv.end(), flag) != argv.end();
}

// The ports of a front-end whose flags carry `p` (empty in its own bridge, "simproto-" ... in turf-sim), bound to
// `listen`; `where` names the process when it is not the front-end's own bridge.
std::string SimprotoLine(const ProcessCommand& c, const std::string& p, const std::string& listen,
                         const std::string& where) {
  auto v = [&](const char* flag, const char* fallback) { return FlagValue(c.argv, "--" + p + flag, fallback); };
  const std::string sync = HasFlag(c.argv, "--" + p + "sync")
                               ? fmt::format("sync {}:{}", v("sync-listen", "127.0.0.1"), v("sync-port", "10303"))
                               : std::string("sync off");
  return fmt::format("SSL simulation protocol{}: UDP {}: control {}, blue {}, yellow {}; {}", where, listen,
                     v("control-port", "10300"), v("blue-port", "10301"), v("yellow-port", "10302"), sync);
}

std::string SimSparkLine(const ProcessCommand& c, const std::string& p, const std::string& listen,
                         const std::string& where) {
  auto v = [&](const char* flag, const char* fallback) { return FlagValue(c.argv, "--" + p + flag, fallback); };
  return fmt::format("SimSpark{}: TCP {}: agents {}, monitors and trainers {}", where, listen, v("agent-port", "3100"),
                     v("monitor-port", "3200"));
}

// What turf-sim serves itself: --simproto, --simspark, --rcssservermj, --booster-sdk.
void InSimLines(const ProcessCommand& c, std::vector<std::string>* lines) {
  auto v = [&c](const std::string& flag, const char* fallback) { return FlagValue(c.argv, flag, fallback); };
  const std::string here = " (in turf-sim)";
  if (HasFlag(c.argv, "--simproto")) lines->push_back(SimprotoLine(c, "simproto-", v("--simproto", "127.0.0.1"), here));
  if (HasFlag(c.argv, "--simspark")) lines->push_back(SimSparkLine(c, "simspark-", v("--simspark", "127.0.0.1"), here));
  if (HasFlag(c.argv, "--rcssservermj"))
    lines->push_back(fmt::format("RCSSServerMJ{}: TCP {}: agents {}, monitor commands {}", here,
                                 v("--rcssservermj", "127.0.0.1"), v("--rcssservermj-agent-port", "60000"),
                                 v("--rcssservermj-monitor-port", "60001")));
  if (HasFlag(c.argv, "--booster-sdk"))
    lines->push_back(
        fmt::format("Booster SDK{}: the first robot's topics on DDS domain {}, the next robot's on the "
                    "next domain",
                    here, v("--booster-sdk", "0")));
}

}  // namespace

std::vector<std::string> WhereToLook(const LaunchPlan& plan) {
  std::vector<std::string> lines;
  for (const ProcessCommand& c : plan.commands) {
    auto v = [&c](const char* flag, const char* fallback) { return FlagValue(c.argv, flag, fallback); };
    if (c.name == "viewer") {
      const std::string host = v("--listen", "127.0.0.1");
      lines.push_back(
          fmt::format("viewer: http://{}:{}/", host == "0.0.0.0" ? "127.0.0.1" : host, v("--port", "8080")));
    } else if (c.name == "grsim") {
      lines.push_back(
          fmt::format("grSim commands and replacement: UDP {}:{} (robot status back to the sender on {}, {})",
                      v("--listen", "0.0.0.0"), v("--port", "20011"), v("--blue-status-port", "30011"),
                      v("--yellow-status-port", "30012")));
    } else if (c.name == "vision") {
      lines.push_back(fmt::format("SSL-Vision: UDP {}:{}", v("--address", "224.5.23.2"), v("--port", "10020")));
    } else if (c.name == "simproto") {
      lines.push_back(SimprotoLine(c, "", v("--listen", "0.0.0.0"), ""));
    } else if (c.name == "sim") {
      InSimLines(c, &lines);
    } else if (c.name == "hlvs") {
      lines.push_back(fmt::format("HLVS robot API: TCP {}: red players {}, blue players {}", v("--listen", "0.0.0.0"),
                                  v("--red-ports", "10001-10004"), v("--blue-ports", "10021-10024")));
    } else if (c.name == "simspark") {
      lines.push_back(SimSparkLine(c, "", v("--listen", "0.0.0.0"), ""));
    }
  }
  return lines;
}

std::string ShellLine(const ProcessCommand& command) {
  auto quote = [](const std::string& s) {
    const bool plain = !s.empty() && s.find_first_not_of(
                                         "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                         "0123456789_-./:=,@%+") == std::string::npos;
    if (plain) return s;
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
  };
  std::vector<std::string> words;
  for (const auto& [name, value] : command.env) words.push_back(name + "=" + quote(value));
  for (const std::string& a : command.argv) words.push_back(quote(a));
  return fmt::format("{}", fmt::join(words, " "));
}

std::string SelfDir() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  return ec ? std::string() : self.parent_path().string();
}

}  // namespace turf::launch
