// A legged scene stepped on physics.island_threads threads: its robots in groups, each group a LeggedWorld of its
// own (the field, those robots, and the ball in the group that has it), stepped side by side.
//
// Robots that touch only the ground and the field are separate constraint islands: MuJoCo >= 3.3.6 (RCSSServerMJ's
// 3.4) and ODE (rcssserver3d's) solve each island apart. Debian's MuJoCo 2.2.2 solves every contact and motor of
// one model as one problem on one core, so turf forms the groups itself. Before each step:
//   bounds  every robot's and the ball's box around its collision shapes, grown by what it can move in two steps
//   islands boxes that overlap join one island (union-find): they may touch within the step
//   groups  kept while no island spans two groups; else (or, after a second, when a better balance saves four
//           robots) islands are dealt to the groups largest first, each to the group with fewest robots
//   move    robots that change group are carried (state, warm start, commands) into a world of the new make-up
// then the groups step, one per thread, and join. A group's world is compiled once per make-up (the robot models
// in order, with or without the ball) and kept for reuse, with canonical names and places: its state comes only
// from what is landed in it, so the bytes of a run do not depend on which worlds were compiled before.
//
// The public interface is LeggedWorld's (legged_world.h), which has the contract of each call. With one thread (or
// one robot) the scene is one LeggedWorld, stepped as before.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/legged/legged_world.h"
#include "core/pinned.h"
#include "core/state_io.h"

namespace turf {

class WorkerThread;

class LeggedIslands : Pinned {
 public:
  // Throws std::invalid_argument as LeggedWorld's constructor.
  explicit LeggedIslands(LeggedScene scene);
  ~LeggedIslands();

  const LeggedScene& scene() const { return scene_; }

  // --- Inputs ---
  JointCommandError SetJointCommand(int robot, const JointCommand& command);
  JointCommandError CheckJointCommand(int robot, const JointCommand& command) const;
  JointCommandError CheckJointCommands(int robot, const std::vector<JointCommand>& commands) const;
  PlacementError PlaceRobot(int robot, const RobotPlacement& placement);
  PlacementError PlaceBall(const std::array<double, 3>& position, const std::array<double, 3>& velocity);
  void Reset();

  // --- Snapshot: the groups and each group's world ---
  void Save(StateWriter& out) const;
  void Restore(StateReader& in);

  // --- One physics step: regroup if needed, then every group's world ---
  void Step();

  // --- Outputs ---
  int RobotIndex(const std::string& name) const;
  int RobotCount() const { return static_cast<int>(scene_.robots.size()); }
  int JointIndex(int robot, const std::string& joint) const;
  int JointCount(int robot) const { return WorldOf(robot).JointCount(SlotOf(robot)); }
  LeggedJointInfo JointInfo(int robot, int joint) const;
  double RobotMass(int robot) const;
  std::array<double, 3> RobotCenterOfMass(int robot) const;
  std::vector<LeggedGeom> RobotGeoms(int robot) const;
  int64_t time_ns() const { return static_cast<int64_t>(frame_) * step_ns_; }
  uint64_t frame() const { return frame_; }
  int64_t step_ns() const { return step_ns_; }
  const LeggedHealth& health() const;
  LeggedWorldState State() const;
  void State(LeggedWorldState* out) const;

  // --- The grouping (tests, benches, logs) ---
  int GroupCount() const { return static_cast<int>(groups_.size()); }
  int GroupOf(int robot) const { return group_of_.at(static_cast<size_t>(robot)); }
  int BallGroup() const;                           // -1 without a ball
  uint64_t regroups() const { return regroups_; }  // since construction (not world state)

 private:
  struct Group {
    std::vector<int> robots;  // scene indices, ascending: robot robots[k] is the world's robot k
    bool ball = false;
    std::unique_ptr<LeggedWorld> world;
  };
  // An assignment of robots (and the ball) to groups.
  struct Plan {
    std::vector<std::vector<int>> robots;
    int ball = -1;
  };

  bool Split() const { return threads_ > 1; }
  LeggedWorld& WorldOf(int robot) const { return *groups_[group_of_[robot]].world; }
  int SlotOf(int robot) const { return slot_of_[robot]; }
  std::string Key(const std::vector<int>& robots, bool ball) const;
  LeggedScene GroupScene(const std::vector<int>& robots, bool ball) const;
  std::unique_ptr<LeggedWorld> Take(const std::vector<int>& robots, bool ball);
  // The worlds of `plan` in place of the current ones (given back as spares), their state as it was left.
  void Install(const Plan& plan);
  std::vector<std::vector<int>> Islands(const std::vector<std::array<double, 6>>& boxes) const;
  Plan Deal(const std::vector<std::vector<int>>& islands) const;
  std::vector<std::array<double, 6>> Boxes() const;
  bool Spans(const std::vector<std::vector<int>>& islands) const;
  int Imbalance(const Plan& plan) const;
  Plan Current() const;
  void Regroup();
  // The worlds of `plan`, each taken up at `frame` with the carried state (robots by scene index, then the ball).
  void Apply(const Plan& plan, uint64_t frame, const std::vector<LeggedCarry>& robots, const LeggedCarry& ball,
             bool forward);

  LeggedScene scene_;
  int threads_ = 1;
  int64_t step_ns_ = 0;
  uint64_t frame_ = 0;
  uint64_t regrouped_frame_ = 0;  // the frame of the last change of groups
  std::vector<int> kind_;         // per robot: the first robot of the scene with the same model and entry
  std::vector<Group> groups_;
  std::vector<int> group_of_;              // per robot
  std::vector<int> slot_of_;               // per robot: its index in its group's world
  std::vector<LeggedCarry> start_robots_;  // the scene's start, as a whole world has it after Reset
  LeggedCarry start_ball_;
  Plan start_plan_;
  std::map<std::string, std::vector<std::unique_ptr<LeggedWorld>>> spare_;  // by Key(): worlds not in use
  std::vector<std::unique_ptr<WorkerThread>> workers_;                      // threads_ - 1
  LeggedHealth retired_;                                                    // of worlds given back
  mutable LeggedHealth health_;
  mutable std::vector<LeggedWorldState> scratch_;
  uint64_t regroups_ = 0;
};

}  // namespace turf
