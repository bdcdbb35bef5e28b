// The scene: an immutable, typed description of one SSL world. Plain data with
// defaults in the declarations; filled by turf_loader from a YAML file (or by
// tests directly) and never changed while a world runs. SI units throughout.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/sensor_realism.h"

namespace turf {

enum class Division : uint8_t { kA = 1, kB = 2 };
enum class Team : uint8_t { kBlue = 0, kYellow = 1 };
inline constexpr int kTeamCount = 2;
inline constexpr int kMaxRobotsPerTeam = 16;

inline const char* TeamName(Team team) { return team == Team::kBlue ? "blue" : "yellow"; }

struct FieldParams {
  Division division = Division::kA;
  double length = 12.0;                   // goal line to goal line
  double width = 9.0;                     // touch line to touch line
  double boundary_width = 0.3;            // beyond the touch lines, to the wall
  double boundary_width_goal_line = 0.6;  // beyond the goal lines, to the wall
  double goal_width = 1.8;                // inner
  double goal_depth = 0.18;               // inner
  double goal_height = 0.16;
  double goal_wall_thickness = 0.02;
  double penalty_area_depth = 1.8;
  double penalty_area_width = 3.6;
  double center_circle_radius = 0.5;
  double line_thickness = 0.01;
  double goal_center_to_penalty_mark = 8.0;
  double wall_height = 0.16;  // boundary walls
  double wall_thickness = 0.05;
  double friction = 0.3;  // walls and goals against ball and robots
};

// The field dimensions of a division (ssl-rules.md); scene files may override.
FieldParams FieldForDivision(Division division);

struct BallParams {
  double radius = 0.0215;
  double mass = 0.046;
  // Straight two-phase model: the ball slides at acc_slide (Coulomb friction
  // with the carpet, mu = -acc_slide / g) until its speed falls to k_switch of
  // the start speed (set by its moment of inertia), then rolls at acc_roll.
  double acc_slide = -3.0;
  double acc_roll = -0.4;
  double k_switch = 0.7;
  double floor_restitution = 0.5;  // vertical speed kept at a bounce
  double wall_restitution = 0.6;   // against walls, goals and robots
  // Published for team software's chip prediction (SSL_BallModelChipFixedLoss): what this ball does, measured
  // (Physics.ThePublishedChipModelIsWhatTheBallDoes: a chip's first bounce keeps 0.683 of its horizontal speed, the
  // carpet's friction spinning it up towards rolling; the next ones 0.95).
  double chip_damping_xy_first_hop = 0.68;
  double chip_damping_xy_other_hops = 0.95;
};

struct DriveParams {
  double max_speed = 3.0;           // m/s
  double max_angular_speed = 10.0;  // rad/s
  double acc_speedup = 3.0;         // m/s^2, traction limit while speeding up
  double acc_brake = 4.5;           // m/s^2, while slowing down
  double acc_angular = 40.0;        // rad/s^2
  // Wheel positions, counter-clockwise from the robot's forward axis (rad), in
  // the order front_right, back_right, back_left, front_left.
  std::array<double, 4> wheel_angles = {-1.0471975511965976, -2.356194490192345, 2.356194490192345, 1.0471975511965976};
  // Robot centre to wheel contact: grSim's wheels (its radius 0.09 m less half the wheel's 5 mm thickness), so
  // wheel speeds a team computes for grSim turn the robot as fast as there (0.08 had turned it 9 % faster).
  double wheel_distance = 0.0875;
  double wheel_radius = 0.027;  // to convert wheel rad/s to rim m/s
};

struct KickerParams {
  double max_flat_speed = 6.5;                     // m/s, the rules' limit
  double max_chip_speed = 5.0;                     // m/s along the launch direction
  double default_chip_angle = 0.7853981633974483;  // rad (45 deg)
  double reach = 0.01;                             // ball may be this far off the face and still be kicked
  // A kick command arms the kicker; it fires at the first step the ball is
  // within reach, or is dropped after this much simulation time. Commands
  // without a kick do not disarm it, so one kick command is enough.
  double arm_time = 0.1;  // s
};

struct DribblerParams {
  // The dribbler bar's bounce: the share of its speed a ball hitting the flat front keeps (ER-Force's simulator:
  // 0.2 for the bar, against 0.6 for the robot's body), so a pass is caught rather than bounced back.
  double restitution = 0.2;
  double max_force = 1.0;           // N the dribbler can pull the ball with
  double stiffness = 40.0;          // N/m towards the hold point
  double damping = 2.0;             // N s/m relative to the hold point
  double capture_distance = 0.012;  // ball surface to face distance to grab it
};

struct RobotParams {
  double radius = 0.09;
  double height = 0.15;
  double mass = 2.5;
  double center_to_dribbler = 0.08;  // centre to the flat front face
  double friction = 0.4;             // against the ball and other robots
  DriveParams drive;
  KickerParams kicker;
  DribblerParams dribbler;
};

struct Pose2 {
  double x = 0.0;
  double y = 0.0;
  double theta = 0.0;
};

struct RobotSetup {
  Team team = Team::kBlue;
  int id = 0;
  bool on_field = true;
  Pose2 pose;
};

struct CameraParams {
  double rate_hz = 60.0;
  double height = 4.0;          // above the field
  double overlap = 0.2;         // width of the strip two neighbouring cameras share
  double focal_length = 390.0;  // pixels, for published calibrations
  int image_width = 780;
  int image_height = 580;
};

struct PhysicsParams {
  double step = 0.002;  // s
  int solver_iterations = 20;
  // Each boundary wall as this many boxes end to end (1: one box). MuJoCo 2.2 sends every robot-wall pair whose
  // bounding spheres overlap to the convex (MPR) test, and a whole wall's sphere holds the field: shorter boxes
  // keep far robots out of it. For learning (python/: turf.FAST_SSL_STEP's configuration); scenes keep 1.
  int wall_segments = 1;
};

struct RateParams {
  double world_state_hz = 100.0;
  double command_timeout = 0.5;  // s of simulation time; then the robot stops
};

struct Scene {
  std::string name = "ssl-div-a";
  uint64_t seed = 1;
  PhysicsParams physics;
  RateParams rates;
  FieldParams field;
  BallParams ball;
  RobotParams robot;
  int robots_per_team = kMaxRobotsPerTeam;  // ids 0..n-1 exist per team
  std::vector<RobotSetup> robots;           // start poses; ids not listed start off the field
  double ball_start_x = 0.0;
  double ball_start_y = 0.0;
  CameraParams cameras;
  SensorRealism realism;  // ideal unless the scene names a preset or sets values
};

// Why a scene cannot be built; empty when it can. Checks ranges and that the
// robots listed fit `robots_per_team` and stand inside the walls.
std::vector<std::string> ValidateScene(const Scene& scene);

}  // namespace turf
