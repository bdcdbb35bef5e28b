#include "participants/sim/ssl_publisher.h"

#include <cmath>

#include "participants/sim/convert.h"
#include "participants/sim/stats_report.h"

namespace turf {

SslPublisher::SslPublisher(dds::Bus& bus)
    : state_writer_(bus.MakeWriter(dds::Topic::kWorldState)),
      field_writer_(bus.MakeWriter(dds::Topic::kSslField)),
      camera_writer_(bus.MakeWriter(dds::Topic::kSslCamera)),
      feedback_writers_{bus.MakeWriter(dds::Topic::kSslFeedbackBlue), bus.MakeWriter(dds::Topic::kSslFeedbackYellow)},
      stats_writer_(bus.MakeWriter(dds::Topic::kStats)) {}

void SslPublisher::PublishField(const SslKernel& kernel) {
  field_writer_->Write(FieldToIdl(kernel.scene(), kernel.cameras()));
}

void SslPublisher::PublishState(const SslKernel& kernel) {
  ToIdl(kernel.state(), &state_sample_);
  state_writer_->Write(state_sample_);
}

void SslPublisher::AfterStep(const SslKernel& kernel, int64_t wall_now_ns, double wall_per_sim) {
  for (const CameraFrame& f : kernel.camera_frames()) {
    ToIdl(f, &camera_sample_);
    const int64_t age = std::llround(static_cast<double>(kernel.time_ns() - f.capture_time_ns) * wall_per_sim);
    camera_writer_->Write(camera_sample_, wall_now_ns - age);
  }
  if (kernel.stats()) {
    stats_writer_->Write(StatsToIdl(*kernel.stats()));
    last_stats_ = *kernel.stats();
  }
  for (const RobotSnapshot& r : kernel.feedback())
    feedback_writers_[static_cast<int>(r.team)]->Write(FeedbackToIdl(r, kernel.time_ns()));
}

}  // namespace turf
