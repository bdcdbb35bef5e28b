// A legged world: the immutable model (scene + MuJoCo model composed from the
// robot files) and the mutable state (MuJoCo data, each joint's command and
// servo reference).
//
// A step runs in named stages; inputs enter only between steps:
//   inputs   SetJointCommand / Reset (validated; a refused input changes nothing)
//   Step():  stops (rcssserver3d's hinge stops when the scene asks: which joint
//            limit rows the next mj_step1 makes, ODE's stop test)
//            mj_step1 (positions, velocities, constraint rows)
//            0 contacts (the scene's contact law on the contact rows: ode_contacts.h)
//            1 servos (commands -> each joint's motor row: target velocity and
//              force bound, as ODE's hinge motor; or, in PD mode, an explicit
//              torque on the joint, as RCSSServerMJ and the Booster SDK)
//            2 physics (mj_step2: one constraint solve, integration)
//            3 health (a non-finite state is undone)
//   outputs  State() and the accessors (read-only)
// Sensor values are MuJoCo's, computed at the start of the last mj_step (after
// it with the scene's sensors_after_step; or by a reset or placement), and so
// are the reported joint angles and speeds (as RCSSServerMJ's jointpos and
// jointvel sensors), read with them. Time is the step counter times the
// scene's step, never a wall clock.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/errors.h"
#include "core/legged/body_forces.h"
#include "core/legged/legged_scene.h"
#include "core/legged/ode_contacts.h"
#include "core/legged/root_accelerometers.h"
#include "core/mj_state.h"
#include "core/pinned.h"

