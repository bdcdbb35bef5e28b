// What a legged kernel publishes, on any dds::Bus: turf-sim's legged node writes
// its topics through this, and so does a Python-driven Sim (python/src/publication.h).
//
// Publishes (topic names <prefix>/...):
//   robots/joint_state, robots/imu, robots/force  AfterStep(): the stream samples their modelled links released
//   stats             SensorStats       AfterStep(), when the step closed a second of sim time
//   robots/state      LeggedState       PublishState(): every robot's measured frame and the ball (first)
//   robots/links      LinkState         PublishState(), per robot
//   world_state       WorldState        PublishState(), scenes with a ball
//   legged/scene      LeggedSceneInfo   PublishSceneInfo(), latched
// The clock is the driver's.
#pragma once

#include <turf/idl/JointsPubSubTypes.h>
#include <turf/idl/SensorStatsPubSubTypes.h>
#include <turf/idl/WorldStatePubSubTypes.h>

#include <memory>

#include "core/pinned.h"
#include "dds/bus.h"
#include "kernel/legged_kernel.h"
#include "kernel/stream_report.h"

namespace turf {

class LeggedPublisher : Pinned {
 public:
  // Makes the writers on `bus`, which must outlive the publisher.
  explicit LeggedPublisher(dds::Bus& bus);

  void PublishSceneInfo(const LeggedKernel& kernel);
  // The stream samples released by the last step (or Reset), and the statistics.
  void AfterStep(const LeggedKernel& kernel);
  // Only the released stream samples.
  void PublishReleased(const LeggedKernel& kernel);
  void PublishState(const LeggedKernel& kernel);
  const StreamReport& last_stats() const { return last_stats_; }
  // Readers matched to robots/state.
  int StateReaders() const { return state_writer_->Matched(); }

 private:
  dds::WriterOf<dds::Topic::kRobotJointState> joint_writer_;
  dds::WriterOf<dds::Topic::kRobotImu> imu_writer_;
  dds::WriterOf<dds::Topic::kRobotForce> force_writer_;
  dds::WriterOf<dds::Topic::kRobotLinks> links_writer_;
  dds::WriterOf<dds::Topic::kRobotsState> state_writer_;
  dds::WriterOf<dds::Topic::kWorldState> world_writer_;
  dds::WriterOf<dds::Topic::kLeggedScene> scene_writer_;
  dds::WriterOf<dds::Topic::kStats> stats_writer_;

  LeggedWorldState state_;
  idl::LeggedState frame_sample_;
  idl::JointState joint_sample_;
  idl::ImuState imu_sample_;
  idl::ForceState force_sample_;
  StreamReport last_stats_;
};

}  // namespace turf
