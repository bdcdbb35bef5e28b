// Shared test inputs for the SSL simulation protocol codec: a division A field
// as turf-sim publishes it, a world state, and byte helpers.
#pragma once

#include <turf/idl/SslVision.h>
#include <turf/idl/WorldState.h>

#include <cstdint>
#include <string>
#include <vector>

#include "codecs/proto/ssl_simulation.pb.h"
#include "tests/support/idl_values.h"

namespace turf::simproto::test {

inline idl::SslField DivAField(int robots_per_team = 6) {
  idl::SslField f;
  f.division(1);
  f.field_length(12.0);
  f.field_width(9.0);
  f.boundary_width(0.3);
  f.boundary_width_goal_line(0.6);
  f.ball_radius(0.0215);
  f.max_robot_radius(0.09);
  f.robot_height(0.15);
  f.camera_rate_hz(60.0);
  f.robots_per_team(static_cast<uint8_t>(robots_per_team));
  for (uint32_t id = 0; id < 4; ++id) {
    idl::CameraInfo c;
    c.id(id);
    c.focal_length(500.0);
    c.image_width(780);
    c.image_height(580);
    idl::Vec3 p;
    p.x(id == 0 || id == 3 ? 3.0 : -3.0);
    p.y(id < 2 ? 2.25 : -2.25);
    p.z(4.0);
    c.position(p);
    f.cameras().push_back(c);
  }
  return f;
}

// Ball at (0.5, -0.5) on the ground; blue 0 at (1, 1), blue 1 off the field,
// yellow 2 at (-2, 0.5) facing +y.
inline idl::WorldState World() {
  using turf::test::RobotAt;
  return turf::test::StateAt(
      1'000'000'000, 500, turf::test::V3(0.5, -0.5, 0.0215),
      {RobotAt(idl::TEAM_BLUE, 0, 1.0, 1.0, 0.25), RobotAt(idl::TEAM_BLUE, 1, 0.0, 0.0, 0.0, false),
       RobotAt(idl::TEAM_YELLOW, 2, -2.0, 0.5, 1.5707963)});
}

inline std::vector<uint8_t> Bytes(const std::string& s) { return std::vector<uint8_t>(s.begin(), s.end()); }

// Also messages that lack required fields (to test their refusal).
template <class Message>
std::vector<uint8_t> Serialize(const Message& m) {
  std::vector<uint8_t> out(m.ByteSizeLong());
  m.SerializePartialToArray(out.data(), static_cast<int>(out.size()));
  return out;
}

}  // namespace turf::simproto::test

namespace turf::simproto::test {

// A robot command moving robot `id` forward at `forward` m/s in its own frame.
inline wire::simulation::RobotCommand* AddLocal(wire::simulation::RobotControl* rc, uint32_t id, float forward) {
  wire::simulation::RobotCommand* c = rc->add_robot_commands();
  c->set_id(id);
  auto* v = c->mutable_move_command()->mutable_local_velocity();
  v->set_forward(forward);
  v->set_left(0.0f);
  v->set_angular(0.0f);
  return c;
}

}  // namespace turf::simproto::test

namespace turf::simproto {
// What every codec test of this folder names unqualified.
namespace ws = wire::simulation;
using test::AddLocal;
using test::Serialize;
}  // namespace turf::simproto
