#include "participants/sim/sim_node.h"

#include <spdlog/spdlog.h>
#include <turf/idl/ClockPubSubTypes.h>
#include <turf/idl/SensorStatsPubSubTypes.h>
#include <turf/idl/SimControlPubSubTypes.h>
#include <turf/idl/SslRobotPubSubTypes.h>
#include <turf/idl/SslVisionPubSubTypes.h>
#include <turf/idl/WorldStatePubSubTypes.h>

#include <atomic>
#include <cmath>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <thread>

#include "config/realism_yaml.h"
#include "core/input_limits.h"
#include "core/link_model.h"
#include "core/rng.h"
#include "core/ssl_cameras.h"
#include "core/stream_stats.h"
#include "core/world.h"
#include "dds/participant.h"
#include "participants/common/process.h"
#include "participants/common/wakeup.h"
#include "participants/sim/convert.h"

namespace turf {

namespace {

constexpr double kMaxSpeed = 1000.0;  // multiples of real time a client may ask for
constexpr uint32_t kMaxStepRequest = 1000000;

struct PendingStep {
  uint64_t done_at_frame;
  idl::SimControl request;
};

// A team's command on its modelled radio link, due to reach the robot.
struct PendingCommand {
  int64_t due_ns;
  int64_t sent_ns;
  RobotCommand command;
};

constexpr int64_t kStatsWindowNs = 1'000'000'000;

int64_t UnixNowNs() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

std::string CommandStreamName(int team) { return std::string("ssl/command/") + TeamName(static_cast<Team>(team)); }

}  // namespace

class SimNode::Impl {
 public:
  Impl(Scene scene, SimNodeOptions options)
      : options_(std::move(options)),
        world_(std::move(scene)),
        cameras_(world_.scene()),
        participant_({options_.domain, options_.name, options_.prefix, options_.qos_file}),
        clock_writer_(participant_.MakeWriter<idl::ClockPubSubType>(dds::Topic::kClock)),
        state_writer_(participant_.MakeWriter<idl::WorldStatePubSubType>(dds::Topic::kWorldState)),
        field_writer_(participant_.MakeWriter<idl::SslFieldPubSubType>(dds::Topic::kSslField)),
        camera_writer_(participant_.MakeWriter<idl::CameraFramePubSubType>(dds::Topic::kSslCamera)),
        feedback_writers_{participant_.MakeWriter<idl::SslRobotFeedbackPubSubType>(dds::Topic::kSslFeedbackBlue),
                          participant_.MakeWriter<idl::SslRobotFeedbackPubSubType>(dds::Topic::kSslFeedbackYellow)},
        reply_writer_(participant_.MakeWriter<idl::SimControlReplyPubSubType>(dds::Topic::kControlReply)),
        stats_writer_(participant_.MakeWriter<idl::SensorStatsPubSubType>(dds::Topic::kStats)),
        command_readers_{participant_.MakeReader<idl::SslRobotCommandPubSubType>(dds::Topic::kSslCommandBlue,
                                                                                 [this] { wakeup_.Notify(); }),
                         participant_.MakeReader<idl::SslRobotCommandPubSubType>(dds::Topic::kSslCommandYellow,
                                                                                 [this] { wakeup_.Notify(); })},
        control_reader_(
            participant_.MakeReader<idl::SimControlPubSubType>(dds::Topic::kControl, [this] { wakeup_.Notify(); })),
        rejects_("input") {
    mode_ = options_.mode;
    speed_ = options_.mode == TimeMode::kScaled ? options_.speed : 1.0;
    paused_ = options_.start_paused;
    const Scene& s = world_.scene();
    state_every_ = std::max<int64_t>(1, std::llround(1.0 / (s.rates.world_state_hz * s.physics.step)));
    world_.Snapshot(&snapshot_);
    published_feedback_ = snapshot_.robots;
    for (int t = 0; t < kTeamCount; ++t)
      command_links_.emplace_back(s.realism.command, StreamSeed(s.seed, CommandStreamName(t)));
    SetRealism(s.realism);
  }

