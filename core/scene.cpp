#include "core/scene.h"

#include <cmath>
#include <set>
#include <utility>

#include <fmt/format.h>

namespace turf {

FieldParams FieldForDivision(Division division) {
  FieldParams f;
  f.division = division;
  if (division == Division::kB) {
    f.length = 9.0;
    f.width = 6.0;
    f.boundary_width = 0.3;
    f.boundary_width_goal_line = 0.3;
    f.goal_width = 1.0;
    f.penalty_area_depth = 1.0;
    f.penalty_area_width = 2.0;
    f.goal_center_to_penalty_mark = 6.0;
  }
  return f;
}

namespace {

class Checker {
 public:
  void Positive(const char* key, double v) {
    if (!(std::isfinite(v) && v > 0)) errors_.push_back(fmt::format("{} must be > 0 (got {})", key, v));
  }
  void Range(const char* key, double v, double lo, double hi) {
    if (!(std::isfinite(v) && v >= lo && v <= hi))
      errors_.push_back(fmt::format("{} must be in [{}, {}] (got {})", key, lo, hi, v));
  }
  void Fail(std::string message) { errors_.push_back(std::move(message)); }
  std::vector<std::string> Take() { return std::move(errors_); }

 private:
  std::vector<std::string> errors_;
};

}  // namespace

std::vector<std::string> ValidateScene(const Scene& s) {
  Checker c;
  c.Range("physics.step", s.physics.step, 1e-4, 0.01);
  c.Range("physics.solver_iterations", s.physics.solver_iterations, 1, 1000);
  c.Range("physics.wall_segments", s.physics.wall_segments, 0, 64);  // 0: none (core/mjcf.cpp, FieldGeoms)
  c.Range("rates.world_state_hz", s.rates.world_state_hz, 1, 1000);
  c.Range("rates.command_timeout", s.rates.command_timeout, 0.01, 60);

  const FieldParams& f = s.field;
  c.Range("field.length", f.length, 1, 100);
  c.Range("field.width", f.width, 1, 100);
  c.Range("field.boundary_width", f.boundary_width, 0.05, 10);
  c.Range("field.boundary_width_goal_line", f.boundary_width_goal_line, f.goal_depth + f.goal_wall_thickness, 10);
  c.Range("field.goal_width", f.goal_width, 0.1, f.width);
  c.Positive("field.goal_depth", f.goal_depth);
  // Sizes of things on a field: positive and at most 10 m (a wall 1e300 m thick was NaN at the first step).
  c.Range("field.goal_height", f.goal_height, 1e-4, 10);
  c.Range("field.goal_wall_thickness", f.goal_wall_thickness, 1e-4, 10);
  c.Range("field.penalty_area_depth", f.penalty_area_depth, 0, f.length / 2);
  c.Range("field.penalty_area_width", f.penalty_area_width, 0, f.width);
  c.Range("field.center_circle_radius", f.center_circle_radius, 0, f.width / 2);
  c.Range("field.line_thickness", f.line_thickness, 1e-4, 10);
  c.Range("field.goal_center_to_penalty_mark", f.goal_center_to_penalty_mark, 0, f.length);
  c.Range("field.wall_height", f.wall_height, 1e-4, 10);
  c.Range("field.wall_thickness", f.wall_thickness, 1e-4, 10);
  c.Range("field.friction", f.friction, 0, 5);

  const BallParams& b = s.ball;
  c.Range("ball.radius", b.radius, 0.005, 0.5);
  c.Range("ball.mass", b.mass, 0.001, 10);
  c.Range("ball.acc_slide", b.acc_slide, -50, -0.01);
  c.Range("ball.acc_roll", b.acc_roll, -10, 0);
  // k_switch = 1 / (1 + I / (m r^2)): 5/7 for a solid sphere, 3/5 for a shell.
  c.Range("ball.k_switch", b.k_switch, 0.55, 0.95);
  c.Range("ball.floor_restitution", b.floor_restitution, 0.01, 0.95);
  c.Range("ball.wall_restitution", b.wall_restitution, 0.01, 0.95);
  c.Range("ball.chip_damping_xy_first_hop", b.chip_damping_xy_first_hop, 0, 1);
  c.Range("ball.chip_damping_xy_other_hops", b.chip_damping_xy_other_hops, 0, 1);
  if (b.acc_roll <= b.acc_slide) c.Fail("ball.acc_roll must be gentler than ball.acc_slide");

  const RobotParams& r = s.robot;
  c.Range("robot.radius", r.radius, 0.02, 1);
  c.Range("robot.height", r.height, 0.02, 1);
  c.Range("robot.mass", r.mass, 0.1, 100);
  c.Range("robot.center_to_dribbler", r.center_to_dribbler, 0.3 * r.radius, 0.999 * r.radius);
  c.Range("robot.friction", r.friction, 0, 5);
  c.Range("robot.drive.max_speed", r.drive.max_speed, 0.01, 20);
  c.Range("robot.drive.max_angular_speed", r.drive.max_angular_speed, 0.01, 100);
  c.Range("robot.drive.acc_speedup", r.drive.acc_speedup, 0.01, 100);
  c.Range("robot.drive.acc_brake", r.drive.acc_brake, 0.01, 100);
  c.Range("robot.drive.acc_angular", r.drive.acc_angular, 0.01, 1000);
  for (double a : r.drive.wheel_angles) c.Range("robot.drive.wheel_angles", a, -7, 7);
  c.Range("robot.drive.wheel_distance", r.drive.wheel_distance, 0.01, 1);
  c.Range("robot.drive.wheel_radius", r.drive.wheel_radius, 0.001, 0.5);
  c.Range("robot.kicker.max_flat_speed", r.kicker.max_flat_speed, 0, 30);
  c.Range("robot.kicker.max_chip_speed", r.kicker.max_chip_speed, 0, 30);
  c.Range("robot.kicker.default_chip_angle", r.kicker.default_chip_angle, 0.05, 1.5);
  c.Range("robot.kicker.reach", r.kicker.reach, 0, 0.1);
  c.Range("robot.kicker.arm_time", r.kicker.arm_time, 0, 0.5);
  c.Range("robot.dribbler.restitution", r.dribbler.restitution, 0.01, 0.95);
  c.Range("robot.dribbler.max_force", r.dribbler.max_force, 0, 100);
  c.Range("robot.dribbler.stiffness", r.dribbler.stiffness, 0, 1e4);
  c.Range("robot.dribbler.damping", r.dribbler.damping, 0, 1e3);
  c.Range("robot.dribbler.capture_distance", r.dribbler.capture_distance, 0, 0.1);

  c.Range("cameras.rate_hz", s.cameras.rate_hz, 1, 1000);
  c.Range("cameras.height", s.cameras.height, 0.5, 50);
  c.Range("cameras.overlap", s.cameras.overlap, 0, 5);
  c.Positive("cameras.focal_length", s.cameras.focal_length);
  c.Range("cameras.image_width", s.cameras.image_width, 1, 100000);
  c.Range("cameras.image_height", s.cameras.image_height, 1, 100000);

  if (const char* e = CheckRealism(s.realism); *e != '\0') c.Fail(std::string("realism: ") + e);
  c.Range("robots_per_team", s.robots_per_team, 0, kMaxRobotsPerTeam);
  const double x_in = f.length / 2 + f.boundary_width_goal_line;
  const double y_in = f.width / 2 + f.boundary_width;
  std::set<std::pair<int, int>> seen;
  for (const RobotSetup& rs : s.robots) {
    const std::string who = fmt::format("robot {} {}", TeamName(rs.team), rs.id);
    if (rs.id < 0 || rs.id >= s.robots_per_team)
      c.Fail(fmt::format("{}: id must be in [0, {})", who, s.robots_per_team));
    if (!seen.insert({static_cast<int>(rs.team), rs.id}).second) c.Fail(who + ": listed twice");
    const Pose2& p = rs.pose;
    if (!(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.theta)) || std::abs(p.x) > x_in - r.radius ||
        std::abs(p.y) > y_in - r.radius)
      c.Fail(who + ": start pose must be finite and inside the walls");
  }
  if (!(std::isfinite(s.ball_start_x) && std::isfinite(s.ball_start_y)) || std::abs(s.ball_start_x) > x_in - b.radius ||
      std::abs(s.ball_start_y) > y_in - b.radius)
    c.Fail("ball start must be finite and inside the walls");
  return c.Take();
}

}  // namespace turf
