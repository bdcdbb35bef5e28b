// The SimSpark front-end's flags, one definition for its two homes: turf-simspark-bridge (`--agent-port`,
// `--sync`, `--operator-allow`, ...) and turf-sim's in-process front-end (`--simspark-agent-port`, ...); and the
// bridge's own other flags. Header-only (CLI11).
#pragma once

#include <CLI/CLI.hpp>

#include <string>

#include "participants/common/cli_checks.h"
#include "participants/common/participant_main.h"
#include "participants/simspark_bridge/simspark_bridge.h"

namespace turf {

// `prefix` goes before the flag's name ("simspark-"), `help_prefix` before its help ("with --simspark: ").
inline void AddSimSparkOperatorFlag(CLI::App& app, SimSparkBridgeOptions& o, const std::string& prefix = "",
                                    const std::string& help_prefix = "") {
  app.add_option("--" + prefix + "operator-allow", o.operator_allow,
                 help_prefix +
                     "a monitor-port client from this IPv4/IPv6 address or range is an operator, who alone may send "
                     "the trainer commands that end, restart or rewrite the match (killsim, kill, kickOff, time, "
                     "score, turfResetTeam, playMode BeforeKickOff/KickOff_*/GameOver); repeatable or "
                     "comma-separated; given, it replaces the default (this machine)")
      ->type_name("ADDR[/PREFIX]")
      ->delimiter(',')
      ->check(AddressRangeCheck(/*ipv4_only=*/false))
      ->capture_default_str();
}

// The front-end's ports, sync mode and operator flag; prefixes as AddSimSparkOperatorFlag's.
inline void AddSimSparkFrontEndFlags(CLI::App& app, SimSparkBridgeOptions& o, const std::string& prefix = "",
                                     const std::string& help_prefix = "") {
  AddPortOption(app, "--" + prefix + "agent-port", o.agent_port, help_prefix + "TCP port for agents (0: any free port)",
                true);
  AddPortOption(app, "--" + prefix + "monitor-port", o.monitor_port,
                help_prefix + "TCP port for monitors and trainers (0: any free port)", true);
  app.add_flag("--" + prefix + "sync", o.sync_mode,
               help_prefix +
                   "sync mode: a cycle as soon as every agent sent (syn), as fast as they answer (rcssserver3d's "
                   "agentSyncMode); default: real time, one cycle per 20 ms");
  app.add_option(
         "--" + prefix + "sync-grace-cycles", o.sync_grace_cycles,
         help_prefix + "sync mode: cycles after an agent's (scene) that run without its (syn) (rcssserver3d: 0)")
      ->capture_default_str()
      ->check(CLI::Range(0, 1000));
  AddSimSparkOperatorFlag(app, o, prefix, help_prefix);
}

// turf-simspark-bridge's flags (main.cpp): the common ones, ports, sync mode, seed, duration and the operator flag.
// `sync_timeout_ms`: --sync-timeout-ms, into options.sync_timeout once parsed.
inline void AddSimSparkBridgeFlags(ParticipantMain& participant, SimSparkBridgeOptions& options, int& sync_timeout_ms) {
  CLI::App& app = participant.app();
  participant.AddCommonFlags(options);
  app.add_option("--listen", options.listen, "IPv4 address both TCP ports bind to")->capture_default_str();
  AddSimSparkFrontEndFlags(app, options);
  app.add_option("--sync-timeout-ms", sync_timeout_ms,
                 "sync mode: drop an agent that sends no (syn) for this long (0: wait forever)")
      ->capture_default_str()
      ->check(CLI::Range(0, 3600000));
  app.add_option("--seed", options.seed, "seed of beam noise and each agent's vision noise")->capture_default_str();
  app.add_option("--duration", options.duration, "stop after this many simulated seconds (0: run until Ctrl-C)")
      ->check(FiniteAtLeastZero());
}

}  // namespace turf