namespace turf {

// kPd is RCSSServerMJ's and the Booster SDK's motor (MotorCmd): every physics
// step the joint gets the torque kp (value - q) + kd (dq - q') + tau, clamped
// to the joint's effort limit, applied explicitly (no constraint row). The
// effort limit is the joint's first `user` value in the robot file (N m; the
// reference's actuatorfrcrange), else the robot's motors.max_torque; it bounds
// the other modes' motor too. In PD mode a joint keeps its passive friction
// (the file's frictionloss), which the other modes' motor row replaces.
enum class JointMode : uint8_t { kVelocity, kPosition, kTorque, kPd };
inline constexpr int kJointModeCount = 4;

// Bounds of what a PD command may carry: guards against garbage, far beyond any
// real servo's (the T1's largest SDK gain is 550 N m/rad), not limits of the
// law. A target beyond the joint's range or a feed-forward torque above its
// effort limit is a legitimate command, as on RCSSServerMJ (whose position
// actuators have no control range) and a real servo: the law's torque is what
// gets clamped to the effort limit. The target bounds equal the RCSSServerMJ
// parser's (codecs/rcssservermj/actions.h), so whatever it accepts acts as sent.
inline constexpr double kMaxPdKp = 1e4;            // N m / rad
inline constexpr double kMaxPdKd = 1e3;            // N m s / rad
inline constexpr double kMaxPdTarget = 20 * M_PI;  // rad: ten turns (3600 deg)
inline constexpr double kMaxPdSpeed = 200 * M_PI;  // rad/s (36000 deg/s)
inline constexpr double kMaxPdTau = 1e3;           // N m, feed-forward

// A command for one joint; it holds until the next command for that joint
// (SimSpark's hinge effectors behave so). At start every joint is in velocity
// mode with target 0 (it holds its angle), or in PD mode at the scene's start
// angle and gains (LeggedRobot::start_joints).
struct JointCommand {
  std::string joint;  // the model's name, without the robot prefix ("rlj4")
  JointMode mode = JointMode::kVelocity;
  double value = 0.0;  // rad/s, rad, or N m (m/s, m, N for slide joints); kPd: target q, rad
  double kp = -1.0;    // position mode: gains; negative = the robot's defaults. kPd: >= 0
  double kd = -1.0;
  double dq = 0.0;   // kPd: target velocity, rad/s
  double tau = 0.0;  // kPd: feed-forward torque, N m
};

// Joint commands answer kOk, kUnknownRobot, kUnknownJoint, kNotFinite or
// kOutOfRange (beyond max speed, max torque or the joint's range; position
// mode: kp or kd above kMaxPdKp / kMaxPdKd; kPd: |q|, |dq|, |tau| above
// kMaxPdTarget, kMaxPdSpeed, kMaxPdTau, kp or kd negative or above kMaxPdKp /
// kMaxPdKd): core/errors.h.

// Where a robot's root body goes (a SimSpark beam, a trainer's move, parking).
struct RobotPlacement {
  std::array<double, 3> position{};               // root body origin, world frame
  std::array<double, 4> orientation{1, 0, 0, 0};  // w, x, y, z (normalised by the world)
  bool reset_joints = false;  // joints back to their start (the scene's start_joints, else zero), holding there
};

// Placements answer kOk, kUnknownRobot, kNotFinite or kNoBall (core/errors.h).

struct ForceReading {
  std::string name;            // the sensor's name in the robot file ("lf")
  std::vector<double> values;  // touch: 1 value (N); force/torque: 3 (sensor frame)
  // Touch sensors only: every contact on the site's body, summed, in the
  // site's frame (SimSpark's FRP): the force on the body, and the contact
  // point weighted by normal force. contact is false when nothing touches.
  bool contact = false;
  std::array<double, 3> force{};
  std::array<double, 3> point{};
};

// A joint as the model has it (static).
struct LeggedJointInfo {
  bool limited = false;
  double lo = 0.0;  // rad (m)
  double hi = 0.0;
  double effort_limit = 0.0;  // N m: the file's first `user` value, else motors.max_torque
  double frictionloss = 0.0;  // N m, the file's
  double armature = 0.0;      // kg m^2, the file's
};

// A body's pose in the world frame (for vision models and viewers).
struct LinkPose {
  std::string name;  // the robot file's body name ("head", "rfoot")
  std::array<double, 3> position{};
  std::array<double, 4> orientation{1, 0, 0, 0};  // w, x, y, z: world <- body
};

// A robot's collision and visual shapes, for drawing (static: the model's).
struct LeggedGeom {
  std::string body;  // the body it is fixed to (robot file name)
  enum class Shape : uint8_t { kBox, kSphere, kCapsule, kCylinder, kEllipsoid, kOther } shape = Shape::kOther;
  std::array<double, 3> size{};                   // MuJoCo's geom size (half sizes, radius, half length)
  std::array<double, 3> position{};               // in the body frame
  std::array<double, 4> orientation{1, 0, 0, 0};  // body <- geom
};

struct LeggedRobotState {
  std::string name;
  int id = 0;
  std::array<double, 3> base_position{};     // the robot's root body, world frame
  std::array<double, 4> base_orientation{};  // w, x, y, z
  std::array<double, 3> base_velocity{};     // m/s of the root body's origin, world frame (0: fixed to the world)
  std::vector<std::string> joint_names;      // hinge and slide joints, model order
  std::vector<double> joint_positions;
  std::vector<double> joint_velocities;
  std::vector<double> joint_efforts;              // torque of the joint's motor in the last step
  bool has_imu = false;                           // the model has a gyro or an accelerometer
  std::array<double, 3> gyro{};                   // rad/s, sensor frame
  std::array<double, 3> accelerometer{};          // m/s^2, proper acceleration, sensor frame
  std::array<double, 4> orientation{1, 0, 0, 0};  // framequat sensor, or the base's
  std::vector<ForceReading> forces;
  std::vector<LinkPose> links;  // every body of the robot, model order
  // The simulation time at the end of the last physics step in which a body of the robot touched the ball (-1:
  // never). A referee compares it with its last look, so no touch in any step is missed (rcssserver3d records
  // the ball's collisions of its whole 20 ms step).
  int64_t ball_touch_ns = -1;
};

// Two robots touching in the last physics step (a referee's input: rcssserver3d's charging foul).
struct RobotContact {
  int robot_a = 0;  // indices into LeggedWorldState::robots, robot_a < robot_b
  int robot_b = 0;
  std::array<double, 3> point{};  // m, world frame: the mean of the contact points between their bodies
  int points = 0;                 // how many contact points
};

struct LeggedWorldState {
  int64_t time_ns = 0;
  uint64_t frame = 0;
  std::vector<LeggedRobotState> robots;
  std::vector<RobotContact> robot_contacts;  // every pair of robots touching, ordered by (robot_a, robot_b)
  bool has_ball = false;
  std::array<double, 3> ball_position{};
  std::array<double, 3> ball_velocity{};
};

struct LeggedHealth {
  uint64_t instability_recoveries = 0;  // a non-finite step undone
  // Steps whose constraint solver stopped at physics.solver_iterations before converging: every robot's contacts
  // and motors are one problem, so then one robot's motion depends on what the others do (raise the cap).
  uint64_t solver_capped_steps = 0;
  // Over every step of this object: the constraint solver's iterations and the constraint rows it solved, a meter
  // for benches (they divide by the steps); not part of the world's state, so neither in snapshots nor reset.
  uint64_t solver_iterations = 0;
  uint64_t constraint_rows = 0;
};

// A robot's (or the ball's) motion and motor state, lifted out of one world and set down in another world that holds
// the same robot model (core/legged/legged_islands.h steps groups of robots as worlds of their own).
struct LeggedJointCarry {
  JointCommand command;
  double reference = 0.0, effort = 0.0, stop_target = 0.0, impulse = 0.0, sensed_q = 0.0, sensed_qd = 0.0;
  int row = -1, stop = 0, stop_row = -1;
};
struct LeggedCarry {
  std::vector<double> qpos, qvel, warmstart;  // its slices of MuJoCo's state and solver warm start, model order
  std::vector<LeggedJointCarry> joints;
  int64_t ball_touch_ns = -1;
};

class LeggedWorld : Pinned {
 public:
  // Throws std::invalid_argument if the scene is invalid or MuJoCo cannot
  // compile the composed model; a constructed world is always usable.
  explicit LeggedWorld(LeggedScene scene);
  ~LeggedWorld();

