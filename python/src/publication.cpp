#include "python/src/publication.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>

#include "dds/topic_prefix.h"
#include "python/src/sim_error.h"

namespace turf::py {

namespace {

int64_t UnixNowNs() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

}  // namespace

// turf-sim's --domain range and its topic prefix rule (dds/topic_prefix.h); a QoS file that exists.
dds::ParticipantOptions CheckPublishOptions(const PublishOptions& o) {
  if (o.domain < 0 || o.domain > 232) Check(Error::kOutOfRange, "domain " + std::to_string(o.domain) + " (0..232)");
  if (!dds::ValidTopicPrefix(o.prefix))
    Check(Error::kMalformed, "prefix '" + o.prefix + "' (a topic name prefix: " + dds::kTopicPrefixRule + ")");
  if (!o.qos_file.empty() && !std::filesystem::is_regular_file(o.qos_file))
    Check(Error::kMalformed, "qos_file '" + o.qos_file + "' (no such file)");
  dds::ParticipantOptions d;
  d.domain = o.domain;
  d.name = o.name;
  d.prefix = o.prefix;
  d.qos_file = o.qos_file;
  return d;
}

namespace {

double LeggedStateHz(const LeggedKernel& k) {
  return 1.0 / (k.scene().physics.step * static_cast<double>(k.sensor_every()));
}

}  // namespace

Publication::Publication(const PublishOptions& options, double step_s, double state_hz)
    : participant_(CheckPublishOptions(options)),
      options_(options),
      step_s_(step_s),
      state_every_(static_cast<uint64_t>(std::max<int64_t>(1, std::llround(1.0 / (state_hz * step_s))))),
      clock_writer_(participant_.MakeWriter(dds::Topic::kClock)) {}

void Publication::WriteClock(int64_t time_ns, uint64_t frame) {
  if (last_time_ns_ < 0) epoch_ns_ = UnixNowNs() - time_ns;
  if (time_ns < last_time_ns_) epoch_ns_ += last_time_ns_ - time_ns;  // epoch + sim time never goes back
  last_time_ns_ = time_ns;
  state_frame_ = frame;
  idl::Clock clock;
  clock.sim_time_ns(time_ns);
  clock.frame(frame);
  clock.step_s(step_s_);
  clock.paused(false);
  clock.mode(idl::TIME_LOCKSTEP);
  clock.speed(1.0);
  clock.real_time_factor(0.0);
  clock.run_epoch_unix_ns(epoch_ns_);
  clock_writer_->Write(clock);
}

SslPublication::SslPublication(const PublishOptions& options, const SslKernel& kernel)
    : Publication(options, kernel.scene().physics.step, kernel.scene().rates.world_state_hz), publisher_(participant_) {
  publisher_.PublishField(kernel);
  PublishState(kernel, true);
}

// As turf-sim's loop: the state (clock first) when due, then the step's other outputs. Sim time has no wall-clock
// pace here: camera frames carry the wall time they are written at.
void SslPublication::AfterStep(const SslKernel& kernel) {
  if (StateDue(kernel.frame())) PublishState(kernel, true);
  publisher_.AfterStep(kernel, kernel.camera_frames().empty() ? 0 : UnixNowNs(), 0.0);
}

void SslPublication::PublishState(const SslKernel& kernel, bool force) {
  if (!force && Published(kernel.frame())) return;
  WriteClock(kernel.time_ns(), kernel.frame());
  publisher_.PublishState(kernel);
}

LeggedPublication::LeggedPublication(const PublishOptions& options, const LeggedKernel& kernel)
    : Publication(options, kernel.scene().physics.step, LeggedStateHz(kernel)), publisher_(participant_) {
  publisher_.PublishSceneInfo(kernel);
  publisher_.PublishReleased(kernel);
  PublishState(kernel, true);
}

void LeggedPublication::AfterStep(const LeggedKernel& kernel) {
  if (StateDue(kernel.frame())) PublishState(kernel, true);
  publisher_.AfterStep(kernel);
}

void LeggedPublication::PublishState(const LeggedKernel& kernel, bool force) {
  if (!force && Published(kernel.frame())) return;
  WriteClock(kernel.time_ns(), kernel.frame());
  publisher_.PublishState(kernel);
}

void LeggedPublication::StateChanged(const LeggedKernel& kernel, bool released) {
  if (released) publisher_.PublishReleased(kernel);
  PublishState(kernel, true);
}

}  // namespace turf::py
