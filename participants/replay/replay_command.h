// What a control request or a terminal line asks turf-replay to do (replay_control.h, replay_keys.h), and the
// named refusals of what it cannot do. Pure: no DDS.
#pragma once

#include <turf/idl/SimControl.h>

#include <cstdint>
#include <string>
#include <variant>

namespace turf {

// A replay's speed, a multiple of the recorded pace: within these, or "max" (0). Below the minimum a second of
// recording would take more than 17 minutes; the waits stay far inside the clock's range (replay_clock.h).
constexpr double kMinReplaySpeed = 1e-3;
constexpr double kMaxReplaySpeed = 1e6;
// The one check of a speed given on the command line, the control topic or the terminal: "" when in range, else
// why not.
std::string ReplaySpeedProblem(double speed);

// What a request asks a replay to do.
struct ReplayCommand {
  enum class Kind { kPause, kResume, kSpeed, kSeek };
  Kind kind = Kind::kPause;
  double speed = 1;          // kSpeed: a multiple of the recorded pace; 0: as fast as possible
  int64_t seek_time_ns = 0;  // kSeek: simulation time
  idl::SimControl request;   // for the reply
  bool local = false;        // a terminal command (replay_keys.h): no reply is written
};

// Why a request was refused: its code and the reason in words (both go into the reply).
struct ReplayRefusal {
  idl::ControlError code = idl::CONTROL_OK;
  std::string reason;
};

// The command `request` asks for, or why it is refused. Pure.
std::variant<ReplayCommand, ReplayRefusal> ReplayCommandOf(const idl::SimControl& request);

}  // namespace turf
