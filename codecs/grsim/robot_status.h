// grSim robot status (Robots_Status, codecs/proto/grsim.proto) from turf's
// SslRobotFeedback. Pure: a state machine and an encoder, no sockets or clocks.
//
// As the reference simulator does, a robot appears in its team's status packet
// only when one of its booleans changes. infrared is the feedback's
// ball_contact. flat_kick / chip_kick are true in the change that carries a new
// kick (kick_count moved on) and false again in the robot's next change.
#pragma once

#include <turf/idl/SslRobot.h>

#include <array>
#include <cstdint>
#include <vector>

namespace turf::grsim {

struct RobotStatus {
  int robot_id = 0;
  bool infrared = false;
  bool flat_kick = false;
  bool chip_kick = false;
  bool operator==(const RobotStatus& o) const {
    return robot_id == o.robot_id && infrared == o.infrared && flat_kick == o.flat_kick && chip_kick == o.chip_kick;
  }
};

// Robots_Status wire bytes for these robots, in the given order.
std::vector<uint8_t> EncodeStatus(const std::vector<RobotStatus>& robots);

class StatusTracker {
 public:
  static constexpr int kMaxRobots = 16;  // ids 0..15 a team

  // Takes one feedback sample (samples of other teams or ids >= 16 are ignored).
  // The first sample of a robot sets its kick baseline: a kick counted before
  // the bridge listened is not reported. A sample older than the last one of
  // that robot means the world was reset: kick counts start again from 0.
  void Feed(const idl::SslRobotFeedback& sample);

  // The status packets for `team` since the last call: each holds the robots
  // that changed, in order of change; a robot that changed again starts a new
  // packet, so no change (e.g. a kick's single true) is lost. Empty: nothing changed.
  std::vector<std::vector<RobotStatus>> TakePackets(idl::Team team);

 private:
  struct Robot {
    bool seen = false;
    int64_t sim_time_ns = 0;
    uint32_t kick_count = 0;
    RobotStatus status;
  };
  std::array<std::array<Robot, kMaxRobots>, 2> robots_{};
  std::array<std::vector<std::vector<RobotStatus>>, 2> pending_{};
};

}  // namespace turf::grsim
