// One SSL world: the immutable model (scene + compiled MuJoCo model) and the
// mutable state (MuJoCo data, per-robot commands and feedback).
//
// A step runs in named stages; inputs enter only between steps:
//   inputs   SetCommand / TeleportBall / TeleportRobot / Reset (validated)
//   Step():  1 watchdog  2 drive  3 ball handling (kick, dribble)
//            4 ball model  5 physics (mj_step's calls; between MuJoCo's collision and its constraints, the dribbler
//            bar's contacts)  6 containment  7 feedback
//   outputs  Snapshot() and the accessors (read-only)
// Time is the step counter times the scene's step: never a wall clock.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/ball_handling.h"
#include "core/mj_state.h"
#include "core/pinned.h"
#include "core/scene.h"
#include "core/types.h"

namespace turf {

// A robot as the world reports it: its pose and velocity (RobotKinematics: x, y, yaw, vx, vy, omega) and more.
struct RobotSnapshot : RobotKinematics {
  Team team = Team::kBlue;
  int id = 0;
  bool on_field = false;
  bool ball_contact = false;
  uint32_t kick_count = 0;
  KickKind last_kick = KickKind::kNone;
};

using BallSnapshot = BallState;

struct WorldSnapshot {
  int64_t time_ns = 0;
  uint64_t frame = 0;
  BallSnapshot ball;
  std::vector<RobotSnapshot> robots;  // every robot of the model, team-major
};

// Counters of what the world corrected to stay sane; non-zero values are worth
// a log line.
struct WorldHealth {
  uint64_t containment_corrections = 0;  // a body pushed back inside the walls
  uint64_t instability_recoveries = 0;   // a non-finite step undone
  uint64_t solver_capped_steps = 0;      // the constraint solver stopped at physics.solver_iterations
};

class World : Pinned {
 public:
  // Throws std::invalid_argument if the scene fails ValidateScene or MuJoCo
  // cannot compile it; a constructed World is always usable.
  explicit World(Scene scene);
  ~World();

  const Scene& scene() const { return scene_; }

  // --- Inputs: validated; a refused input changes nothing. ---
  InputError SetCommand(const RobotCommand& command);
  InputError TeleportBall(const BallTeleport& teleport);
  InputError TeleportRobot(const RobotTeleport& teleport);
  // Back to the scene's start: time 0, start poses, no commands.
  void Reset();

  // --- Snapshot: everything mutable (MuJoCo's data, commands, kickers,
  // counters); a restored world steps on exactly as the saved one. A snapshot
  // of another scene fails the reader; after a failed read the world is
  // inconsistent until Reset (the kernel restores its backup).
  void Save(StateWriter& out) const;
  void Restore(StateReader& in);

  // --- One physics step through all stages. ---
  void Step();

  // --- Outputs. ---
  int64_t time_ns() const { return frame_ * step_ns_; }
  uint64_t frame() const { return frame_; }
  int64_t step_ns() const { return step_ns_; }
  const WorldHealth& health() const { return health_; }
  WorldSnapshot Snapshot() const;
  void Snapshot(WorldSnapshot* out) const;  // reuses out's storage
  // Index of a robot in Snapshot().robots, or -1 if the scene has no such robot.
  int RobotIndex(Team team, int id) const;

 private:
  struct RobotSlot;

  template <class Io, class Self>
  static void Fields(Io& io, Self& self);

  RobotKinematics Kinematics(const RobotSlot& slot) const;
  BallState Ball() const;
  double FloorNormalForce() const;
  void PlaceRobot(RobotSlot& slot, double x, double y, double yaw, const Vec3& velocity);
  void StageWatchdog();
  void StageDrive();
  void StageBallHandling();
  void StageBallModel();
  void StageDribblerContacts();
  bool StagePhysics();
  void StageContainment();
  void StageFeedback();

  Scene scene_;
  MjModelPtr model_;
  MjDataPtr data_;
  std::vector<RobotSlot> robots_;
  int ball_qpos_ = 0;
  int ball_qvel_ = 0;
  int ball_body_ = 0;
  int ball_geom_ = 0;
  int floor_geom_ = 0;
  double floor_normal_force_ = 0.0;  // carpet on ball, from the last step
  double ball_inertia_ = 0.0;
  int64_t step_ns_ = 0;
  uint64_t frame_ = 0;
  LastGoodState last_good_;
  WorldHealth health_;
};

}  // namespace turf
