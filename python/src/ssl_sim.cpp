#include "python/src/ssl_sim.h"

#include <cmath>

#include "python/src/controls.h"
#include "python/src/sim_error.h"

namespace turf::py {

namespace {

std::string RobotName(Team team, int id) { return std::string(TeamName(team)) + " robot " + std::to_string(id); }

}  // namespace

SslSim::SslSim(const SceneRequest& request)
    : KernelHost(std::make_unique<SslKernel>(LoadSsl(request))), request_(request) {
  robots_.resize(static_cast<size_t>(robot_count()) * kRobotColumns);
  for (const RobotSnapshot& r : kernel_->state().robots) {
    robot_ids_.push_back(static_cast<int32_t>(r.team));
    robot_ids_.push_back(r.id);
  }
  Refresh();
}

// The chip column is an enum (0 flat, 1 chip): anything else is refused as the IDL's unknown enum values are.
RobotCommand SslSim::FromRow(Team team, int id, const double* row) const {
  RobotCommand c;
  c.team = team;
  c.id = id;
  c.move = MoveKind::kLocalVelocity;
  c.velocity = {row[0], row[1], row[2]};
  c.kick_speed = row[3];
  if (!std::isfinite(row[4])) Check(Error::kNotFinite, RobotName(team, id) + " chip");
  if (row[4] != 0.0 && row[4] != 1.0) Check(Error::kUnknownEnum, RobotName(team, id) + " chip (0 or 1)");
  c.kick = row[3] > 0.0 ? (row[4] == 1.0 ? KickKind::kChip : KickKind::kFlat) : KickKind::kNone;
  c.dribbler_speed = row[5];
  return c;
}

void SslSim::CheckCommands(const std::vector<TeamCommands>& commands) {
  batch_.clear();
  for (const TeamCommands& t : commands) {
    for (int id = 0; id < robots_per_team(); ++id) {
      batch_.push_back(FromRow(t.team, id, t.rows + static_cast<size_t>(id) * kCommandColumns));
      Check(kernel_->CheckCommandInput(t.team, batch_.back()), RobotName(t.team, id) + " command");
    }
  }
}

void SslSim::Step(const std::vector<TeamCommands>& commands, int64_t n) {
  CheckStepCount(n);
  CheckCommands(commands);
  for (const RobotCommand& c : batch_) kernel_->Command(c.team, c);
  ClearCameras();
  for (int64_t i = 0; i < n; ++i) {
    kernel_->Step();
    CollectCameras();
    if (publication_) publication_->AfterStep(*kernel_);
  }
  Refresh();
  if (publication_) publication_->PublishState(*kernel_);
}

void SslSim::Command(const RobotCommand& command) {
  Check(kernel_->Command(command.team, command), RobotName(command.team, command.id) + " command");
}

void SslSim::TeleportBall(const BallTeleport& teleport) {
  Check(kernel_->TeleportBall(teleport), "ball teleport");
  StateChanged();
}

void SslSim::TeleportRobot(const RobotTeleport& teleport) {
  Check(kernel_->TeleportRobot(teleport), RobotName(teleport.team, teleport.id) + " teleport");
  StateChanged();
}

void SslSim::SetRealism(const std::string& preset, const std::vector<std::pair<std::string, double>>& values) {
  ChangeRealism(preset, values);
}

void SslSim::Reset(std::optional<uint64_t> seed) {
  ResetKernel(seed);
  StateChanged();
}

void SslSim::Restore(const std::string& snapshot) {
  RestoreKernel(snapshot);
  StateChanged();
}

// A teleport, reset or restore: the observation it returns holds no camera frames (none was released since).
void SslSim::StateChanged() {
  ClearCameras();
  Refresh();
  if (publication_) publication_->PublishState(*kernel_, /*force=*/true);
}

void SslSim::ClearCameras() {
  ball_detections_.clear();
  robot_detections_.clear();
  frames_.clear();
}

void SslSim::CollectCameras() {
  for (const CameraFrame& f : kernel_->camera_frames()) {
    const double cam = f.camera_id, number = static_cast<double>(f.frame_number), t = f.capture_time_ns * 1e-9;
    frames_.insert(frames_.end(), {cam, number, t, f.sent_time_ns * 1e-9});
    for (const DetectedBall& b : f.balls)
      ball_detections_.insert(ball_detections_.end(),
                              {cam, number, t, b.position.x, b.position.y, b.position.z, b.confidence});
    for (const DetectedRobot& r : f.robots)
      robot_detections_.insert(robot_detections_.end(),
                               {cam, number, t, static_cast<double>(r.team), static_cast<double>(r.id), r.x, r.y,
                                r.orientation, r.confidence});
  }
}

void SslSim::Refresh() {
  const WorldSnapshot& s = kernel_->state();
  const BallSnapshot& b = s.ball;
  ball_ = {b.position.x, b.position.y, b.position.z, b.velocity.x, b.velocity.y, b.velocity.z};
  double* out = robots_.data();
  for (const RobotSnapshot& r : s.robots) {
    const double row[kRobotColumns] = {r.x,
                                       r.y,
                                       r.yaw,
                                       r.vx,
                                       r.vy,
                                       r.omega,
                                       static_cast<double>(r.on_field),
                                       static_cast<double>(r.ball_contact),
                                       static_cast<double>(r.kick_count)};
    std::copy(row, row + kRobotColumns, out);
    out += kRobotColumns;
  }
}

}  // namespace turf::py
