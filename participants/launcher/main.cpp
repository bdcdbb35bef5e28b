// turf: the launcher. `turf launch <profile>` starts a league profile's
// processes (configs/launch/*.yaml; schema in launch_profile.h), supervises
// them (supervisor.h) and stops them all on Ctrl-C; `--print` shows the
// command of each instead, to run them on separate hosts by hand. Its flags
// and what it does with them: launch_command.h. `turf security init DIR`
// makes a match's DDS Security files (security_command.h); `turf log info FILE` describes an MCAP recording
// (log_command.h); `turf record` and `turf replay` run turf-record and turf-replay (forward_command.h). It is no DDS
// participant, so it does not use participant_main.h: no domain of its own, logging only when it supervises, and the
// supervised processes' status as its own.
#include <CLI/CLI.hpp>

#include "participants/launcher/forward_command.h"
#include "participants/launcher/launch_command.h"
#include "participants/launcher/log_command.h"
#include "participants/launcher/security_command.h"

int main(int argc, char** argv) {
  CLI::App app{"turf: runs a match's processes (turf-sim and its bridges) from a league profile"};
  app.require_subcommand(1);
  turf::launch::LaunchCommand launch(app);
  turf::launch::SecurityCommand security(app);
  turf::launch::LogCommand log(app);
  turf::launch::ForwardCommand record(app, "record", "turf-record", "recorder",
                                      "record a match's DDS topics into an MCAP file");
  turf::launch::ForwardCommand replay(app, "replay", "turf-replay", "replay",
                                      "play a recording's outputs back onto a DDS domain");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int printed = app.exit(e);  // --help: 0; a refused flag: says why
    return printed == 0 ? 0 : 2;      // every refused flag or value is a configuration error (exit status 2)
  }
  if (log.Chosen()) return log.Run();
  if (record.Chosen()) return record.Run();
  if (replay.Chosen()) return replay.Run();
  return security.Chosen() ? security.Run() : launch.Run();
}
