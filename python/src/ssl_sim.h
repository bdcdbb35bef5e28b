// turf.SslSim's C++ side: an SslKernel stepped in-process, its outputs kept
// in flat arrays the module hands to NumPy (ball and robots without copies).
//
// Commands: per team a row per robot id (0..robots_per_team-1) of
// kCommandColumns numbers, {vx, vy, omega, kick_speed, chip, dribbler_rpm}:
// velocities in the robot's frame (m/s, rad/s), a kick when kick_speed > 0
// (chip 0: flat, 1: chip at the scene's angle), dribbler in rpm. A batch is
// checked whole (SslKernel::CheckCommandInput) before any command is sent:
// a refused batch changes nothing. Sent commands travel the team's modelled
// radio link.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "kernel/ssl_kernel.h"
#include "python/src/kernel_host.h"
#include "python/src/publication.h"
#include "python/src/scene_source.h"

namespace turf::py {

inline constexpr int kCommandColumns = 6;
inline constexpr int kBallColumns = 6;           // x, y, z, vx, vy, vz
inline constexpr int kRobotColumns = 9;          // x, y, yaw, vx, vy, omega, on_field, ball_contact, kick_count
inline constexpr int kBallDetectionColumns = 7;  // camera, frame, capture_time, x, y, z, confidence
inline constexpr int kRobotDetectionColumns =
    9;                                   // camera, frame, capture_time, team, id, x, y, orientation, confidence
inline constexpr int kFrameColumns = 4;  // camera, frame, capture_time, sent_time

class SslSim : public KernelHost<SslKernel, SslPublication> {
 public:
  explicit SslSim(const SceneRequest& request);

  int robots_per_team() const { return kernel_->scene().robots_per_team; }
  int robot_count() const { return static_cast<int>(kernel_->state().robots.size()); }

  // A team's commands: rows * kCommandColumns numbers, rows == robots_per_team (checked by the caller).
  struct TeamCommands {
    Team team;
    const double* rows;
  };
  // Checks every command (throws SimError for the first refused one), sends them, then runs `n` physics steps.
  void Step(const std::vector<TeamCommands>& commands, int64_t n);
  // What Step would refuse of `commands`, changing nothing.
  void CheckCommands(const std::vector<TeamCommands>& commands);
  // One command with every field (wheel speeds, global velocity, chip angle).
  void Command(const RobotCommand& command);

  void TeleportBall(const BallTeleport& teleport);
  void TeleportRobot(const RobotTeleport& teleport);
  void SetRealism(const std::string& preset, const std::vector<std::pair<std::string, double>>& values);
  // Back to the scene's start; a new seed rebuilds the kernel (the realism is kept).
  void Reset(std::optional<uint64_t> seed);
  void Restore(const std::string& snapshot);

  // Outputs, refreshed by every input and step. ball/robots have a fixed size (views stay valid).
  const double* ball() const { return ball_.data(); }
  const double* robots() const { return robots_.data(); }
  const std::vector<int32_t>& robot_ids() const { return robot_ids_; }  // team, id per robot
  // Camera output released during the last Step call (rows of the *Columns above).
  const std::vector<double>& ball_detections() const { return ball_detections_; }
  const std::vector<double>& robot_detections() const { return robot_detections_; }
  const std::vector<double>& frames() const { return frames_; }

 private:
  RobotCommand FromRow(Team team, int id, const double* row) const;
  void CollectCameras();
  void Refresh();
  void ClearCameras();
  // After an input that changed the state outside a step (teleport, reset, restore).
  void StateChanged();

  SceneRequest request_;
  std::array<double, kBallColumns> ball_{};
  std::vector<double> robots_;
  std::vector<int32_t> robot_ids_;
  std::vector<double> ball_detections_, robot_detections_, frames_;
  std::vector<RobotCommand> batch_;
};

}  // namespace turf::py
