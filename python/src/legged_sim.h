// turf.LeggedSim's C++ side: a LeggedKernel stepped in-process.
//
// Commands: per robot a row per joint (model order, joint_names()) of
// kJointColumns numbers {q, dq, kp, kd, tau}: the PD motor mode of
// RCSSServerMJ and the Booster SDK (core/legged/legged_world.h). A batch is
// checked whole (LeggedWorld::CheckJointCommands) before any command is set:
// a refused batch changes nothing.
// Observations: Measure(), the state at the current frame with the realism's
// sensor noise, bias and resolution (the links' delay and loss apply to the
// kernel's streams, not to this view), and the state without noise.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "kernel/legged_kernel.h"
#include "python/src/kernel_host.h"
#include "python/src/publication.h"
#include "python/src/scene_source.h"

namespace turf::py {

inline constexpr int kJointColumns = 5;

class LeggedSim : public KernelHost<LeggedKernel, LeggedPublication> {
 public:
  explicit LeggedSim(const SceneRequest& request);

  int robot_count() const { return kernel_->world().RobotCount(); }
  const std::vector<std::string>& joint_names(int robot) const;
  // The robot's index; throws SimError (unknown_robot).
  int RobotIndex(const std::string& name) const;

  struct RobotCommands {
    int robot;
    const double* rows;  // joint_names(robot).size() rows
  };
  void Step(const std::vector<RobotCommands>& commands, int64_t n);
  // What Step would refuse of `commands` (throws SimError for the first refused robot), changing nothing.
  void CheckCommands(const std::vector<RobotCommands>& commands);
  void SetJointCommand(int robot, const JointCommand& command);
  void PlaceRobot(int robot, const RobotPlacement& placement);
  void PlaceBall(const std::array<double, 3>& position, const std::array<double, 3>& velocity);
  void SetRealism(const std::string& preset, const std::vector<std::pair<std::string, double>>& values);
  void Reset(std::optional<uint64_t> seed);
  void Restore(const std::string& snapshot);

  const LeggedWorldState& measured() const { return measured_; }
  const LeggedWorldState& truth() const { return truth_; }

 private:
  void CheckRobot(int robot) const;
  void Refresh();
  // After an input that changed the state outside a step (teleport, reset, restore).
  void StateChanged(bool released = false);

  LeggedWorldState measured_, truth_;
  std::vector<std::vector<std::string>> joint_names_;
  std::vector<std::vector<JointCommand>> batch_;
};

}  // namespace turf::py
