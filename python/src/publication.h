// sim.publish(domain=...): a Python-driven Sim's topics on a DDS domain, so the viewer, turf-record and team
// tools can watch a run the caller steps. The topics and their samples are turf-sim's, written by turf-sim's own
// publishers (participants/sim/ssl_publisher.h, legged_publisher.h) at the same points of a step: the state (with
// the clock first) every 1/world_state_hz of sim time (SSL; legged scenes: every sensor frame), and at the end of
// every step() call, teleport, reset and restore, so every observation step() returns is also published; camera
// frames, feedback, the legged streams and statistics as the steps release them; the field or scene description
// latched, once. The clock says lockstep (the caller steps), never paused, its run epoch the wall clock at
// publish() less the sim time then, advanced past every step back in sim time (reset, restore of an earlier
// snapshot) so epoch + sim time never goes back.
// Watch-only: nothing is subscribed (no commands, no control requests: the caller owns the world).
#pragma once

#include <turf/idl/ClockPubSubTypes.h>

#include <cstdint>
#include <limits>
#include <memory>
#include <string>

#include "dds/participant.h"
#include "kernel/legged_kernel.h"
#include "kernel/ssl_kernel.h"
#include "participants/sim/legged_publisher.h"
#include "participants/sim/ssl_publisher.h"

namespace turf::py {

struct PublishOptions {
  int domain = 0;  // 0..232, as turf-sim's --domain
  std::string prefix = "turf";
  std::string qos_file;  // empty: configs/qos/turf_qos.xml
  std::string name = "turf-python";
};

// The participant's options for `options`; throws SimError (out_of_range, malformed) for options turf-sim would
// refuse, changing nothing.
dds::ParticipantOptions CheckPublishOptions(const PublishOptions& options);

// The participant and the clock both kinds share.
class Publication {
 public:
  // Throws SimError (out_of_range, malformed) for options turf-sim would refuse, std::runtime_error for DDS.
  Publication(const PublishOptions& options, double step_s, double state_hz);
  virtual ~Publication() = default;
  Publication(const Publication&) = delete;
  Publication& operator=(const Publication&) = delete;

  const PublishOptions& options() const { return options_; }
  // Readers matched to the state topic (world_state; legged: robots/state).
  virtual int StateReaders() const = 0;
  std::string Describe() const { return participant_.Describe(); }

 protected:
  bool StateDue(uint64_t frame) const { return frame % state_every_ == 0; }
  // The clock at (time_ns, frame), then remembers the frame as published.
  void WriteClock(int64_t time_ns, uint64_t frame);
  bool Published(uint64_t frame) const { return frame == state_frame_; }

  dds::Participant participant_;

 private:
  PublishOptions options_;
  double step_s_;
  uint64_t state_every_;
  std::unique_ptr<dds::Writer<idl::ClockPubSubType>> clock_writer_;
  int64_t epoch_ns_ = 0;
  int64_t last_time_ns_ = -1;
  uint64_t state_frame_ = std::numeric_limits<uint64_t>::max();
};

class SslPublication final : public Publication {
 public:
  SslPublication(const PublishOptions& options, const SslKernel& kernel);
  // After each physics step: the state when due, then the step's camera frames, feedback and statistics.
  void AfterStep(const SslKernel& kernel);
  // At the end of a step() call and after an input that changed the state: the state unless just published.
  void PublishState(const SslKernel& kernel, bool force = false);
  int StateReaders() const override { return publisher_.StateReaders(); }

 private:
  SslPublisher publisher_;
};

class LeggedPublication final : public Publication {
 public:
  LeggedPublication(const PublishOptions& options, const LeggedKernel& kernel);
  void AfterStep(const LeggedKernel& kernel);
  void PublishState(const LeggedKernel& kernel, bool force = false);
  // After a teleport, reset (`released`: with the readings it released) or restore.
  void StateChanged(const LeggedKernel& kernel, bool released);
  int StateReaders() const override { return publisher_.StateReaders(); }

 private:
  LeggedPublisher publisher_;
};

}  // namespace turf::py