  void Run(const std::function<bool()>& stop) {
    ReportStartup();
    field_writer_->Write(FieldToIdl(world_.scene(), cameras_.cameras()));
    PublishState();
    const int64_t end_ns = options_.duration > 0 ? std::llround(options_.duration * 1e9) : -1;
    pacer_.Anchor(Pacer::Clock::now(), world_.time_ns());
    auto next_status = Pacer::Clock::now() + std::chrono::seconds(10);
    while (!stop()) {
      HandleInputs();
      const auto now = Pacer::Clock::now();
      pacer_.Measure(now, world_.time_ns());
      if (now >= next_status) {
        ReportStatus();
        next_status = now + std::chrono::seconds(10);
      }
      if (!CanStep()) {
        wakeup_.WaitUntil(now + std::chrono::milliseconds(50));
        pacer_.Anchor(Pacer::Clock::now(), world_.time_ns());
        continue;
      }
      if (pending_steps_ == 0) Pace();
      ApplyDueCommands();
      world_.Step();
      if (pending_steps_ > 0) --pending_steps_;
      AfterStep();
      if (end_ns >= 0 && world_.time_ns() >= end_ns) break;
    }
    ReportStatus();
  }

  SimNodeStats Stats() const { return {frame_.load(), time_ns_.load(), rejected_.load(), rtf_.load()}; }
  uint64_t Rejected(const std::string& kind) const {
    std::lock_guard<std::mutex> lock(rejects_mutex_);
    return rejects_.Count(kind);
  }

 private:
  bool CanStep() const { return pending_steps_ > 0 || (!paused_ && mode_ != TimeMode::kLockstep); }

  void Pace() {
    if (mode_ != TimeMode::kRealtime && mode_ != TimeMode::kScaled) return;
    const auto deadline = pacer_.Deadline(world_.time_ns() + world_.step_ns(), speed_);
    const auto now = Pacer::Clock::now();
    if (pacer_.CatchUp(now, deadline, world_.time_ns())) {
      spdlog::debug("fell behind real time at t={:.3f}s; re-anchored", world_.time_ns() * 1e-9);
      return;
    }
    if (deadline > now) std::this_thread::sleep_until(deadline);
  }

  // --- Inputs ---

  void Reject(const std::string& kind, const std::string& detail) {
    std::lock_guard<std::mutex> lock(rejects_mutex_);
    rejects_.Reject(kind, detail);
    rejected_.store(rejects_.Total());
  }

  void HandleInputs() {
    for (int t = 0; t < kTeamCount; ++t) {
      if (!command_readers_[t]->Take(&command_inbox_)) continue;
      for (const idl::SslRobotCommand& c : command_inbox_) ApplyCommand(c, static_cast<Team>(t));
    }
    if (control_reader_->Take(&control_inbox_)) {
      for (const idl::SimControl& c : control_inbox_) HandleControl(c);
    }
    const uint64_t overflow =
        command_readers_[0]->Overflowed() + command_readers_[1]->Overflowed() + control_reader_->Overflowed();
    if (overflow > reported_overflow_) {
      Reject("queue_overflow",
             fmt::format("{} samples arrived faster than the loop could take them", overflow - reported_overflow_));
      reported_overflow_ = overflow;
    }
  }

  // False (and counted) if the command was refused.
  bool ApplyCommand(const idl::SslRobotCommand& in, Team topic_team) {
    RobotCommand c;
    InputError error = FromIdl(in, &c);
    if (error == InputError::kOk && c.team != topic_team) {
      Reject("command.team_mismatch",
             fmt::format("a {} command on the {} command topic", TeamName(c.team), TeamName(topic_team)));
      return false;
    }
    if (error == InputError::kOk && world_.RobotIndex(c.team, c.id) < 0) error = InputError::kUnknownRobot;
    if (error == InputError::kOk) error = CheckCommand(c);
    if (error != InputError::kOk) {
      Reject(fmt::format("command.{}", InputErrorName(error)),
             fmt::format("{} robot {}", TeamName(topic_team), static_cast<int>(in.id())));
      return false;
    }
    // Valid: now it travels the team's modelled radio link (which may lose it).
    const int t = static_cast<int>(c.team);
    command_stats_[t].Sent();
    const std::optional<int64_t> due = command_links_[t].Transmit(world_.time_ns());
    if (!due) {
      command_stats_[t].Lost();
      return true;
    }
    pending_commands_[t].push_back({*due, world_.time_ns(), c});
    return true;
  }

