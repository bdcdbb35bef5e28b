// The SSL simulation protocol's port and allowlist flags, one definition for its two homes: turf-simproto-bridge
// (`--control-port`, `--blue-allow`, ...) and turf-sim's in-process front-end (`--simproto-control-port`,
// `--simproto-blue-allow`, ...). Header-only (CLI11).
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

// Who may send to each port (source_gate.h); `prefix` and `help_prefix` as above.
inline void AddSimprotoAllowFlags(CLI::App& app, SimprotoBridgeOptions& o, const std::string& prefix = "",
                                  const std::string& help_prefix = "") {
  const auto flag = [&prefix](const char* name) { return "--" + prefix + name; };
  AddAllowOption(app, flag("blue-allow"), o.allow.blue,
                 help_prefix +
                     "the blue port takes datagrams only from this IPv4 address or range (others: "
                     "answered TURF_NOT_ALLOWED, counted, logged)");
  AddAllowOption(app, flag("yellow-allow"), o.allow.yellow,
                 help_prefix + "the yellow port takes datagrams only from this IPv4 address or range");
  AddAllowOption(app, flag("operator-allow"), o.allow.operators,
                 help_prefix +
                     "the control and sync ports (teleports, speed, realism, lockstep steps) take datagrams only "
                     "from this IPv4 address or range");
}

}  // namespace turf
