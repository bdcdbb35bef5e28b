#include "participants/sim/control_loop.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

namespace turf {

namespace {

constexpr double kMaxSpeed = 1000.0;  // multiples of real time a client may ask for
constexpr uint32_t kMaxStepRequest = 1000000;

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

ControlLoop::ControlLoop(dds::Participant& participant, const SimNodeOptions& options, Timing timing, Node& node)
    : node_(node),
      options_(options),
      timing_(timing),
      state_every_(std::max<int64_t>(1, std::llround(1.0 / (timing.state_hz * timing.step_s)))),
      clock_writer_(participant.MakeWriter<idl::ClockPubSubType>(dds::Topic::kClock)),
      reply_writer_(participant.MakeWriter<idl::SimControlReplyPubSubType>(dds::Topic::kControlReply)),
      control_reader_(participant.MakeReader<idl::SimControlPubSubType>(dds::Topic::kControl, [this] { Wake(); })),
      mode_(options.mode),
      speed_(options.mode == TimeMode::kScaled ? options.speed : 1.0),
      paused_(options.start_paused),
      rejects_("input") {}

void ControlLoop::Run(const std::function<bool()>& stop) {
  // The run's epoch: the wall clock once, here; sim time then counts on from it.
  run_epoch_unix_ns_.store(UnixNowNs() - node_.TimeNs());
  PublishState();
  const int64_t end_ns = options_.duration > 0 ? std::llround(options_.duration * 1e9) : -1;
  pacer_.Anchor(Pacer::Clock::now(), node_.TimeNs());
  auto next_status = Pacer::Clock::now() + std::chrono::seconds(10);
  while (!stop()) {
    TakeInputs();
    const auto now = Pacer::Clock::now();
    pacer_.Measure(now, node_.TimeNs());
    if (now >= next_status) {
      node_.ReportStatus();
      next_status = now + std::chrono::seconds(10);
    }
    if (!CanStep()) {
      wakeup_.WaitUntil(now + std::chrono::milliseconds(50));
      pacer_.Anchor(Pacer::Clock::now(), node_.TimeNs());
      continue;
    }
    if (pending_steps_ == 0) Pace();
    node_.Step();
    if (pending_steps_ > 0) --pending_steps_;
    AfterStep();
    if (end_ns >= 0 && node_.TimeNs() >= end_ns) break;
  }
  node_.ReportStatus();
}

void ControlLoop::Reject(const std::string& kind, const std::string& detail) {
  std::lock_guard<std::mutex> lock(rejects_mutex_);
  rejects_.Reject(kind, detail);
  rejected_.store(rejects_.Total());
}

uint64_t ControlLoop::Rejected(const std::string& kind) const {
  std::lock_guard<std::mutex> lock(rejects_mutex_);
  return rejects_.Count(kind);
}

void ControlLoop::ReportTimeMode() const {
  spdlog::info("time: {}{}{}", TimeModeName(mode_), mode_ == TimeMode::kScaled ? fmt::format(" x{}", speed_) : "",
               paused_ ? ", paused" : "");
}

void ControlLoop::Pace() {
  if (mode_ != TimeMode::kRealtime && mode_ != TimeMode::kScaled) return;
  const auto deadline = pacer_.Deadline(node_.TimeNs() + timing_.step_ns, speed_);
  const auto now = Pacer::Clock::now();
  if (pacer_.CatchUp(now, deadline, node_.TimeNs())) {
    spdlog::debug("fell behind real time at t={:.3f}s; re-anchored", node_.TimeNs() * 1e-9);
    return;
  }
  if (deadline > now) std::this_thread::sleep_until(deadline);
}

void ControlLoop::TakeInputs() {
  node_.TakeCommands();
  if (control_reader_->Take(&control_inbox_)) {
    for (const idl::SimControl& c : control_inbox_) HandleControl(c);
  }
  const uint64_t overflow = node_.CommandsOverflowed() + control_reader_->Overflowed();
  if (overflow > reported_overflow_) {
    Reject("queue_overflow",
           fmt::format("{} samples arrived faster than the loop could take them", overflow - reported_overflow_));
    reported_overflow_ = overflow;
  }
}

void ControlLoop::HandleControl(const idl::SimControl& request) {
  ControlAnswer answer;
  switch (request.op()) {
    case idl::OP_TELEPORT_BALL:
      answer = node_.TeleportBall(request);
      break;
    case idl::OP_TELEPORT_ROBOT:
      answer = node_.TeleportRobot(request);
      break;
    case idl::OP_PAUSE:
      paused_ = true;
      break;
    case idl::OP_RESUME:
      paused_ = false;
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
      answer = node_.ChangeRealism(request.realism());
      break;
    default:
      answer = {idl::CONTROL_UNKNOWN_OP, fmt::format("unknown op {}", static_cast<int>(request.op()))};
      break;
  }
  if (!answer.ok()) Reject("control", fmt::format("from '{}': {}", request.client(), answer.reason));
  Reply(request, answer);
  // Teleports and resets show in the state right away, also while paused.
  PublishState();
}

ControlAnswer ControlLoop::QueueSteps(const idl::SimControl& request) {
  if (!paused_ && mode_ != TimeMode::kLockstep)
    return {idl::CONTROL_NOT_ALLOWED, "step needs a paused simulation or lockstep mode"};
  if (request.step_count() == 0 || request.step_count() > kMaxStepRequest)
    return {idl::CONTROL_OUT_OF_RANGE, fmt::format("step_count must be 1..{}", kMaxStepRequest)};
  ControlAnswer answer = node_.ApplyStepCommands(request);
  if (!answer.ok()) return answer;
  pending_steps_ += request.step_count();
  pending_replies_.push_back({node_.Frame() + pending_steps_, request});
  return {};
}

ControlAnswer ControlLoop::SetTimeMode(idl::TimeMode mode, double speed) {
  switch (mode) {
    case idl::TIME_REALTIME:
      mode_ = TimeMode::kRealtime;
      speed_ = 1.0;
      break;
    case idl::TIME_SCALED:
      if (!(std::isfinite(speed) && speed > 0.0 && speed <= kMaxSpeed))
        return {std::isfinite(speed) ? idl::CONTROL_OUT_OF_RANGE : idl::CONTROL_NOT_FINITE,
                fmt::format("speed must be in (0, {}]", kMaxSpeed)};
      mode_ = TimeMode::kScaled;
      speed_ = speed;
      break;
    case idl::TIME_FREE_RUNNING:
      mode_ = TimeMode::kFreeRunning;
      break;
    case idl::TIME_LOCKSTEP:
      mode_ = TimeMode::kLockstep;
      break;
    default:
      return {idl::CONTROL_UNKNOWN_ENUM, fmt::format("unknown time mode {}", static_cast<int>(mode))};
  }
  spdlog::info("time mode {} (speed {})", TimeModeName(mode_), speed_);
  pacer_.Anchor(Pacer::Clock::now(), node_.TimeNs());
  return {};
}

void ControlLoop::Reset() {
  const int64_t reached_ns = node_.TimeNs();
  node_.ResetWorld();
  // The new timeline starts where the old one ended: epoch + sim time stays monotonic.
  run_epoch_unix_ns_.fetch_add(reached_ns - node_.TimeNs());
  pending_steps_ = 0;
  for (const PendingStep& p : pending_replies_) Reply(p.request, {idl::CONTROL_CANCELLED, "cancelled by a reset"});
  pending_replies_.clear();
  pacer_.Anchor(Pacer::Clock::now(), node_.TimeNs());
}

void ControlLoop::Reply(const idl::SimControl& request, const ControlAnswer& answer) {
  idl::SimControlReply reply;
  reply.client(request.client());
  reply.request_id(request.request_id());
  reply.op(request.op());
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
  const bool steps_done = !pending_replies_.empty() && frame >= pending_replies_.front().done_at_frame;
  if (frame % state_every_ == 0 || steps_done) PublishState();
  node_.AfterStep();
  while (!pending_replies_.empty() && frame >= pending_replies_.front().done_at_frame) {
    Reply(pending_replies_.front().request, {});
    pending_replies_.pop_front();
  }
}

// The clock goes first: a reader that sees a state (a reset's, say) already has
// the clock, and so the run epoch, it belongs to.
void ControlLoop::PublishState() {
  idl::Clock clock;
  clock.sim_time_ns(node_.TimeNs());
  clock.frame(node_.Frame());
  clock.step_s(timing_.step_s);
  clock.paused(paused_);
  clock.mode(static_cast<idl::TimeMode>(mode_));
  clock.speed(speed_);
  clock.real_time_factor(pacer_.real_time_factor());
  clock.run_epoch_unix_ns(run_epoch_unix_ns_.load());
  clock_writer_->Write(clock);
  rtf_.store(pacer_.real_time_factor());
  node_.PublishState();
}

}  // namespace turf
