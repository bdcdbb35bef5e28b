// Before `turf launch` starts anything: every flag a plan gives a turf program is one that program's --help
// lists, so a mistyped `--set sim.sped=2` (or a profile flag a program does not have) is refused at once with
// exit status 2, instead of starting the match and watching a process refuse it.
#pragma once

#include <optional>
#include <set>
#include <string>
#include <vector>

#include "participants/launcher/launch_plan.h"

namespace turf::launch {

// One message per unknown flag: "sim: turf-sim has no flag --sped (turf-sim --help lists its flags)". Runs each
// turf executable of the plan with --help (programs that are no turf executable, the discovery server, are not
// checked).
std::vector<std::string> UnknownFlags(const LaunchPlan& plan);

// The long flags (--name) that `argv... --help` prints; nothing if it printed no --help line (not runnable, or no
// turf program).
std::optional<std::set<std::string>> HelpFlags(const std::vector<std::string>& argv);

// The long flags in a text (a README, a --help output).
std::set<std::string> LongFlags(const std::string& text);

}  // namespace turf::launch
