#include "participants/launcher/forward_command.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <vector>

#include "participants/launcher/launch_plan.h"
#include "participants/launcher/programs.h"

namespace turf::launch {

ForwardCommand::ForwardCommand(CLI::App& app, const std::string& name, const std::string& binary,
                               const std::string& build_dir, const std::string& description)
    : binary_(binary), build_dir_(build_dir) {
  command_ = app.add_subcommand(name, description + " (runs " + binary + "; `turf " + name + " --help`: its flags)");
  command_->prefix_command();
  command_->set_help_flag();  // --help goes to the program
}

int ForwardCommand::Run() {
  const Program program{"", binary_, build_dir_};
  const std::string path = FindBinary(program, "", SelfDir());
  if (path.empty()) {
    std::fprintf(stderr, "turf: %s not found next to turf or on PATH\n", binary_.c_str());
    return 2;
  }
  std::vector<std::string> args = {path};
  for (const std::string& a : command_->remaining()) args.push_back(a);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  execv(path.c_str(), argv.data());
  std::fprintf(stderr, "turf: cannot run %s: %s\n", path.c_str(), std::strerror(errno));
  return 2;
}

}  // namespace turf::launch
