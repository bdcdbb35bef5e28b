// What turf-sim took as input and at which step: the exact record a re-simulation needs (turf replay
// --resimulate, participants/replay/resimulate.h).
//
// Inputs (SSL commands, joint commands, control requests) arrive whenever their writers send them, so the step at
// which turf-sim applies one depends on thread timing and cannot be derived from a recording of the input topics.
// turf-sim therefore writes down what it took: every poll of its inputs (ControlLoop::TakeInputs, between two
// steps) that took any publishes one AppliedInputs sample on <prefix>/sim/applied_inputs: a sequence number, the
// number of steps taken since the run started, the sim time, and each sample's CDR bytes in the order applied
// (refused samples too: a refusal is counted, and the count shows in the outputs). A re-simulation applies exactly
// these samples at exactly these steps, through the same code (ControlLoop::HandleControl and the node's own
// command path), and publishes the same records again.
#pragma once

#include <turf/idl/SimRecordPubSubTypes.h>

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "dds/bus.h"
#include "participants/sim/cdr.h"

namespace turf {

// The writer side, owned by the control loop.
class AppliedInputsLog {
 public:
  explicit AppliedInputsLog(dds::Bus& bus);

  // One sample taken, before it is applied. With no reader of the topic matched (on any bus) the sample is not
  // serialised and the poll's record not written: it would reach no one (the topic is volatile), and a sync request
  // saves the work. The record's number is counted all the same.
  template <class PubSub>
  void Took(const dds::TopicDef<PubSub>& topic, const dds::SampleOf<PubSub>& sample) {
    if (!Read()) return;
    std::vector<uint8_t> cdr;
    if (ToCdr<PubSub>(sample, &cdr)) Took(topic.info().suffix, std::move(cdr));
  }
  void Took(const std::string& topic, std::vector<uint8_t> cdr);
  // After a poll: publishes what it took, if anything, as taken at `step` (steps since the run started).
  void Flush(uint64_t step, int64_t sim_time_ns);

 private:
  // True if a reader is matched; else the poll's record is left out.
  bool Read();

  std::unique_ptr<dds::Writer<idl::AppliedInputsPubSubType>> writer_;
  idl::AppliedInputs pending_;
  uint64_t number_ = 0;
  bool unread_ = false;  // this poll took a sample while no reader was matched
};

// The reading side: a recording's AppliedInputs samples, in sequence order, handed out at their steps.
class InputSchedule {
 public:
  explicit InputSchedule(std::vector<idl::AppliedInputs> records) : records_(std::move(records)) {}
  // The next record if it is due at `step`, else null; each record is handed out once.
  const idl::AppliedInputs* NextDue(uint64_t step) {
    if (next_ >= records_.size() || records_[next_].step() != step) return nullptr;
    return &records_[next_++];
  }
  bool done() const { return next_ >= records_.size(); }
  // The step of the next record (done(): none).
  uint64_t next_step() const { return done() ? 0 : records_[next_].step(); }
  size_t applied() const { return next_; }
  size_t size() const { return records_.size(); }
  // A recorded input that could not be applied (no sample of its topic's type, a topic the node has not): the
  // first such, else empty.
  void Fail(const std::string& why) {
    if (error_.empty()) error_ = why;
  }
  const std::string& error() const { return error_; }

 private:
  std::vector<idl::AppliedInputs> records_;
  size_t next_ = 0;
  std::string error_;
};

}  // namespace turf
