// turf-replay's terminal commands: one per line on its standard input, for whoever runs it by hand (the control
// topic, replay_control.h, is the same for programs and the viewer). Parsed here, carried out like a control
// request with no client (so no reply is written):
//   pause | p            resume | play | r
//   seek SECONDS         (simulation time; s SECONDS)
//   speed X | speed max  (a multiple of the recorded pace)
// A line is outside input: anything else, a number that is not finite or out of range, or a line longer than
// kMaxReplayLine is refused with the reason (a log line), and nothing happens.
#pragma once

#include <string>
#include <string_view>
#include <variant>

#include "participants/replay/replay_command.h"

namespace turf {

constexpr size_t kMaxReplayLine = 256;
constexpr double kMaxSeekSeconds = 1e9;
inline constexpr const char* kReplayKeysHelp = "pause | resume | seek SECONDS | speed X | speed max";

// The command a line asks for, or why it is refused (ReplayRefusal's reason). Pure.
std::variant<ReplayCommand, ReplayRefusal> ParseReplayLine(std::string_view line);

}  // namespace turf
