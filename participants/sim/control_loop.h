// The time and control handling both turf-sim nodes share: the run loop with
// real-time pacing (pacer.h), pause/resume, lockstep, STEP requests (replied at
// the frame they finish), time modes, reset, the clock, replies and the log of
// refused inputs.
//
// Publishes (topic names <prefix>/...):
//   clock          Clock            with every state publication; carries the
//                                   run epoch (Unix ns of sim time 0, read from
//                                   the wall clock once when Run starts and
//                                   advanced by the sim time reached at each
//                                   reset), so epoch + sim time never goes back
//   control_reply  SimControlReply  one per control request
//   sim/run        SimRun           latched, at start: the scene source and seed (options.scene_source)
//   sim/applied_inputs AppliedInputs after each poll that took inputs: what was applied at which step
//                                   (applied_inputs.h); a re-simulation (options.resimulate) takes its
//                                   inputs from a recorded schedule of these instead of from the readers
// Subscribes:
//   control        SimControl       pause/resume, step, reset, time mode here;
//                                   teleports and realism go to the node
// The node (SSL or legged) owns its world and its other topics and answers the
// loop through ControlLoop::Node. Every call to the node is made under the
// loop's run lock, from the loop's thread or from the thread of an in-process
// front-end's control request (below); Stats() and Rejected() may be called from
// any thread.
//
// Served in the caller: a control request written on a dds::MemoryBus (a
// front-end in turf-sim's process, such as the SSL sync port) while the loop is
// idle between steps is handled on the writer's thread, and so are the steps it
// queues in lockstep or paused (up to kInlineStepBudget): its reply is there when
// the write returns, with no hop to the loop's thread and back. In lockstep or
// paused the caller waits for a running loop pass to end (passes are short
// then); in real time it leaves the request to the loop's thread if a pass is
// running. The loop's own thread handles everything else, as it would have.
#pragma once

#include <turf/idl/ClockPubSubTypes.h>
#include <turf/idl/SimControlPubSubTypes.h>

#include <atomic>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "core/legged/legged_world.h"
#include "core/pinned.h"
#include "core/types.h"
#include "dds/bus.h"
#include "loader/realism_change.h"
#include "participants/common/overflow_watch.h"
#include "participants/common/process.h"
#include "participants/common/wakeup.h"
#include "participants/sim/applied_inputs.h"
#include "participants/sim/node_options.h"
#include "participants/sim/pacer.h"

namespace turf {

// What a control request came to: done ({}), or refused with a code and the
// reason in words; both go into the reply.
struct ControlAnswer {
  idl::ControlError code = idl::CONTROL_OK;
  std::string reason;
  bool ok() const { return code == idl::CONTROL_OK; }
};

// The bus a node makes for itself when it is given none: a DDS participant from
// the options' domain, name, prefix and QoS file.
std::unique_ptr<dds::Bus> MakeNodeParticipant(const SimNodeOptions& options);

// The reply's code for a refusal the core names: the same taxonomy
// (core/errors.h), value for value.
idl::ControlError ControlErrorOf(Error error);

class ControlLoop : Pinned {
 public:
  // Steps a request served in its caller's thread may run there; more are left to the loop's thread.
  static constexpr uint64_t kInlineStepBudget = 5000;
  // A control request's client name (echoed in its reply) longer than this is refused unanswered.
  static constexpr size_t kMaxClientName = 256;

  // What a node does for the loop: the requests it handles answer a ControlAnswer.
  class Node {
   public:
    virtual int64_t TimeNs() const = 0;
    virtual uint64_t Frame() const = 0;
    // Takes the node's command topics (before each poll's control requests); tells the loop each sample it takes
    // (ControlLoop::Took) before applying it.
    virtual void TakeCommands() = 0;
    // Re-simulation: applies a recorded sample of one of the node's command topics (its name without prefix) as
    // TakeCommands would; "" or why it could not (an unknown topic, bytes that are no sample of its type).
    virtual std::string ApplyRecordedInput(const std::string& topic, const std::vector<uint8_t>& cdr) = 0;
    // Samples the command readers dropped so far.
    virtual uint64_t CommandsOverflowed() const = 0;
    // One physics step, with whatever commands are due.
    virtual void Step() = 0;
    // After each step: sensors and feedback (the state is published by the loop).
    virtual void AfterStep() = 0;
    // The node's state topics; the loop adds the clock.
    virtual void PublishState() = 0;
    // Commands a STEP request carries, applied before its steps.
    virtual ControlAnswer ApplyStepCommands(const idl::SimControl& request) = 0;
    virtual ControlAnswer TeleportBall(const idl::SimControl& request) = 0;
    virtual ControlAnswer TeleportRobot(const idl::SimControl& request) = 0;
    // OP_SET_REALISM, typed (loader/realism_change.h: ApplyRealismChange).
    virtual ControlAnswer ChangeRealism(const RealismChange& change) = 0;
    // The world back to the scene's start (the loop cancels pending steps).
    virtual void ResetWorld() = 0;
    // The kernel's snapshot, and a restore of one ("" on success, else why, and nothing changed); the scene and
    // seed in one line, so a snapshot is restored only into the match it was taken from.
    virtual std::string SaveKernel() const = 0;
    virtual std::string RestoreKernel(std::string_view snapshot) = 0;
    virtual std::string SceneIdentity() const = 0;
    virtual void ReportStatus() const = 0;

   protected:
    ~Node() = default;
  };

  struct Timing {
    double step_s = 0.0;    // the scene's physics step, as published on the clock
    int64_t step_ns = 0;    // the world's step
    double state_hz = 0.0;  // state publications per second of sim time
  };