  const LeggedScene& scene() const { return scene_; }
  const std::string& mjcf() const { return mjcf_; }

  // --- Inputs ---
  JointCommandError SetJointCommand(int robot, const JointCommand& command);
  // What SetJointCommand would answer, changing nothing; for all-or-nothing
  // batches (the first error, kOk when every command is valid).
  JointCommandError CheckJointCommand(int robot, const JointCommand& command) const;
  JointCommandError CheckJointCommands(int robot, const std::vector<JointCommand>& commands) const;
  // Moves a robot's root body; every velocity of the robot becomes zero and
  // its joints keep their angles (unless reset_joints). Takes effect at once.
  PlacementError PlaceRobot(int robot, const RobotPlacement& placement);
  // Ball centre and linear velocity (world frame); its spin becomes zero.
  PlacementError PlaceBall(const std::array<double, 3>& position, const std::array<double, 3>& velocity);
  // Back to the scene's start: time 0, start poses, every joint holding.
  void Reset();

  // --- Snapshot: MuJoCo's data, every joint's command and servo reference,
  // counters. As World::Save/Restore.
  void Save(StateWriter& out) const;
  void Restore(StateReader& in);

  // --- One physics step through all stages ---
  void Step();

  // --- Moving robots between worlds (legged_islands.h): only between steps ---
  // The robot's (ball's) state, to land in a world built from the same robot file and scene entry.
  LeggedCarry CarryRobot(int robot) const;
  LeggedCarry CarryBall() const;  // empty without a ball
  void LandRobot(int robot, const LeggedCarry& carry);
  void LandBall(const LeggedCarry& carry);
  // A world taken up for other robots: MuJoCo's data cleared (no forward pass), every command the start one, the
  // clock at `frame`, health zero. Then every robot and the ball are landed, and Settle() makes it whole.
  void Reuse(uint64_t frame);
  // After landing: the last good state is this one; with `forward`, MuJoCo's forward pass and the sensed joints
  // too (what a reset or placement does), else the next Step computes them.
  void Settle(bool forward);
  // The box around the robot's (robot -1: the ball's) collision shapes, {min x, y, z, max x, y, z}, as of the last
  // kinematics, grown by `grow` m plus `horizon` s of its root body's speed.
  std::array<double, 6> Bounds(int robot, double grow, double horizon) const;

