// The legged simulation kernel: a legged world (LeggedIslands) plus its robots' sensor
// streams, as one mutable state with a byte snapshot. No DDS, no sockets, no
// clock (see ssl_kernel.h for the contract).
//
// Inputs (between steps; validated, a refused one changes nothing):
//   SetJointCommands  one robot's joint targets, all or none
//   PlaceRobot, PlaceBall, SetRealism, Reset
// Step(), in stages:
//   update  the world's physics step (legged_world.h has its own stages)
//   post    at every sensor frame (1/rates.joint_state_hz of sim time) each
//           robot's joint, IMU and touch readings are measured (noise keyed
//           by the frame) and sent into that stream's modelled link; samples
//           whose delay has passed are released; statistics every second
// Outputs: Measure() (the state with sensor noise, at the current frame: a
// pure function, read it as often as you like), released() (stream samples
// that arrived in the last step or Reset), stats().
#pragma once

#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/legged/legged_islands.h"
#include "core/legged/legged_sensors.h"
#include "core/legged/placement_limits.h"
#include "core/link_model.h"
#include "kernel/snapshots.h"
#include "kernel/stats_window.h"
#include "kernel/stream_report.h"

namespace turf {

enum class LeggedStream : uint8_t { kJoints, kImu, kTouch, kCount };
const char* LeggedStreamName(LeggedStream stream);  // "joint_state", "imu", "force"

// One robot's reading of one stream, as measured at `time_ns`. Only the
// stream's fields of `robot_state` are set (joints: names, positions,
// velocities, efforts; IMU: orientation, gyro, accelerometer, base pose;
// touch: forces), with the robot's name, id and has_imu; the rest is empty.
struct LeggedSample {
  LeggedStream stream = LeggedStream::kJoints;
  int robot = 0;
  int64_t time_ns = 0;
  uint64_t frame = 0;
  LeggedRobotState robot_state;
};

class LeggedKernel : public Snapshots<LeggedKernel, KernelKind::kLegged> {
 public:
  // Throws std::invalid_argument for an invalid scene.
  explicit LeggedKernel(LeggedScene scene);

  const LeggedScene& scene() const { return world_.scene(); }
  const LeggedIslands& world() const { return world_; }
  const SensorRealism& realism() const { return realism_; }
  int64_t time_ns() const { return world_.time_ns(); }
  uint64_t frame() const { return world_.frame(); }
  // Physics steps per sensor frame.
  int64_t sensor_every() const { return sensor_every_; }

  // --- Inputs ---
  JointCommandError SetJointCommands(int robot, const std::vector<JointCommand>& commands);
  // kOutOfRange beyond kMaxLeggedPlacement (and kMaxLeggedBallSpeed), else
  // as LeggedWorld's placements.
  Error PlaceRobot(int robot, const RobotPlacement& placement);
  Error PlaceBall(const std::array<double, 3>& position, const std::array<double, 3>& velocity);
  std::string SetRealism(const SensorRealism& realism);
  void Reset();

  // --- One step through all stages ---
  void Step();

  // --- Outputs ---
  void Measure(LeggedWorldState* out) const;
  const std::vector<LeggedSample>& released() const { return released_; }
  const std::optional<StreamReport>& stats() const { return stats_.report(); }

  // --- Snapshot: Save(), Restore() (snapshots.h) ---

 private:
  friend class Snapshots<LeggedKernel, KernelKind::kLegged>;
  struct Stream {
    Link link;
    StreamStats stats;
  };
  struct InFlight {
    int64_t arrival_ns;
    LeggedSample sample;
  };

  Stream& StreamOf(int robot, LeggedStream s) { return streams_[robot * kStreamsPerRobot + static_cast<int>(s)]; }
  void SendSensorFrame();
  void Release();
  void CollectStats();
  template <class Io, class Self>
  static void Fields(Io& io, Self& self);
  void SaveTo(StateWriter& out) const;
  void RestoreFrom(StateReader& in);

  static constexpr int kStreamsPerRobot = static_cast<int>(LeggedStream::kCount);

  LeggedIslands world_;
  uint64_t sensor_seed_ = 0;  // the seed of sensors_' noise: the scene's, or a restored snapshot's
  LeggedSensors sensors_;
  SensorRealism realism_;
  int64_t sensor_every_ = 1;
  std::vector<Stream> streams_;  // robot-major
  std::deque<InFlight> in_flight_;

  mutable LeggedWorldState scratch_;
  std::vector<LeggedSample> released_;
  StatsWindow stats_;
};

}  // namespace turf
