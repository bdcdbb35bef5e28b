#include "python/src/legged_sim.h"

#include "python/src/controls.h"
#include "python/src/sim_error.h"

namespace turf::py {

LeggedSim::LeggedSim(const SceneRequest& request) : KernelHost(std::make_unique<LeggedKernel>(LoadLegged(request))) {
  Refresh();
  for (const LeggedRobotState& r : truth_.robots) joint_names_.push_back(r.joint_names);
}

const std::vector<std::string>& LeggedSim::joint_names(int robot) const {
  CheckRobot(robot);
  return joint_names_[robot];
}

void LeggedSim::CheckRobot(int robot) const {
  if (robot < 0 || robot >= robot_count()) Check(Error::kUnknownRobot, "robot " + std::to_string(robot));
}

int LeggedSim::RobotIndex(const std::string& name) const {
  const int index = kernel_->world().RobotIndex(name);
  if (index < 0) Check(Error::kUnknownRobot, "robot '" + name + "'");
  return index;
}

void LeggedSim::CheckCommands(const std::vector<RobotCommands>& commands) {
  batch_.assign(commands.size(), {});
  for (size_t i = 0; i < commands.size(); ++i) {
    const int robot = commands[i].robot;
    CheckRobot(robot);
    const std::vector<std::string>& names = joint_names_[robot];
    for (size_t j = 0; j < names.size(); ++j) {
      const double* row = commands[i].rows + j * kJointColumns;
      JointCommand c;
      c.joint = names[j];
      c.mode = JointMode::kPd;
      c.value = row[0];
      c.dq = row[1];
      c.kp = row[2];
      c.kd = row[3];
      c.tau = row[4];
      batch_[i].push_back(std::move(c));
    }
    Check(kernel_->world().CheckJointCommands(robot, batch_[i]),
          "joint commands of robot '" + kernel_->scene().robots[robot].name + "'");
  }
}

void LeggedSim::Step(const std::vector<RobotCommands>& commands, int64_t n) {
  CheckStepCount(n);
  CheckCommands(commands);
  for (size_t i = 0; i < commands.size(); ++i) kernel_->SetJointCommands(commands[i].robot, batch_[i]);
  for (int64_t i = 0; i < n; ++i) {
    kernel_->Step();
    if (publication_) publication_->AfterStep(*kernel_);
  }
  Refresh();
  if (publication_) publication_->PublishState(*kernel_);
}

void LeggedSim::SetJointCommand(int robot, const JointCommand& command) {
  CheckRobot(robot);
  Check(kernel_->SetJointCommands(robot, {command}), "joint command '" + command.joint + "'");
}

void LeggedSim::PlaceRobot(int robot, const RobotPlacement& placement) {
  CheckRobot(robot);
  Check(kernel_->PlaceRobot(robot, placement), "robot teleport");
  StateChanged();
}

void LeggedSim::PlaceBall(const std::array<double, 3>& position, const std::array<double, 3>& velocity) {
  Check(kernel_->PlaceBall(position, velocity), "ball teleport");
  StateChanged();
}

void LeggedSim::SetRealism(const std::string& preset, const std::vector<std::pair<std::string, double>>& values) {
  ChangeRealism(preset, values);
  Refresh();
}

void LeggedSim::Reset(std::optional<uint64_t> seed) {
  ResetKernel(seed);
  StateChanged(/*released=*/true);
}

void LeggedSim::Restore(const std::string& snapshot) {
  RestoreKernel(snapshot);
  StateChanged();
}

// As turf-sim: a reset publishes the readings its streams released.
void LeggedSim::StateChanged(bool released) {
  Refresh();
  if (publication_) publication_->StateChanged(*kernel_, released);
}

void LeggedSim::Refresh() {
  kernel_->Measure(&measured_);
  kernel_->world().State(&truth_);
}

}  // namespace turf::py
