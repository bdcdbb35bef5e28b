// grSim messages the codec and bridge tests build, with turf's own protos.
#pragma once

#include <cstdint>
#include <vector>

#include "codecs/proto/grsim.pb.h"

namespace turf::test {

// A local-velocity command for robot `id` with every required field set.
inline wire::grsim::grSim_Robot_Command GrsimRobot(uint32_t id, float forward = 0, float left = 0, float angular = 0) {
  wire::grsim::grSim_Robot_Command c;
  c.set_id(id);
  c.set_kickspeedx(0);
  c.set_kickspeedz(0);
  c.set_veltangent(forward);
  c.set_velnormal(left);
  c.set_velangular(angular);
  c.set_spinner(false);
  c.set_wheelsspeed(false);
  return c;
}

// One team's commands in a packet (timestamp 1 s: any finite value is accepted).
inline wire::grsim::grSim_Packet GrsimCommands(bool yellow,
                                               const std::vector<wire::grsim::grSim_Robot_Command>& robots) {
  wire::grsim::grSim_Packet p;
  p.mutable_commands()->set_timestamp(1.0);
  p.mutable_commands()->set_isteamyellow(yellow);
  for (const auto& r : robots) *p.mutable_commands()->add_robot_commands() = r;
  return p;
}

}  // namespace turf::test
