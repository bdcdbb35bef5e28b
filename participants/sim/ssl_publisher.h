// What an SSL kernel publishes, on any dds::Bus: turf-sim's SSL node writes its
// topics through this, and so does a Python-driven Sim (python/src/publication.h).
//
// Publishes (topic names <prefix>/..., QoS profiles in configs/qos/turf_qos.xml):
//   world_state         WorldState        PublishState()
//   ssl/field           SslField          PublishField(), latched
//   ssl/camera          CameraFrame       AfterStep(): the frames the last step released
//   ssl/feedback/<team> SslRobotFeedback  AfterStep(): robots whose contact or kick count changed
//   stats               SensorStats       AfterStep(), when the step closed a second of sim time
// The clock is the driver's (turf-sim's control loop, or the Python publication).
#pragma once

#include <turf/idl/SensorStatsPubSubTypes.h>
#include <turf/idl/SslRobotPubSubTypes.h>
#include <turf/idl/SslVisionPubSubTypes.h>
#include <turf/idl/WorldStatePubSubTypes.h>

#include <cstdint>
#include <memory>

#include "core/pinned.h"
#include "dds/bus.h"
#include "kernel/ssl_kernel.h"
#include "kernel/stream_report.h"

namespace turf {

class SslPublisher : Pinned {
 public:
  // Makes the writers on `bus`, which must outlive the publisher.
  explicit SslPublisher(dds::Bus& bus);

  void PublishField(const SslKernel& kernel);
  void PublishState(const SslKernel& kernel);
  // The last step's camera frames (source timestamp: `wall_now_ns` less each frame's age in sim time times
  // `wall_per_sim`, 0 where sim time has no wall-clock pace), feedback and statistics.
  void AfterStep(const SslKernel& kernel, int64_t wall_now_ns, double wall_per_sim);
  // The newest statistics published (for the status log).
  const StreamReport& last_stats() const { return last_stats_; }
  // Readers matched to world_state.
  int StateReaders() const { return state_writer_->Matched(); }

 private:
  dds::WriterOf<dds::Topic::kWorldState> state_writer_;
  dds::WriterOf<dds::Topic::kSslField> field_writer_;
  dds::WriterOf<dds::Topic::kSslCamera> camera_writer_;
  std::unique_ptr<dds::Writer<idl::SslRobotFeedbackPubSubType>> feedback_writers_[kTeamCount];
  dds::WriterOf<dds::Topic::kStats> stats_writer_;
  StreamReport last_stats_;
  idl::WorldState state_sample_;
  idl::CameraFrame camera_sample_;
};

}  // namespace turf