  // Commands whose modelled radio delay has passed reach their robots.
  void ApplyDueCommands() {
    for (int t = 0; t < kTeamCount; ++t) {
      auto& queue = pending_commands_[t];
      while (!queue.empty() && queue.front().due_ns <= world_.time_ns()) {
        world_.SetCommand(queue.front().command);  // validated on arrival
        command_stats_[t].Delivered((world_.time_ns() - queue.front().sent_ns) * 1e-9);
        queue.pop_front();
      }
    }
  }

  void SetRealism(const SensorRealism& realism) {
    realism_ = realism;
    cameras_.SetRealism(realism.camera);
    for (Link& link : command_links_) link.SetParams(realism.command);
  }

  std::string ChangeRealism(const std::string& spec) {
    // From the network: preset names and YAML text only, never file paths.
    const RealismLoadResult loaded = LoadRealism(spec, realism_dir_, /*allow_paths=*/false, realism_);
    if (!loaded.realism) return loaded.errors.empty() ? "invalid realism" : loaded.errors.front();
    SetRealism(*loaded.realism);
    spdlog::info("sensor realism changed ({})", spec.size() < 40 ? spec : spec.substr(0, 40) + "...");
    return "";
  }

  void HandleControl(const idl::SimControl& req) {
    std::string why;
    switch (req.op()) {
      case idl::OP_TELEPORT_BALL: {
        BallTeleport t;
        FromIdl(req.ball(), &t);
        const InputError e = world_.TeleportBall(t);
        if (e != InputError::kOk) why = fmt::format("ball teleport refused: {}", InputErrorName(e));
        break;
      }
      case idl::OP_TELEPORT_ROBOT: {
        RobotTeleport t;
        InputError e = FromIdl(req.robot(), &t);
        if (e == InputError::kOk) e = world_.TeleportRobot(t);
        if (e != InputError::kOk) why = fmt::format("robot teleport refused: {}", InputErrorName(e));
        break;
      }
      case idl::OP_PAUSE:
        paused_ = true;
        break;
      case idl::OP_RESUME:
        paused_ = false;
        break;
      case idl::OP_STEP:
        why = QueueSteps(req);
        if (why.empty()) return;  // replied when the steps are done
        break;
      case idl::OP_RESET:
        ResetWorld();
        break;
      case idl::OP_SET_TIME_MODE:
        why = SetTimeMode(req.time_mode(), req.speed());
        break;
      case idl::OP_SET_REALISM:
        why = ChangeRealism(req.realism());
        break;
      default:
        why = fmt::format("unknown op {}", static_cast<int>(req.op()));
        break;
    }
    if (!why.empty()) Reject("control", fmt::format("from '{}': {}", req.client(), why));
    Reply(req, why);
    // Teleports and resets show in the world state right away, also while paused.
    PublishState();
  }

  std::string QueueSteps(const idl::SimControl& req) {
    if (!paused_ && mode_ != TimeMode::kLockstep) return "step needs a paused simulation or lockstep mode";
    if (req.step_count() == 0 || req.step_count() > kMaxStepRequest)
      return fmt::format("step_count must be 1..{}", kMaxStepRequest);
    for (const idl::SslRobotCommand& c : req.commands()) {
      Team team;
      if (!FromIdl(c.team(), &team)) return "a command has an unknown team";
      ApplyCommand(c, team);
    }
    pending_steps_ += req.step_count();
    pending_replies_.push_back({world_.frame() + pending_steps_, req});
    return "";
  }

