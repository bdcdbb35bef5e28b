// Commands of the RCSSServerMJ monitor port (shared/protocols/rcssservermj.md,
// "Monitor port 60001"): kickOff, dropBall, ball, agent (pos / move / move3d),
// playMode, killsim. Pure parsing; the session carries them out. A malformed
// or non-finite command is refused with a named error and changes nothing.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "core/errors.h"

namespace turf::rcssservermj {

enum class TeamRef : uint8_t { kLeft, kRight, kName };

struct KickOffCommand {
  std::optional<bool> left;  // nullopt: a random side
};
struct DropBallCommand {};
struct BallCommand {
  double x = 0, y = 0;  // only x and y count (z = ball radius; velocity ignored, as the reference)
};
struct AgentCommand {
  int unum = 0;
  TeamRef team = TeamRef::kName;
  std::string team_name;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  // pos: identity; move: yaw; move3d: given
};
struct PlayModeCommand {
  std::string mode;  // checked by the session (referee.h)
};
struct KillSimCommand {};

using MonitorCommand =
    std::variant<KickOffCommand, DropBallCommand, BallCommand, AgentCommand, PlayModeCommand, KillSimCommand>;

struct MonitorIssue {
  turf::Error error = turf::Error::kOk;
  std::string detail;
};

struct MonitorMessage {
  std::vector<MonitorCommand> commands;
  std::vector<MonitorIssue> issues;
};

MonitorMessage ParseMonitorMessage(std::string_view payload);

}  // namespace turf::rcssservermj
