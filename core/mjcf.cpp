#include "core/mjcf.h"

#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

namespace turf {

namespace {

constexpr int kHullSegments = 24;

// Collision groups: walls/goals (static), robots and the ball collide with each
// other through bit 1; the floor touches only the ball, through an explicit pair.
constexpr const char* kSolidContact = R"(contype="2" conaffinity="2")";

std::string Box(const char* name, double x, double y, double z, double hx, double hy, double hz, double friction) {
  return fmt::format(R"(    <geom name="{}" type="box" pos="{:.6f} {:.6f} {:.6f}" size="{:.6f} {:.6f} {:.6f}" )"
                     R"(friction="{:.4f} 0.005 0.0001" {} rgba="0.8 0.8 0.8 1"/>)"
                     "\n",
                     name, x, y, z, hx, hy, hz, friction, kSolidContact);
}

// A cylinder with its front cut flat at `center_to_dribbler`, as a convex hull.
std::string RobotHullVertices(const RobotParams& r) {
  const double half_face = std::sqrt(r.radius * r.radius - r.center_to_dribbler * r.center_to_dribbler);
  const double face_angle = std::atan2(half_face, r.center_to_dribbler);
  std::string v;
  for (double z : {0.0, r.height}) {
    v += fmt::format("{:.6f} {:.6f} {:.6f} {:.6f} {:.6f} {:.6f} ", r.center_to_dribbler, -half_face, z,
                     r.center_to_dribbler, half_face, z);
    for (int i = 0; i <= kHullSegments; ++i) {
      const double a = face_angle + (2 * M_PI - 2 * face_angle) * i / kHullSegments;
      v += fmt::format("{:.6f} {:.6f} {:.6f} ", r.radius * std::cos(a), r.radius * std::sin(a), z);
    }
  }
  return v;
}

constexpr const char* kBallSolimp = "0.99 0.99 0.001";

// `geoms` in a static body of their own (no joint: welded to the world).
std::string StaticBody(const std::string& name, const std::string& geoms) {
  return fmt::format("    <body name=\"{}\">\n{}    </body>\n", name, geoms);
}

// A wall along x (along_x) or y centred at (cx, cy) with half sizes (hx, hy, hz), as `segments` boxes end to end,
// each (when more than one) in a static body of its own.
std::string Wall(const char* name, double cx, double cy, double hx, double hy, double hz, bool along_x, int segments,
                 double friction) {
  if (segments <= 1) return Box(name, cx, cy, hz, hx, hy, hz, friction);
  std::string out;
  const double half = (along_x ? hx : hy) / segments;
  for (int i = 0; i < segments; ++i) {
    const double offset = -(along_x ? hx : hy) + half * (2 * i + 1);
    const std::string box = fmt::format("{}_{}", name, i);
    out += StaticBody(box, Box(box.c_str(), cx + (along_x ? offset : 0), cy + (along_x ? 0 : offset), hz,
                               along_x ? half : hx, along_x ? hy : half, hz, friction));
  }
  return out;
}

// The walls and goals. physics.wall_segments: 1 (the scenes): each boundary wall one box of the world body.
// More (the learning configuration's choices): every wall box and every goal is a static body of its own: MuJoCo
// 2.2 pairs each geom of the world body with every body, each pair costing a filter and a bounding-sphere test (a
// convex test where the spheres overlap), while other bodies go through its sweep-and-prune broadphase, which
// never pairs a robot with a wall or goal whose box around its bounding spheres it is not in. The same boxes touch
// the same robots; only contacts' order in MuJoCo's list differs (and so the solver's last bits). 0 (turf.FAST_SSL):
// no boundary wall boxes at all, goals as for more. They are never touched: World::StageContainment puts the ball
// and every robot on the field back at a wall's inner face after each step, so at the next collision test nothing
// is inside a wall (tests/core: Physics.WallBoxesInBodiesBounceTheBallAsOneBoxWallsDo, the same path with 0, 1, 2).
std::string FieldGeoms(const FieldParams& f, int wall_segments) {
  std::string out;
  const double wt = f.wall_thickness;
  const double wh = f.wall_height / 2;
  const double x_in = f.length / 2 + f.boundary_width_goal_line;
  const double y_in = f.width / 2 + f.boundary_width;
  // Boundary walls, their inner faces at x_in and y_in.
  const int n = wall_segments;
  if (n >= 1) {
    out += Wall("wall_left", -x_in - wt / 2, 0, wt / 2, y_in + wt, wh, false, n, f.friction);
    out += Wall("wall_right", x_in + wt / 2, 0, wt / 2, y_in + wt, wh, false, n, f.friction);
    out += Wall("wall_top", 0, y_in + wt / 2, x_in + wt, wt / 2, wh, true, n, f.friction);
    out += Wall("wall_bottom", 0, -y_in - wt / 2, x_in + wt, wt / 2, wh, true, n, f.friction);
  }
  // Goals: two side walls (their front ends are the posts) and a back wall.
  const double gt = f.goal_wall_thickness;
  const double gh = f.goal_height / 2;
  for (int side : {-1, 1}) {
    const char* name = side < 0 ? "left" : "right";
    const double x_line = side * f.length / 2;
    const double x_mid = x_line + side * (f.goal_depth + gt) / 2;
    const double y_side = f.goal_width / 2 + gt / 2;
    std::string goal;
    goal += Box(fmt::format("goal_{}_post_pos", name).c_str(), x_mid, y_side, gh, (f.goal_depth + gt) / 2, gt / 2, gh,
                f.friction);
    goal += Box(fmt::format("goal_{}_post_neg", name).c_str(), x_mid, -y_side, gh, (f.goal_depth + gt) / 2, gt / 2, gh,
                f.friction);
    goal += Box(fmt::format("goal_{}_back", name).c_str(), x_line + side * (f.goal_depth + gt / 2), 0, gh, gt / 2,
                f.goal_width / 2 + gt, gh, f.friction);
    out += wall_segments != 1 ? StaticBody(fmt::format("goal_{}", name), goal) : goal;
  }
  return out;
}

}  // namespace

std::string RobotBodyName(Team team, int id) { return fmt::format("{}_{}", TeamName(team), id); }

// A half period of several steps, so that integration stays stable. In MuJoCo's standard form (timeconst,
// dampratio) the spring is k = 1 / (timeconst * dampratio)^2 and the damping b = 2 / timeconst; the constant
// impedance (solimp) keeps them as given.
BallSpring BallContactSpring(double restitution, double step) {
  constexpr double kStepsPerContact = 6.0;
  const double omega = M_PI / (kStepsPerContact * step);
  const double zeta = DampingRatioForRestitution(restitution);
  return {1.0 / (omega * zeta), zeta};
}

double DampingRatioForRestitution(double restitution) {
  const double l = std::log(restitution);
  return -l / std::sqrt(M_PI * M_PI + l * l);
}

Pose2 ParkingPose(const Scene& scene, Team team, int id) {
  const FieldParams& f = scene.field;
  const double y = f.width / 2 + f.boundary_width + f.wall_thickness + 1.0 + (team == Team::kYellow ? 0.5 : 0);
  return Pose2{-f.length / 2 + 0.3 * id, y, 0.0};
}

std::string BuildMjcf(const Scene& s) {
  const BallParams& b = s.ball;
  const RobotParams& r = s.robot;
  const int robot_count = kTeamCount * s.robots_per_team;
  // Worst case (every robot on one spot) plus the ball's contacts.
  const int nconmax = robot_count * robot_count / 2 + robot_count + 16;

  std::string x;
  x += fmt::format(R"(<mujoco model="turf_{}">)"
                   "\n",
                   s.name);
  x += R"(  <compiler autolimits="true" angle="radian"/>)"
       "\n";
  x += fmt::format(R"(  <option timestep="{}" iterations="{}" cone="elliptic" gravity="0 0 {}" integrator="Euler"/>)"
                   "\n",
                   s.physics.step, s.physics.solver_iterations, -kGravity);
  x += fmt::format(R"(  <size nconmax="{}" njmax="{}"/>)"
                   "\n",
                   nconmax, 4 * nconmax);
  x += fmt::format(R"(  <asset><mesh name="robot_hull" vertex="{}"/></asset>)"
                   "\n",
                   RobotHullVertices(r));
  x += "  <worldbody>\n";
  x += fmt::format(
      R"(    <geom name="{}" type="plane" size="{:.3f} {:.3f} 0.1" contype="0" conaffinity="0" rgba="0.1 0.5 0.1 1"/>)"
      "\n",
      kFloorGeom, s.field.length, s.field.width);
  x += FieldGeoms(s.field, s.physics.wall_segments);

  // Ball: inertia chosen so that sliding turns into rolling at k_switch.
  const double inertia_factor = 1.0 / b.k_switch - 1.0;
  const double inertia = inertia_factor * b.mass * b.radius * b.radius;
  x += fmt::format(R"(    <body name="{}" pos="{:.6f} {:.6f} {:.6f}">)"
                   "\n",
                   kBallBody, s.ball_start_x, s.ball_start_y, b.radius);
  x += "      <freejoint/>\n";
  x += fmt::format(R"(      <inertial pos="0 0 0" mass="{}" diaginertia="{:.9g} {:.9g} {:.9g}"/>)"
                   "\n",
                   b.mass, inertia, inertia, inertia);
  // Against walls, goals and robots: MuJoCo's contacts (broadphase-filtered).
  // The ball has no friction of its own (the other surface's counts, MuJoCo
  // takes the larger) and its huge solmix makes its bounce win the mixing.
  const BallSpring wall = BallContactSpring(b.wall_restitution, s.physics.step);
  x += fmt::format(R"(      <geom name="ball" type="sphere" size="{}" {} condim="3" friction="0 0 0" solmix="1e6" )"
                   R"(solref="{:.6f} {:.6f}" solimp="{}" rgba="1 0.5 0 1"/>)"
                   "\n",
                   b.radius, kSolidContact, wall.timeconst, wall.dampratio, kBallSolimp);
  x += "    </body>\n";

  // Robots on planar joints: no floor contact, driven by forces on the joints.
  const double i_z = 0.5 * r.mass * r.radius * r.radius;
  const double i_xy = r.mass * (3 * r.radius * r.radius + r.height * r.height) / 12;
  for (Team team : {Team::kBlue, Team::kYellow}) {
    for (int id = 0; id < s.robots_per_team; ++id) {
      const std::string name = RobotBodyName(team, id);
      const char* rgba = team == Team::kBlue ? "0.1 0.2 0.9 1" : "0.9 0.9 0.1 1";
      x += fmt::format(R"(    <body name="{}" pos="0 0 0">)"
                       "\n",
                       name);
      x += fmt::format(R"(      <inertial pos="0 0 {:.6f}" mass="{}" diaginertia="{:.9g} {:.9g} {:.9g}"/>)"
                       "\n",
                       r.height / 2, r.mass, i_xy, i_xy, i_z);
      x += fmt::format(R"(      <joint name="{0}_x" type="slide" axis="1 0 0" damping="0"/>)"
                       "\n"
                       R"(      <joint name="{0}_y" type="slide" axis="0 1 0" damping="0"/>)"
                       "\n"
                       R"(      <joint name="{0}_yaw" type="hinge" axis="0 0 1" damping="0"/>)"
                       "\n",
                       name);
      x += fmt::format(R"(      <geom name="{}" type="mesh" mesh="robot_hull" {} condim="3" )"
                       R"(friction="{:.4f} 0.005 0.0001" rgba="{}"/>)"
                       "\n",
                       name, kSolidContact, r.friction, rgba);
      x += "    </body>\n";
    }
  }
  x += "  </worldbody>\n";

  // The carpet: an explicit, normal-only pair; the ball model applies the
  // carpet's friction (MuJoCo's soft friction cone makes a sliding ball hop).
  const BallSpring carpet = BallContactSpring(b.floor_restitution, s.physics.step);
  x += "  <contact>\n";
  x += fmt::format(R"(    <pair geom1="{}" geom2="ball" condim="1" solref="{:.6f} {:.6f}" solimp="{}"/>)"
                   "\n",
                   kFloorGeom, carpet.timeconst, carpet.dampratio, kBallSolimp);
  x += "  </contact>\n";
  x += "</mujoco>\n";
  return x;
}

}  // namespace turf