  std::string SetTimeMode(idl::TimeMode mode, double speed) {
    switch (mode) {
      case idl::TIME_REALTIME:
        mode_ = TimeMode::kRealtime;
        speed_ = 1.0;
        break;
      case idl::TIME_SCALED:
        if (!(std::isfinite(speed) && speed > 0.0 && speed <= kMaxSpeed))
          return fmt::format("speed must be in (0, {}]", kMaxSpeed);
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
        return fmt::format("unknown time mode {}", static_cast<int>(mode));
    }
    spdlog::info("time mode {} (speed {})", TimeModeName(mode_), speed_);
    pacer_.Anchor(Pacer::Clock::now(), world_.time_ns());
    return "";
  }

  void ResetWorld() {
    world_.Reset();
    cameras_.Reset();
    for (int t = 0; t < kTeamCount; ++t) {
      command_links_[t].Reset(StreamSeed(world_.scene().seed, CommandStreamName(t)));
      pending_commands_[t].clear();
    }
    pending_steps_ = 0;
    for (const PendingStep& p : pending_replies_) Reply(p.request, "cancelled by a reset");
    pending_replies_.clear();
    world_.Snapshot(&snapshot_);
    published_feedback_ = snapshot_.robots;
    pacer_.Anchor(Pacer::Clock::now(), world_.time_ns());
  }

  void Reply(const idl::SimControl& req, const std::string& why) {
    idl::SimControlReply reply;
    reply.client(req.client());
    reply.request_id(req.request_id());
    reply.op(req.op());
    reply.result(why.empty() ? idl::RESULT_OK : idl::RESULT_REJECTED);
    reply.reason(why);
    reply.sim_time_ns(world_.time_ns());
    reply.frame(world_.frame());
    reply_writer_->Write(reply);
  }

  // --- Outputs ---

  void AfterStep() {
    world_.Snapshot(&snapshot_);
    frame_.store(world_.frame());
    time_ns_.store(world_.time_ns());
    const bool steps_done = !pending_replies_.empty() && world_.frame() >= pending_replies_.front().done_at_frame;
    if (world_.frame() % state_every_ == 0 || steps_done) PublishState();
    if (cameras_.Due(world_.time_ns())) cameras_.Capture(snapshot_);
    cameras_.Release(world_.time_ns(), &camera_frames_);
    if (!camera_frames_.empty()) {
      // Source timestamp: the wall time the simulation was at the capture.
      const int64_t wall_now = UnixNowNs();
      const double per_sim_ns = (mode_ == TimeMode::kRealtime || mode_ == TimeMode::kScaled) ? 1.0 / speed_ : 0.0;
      for (const CameraFrame& f : camera_frames_) {
        ToIdl(f, &camera_sample_);
        const int64_t age = std::llround((world_.time_ns() - f.capture_time_ns) * per_sim_ns);
        camera_writer_->Write(camera_sample_, wall_now - age);
      }
    }
    if (world_.time_ns() >= next_stats_ns_) PublishStats();
    PublishFeedback();
    while (!pending_replies_.empty() && world_.frame() >= pending_replies_.front().done_at_frame) {
      Reply(pending_replies_.front().request, "");
      pending_replies_.pop_front();
    }
  }

  void PublishState() {
    world_.Snapshot(&snapshot_);
    ToIdl(snapshot_, &state_sample_);
    state_writer_->Write(state_sample_);
    idl::Clock clock;
    clock.sim_time_ns(world_.time_ns());
    clock.frame(world_.frame());
    clock.step_s(world_.scene().physics.step);
    clock.paused(paused_);
    clock.mode(static_cast<idl::TimeMode>(mode_));
    clock.speed(speed_);
    clock.real_time_factor(pacer_.real_time_factor());
    clock_writer_->Write(clock);
    rtf_.store(pacer_.real_time_factor());
  }

