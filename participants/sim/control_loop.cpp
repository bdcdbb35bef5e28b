#include "participants/sim/control_loop.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

#include "dds/memory_bus.h"
#include "dds/participant.h"
#include "participants/sim/resume_file.h"

namespace turf {

namespace {

int64_t UnixNowNs() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

}  // namespace

// Every error of the taxonomy is the IDL constant of the same value.
#define TURF_ERROR_MATCHES_IDL(e, name, idl_constant, meaning) \
  static_assert(static_cast<int>(Error::e) == static_cast<int>(idl::idl_constant), name);
TURF_ERRORS(TURF_ERROR_MATCHES_IDL)
#undef TURF_ERROR_MATCHES_IDL

idl::ControlError ControlErrorOf(Error error) { return static_cast<idl::ControlError>(error); }

// Every realism parameter is the IDL constant of the same value (the IDL's count
// is checked by tests/loader/realism_change_test.cpp, which reads the IDL).
#define TURF_REALISM_FIELD_MATCHES_IDL(e, name, idl_constant, member, unit, min, max, meaning) \
  static_assert(static_cast<int>(RealismField::e) == static_cast<int>(idl::idl_constant), name);
TURF_REALISM_FIELDS(TURF_REALISM_FIELD_MATCHES_IDL)
#undef TURF_REALISM_FIELD_MATCHES_IDL

namespace {

RealismChange RealismChangeOf(const idl::SimControl& request) {
  RealismChange change{request.realism_preset(), {}};
  for (const idl::RealismValue& v : request.realism_values())
    change.values.push_back({static_cast<uint32_t>(v.parameter()), v.value()});
  return change;
}

}  // namespace

std::unique_ptr<dds::Bus> MakeNodeParticipant(const SimNodeOptions& options) {
  return std::make_unique<dds::Participant>(DdsOptions(options));
}

ControlLoop::ControlLoop(dds::Bus& bus, const SimNodeOptions& options, Timing timing, Node& node)
    : node_(node),
      options_(options),
      timing_(timing),
      state_every_(std::max<int64_t>(1, std::llround(1.0 / (timing.state_hz * timing.step_s)))),
      clock_writer_(bus.MakeWriter<idl::ClockPubSubType>(dds::Topic::kClock)),
      reply_writer_(bus.MakeWriter<idl::SimControlReplyPubSubType>(dds::Topic::kControlReply)),
      control_reader_(bus.MakeReader<idl::SimControlPubSubType>(dds::Topic::kControl, [this] { OnControl(); })),
      run_writer_(bus.MakeWriter(dds::Topic::kSimRun)),
      applied_(bus),
      schedule_(options.resimulate.get()),
      time_(options.mode, options.speed, options.start_paused),
      rejects_("input") {}

class ControlLoop::RunLock {
 public:
  RunLock(ControlLoop& loop, bool try_only) : loop_(loop) {
    if (loop.run_holder_.load() == std::this_thread::get_id()) return;  // held further up this thread's stack
    owns_ = try_only ? loop.run_mutex_.try_lock() : (loop.run_mutex_.lock(), true);
    if (owns_) loop.run_holder_.store(std::this_thread::get_id());
  }
  explicit RunLock(ControlLoop& loop) : RunLock(loop, false) {}
  ~RunLock() {
    if (!owns_) return;
    loop_.run_holder_.store(std::thread::id());
    loop_.run_mutex_.unlock();
  }
  RunLock(const RunLock&) = delete;
  RunLock& operator=(const RunLock&) = delete;
  bool owns() const { return owns_; }