  // --- Outputs ---
  int RobotIndex(const std::string& name) const;  // -1 if unknown
  int RobotCount() const;
  int JointIndex(int robot, const std::string& joint) const;  // -1 if unknown
  int JointCount(int robot) const;
  // A joint's range and effort limit (N m, PD mode's clamp); all zero if unknown.
  LeggedJointInfo JointInfo(int robot, int joint) const;
  double RobotMass(int robot) const;  // kg, every body of the robot; 0 if unknown
  // The robot's centre of mass, world frame (as of the last step); zeros if unknown.
  std::array<double, 3> RobotCenterOfMass(int robot) const;
  std::vector<LeggedGeom> RobotGeoms(int robot) const;  // empty if unknown
  int64_t time_ns() const { return static_cast<int64_t>(frame_) * step_ns_; }
  uint64_t frame() const { return frame_; }
  int64_t step_ns() const { return step_ns_; }
  const LeggedHealth& health() const { return health_; }
  LeggedWorldState State() const;
  void State(LeggedWorldState* out) const;  // reuses out's storage

 private:
  struct JointSlot;
  struct SensorRef;
  struct RobotSlot;

  template <class Io, class Self>
  static void Fields(Io& io, Self& self);

  void StageStops();
  void LatchStop(JointSlot* joint) const;
  void StopRow(const JointSlot& joint, int row);
  void StopMotor(JointSlot* joint, double command, double torque);
  double ImpulseBound(JointSlot* joint) const;
  void StageServos();
  void StageBodyForces();
  void ServoPd(JointSlot* joint);
  static void SliceOf(const mjModel_* m, RobotSlot* slot);
  template <class Slot, class Carry, class Copy>
  static void EachJointField(Slot& j, Carry& c, Copy copy);
  static void ApplyStartJoints(const LeggedRobot& spec, std::vector<JointSlot>* joints);
  bool StagePhysics();
  void ResetCommands();
  void ResetCommands(RobotSlot* robot);
  void AcceptState();  // the current state is the last good one
  void SenseJoints();  // each joint's sensed angle and speed: the current ones, where MuJoCo computes its sensors
  void ContactWrench(int site, ForceReading* out) const;
  void RobotContacts(std::vector<RobotContact>* out) const;
  void RecordBallTouches();  // after a step: every robot with a body in contact with the ball
  void Forward();            // mj_forward and the readings it leaves to turf (the IMUs' accelerometers)

  LeggedScene scene_;
  std::string mjcf_;
  MjModelPtr model_;
  MjDataPtr data_;
  std::vector<RobotSlot> robots_;
  std::vector<int> robot_of_body_;                 // body -> index into robots_, -1 for none
  std::vector<int64_t> ball_touch_ns_;             // per robot, LeggedRobotState::ball_touch_ns
  std::vector<std::pair<int, int>> motor_of_dof_;  // dof -> (robot, joint), -1 for none
  Fluid air_;                                      // the scene's air (StageBodyForces), off in the model
  std::vector<mjtNum> body_wrenches_;              // per body, StageBodyForces' scratch
  std::vector<mjtNum> wrench_scratch_;
  std::unique_ptr<OdeContacts> ode_contacts_;  // the scene's contact law, when it asks for rcssserver3d's
  int impulse_steps_ = 0;  // physics steps per motor impulse window (scene physics.motor_impulse_window), 0 = off
  int stop_steps_ = 0;     // physics steps per ODE step with the scene's joint_stops, 0 = MuJoCo's limits
  std::vector<mjtNum> compiled_jnt_margin_;  // the model's joint margins as compiled (the stops change them)
  int steps_since_stop_test_ = 0;
  bool commanded_ = false;  // a joint command came in since the last step
  int ball_body_ = -1;
  int ball_qvel_ = -1;
  int64_t step_ns_ = 0;
  uint64_t frame_ = 0;
  LastGoodState last_good_;
  LeggedHealth health_;
  std::vector<RootAccelerometer> accelerometers_;  // the IMUs, read in turf's pass (root_accelerometers.h)
};

}  // namespace turf
