// The RCSSServerMJ front-end's flags, one definition for its two homes: turf-rcssservermj-bridge (`--agent-port`,
// `--sync`, ...) and turf-sim's in-process front-end (`--rcssservermj-agent-port`, `--rcssservermj-sync`, ...).
// Header-only (CLI11).
#pragma once

#include <CLI/CLI.hpp>

#include <string>

#include "participants/common/cli_checks.h"
#include "participants/rcssservermj_bridge/rcssservermj_bridge.h"

namespace turf {

// `prefix` goes before each flag's name ("rcssservermj-"), `help_prefix` before its help ("with --rcssservermj: ").
inline void AddRcssServerMjFlags(CLI::App& app, RcssServerMjOptions& o, const std::string& prefix = "",
                                 const std::string& help_prefix = "") {
  AddPortOption(app, "--" + prefix + "agent-port", o.agent_port, help_prefix + "TCP port for agents (0: any free port)",
                true);
  AddPortOption(app, "--" + prefix + "monitor-port", o.monitor_port,
                help_prefix + "TCP port for monitor commands (0: any free port)", true);
  app.add_option("--" + prefix + "monitor-allow", o.monitor_allow,
                 help_prefix +
                     "a monitor-port client from this IPv4/IPv6 address or range may connect (its commands move "
                     "players and the ball, set play modes, stop the server); repeatable or comma-separated; given, "
                     "it replaces the default (this machine)")
      ->type_name("ADDR[/PREFIX]")
      ->delimiter(',')
      ->check(AddressRangeCheck(/*ipv4_only=*/false))
      ->capture_default_str();
  app.add_flag("--" + prefix + "sync", o.sync_mode,
               help_prefix + "sync mode: a cycle needs exactly one message from every agent (RCSSServerMJ's -s)");
  app.add_flag("--" + prefix + "sequential", o.sequential,
               help_prefix +
                   "sequential loop: an action acts in the next physics step, no cycle of latency (RCSSServerMJ's "
                   "-S; implies sync)");
  app.add_flag(
      "--" + prefix + "realtime,!--" + prefix + "no-realtime", o.realtime,
      help_prefix +
          "real time (default): one cycle per 20 ms; --no-realtime: as fast as the agents answer (implies sync)");
  app.add_option("--" + prefix + "rules", o.rules,
                 help_prefix + "rule book: fifa, ssim, ssim_2025, hl_adult, hl_adult_2025")
      ->check(CLI::IsMember({"fifa", "ssim", "ssim_2025", "hl_adult", "hl_adult_2025"}))
      ->capture_default_str();
  app.add_option("--" + prefix + "field", o.field,
                 help_prefix +
                     "field version for the referee and vision (default: the rule book's): fifa, "
                     "sim3d_7vs7, hl_adult_2020, hl_adult_2019, hl_adult_2014")
      ->check(CLI::IsMember({"fifa", "sim3d_7vs7", "hl_adult", "hl_adult_2020", "hl_adult_2019", "hl_adult_2014"}));
}

}  // namespace turf
