// DDS samples for the viewer's unit tests, built in code.
#pragma once

#include <turf/idl/Clock.h>
#include <turf/idl/Joints.h>
#include <turf/idl/SensorStats.h>
#include <turf/idl/SslVision.h>
#include <turf/idl/WorldState.h>

#include <limits>

#include "tests/support/idl_values.h"

namespace turf::test {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Division B: 9 x 6 m, boundary 0.3 m, ball 21.5 mm, robot 90 mm, 6 ids a team.
inline idl::SslField DivBField() {
  idl::SslField f;
  f.division(2);
  f.field_length(9.0);
  f.field_width(6.0);
  f.boundary_width(0.3);
  f.boundary_width_goal_line(0.3);
  f.goal_width(1.0);
  f.goal_depth(0.18);
  f.goal_height(0.155);
  f.penalty_area_depth(1.0);
  f.penalty_area_width(2.0);
  f.center_circle_radius(0.5);
  f.line_thickness(0.01);
  f.ball_radius(0.0215);
  f.max_robot_radius(0.09);
  f.robot_height(0.15);
  f.robots_per_team(6);
  idl::CameraInfo c;
  c.id(0);
  c.area_min().x(-4.8);
  c.area_min().y(-3.3);
  c.area_max().x(0.1);
  c.area_max().y(3.3);
  f.cameras().push_back(c);
  return f;
}

inline idl::RobotState Robot(idl::Team team, int id, double x, double y, double yaw, bool on = true) {
  idl::RobotState r = RobotAt(team, id, x, y, yaw, on);
  r.orientation().w(1.0);
  return r;
}

// t = 1.5 s: ball in flight at (1, -0.5, 0.3), blue 0 and yellow 3 on the field, yellow 5 off.
inline idl::WorldState SampleState() {
  idl::WorldState s =
      StateAt(1'500'000'000, 750, V3(1.0, -0.5, 0.3),
              {Robot(idl::TEAM_BLUE, 0, -1.25, 0.5, 0.7853981633974483), Robot(idl::TEAM_YELLOW, 3, 2.0, -1.0, 3.14159),
               Robot(idl::TEAM_YELLOW, 5, 0.0, 0.0, 0.0, false)});
  s.ball().velocity().x(2.0);
  return s;
}

inline idl::Clock SampleClock(bool paused) {
  idl::Clock c;
  c.sim_time_ns(1'500'000'000);
  c.frame(750);
  c.step_s(0.002);
  c.paused(paused);
  c.mode(idl::TIME_SCALED);
  c.speed(2.0);
  c.real_time_factor(1.98);
  return c;
}

inline idl::CameraFrame SampleFrame(uint32_t camera, int64_t capture_ns) {
  idl::CameraFrame f;
  f.camera_id(camera);
  f.frame_number(10);
  f.capture_time_ns(capture_ns);
  f.sent_time_ns(capture_ns + 1'000'000);
  idl::DetectedBall b;
  b.position().x(1.01);
  b.position().y(-0.49);
  b.confidence(0.9f);
  f.balls().push_back(b);
  idl::DetectedRobot r;
  r.team(idl::TEAM_BLUE);
  r.id(0);
  r.position().x(-1.26);
  r.position().y(0.51);
  r.orientation(0.78);
  r.confidence(0.95f);
  f.robots().push_back(r);
  return f;
}

inline idl::RobotGeom Geom(const char* body, idl::GeomShape shape, double sx, double sy, double sz, double pz = 0.0) {
  idl::RobotGeom g;
  g.body(body);
  g.shape(shape);
  g.size().x(sx);
  g.size().y(sy);
  g.size().z(sz);
  g.position().z(pz);
  g.orientation().w(1.0);
  return g;
}

// A legged scene with the 3D field and two robots of three shapes on two
// bodies: torso (a box and a capsule neck) and head (a sphere).
inline idl::LeggedSceneInfo LeggedScene() {
  idl::LeggedSceneInfo s;
  s.name("simspark-3d");
  s.has_field(true);
  s.field_length(30.0);
  s.field_width(20.0);
  s.goal_width(2.1);
  s.goal_depth(0.6);
  s.goal_height(0.8);
  s.ball_radius(0.042);
  for (int i = 1; i <= 2; ++i) {
    idl::RobotDescription r;
    r.robot("nao_" + std::to_string(i));
    r.id(i);
    r.model("nao");
    r.geoms().push_back(Geom("torso", idl::GEOM_BOX, 0.05, 0.05, 0.09));
    r.geoms().push_back(Geom("torso", idl::GEOM_CAPSULE, 0.015, 0.04, 0.0, 0.09));
    r.geoms().push_back(Geom("head", idl::GEOM_SPHERE, 0.065, 0.0, 0.0, 0.05));
    s.robots().push_back(r);
  }
  return s;
}

inline idl::LinkPose Link(const char* name, double x, double y, double z, double qw, double qz) {
  idl::LinkPose l;
  l.name(name);
  l.position().x(x);
  l.position().y(y);
  l.position().z(z);
  l.orientation().w(qw);
  l.orientation().z(qz);
  return l;
}

// nao_1's bodies at t = 2 s, turned -90 deg about z; `head` before `torso`
// (the poses are matched by name, not order) and an extra body without shapes.
inline idl::LinkState Links(const std::string& robot = "nao_1", double x = -14.2, double y = 0.0) {
  idl::LinkState l;
  l.robot(robot);
  l.sim_time_ns(2'000'000'000);
  l.frame(1000);
  l.links().push_back(Link("head", x, y, 0.51234, 0.70710678, -0.70710678));
  l.links().push_back(Link("torso", x, y, 0.38567, 0.70710678, -0.70710678));
  l.links().push_back(Link("lhip1", x, y + 0.05, 0.2, 1.0, 0.0));
  return l;
}

}  // namespace turf::test