  void PublishStats() {
    idl::SensorStats out;
    out.sim_time_ns(world_.time_ns());
    out.window_s(kStatsWindowNs * 1e-9);
    auto add = [&](const std::string& name, const StreamWindow& w) {
      idl::StreamStats s;
      s.name(name);
      s.rate_hz(w.delivered / out.window_s());
      s.sent(w.sent);
      s.lost(w.lost);
      s.loss_ratio(w.sent > 0 ? static_cast<double>(w.lost) / w.sent : 0.0);
      s.latency_mean(w.latency_mean);
      s.latency_stddev(w.latency_stddev);
      out.streams().push_back(s);
    };
    for (size_t c = 0; c < cameras_.cameras().size(); ++c)
      add(fmt::format("ssl/camera/{}", c), cameras_.TakeStats(static_cast<int>(c)));
    for (int t = 0; t < kTeamCount; ++t) add(CommandStreamName(t), command_stats_[t].Take());
    stats_writer_->Write(out);
    last_stats_ = out;
    next_stats_ns_ = world_.time_ns() + kStatsWindowNs;
  }

  void PublishFeedback() {
    for (size_t i = 0; i < snapshot_.robots.size(); ++i) {
      const RobotSnapshot& now = snapshot_.robots[i];
      RobotSnapshot& last = published_feedback_[i];
      if (now.ball_contact == last.ball_contact && now.kick_count == last.kick_count) continue;
      feedback_writers_[static_cast<int>(now.team)]->Write(FeedbackToIdl(now, world_.time_ns()));
      last = now;
    }
  }

  void ReportStartup() const {
    const Scene& s = world_.scene();
    int on_field[2] = {0, 0};
    for (const RobotSnapshot& r : snapshot_.robots) on_field[static_cast<int>(r.team)] += r.on_field;
    spdlog::info(
        "scene '{}': division {}, {} blue + {} yellow robots on the field ({} ids a team), step {} ms, seed {}", s.name,
        s.field.division == Division::kA ? "A" : "B", on_field[0], on_field[1], s.robots_per_team, s.physics.step * 1e3,
        s.seed);
    spdlog::info("DDS domain {}, QoS profiles {}", options_.domain, participant_.options().qos_file);
    auto name = [this](dds::Topic t) { return participant_.TopicName(t); };
    spdlog::info("publishing {} and {} at {:.0f} Hz of sim time", name(dds::Topic::kWorldState),
                 name(dds::Topic::kClock), s.rates.world_state_hz);
    spdlog::info("publishing {} ({} cameras at {:.0f} Hz), {} (latched)", name(dds::Topic::kSslCamera),
                 cameras_.cameras().size(), s.cameras.rate_hz, name(dds::Topic::kSslField));
    spdlog::info("publishing {} and {} on change, {}, {} every second of sim time",
                 name(dds::Topic::kSslFeedbackBlue), name(dds::Topic::kSslFeedbackYellow),
                 name(dds::Topic::kControlReply), name(dds::Topic::kStats));
    const CameraRealism& c = realism_.camera;
    spdlog::info("sensor realism: camera noise {:.1f} mm / {:.3f} rad, vanish {:.1f}%/{:.1f}%, occlusion {}, "
                 "delay {:.1f} ms + link {:.1f} ms, link loss {:.1f}%{}; command link {:.1f} ms, loss {:.1f}%{}",
                 c.robot_position_stddev * 1e3, c.robot_orientation_stddev, c.robot_vanish * 100, c.ball_vanish * 100,
                 c.ball_occlusion ? "on" : "off", c.processing_delay * 1e3, c.link.latency * 1e3, c.link.loss * 100,
                 c.link.burst.enabled ? " (bursts)" : "", realism_.command.latency * 1e3, realism_.command.loss * 100,
                 realism_.command.burst.enabled ? " (bursts)" : "");
    spdlog::info("subscribing {}, {}, {}; command timeout {} s", name(dds::Topic::kSslCommandBlue),
                 name(dds::Topic::kSslCommandYellow), name(dds::Topic::kControl), s.rates.command_timeout);
    spdlog::info("time: {}{}{}", TimeModeName(mode_), mode_ == TimeMode::kScaled ? fmt::format(" x{}", speed_) : "",
                 paused_ ? ", paused" : "");
  }