 private:
  ControlLoop& loop_;
  bool owns_ = false;
};

void ControlLoop::Run(const std::function<bool()>& stop) {
  {
    const RunLock lock(*this);
    PublishRun(Resume());
    // The run's epoch: the wall clock once, here; sim time then counts on from it.
    run_epoch_unix_ns_.store(UnixNowNs() - node_.TimeNs());
    PublishState();
    end_ns_ = options_.duration > 0 ? std::llround(options_.duration * 1e9) : -1;
    pacer_.Anchor(Pacer::Clock::now(), node_.TimeNs());
    next_status_ = Pacer::Clock::now() + std::chrono::seconds(10);
    steps_on_request_.store(time_.paused() || time_.mode() == TimeMode::kLockstep);
    running_ = true;
  }
  while (!stop()) {
    bool idle = false;
    {
      const RunLock lock(*this);
      if (end_ns_ >= 0 && node_.TimeNs() >= end_ns_) break;
      idle = !Iterate();
    }
    if (!idle) continue;
    if (schedule_ != nullptr) break;  // re-simulating: nothing arrives later; the world cannot step any more
    wakeup_.WaitUntil(Pacer::Clock::now() + std::chrono::milliseconds(50));
    const RunLock lock(*this);
    pacer_.Anchor(Pacer::Clock::now(), node_.TimeNs());
  }
  const RunLock lock(*this);
  running_ = false;
  node_.ReportStatus();
}

bool ControlLoop::Iterate() {
  TakeInputs();
  const auto now = Pacer::Clock::now();
  pacer_.Measure(now, node_.TimeNs());
  if (now >= next_status_) {
    node_.ReportStatus();
    next_status_ = now + std::chrono::seconds(10);
  }
  if (!time_.CanStep()) return false;
  if (time_.Paces() && schedule_ == nullptr) Pace();
  StepOnce();
  return true;
}

void ControlLoop::StepOnce() {
  node_.Step();
  ++steps_;
  AfterStep();
}

void ControlLoop::PublishRun(bool resumed) {
  const SceneSource& s = options_.scene_source;
  idl::SimRun run;
  run.kind(s.kind);
  run.scene_name(s.name);
  run.scene_path(s.path);
  run.scene_dir(s.dir);
  run.scene_yaml(s.yaml);
  run.realism(s.realism);
  run.seed(s.seed);
  run.resumed(resumed);
  run_writer_->Write(run);
}

void ControlLoop::OnControl() {
  if (dds::MemoryBus::DeliveringOnThisThread() && ServeInCaller()) return;
  Wake();
}

// In the writer's thread, inside its MemoryBus::Write. Not while another thread holds the run lock (the loop's
// thread takes the request at its next pass), nor on a thread that holds it already.
bool ControlLoop::ServeInCaller() {
  const RunLock lock(*this, !steps_on_request_.load());
  if (!lock.owns() || !running_) return false;
  TakeInputs();
  if (steps_on_request_.load() && time_.pending_steps() <= kInlineStepBudget) {
    while (time_.CanStep() && (end_ns_ < 0 || node_.TimeNs() < end_ns_)) StepOnce();
  }
  // Whatever is left (real time runs on, a long STEP) goes on in the loop's thread.
  if (time_.CanStep()) Wake();
  return true;
}

void ControlLoop::ReportTimeMode() const {
  spdlog::info(
      "publishing {} (latched: the run's scene, seed and options) and {} (every input applied, at its step: "
      "for turf replay --resimulate)",
      dds::TopicName(options_.prefix, dds::Topic::kSimRun),
      dds::TopicName(options_.prefix, dds::Topic::kAppliedInputs));
  spdlog::info("time: {}{}{}", TimeModeName(time_.mode()),
               time_.mode() == TimeMode::kScaled ? fmt::format(" x{}", time_.speed()) : "",
               time_.paused() ? ", paused" : "");
}

void ControlLoop::ReportStatusLine(const std::string& health) const {
  spdlog::info("t={:.1f}s frame={} rtf={:.2f} refused={} {}", node_.TimeNs() * 1e-9, node_.Frame(),
               pacer_.real_time_factor(), rejects_.Total(), health);
}

void ControlLoop::Pace() {
  const auto deadline = pacer_.Deadline(node_.TimeNs() + timing_.step_ns, time_.speed());
  const auto now = Pacer::Clock::now();
  if (pacer_.CatchUp(now, deadline, node_.TimeNs())) {
    spdlog::debug("fell behind real time at t={:.3f}s; re-anchored", node_.TimeNs() * 1e-9);
    return;
  }
  if (deadline > now) std::this_thread::sleep_until(deadline);
}

void ControlLoop::TakeInputs() {
  if (schedule_ != nullptr) {
    TakeScheduled();
    return;
  }
  node_.TakeCommands();
  if (control_reader_->Take(&control_inbox_)) {
    for (const idl::SimControl& c : control_inbox_) {
      applied_.Took(dds::Topic::kControl, c);
      HandleControl(c);
    }
  }
  applied_.Flush(steps_, node_.TimeNs());
  const uint64_t overflow = node_.CommandsOverflowed() + control_reader_->Overflowed();
  overflow_.Check(overflow, [this](const char* kind, const std::string& detail) { Reject(kind, detail); });
  steps_on_request_.store(time_.paused() || time_.mode() == TimeMode::kLockstep);
}

void ControlLoop::TakeScheduled() {
  const std::string control = dds::Topic::kControl.info().suffix;
  while (const idl::AppliedInputs* record = schedule_->NextDue(steps_)) {
    for (const idl::AppliedInput& in : record->inputs()) {
      applied_.Took(in.topic(), in.cdr());
      if (in.topic() != control) {
        if (std::string e = node_.ApplyRecordedInput(in.topic(), in.cdr()); !e.empty()) schedule_->Fail(e);
        continue;
      }
      idl::SimControl request;
      if (FromCdr<idl::SimControlPubSubType>(in.cdr().data(), in.cdr().size(), &request)) {
        HandleControl(request);
      } else {
        schedule_->Fail(fmt::format("applied inputs #{}: a control sample that is no SimControl", record->number()));
      }
    }
    applied_.Flush(steps_, node_.TimeNs());
  }
  steps_on_request_.store(time_.paused() || time_.mode() == TimeMode::kLockstep);
}

void ControlLoop::HandleControl(const idl::SimControl& request) {
  // The reply carries the client's name back: an oversized one gets none (nor a log line of it).
  if (request.client().size() > kMaxClientName) {
    Reject("control.too_large", fmt::format("a request whose client name is {} bytes (at most {}): not answered",
                                            request.client().size(), kMaxClientName));
    return;
  }
  ControlAnswer answer;
  switch (request.op()) {
    case idl::OP_TELEPORT_BALL:
      answer = node_.TeleportBall(request);
      break;
    case idl::OP_TELEPORT_ROBOT:
      answer = node_.TeleportRobot(request);
      break;
    case idl::OP_PAUSE:
      time_.Pause();
      break;
    case idl::OP_RESUME:
      time_.Resume();
      break;
    case idl::OP_STEP:
      answer = QueueSteps(request);
      if (answer.ok()) return;  // replied when the steps are done
      break;
    case idl::OP_RESET:
      Reset();
      break;
    case idl::OP_SET_TIME_MODE:
      answer = SetTimeMode(request.time_mode(), request.speed());
      break;
    case idl::OP_SET_REALISM:
      answer = node_.ChangeRealism(RealismChangeOf(request));
      break;
    case idl::OP_SEEK:
      answer = {idl::CONTROL_NOT_ALLOWED, "seek is turf-replay's: a running simulation does not go back in time"};
      break;
    default:
      answer = {idl::CONTROL_UNKNOWN_OP, fmt::format("unknown op {}", static_cast<int>(request.op()))};
      break;
  }
  if (!answer.ok()) {
    Reject("control", fmt::format("from '{}': {}", request.client(), answer.reason));
    Reply(ReplyToOf(request), answer);
    return;  // nothing changed: no state to show (a flood of refused requests is no flood of world states)
  }
  // Teleports and resets show in the state right away, also while paused: written before the reply, as a STEP's.
  PublishState();
  Reply(ReplyToOf(request), answer);
}

ControlAnswer ControlLoop::QueueSteps(const idl::SimControl& request) {
  const Error e = time_.CheckSteps(request.step_count());
  if (e == Error::kNotAllowed) return {ControlErrorOf(e), "step needs a paused simulation or lockstep mode"};
  if (e != Error::kOk)
    return {ControlErrorOf(e),
            fmt::format("step_count must be 1..{} with the {} steps queued", kMaxStepRequest, time_.pending_steps())};
  ControlAnswer answer = node_.ApplyStepCommands(request);
  if (!answer.ok()) return answer;
  const uint64_t token = next_token_++;
  time_.QueueSteps(request.step_count(), node_.Frame(), token);
  step_requests_.emplace(token, ReplyToOf(request));
  return {};
}

ControlAnswer ControlLoop::SetTimeMode(idl::TimeMode mode, double speed) {
  const auto raw = static_cast<uint32_t>(mode);
  const TimeMode wanted = raw < static_cast<uint32_t>(TimeMode::kCount) ? static_cast<TimeMode>(raw) : TimeMode::kCount;
  const Error e = time_.SetMode(wanted, speed);
  if (e == Error::kUnknownEnum) return {ControlErrorOf(e), fmt::format("unknown time mode {}", static_cast<int>(mode))};
  if (e != Error::kOk)
    return {ControlErrorOf(e), fmt::format("speed must be in [{}, {}]", kMinTimeSpeed, kMaxTimeSpeed)};
  spdlog::info("time mode {} (speed {})", TimeModeName(time_.mode()), time_.speed());
  pacer_.Anchor(Pacer::Clock::now(), node_.TimeNs());
  return {};
}

void ControlLoop::Reset() {
  const int64_t reached_ns = node_.TimeNs();
  node_.ResetWorld();
  // The new timeline starts where the old one ended: epoch + sim time stays monotonic.
  run_epoch_unix_ns_.fetch_add(reached_ns - node_.TimeNs());
  for (uint64_t token : time_.Reset()) {
    Reply(step_requests_.at(token), {idl::CONTROL_CANCELLED, "cancelled by a reset"});
    step_requests_.erase(token);
  }
  pacer_.Anchor(Pacer::Clock::now(), node_.TimeNs());
}

void ControlLoop::Reply(const ReplyTo& to, const ControlAnswer& answer) {
  idl::SimControlReply reply;
  reply.client(to.client);
  reply.request_id(to.request_id);
  reply.op(to.op);
  reply.result(answer.ok() ? idl::RESULT_OK : idl::RESULT_REJECTED);
  reply.error(answer.code);
  reply.reason(answer.reason);
  reply.sim_time_ns(node_.TimeNs());
  reply.frame(node_.Frame());
  reply_writer_->Write(reply);
}

// State when due and at the frame a STEP request finishes, then the node's
// sensors, then the replies of finished STEP requests.
void ControlLoop::AfterStep() {
  const uint64_t frame = node_.Frame();
  frame_.store(frame);
  time_ns_.store(node_.TimeNs());
  if (frame % state_every_ == 0 || time_.FinishesAt(frame)) PublishState();
  node_.AfterStep();
  WriteSnapshotIfDue();
  finished_.clear();
  time_.Stepped(frame, &finished_);
  for (uint64_t token : finished_) {
    Reply(step_requests_.at(token), {});
    step_requests_.erase(token);
  }
}

bool ControlLoop::Resume() {
  if (options_.resume_dir.empty()) return false;
  const std::string path = ResumePath(options_.resume_dir, options_.prefix);
  const ResumeRead read = ReadResumeFile(path, node_.SceneIdentity());
  if (!read.why_not.empty()) spdlog::warn("not resuming: {}; starting from the scene's start", read.why_not);
  bool resumed = false;
  if (read.snapshot) {
    if (const std::string e = node_.RestoreKernel(*read.snapshot); !e.empty()) {
      spdlog::warn("not resuming from {}: {}; starting from the scene's start", path, e);
    } else {
      spdlog::info("resumed from {} at t={:.3f}s (frame {})", path, node_.TimeNs() * 1e-9, node_.Frame());
      resumed = true;
    }
  }
  const int64_t every_ns = std::max<int64_t>(timing_.step_ns, std::llround(options_.snapshot_every * 1e9));
  next_snapshot_ns_ = (node_.TimeNs() / every_ns + 1) * every_ns;
  spdlog::info("writing a snapshot every {} s of sim time to {}", every_ns * 1e-9, path);
  return resumed;
}

// At the first step at or past each multiple of snapshot_every: a crash loses at most that much simulated time.
void ControlLoop::WriteSnapshotIfDue() {
  if (options_.resume_dir.empty() || node_.TimeNs() < next_snapshot_ns_) return;
  const int64_t every_ns = std::max<int64_t>(timing_.step_ns, std::llround(options_.snapshot_every * 1e9));
  next_snapshot_ns_ = (node_.TimeNs() / every_ns + 1) * every_ns;
  const std::string path = ResumePath(options_.resume_dir, options_.prefix);
  if (const std::string e = WriteResumeFile(path, node_.SceneIdentity(), node_.SaveKernel()); !e.empty())
    Reject("snapshot", e);
}

// The clock goes first: a reader that sees a state (a reset's, say) already has
// the clock, and so the run epoch, it belongs to.
void ControlLoop::PublishState() {
  idl::Clock clock;
  clock.sim_time_ns(node_.TimeNs());
  clock.frame(node_.Frame());
  clock.step_s(timing_.step_s);
  clock.paused(time_.paused());
  clock.mode(static_cast<idl::TimeMode>(time_.mode()));
  clock.speed(time_.speed());
  clock.real_time_factor(pacer_.real_time_factor());
  clock.run_epoch_unix_ns(run_epoch_unix_ns_.load());
  clock_writer_->Write(clock);
  rtf_.store(pacer_.real_time_factor());
  node_.PublishState();
}

}  // namespace turf
