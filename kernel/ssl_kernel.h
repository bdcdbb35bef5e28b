// The SSL simulation kernel: a World plus everything that gives it SSL
// semantics and realism, as one mutable state with a byte snapshot. No DDS,
// no sockets, no clock: a driver (turf-sim's node, a test, later Python) feeds
// inputs, calls Step() when it decides to, and reads the outputs.
//
// Inputs (between steps; each validated, a refused one changes nothing):
//   Command          a team's robot command; it travels the team's modelled
//                    radio link and reaches the robot when its delay has passed
//   TeleportBall, TeleportRobot, SetRealism, Reset
// Step(), in stages (time is the world's frame counter, a value):
//   pre     commands whose radio delay has passed reach their robots
//   update  the world's physics step (world.h has its own stages)
//   post    cameras capture and release frames through their links; robot
//           feedback on change; stream statistics every second of sim time
// Outputs (valid until the next Step or Reset): state(), camera_frames(),
// feedback(), stats().
// Save()/Restore(): every mutable part, random streams included; a restored
// kernel produces the same outputs, byte for byte, as the saved one would.
#pragma once

#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/link_model.h"
#include "core/ssl_cameras.h"
#include "core/stream_stats.h"
#include "core/world.h"
#include "kernel/snapshots.h"
#include "kernel/stats_window.h"
#include "kernel/stream_report.h"

namespace turf {

class SslKernel : public Snapshots<SslKernel, KernelKind::kSsl> {
 public:
  // Throws std::invalid_argument for an invalid scene.
  explicit SslKernel(Scene scene);

  const Scene& scene() const { return world_.scene(); }
  const World& world() const { return world_; }
  const std::vector<CameraSpec>& cameras() const { return cameras_.cameras(); }
  const SensorRealism& realism() const { return realism_; }
  int64_t time_ns() const { return world_.time_ns(); }
  uint64_t frame() const { return world_.frame(); }

  // --- Inputs ---
  // A command read from `topic_team`'s command stream: refused if it names
  // the other team (kWrongTeam), an unknown robot or out-of-range values.
  InputError Command(Team topic_team, const RobotCommand& command);
  // What Command would answer, changing nothing (for all-or-nothing batches).
  InputError CheckCommandInput(Team topic_team, const RobotCommand& command) const;
  // Teleports show in state() at once.
  InputError TeleportBall(const BallTeleport& teleport);
  InputError TeleportRobot(const RobotTeleport& teleport);
  // Empty on success, else why the realism is unusable.
  std::string SetRealism(const SensorRealism& realism);
  void Reset();

  // --- One step through all stages ---
  void Step();

  // --- Outputs ---
  const WorldSnapshot& state() const { return state_; }
  // Camera frames that reached the network in the last step, oldest first.
  const std::vector<CameraFrame>& camera_frames() const { return camera_frames_; }
  // Robots whose ball contact or kick count changed in the last step.
  const std::vector<RobotSnapshot>& feedback() const { return feedback_; }
  // Set in the step that closes a one-second window of sim time.
  const std::optional<StreamReport>& stats() const { return stats_.report(); }

  // --- Snapshot: Save(), Restore() (snapshots.h) ---

 private:
  friend class Snapshots<SslKernel, KernelKind::kSsl>;
  struct PendingCommand {
    int64_t due_ns;
    int64_t sent_ns;
    RobotCommand command;
    template <class Io>
    friend void Fields(Io& io, IoRef<Io, PendingCommand> p) {
      io(p.due_ns, p.sent_ns, p.command);
    }
  };

  template <class Io, class Self>
  static void Fields(Io& io, Self& self);
  void SaveTo(StateWriter& out) const;
  void RestoreFrom(StateReader& in);
  void StagePre();
  void StagePost();
  void CollectFeedback();
  void CollectStats();

  World world_;
  SslCameraSystem cameras_;
  SensorRealism realism_;
  std::vector<Link> command_links_;
  std::deque<PendingCommand> pending_[kTeamCount];
  StreamStats command_stats_[kTeamCount];
  std::vector<RobotSnapshot> last_feedback_;

  WorldSnapshot state_;
  std::vector<CameraFrame> camera_frames_;
  std::vector<RobotSnapshot> feedback_;
  StatsWindow stats_;
};

}  // namespace turf