  void ReportStatus() const {
    const WorldHealth& h = world_.health();
    spdlog::info("t={:.1f}s frame={} rtf={:.2f} refused={} containment={} recoveries={}", world_.time_ns() * 1e-9,
                 world_.frame(), pacer_.real_time_factor(), rejected_.load(), h.containment_corrections,
                 h.instability_recoveries);
    std::string streams;
    for (const idl::StreamStats& st : last_stats_.streams()) {
      if (st.sent() == 0) continue;
      streams += fmt::format(" {} {:.0f}/s loss {:.1f}% latency {:.1f}+-{:.1f}ms;", st.name(), st.rate_hz(),
                             100.0 * st.loss_ratio(), st.latency_mean() * 1e3, st.latency_stddev() * 1e3);
    }
    if (!streams.empty()) spdlog::info("streams (last second of sim time):{}", streams);
  }

  SimNodeOptions options_;
  World world_;
  SslCameraSystem cameras_;
  Pacer pacer_;
  Wakeup wakeup_;
  dds::Participant participant_;
  std::unique_ptr<dds::Writer<idl::ClockPubSubType>> clock_writer_;
  std::unique_ptr<dds::Writer<idl::WorldStatePubSubType>> state_writer_;
  std::unique_ptr<dds::Writer<idl::SslFieldPubSubType>> field_writer_;
  std::unique_ptr<dds::Writer<idl::CameraFramePubSubType>> camera_writer_;
  std::unique_ptr<dds::Writer<idl::SslRobotFeedbackPubSubType>> feedback_writers_[kTeamCount];
  std::unique_ptr<dds::Writer<idl::SimControlReplyPubSubType>> reply_writer_;
  std::unique_ptr<dds::Writer<idl::SensorStatsPubSubType>> stats_writer_;
  std::unique_ptr<dds::Reader<idl::SslRobotCommandPubSubType>> command_readers_[kTeamCount];
  std::unique_ptr<dds::Reader<idl::SimControlPubSubType>> control_reader_;

  TimeMode mode_ = TimeMode::kRealtime;
  double speed_ = 1.0;
  bool paused_ = false;
  int64_t state_every_ = 1;
  uint64_t pending_steps_ = 0;
  std::deque<PendingStep> pending_replies_;
  uint64_t reported_overflow_ = 0;

  SensorRealism realism_;
  std::string realism_dir_ = DefaultRealismDir();
  std::vector<Link> command_links_;
  std::deque<PendingCommand> pending_commands_[kTeamCount];
  StreamStats command_stats_[kTeamCount];
  int64_t next_stats_ns_ = kStatsWindowNs;
  idl::SensorStats last_stats_;

  WorldSnapshot snapshot_;
  std::vector<RobotSnapshot> published_feedback_;
  std::vector<CameraFrame> camera_frames_;
  idl::WorldState state_sample_;
  idl::CameraFrame camera_sample_;
  std::vector<idl::SslRobotCommand> command_inbox_;
  std::vector<idl::SimControl> control_inbox_;

  mutable std::mutex rejects_mutex_;
  RejectLog rejects_;
  std::atomic<uint64_t> rejected_{0};
  std::atomic<uint64_t> frame_{0};
  std::atomic<int64_t> time_ns_{0};
  std::atomic<double> rtf_{0.0};
};

SimNode::SimNode(Scene scene, SimNodeOptions options)
    : impl_(std::make_unique<Impl>(std::move(scene), std::move(options))) {}
SimNode::~SimNode() = default;
void SimNode::Run(const std::function<bool()>& stop) { impl_->Run(stop); }
SimNodeStats SimNode::Stats() const { return impl_->Stats(); }
uint64_t SimNode::Rejected(const std::string& kind) const { return impl_->Rejected(kind); }

}  // namespace turf