  // Makes the control reader and the clock and reply writers on `bus`.
  ControlLoop(dds::Bus& bus, const SimNodeOptions& options, Timing timing, Node& node);

  // Publishes the state, then steps until `stop()` answers true (checked every
  // step and at least every 50 ms while idle) or the duration is reached.
  void Run(const std::function<bool()>& stop);

  // For the node's command readers' on_data callbacks (any thread).
  void Wake() { wakeup_.Notify(); }
  // The node took `sample` from `topic` and applies it next (the applied-inputs record).
  template <class PubSub>
  void Took(const dds::TopicDef<PubSub>& topic, const dds::SampleOf<PubSub>& sample) {
    applied_.Took(topic, sample);
  }
  // Counts and logs (rate-limited) a refused input of `kind`.
  void Reject(const std::string& kind, const std::string& detail) { rejects_.Reject(kind, detail); }
  // Logs the loop's own topics (sim/run, sim/applied_inputs) and the time mode, the last lines of a node's
  // startup report.
  void ReportTimeMode() const;
  // The status line a node logs every 10 s: sim time, frame, real-time factor, refusals, then the node's `health`.
  void ReportStatusLine(const std::string& health) const;

  TimeMode mode() const { return time_.mode(); }
  double speed() const { return time_.speed(); }
  double real_time_factor() const { return pacer_.real_time_factor(); }
  // Unix ns of sim time 0 of this run (0 until Run starts).
  int64_t run_epoch_unix_ns() const { return run_epoch_unix_ns_.load(); }
  uint64_t rejected() const { return rejects_.Total(); }

  SimNodeStats Stats() const { return {frame_.load(), time_ns_.load(), rejects_.Total(), rtf_.load()}; }
  uint64_t Rejected(const std::string& kind) const { return rejects_.Count(kind); }

 private:
  // One pass of Run under the run lock: inputs, status, and a step if one may run; false if the loop is idle.
  bool Iterate();
  // The control reader's on_data: serves the request here if it came on a MemoryBus and the loop is idle.
  void OnControl();
  bool ServeInCaller();
  void Pace();
  void TakeInputs();
  // Re-simulation: the recorded inputs due at this step, each record applied and logged again as it was.
  void TakeScheduled();
  // One physics step and what follows it.
  void StepOnce();
  void PublishRun(bool resumed);
  void HandleControl(const idl::SimControl& request);
  ControlAnswer QueueSteps(const idl::SimControl& request);
  ControlAnswer SetTimeMode(idl::TimeMode mode, double speed);
  void Reset();
  // Who a reply goes to: what a STEP request keeps until its steps are done (not its commands).
  struct ReplyTo {
    std::string client;
    uint64_t request_id = 0;
    idl::ControlOp op = idl::OP_STEP;
  };
  static ReplyTo ReplyToOf(const idl::SimControl& request) {
    return {request.client(), request.request_id(), request.op()};
  }
  void Reply(const ReplyTo& to, const ControlAnswer& answer);
  void AfterStep();
  void PublishState();
  // --resume-dir: continue from the match's resume file, if there is one; then write one every snapshot_every.
  bool Resume();
  void WriteSnapshotIfDue();

  Node& node_;
  const SimNodeOptions options_;
  const Timing timing_;
  int64_t state_every_ = 1;
  Pacer pacer_;
  Wakeup wakeup_;
  // Held while the node, the time control and the pacer are used: the whole of a loop pass (not its idle wait), or
  // a request served in its caller. Its holder is known, so a delivery on the holding thread never takes it again.
  class RunLock;
  std::mutex run_mutex_;
  std::atomic<std::thread::id> run_holder_{};
  bool running_ = false;  // under run_mutex_: Run is between its first and last publication
  // Paused or lockstep (written under run_mutex_): the loop's passes then never wait for the wall clock, so a
  // request served in its caller waits for a pass to end rather than handing over to the loop's thread.
  std::atomic<bool> steps_on_request_{false};
  int64_t end_ns_ = -1;  // under run_mutex_: the duration's end in sim time, -1 for none
  Pacer::Clock::time_point next_status_;
  int64_t next_snapshot_ns_ = 0;  // under run_mutex_
  std::unique_ptr<dds::Writer<idl::ClockPubSubType>> clock_writer_;
  std::unique_ptr<dds::Writer<idl::SimControlReplyPubSubType>> reply_writer_;
  std::unique_ptr<dds::Reader<idl::SimControlPubSubType>> control_reader_;
  std::unique_ptr<dds::Writer<idl::SimRunPubSubType>> run_writer_;
  AppliedInputsLog applied_;
  InputSchedule* schedule_ = nullptr;  // options_.resimulate
  uint64_t steps_ = 0;                 // under run_mutex_: steps since Run started (resets do not restart it)

  TimeControl time_;                           // modes, pause, STEP requests (kernel/time_control.h)
  std::map<uint64_t, ReplyTo> step_requests_;  // by TimeControl token
  uint64_t next_token_ = 0;
  std::vector<uint64_t> finished_;
  OverflowWatch overflow_;
  std::vector<idl::SimControl> control_inbox_;

  RejectLog rejects_;
  std::atomic<uint64_t> frame_{0};
  std::atomic<int64_t> time_ns_{0};
  std::atomic<double> rtf_{0.0};
  // Wall-clock context for the clock topic only: never read by the node or the core.
  std::atomic<int64_t> run_epoch_unix_ns_{0};
};

}  // namespace turf
