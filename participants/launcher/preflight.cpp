#include "participants/launcher/preflight.h"

#include <fmt/format.h>

#include <regex>
#include <set>

#include "participants/launcher/programs.h"
#include "participants/launcher/run_program.h"

namespace turf::launch {

namespace {

// What `argv... --help` prints (stdout and stderr), or "" if it cannot be run.
std::string HelpText(std::vector<std::string> argv) {
  argv.push_back("--help");
  return RunProgram(argv).output;
}

}  // namespace

std::set<std::string> LongFlags(const std::string& text) {
  static const std::regex kFlag("--[a-z0-9][a-z0-9-]*[a-z0-9]");
  std::set<std::string> flags;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), kFlag); it != std::sregex_iterator(); ++it)
    flags.insert(it->str());
  return flags;
}

std::optional<std::set<std::string>> HelpFlags(const std::vector<std::string>& argv) {
  const std::string help = HelpText(argv);
  if (help.find("--help") == std::string::npos) return std::nullopt;
  return LongFlags(help);
}

std::vector<std::string> UnknownFlags(const LaunchPlan& plan) {
  std::vector<std::string> errors;
  for (const ProcessCommand& c : plan.commands) {
    const Program* program = FindProgram(c.name);
    if (program == nullptr || program->build_dir.empty() || c.argv.empty()) continue;
    const std::optional<std::set<std::string>> known = HelpFlags({c.argv[0]});
    if (!known) {
      errors.push_back(fmt::format("{}: {} --help printed no flags: is it a turf executable?", c.name, c.argv[0]));
      continue;
    }
    for (size_t i = 1; i < c.argv.size(); ++i) {
      const std::string& arg = c.argv[i];
      if (arg.rfind("--", 0) != 0) continue;
      const std::string flag = arg.substr(0, arg.find('='));
      if (!known->count(flag))
        errors.push_back(fmt::format("{}: {} has no flag {} ({} --help lists its flags)", c.name, program->binary, flag,
                                     program->binary));
    }
  }
  return errors;
}

}  // namespace turf::launch
