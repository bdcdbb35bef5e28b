// The SSL simulation protocol's port flags, one definition for its two homes: turf-simproto-bridge
// (`--control-port`, ...) and turf-sim's in-process front-end (`--simproto-control-port`, ...). Header-only (CLI11).
#pragma once

#include <CLI/CLI.hpp>

#include <string>

#include "participants/common/cli_checks.h"
#include "participants/simproto_bridge/simproto_bridge.h"

namespace turf {

// `prefix` goes before each flag's name ("simproto-"), `help_prefix` before its help ("with --simproto: ").
inline void AddSimprotoPortFlags(CLI::App& app, SimprotoBridgeOptions& o, const std::string& prefix = "",
                                 const std::string& help_prefix = "") {
  const auto flag = [&prefix](const char* name) { return "--" + prefix + name; };
  AddPortOption(app, flag("control-port"), o.control_port,
                help_prefix + "UDP port for SimulatorCommand -> SimulatorResponse (teleports, speed, config; 0: off)",
                true);
  AddPortOption(app, flag("blue-port"), o.blue_port, help_prefix + "UDP port for the blue team's RobotControl (0: off)",
                true);
  AddPortOption(app, flag("yellow-port"), o.yellow_port,
                help_prefix + "UDP port for the yellow team's RobotControl (0: off)", true);
  AddPortOption(app, flag("sync-port"), o.sync_port,
                help_prefix +
                    "UDP port for SimulationSyncRequest (lockstep: apply, step sim_step, answer with detections); "
                    "robot ids 0..15 are blue, 16..31 yellow (0: off)",
                true);
  app.add_flag(flag("sync"), o.sync,
               help_prefix +
                   "allow synchronous mode: a SimulationSyncRequest switches the match to lockstep (vision stops "
                   "for every team until someone resumes); off: such requests are answered TURF_SYNC_DISABLED");
  app.add_option(flag("sync-listen"), o.sync_listen, help_prefix + "IPv4 address the sync port binds to")
      ->capture_default_str();
}

}  // namespace turf
