// The SimSpark front-end's operator flag, one definition for its two homes: turf-simspark-bridge
// (`--operator-allow`) and turf-sim's in-process front-end (`--simspark-operator-allow`). Header-only (CLI11).
#pragma once

#include <CLI/CLI.hpp>

#include <string>

#include "participants/common/cli_checks.h"
#include "participants/simspark_bridge/simspark_bridge.h"

namespace turf {

// `prefix` goes before the flag's name ("simspark-"), `help_prefix` before its help ("with --simspark: ").
inline void AddSimSparkOperatorFlag(CLI::App& app, SimSparkBridgeOptions& o, const std::string& prefix = "",
                                    const std::string& help_prefix = "") {
  app.add_option("--" + prefix + "operator-allow", o.operator_allow,
                 help_prefix +
                     "a monitor-port client from this IPv4/IPv6 address or range is an operator, who alone may send "
                     "the trainer commands that end, restart or rewrite the match (killsim, kill, kickOff, time, "
                     "score, turfResetTeam, playMode BeforeKickOff/KickOff_*/GameOver); repeatable; given, it "
                     "replaces the default (this machine)")
      ->type_name("ADDR[/PREFIX]")
      ->check(AddressRangeCheck(/*ipv4_only=*/false))
      ->capture_default_str();
}

}  // namespace turf
