// A legged scene: any MJCF robots placed on a ground (optionally the RoboCup
// 3D soccer field and ball). Plain typed data with defaults; filled by
// loader/legged_scene_yaml.* and checked by ValidateLeggedScene. The robot
// models arrive as MJCF text: core never opens files.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/sensor_realism.h"

namespace turf {

struct LeggedPhysics {
  double step = 0.002;  // s
  int solver_iterations = 50;
  // The IMU, the links' poses and the other position and velocity sensors as they are after each step (as ODE's
  // perceptors read them: rcssserver3d's scenes), instead of MuJoCo's values from the start of the last step
  // (what mj_step leaves, and what RCSSServerMJ reads).
  bool sensors_after_step = false;
  // s, 0 = off: a velocity motor's force bound holds for its impulse since the window began (max_torque x the
  // time elapsed in it), so a physics step may make up what the window's earlier steps left unspent, as ODE's
  // motor bounds the force of one whole step (the reference's 20 ms; rcssserver3d's scenes).
  double motor_impulse_window = 0.0;
  // MuJoCo's fluid forces on every body (<option density viscosity>): RCSSServerMJ's air, 1.2 kg/m^3 and
  // 2e-5 Pa s. 0 = none (SimSpark has no air).
  double fluid_density = 0.0;
  double fluid_viscosity = 0.0;
  // rcssserver3d's DragController on every body of a robot (rsg/agent/nao/dragcontroller.rsg): before each step a
  // force -linear v (N s/m, v the body's centre-of-mass velocity) and a torque -angular w (N m s/rad), both in the
  // world frame. 0 = none.
  double body_linear_drag = 0.0;
  double body_angular_drag = 0.0;
  // Threads that step the scene's robots, in groups that cannot touch each other in the next step (they touch only
  // the ground and the field: MuJoCo >= 3.3.6's and ODE's constraint islands, solved apart as those engines do),
  // each group a world of its own (core/legged/legged_islands.h). 1: one world, one solve for everything.
  int island_threads = 1;
};

struct LeggedRates {
  double joint_state_hz = 50.0;  // joints, IMU, force sensors (SimSpark's cycle is 50 Hz)
};

// Joint motors (per robot). Velocity mode is SimSpark's hinge motor (ODE's
// dParamVel/dParamFMax): a velocity constraint solved with the contacts in
// each step, reaching the target within the step unless that needs more than
// max_torque. Position mode is an implicit PD with the command's gains, or
// these defaults, bounded by max_torque too.
struct MotorParams {
  double max_torque = 10.0;   // N m, SimSpark's motor FMax (for joints without an effort limit in the file)
  double max_speed = 6.1395;  // rad/s, |target velocity| is clamped to it
  double position_kp = 50.0;  // default gains of position mode
  double position_kd = 1.0;
  // Unused since velocity mode is a constraint (no reference-angle PD); still
  // accepted so that scene files that set them keep loading.
  double velocity_kp = 200.0;
  double velocity_kd = 2.0;
  double max_reference_lead = 0.05;
};

// A joint's start: its angle at the scene's start (and after a reset), and the
// PD motor (JointMode::kPd) that holds it there with these gains until the
// first command for that joint. Joints not listed start at the model's zero
// pose in velocity mode (target 0).
struct JointStart {
  std::string joint;      // the robot file's joint name
  double position = 0.0;  // rad (m for slide joints)
  double kp = 0.0;        // N m / rad
  double kd = 0.0;        // N m s / rad
};

// A camera declared in the scene for one robot (robots[].cameras): overrides of the robot file's MJCF camera of
// that name, or a new camera on `body`. Absent values: the MJCF camera's, else the defaults of CameraSpec
// (core/camera/camera_model.h). Resolved against the compiled model by core/legged/legged_cameras.h.
struct CameraDecl {
  std::string name;
  std::optional<std::string> body;
  std::optional<std::array<double, 3>> pos;
  std::optional<std::array<double, 6>> xyaxes;  // image right and image up, in the body frame (MJCF's xyaxes)
  std::optional<int> width;
  std::optional<int> height;
  std::optional<double> hfov;  // rad
  std::optional<double> rate_hz;
  std::optional<std::string> encoding;  // rgb8, yuv422, jpeg
  std::optional<int> jpeg_quality;
  std::optional<double> noise_stddev;
  std::optional<bool> enabled;
};

// One placement of a robot model.
struct LeggedRobot {
  std::string name;       // unique; prefixes every named element ("nao_1/lj4")
  int id = 0;             // free number (e.g. a SimSpark unum)
  std::string model;      // label of the model (e.g. its file name), for logs
  std::string model_xml;  // the robot's MJCF text
  double x = 0.0;         // ground point under the robot's model origin, m
  double y = 0.0;
  double yaw = 0.0;  // rad about z
  // Height of the root body's origin above the ground; none = the robot
  // file's (its top-level body's pos z).
  std::optional<double> z;
  MotorParams motors;
  // The 3D league's Nao robot type 0..4 the body was built as (core/legged/nao_types.h; scene key nao_type), so
  // that a front-end gives an agent a robot of the type it asks for; -1: not a typed Nao.
  int robot_type = -1;
  std::vector<JointStart> start_joints;
  std::vector<CameraDecl> cameras;  // besides the robot file's MJCF cameras, which are all declared
};

// The RoboCup 3D soccer field (SimSpark), see shared/protocols/simspark.md.
struct Field3d {
  bool enabled = false;
  double length = 30.0;
  double width = 20.0;
  double goal_width = 2.1;
  double goal_depth = 0.6;
  double goal_height = 0.8;
  double goal_wall = 0.04;
  double ball_radius = 0.042;
  double ball_mass = 0.026;
  double ball_x = 0.0;
  double ball_y = 0.0;
  // The ball's MuJoCo contact: geom friction (sliding, torsional, rolling), condim, solref (RCSSServerMJ's ball:
  // 0.4 0.01 0.01, 6, -5000 -20; a contact takes the larger friction and condim of its two geoms).
  std::array<double, 3> ball_friction{0.6, 0.005, 0.0001};
  int ball_condim = 3;
  std::array<double, 2> ball_solref{0.02, 1.0};
  int ball_priority = 0;  // MuJoCo's geom priority: 1 = the ball's own parameters rule its contacts (RCSSServerMJ's)
  // Drag on the ball: a force -linear v and a torque -angular w (SimSpark's DragController on its ball: 0.01 N s/m
  // and 0.00005 N m s/rad), as the damping of the ball's free joint (MuJoCo integrates it implicitly).
  double ball_linear_drag = 0.0;
  double ball_angular_drag = 0.0;
  double wall_distance = 25.0;  // |x|, |y| of the outer walls' centres
  // The four outer walls. RCSSServerMJ's field has none (nothing stops a ball or robot leaving the field); its scene
  // turns them off, which also saves their collision tests against every robot geom in each step.
  bool walls = true;
  // false: the field without its ball (a world stepping some of a scene's robots apart, core/legged/legged_islands.h).
  bool ball = true;
};

// One surface's contact parameters in ODE's terms (core/legged/ode_contacts.h); negative = not set.
struct OdeSurface {
  double erp = -1.0;         // soft ERP
  double cfm = -1.0;         // soft CFM
  double slip = -1.0;        // force-dependent slip, m/(s N)
  double bounce = -1.0;      // restitution in [0, 1]: a contact leaves at least bounce x the speed it came in at
  double bounce_vel = -1.0;  // m/s: ... when it came in faster than this
};

// rcssserver3d's contact law for robots on the ground (ode_contacts.h). Off: MuJoCo's own contacts.
struct OdeContactLaw {
  bool enabled = false;
  // true: ODE's normal spring-damper too (`law: ode`); false: only the tangential law, on MuJoCo's own normal
  // contact (`law: ode_friction`).
  bool ode_normal = true;
  double reference_step = 0.02;  // s: the step ERP and CFM were given for
  double surface_layer = 0.001;  // m of penetration left alone
  double world_erp = 0.2;        // where no surface sets ERP / CFM
  double world_cfm = 1e-5;
  OdeSurface robot;   // every robot geom
  OdeSurface ground;  // the floor
  OdeSurface ball;    // the ball (nothing set: its contacts keep MuJoCo's own law)
};

// rcssserver3d's hinge stops (ODE's joint limit with the Nao's parameters, rsg/agent/nao/hingejoint.rsg), in
// place of MuJoCo's limit for every limited joint. ODE tests a limit only at the start of its step: a joint
// inside its range moves freely for the whole step (a full step beyond the stop at speed); a joint at or beyond
// it gets a one-sided row for the whole step with the target velocity -erp * depth / step, or -bounce times its
// incoming velocity if that is faster (bounce 1 throws it back as fast as it came). During such a step the
// joint's motor is no velocity row but its full torque in the commanded direction, or fudge times it when the
// command points away from the stop (ODE's addLimot). hold_commands_at_stop: a velocity command is taken only
// while the joint is strictly inside its range, else the old one stays (rcssserver3d's HingeEffector).
struct OdeJointStops {
  bool enabled = false;
  double step = 0.02;  // s: ODE's step (the stop is tested every step / physics.step physics steps)
  double erp = 0.8;
  double bounce = 1.0;
  double fudge = 1e-5;
  bool hold_commands_at_stop = true;
};

struct LeggedScene {
  std::string name = "legged";
  uint64_t seed = 1;
  LeggedPhysics physics;
  LeggedRates rates;
  Field3d field;
  double ground_friction = 1.0;
  OdeContactLaw contacts;
  OdeJointStops joint_stops;
  // Encoders and IMU (realism.encoder, realism.imu); the camera and radio
  // parts are the SSL world's and unused here. Ideal by default.
  SensorRealism realism;
  std::vector<LeggedRobot> robots;
};

// Problems with the values (not with the MJCF text, which the world compiles);
// empty when valid.
// At most this many robots in a scene (RCSSServerMJ's match: 22): MuJoCo 2.2.2's constraint arrays grow with the
// square of the contacts a scene allows.
inline constexpr size_t kMaxLeggedRobots = 32;

std::vector<std::string> ValidateLeggedScene(const LeggedScene& scene);

}  // namespace turf
