#include "codecs/grsim/robot_status.h"

#include <algorithm>
#include <utility>

#include "codecs/proto/grsim.pb.h"

namespace turf::grsim {

std::vector<uint8_t> EncodeStatus(const std::vector<RobotStatus>& robots) {
  turf::wire::grsim::Robots_Status packet;
  for (const RobotStatus& r : robots) {
    turf::wire::grsim::Robot_Status* s = packet.add_robots_status();
    s->set_robot_id(r.robot_id);
    s->set_infrared(r.infrared);
    s->set_flat_kick(r.flat_kick);
    s->set_chip_kick(r.chip_kick);
  }
  std::vector<uint8_t> bytes(packet.ByteSizeLong());
  packet.SerializeWithCachedSizesToArray(bytes.data());
  return bytes;
}

void StatusTracker::Feed(const idl::SslRobotFeedback& sample) {
  const int team = static_cast<int>(sample.team());
  if ((sample.team() != idl::TEAM_BLUE && sample.team() != idl::TEAM_YELLOW) || sample.id() >= kMaxRobots) return;
  Robot& robot = robots_[team][sample.id()];
  bool kicked = false;
  if (robot.seen) {
    if (sample.sim_time_ns() < robot.sim_time_ns) robot.kick_count = 0;  // the world was reset
    kicked = sample.kick_count() != robot.kick_count && sample.kick_count() != 0;
  }
  robot.seen = true;
  robot.sim_time_ns = sample.sim_time_ns();
  robot.kick_count = sample.kick_count();

  RobotStatus now;
  now.robot_id = sample.id();
  now.infrared = sample.ball_contact();
  now.flat_kick = kicked && sample.last_kick() == idl::KICK_FLAT;
  now.chip_kick = kicked && sample.last_kick() == idl::KICK_CHIP;
  const RobotStatus& was = robot.status;
  if (now.infrared == was.infrared && now.flat_kick == was.flat_kick && now.chip_kick == was.chip_kick) return;
  robot.status = now;

  std::vector<std::vector<RobotStatus>>& packets = pending_[team];
  const auto same_robot = [&](const RobotStatus& s) { return s.robot_id == now.robot_id; };
  if (packets.empty() || std::any_of(packets.back().begin(), packets.back().end(), same_robot)) packets.emplace_back();
  packets.back().push_back(now);
}

std::vector<std::vector<RobotStatus>> StatusTracker::TakePackets(idl::Team team) {
  std::vector<std::vector<RobotStatus>> out;
  if (team != idl::TEAM_BLUE && team != idl::TEAM_YELLOW) return out;
  out.swap(pending_[static_cast<int>(team)]);
  return out;
}

}  // namespace turf::grsim
