// Values of turf's IDL types from plain numbers, for tests that build samples.
#pragma once

#include <turf/idl/Common.h>
#include <turf/idl/WorldState.h>

#include <cstdint>
#include <utility>
#include <vector>

#include "idl/values.h"

namespace turf::test {

using idl::V2;
using idl::V3;

// A robot at (x, y) facing `yaw`, on the field or off it; nothing else set.
inline idl::RobotState RobotAt(idl::Team team, int id, double x, double y, double yaw, bool on_field = true) {
  idl::RobotState r;
  r.team(team);
  r.id(static_cast<uint8_t>(id));
  r.on_field(on_field);
  r.position().x(x);
  r.position().y(y);
  r.yaw(yaw);
  return r;
}

// A world state at `sim_time_ns` (frame `frame`): the ball at rest at `ball`,
// and `robots`.
inline idl::WorldState StateAt(int64_t sim_time_ns, uint32_t frame, const idl::Vec3& ball,
                               std::vector<idl::RobotState> robots) {
  idl::WorldState s;
  s.sim_time_ns(sim_time_ns);
  s.frame(frame);
  s.ball().position(ball);
  s.robots(std::move(robots));
  return s;
}

}  // namespace turf::test
