#include "participants/sim/sim_node.h"

#include <spdlog/spdlog.h>
#include <turf/idl/SensorStatsPubSubTypes.h>
#include <turf/idl/SslRobotPubSubTypes.h>
#include <turf/idl/SslVisionPubSubTypes.h>
#include <turf/idl/WorldStatePubSubTypes.h>

#include <cmath>
#include <deque>

#include "core/input_limits.h"
#include "core/link_model.h"
#include "core/rng.h"
#include "core/ssl_cameras.h"
#include "core/stream_stats.h"
#include "core/world.h"
#include "dds/participant.h"
#include "loader/realism_yaml.h"
#include "participants/sim/control_loop.h"
#include "participants/sim/convert.h"

namespace turf {

namespace {

// A team's command on its modelled radio link, due to reach the robot.
struct PendingCommand {
  int64_t due_ns;
  int64_t sent_ns;
  RobotCommand command;
};

constexpr int64_t kStatsWindowNs = 1'000'000'000;

// A robot radio acknowledges kick requests and sends a lost one again at once,
// so link loss delays a kick by a few retries instead of losing it: a team's
// single kick command always reaches the robot (see the kicker's arm time).
constexpr int64_t kKickRetryNs = 1'000'000;
constexpr int kKickTries = 50;

int64_t UnixNowNs() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

std::string CommandStreamName(int team) { return std::string("ssl/command/") + TeamName(static_cast<Team>(team)); }

}  // namespace

class SimNode::Impl final : private ControlLoop::Node {
 public:
  Impl(Scene scene, SimNodeOptions options)
      : options_(std::move(options)),
        world_(std::move(scene)),
        cameras_(world_.scene()),
        participant_({options_.domain, options_.name, options_.prefix, options_.qos_file}),
        loop_(participant_, options_, LoopTiming(world_.scene(), world_.step_ns()), *this),
        state_writer_(participant_.MakeWriter<idl::WorldStatePubSubType>(dds::Topic::kWorldState)),
        field_writer_(participant_.MakeWriter<idl::SslFieldPubSubType>(dds::Topic::kSslField)),
        camera_writer_(participant_.MakeWriter<idl::CameraFramePubSubType>(dds::Topic::kSslCamera)),
        feedback_writers_{participant_.MakeWriter<idl::SslRobotFeedbackPubSubType>(dds::Topic::kSslFeedbackBlue),
                          participant_.MakeWriter<idl::SslRobotFeedbackPubSubType>(dds::Topic::kSslFeedbackYellow)},
        stats_writer_(participant_.MakeWriter<idl::SensorStatsPubSubType>(dds::Topic::kStats)),
        command_readers_{participant_.MakeReader<idl::SslRobotCommandPubSubType>(dds::Topic::kSslCommandBlue,
                                                                                 [this] { loop_.Wake(); }),
                         participant_.MakeReader<idl::SslRobotCommandPubSubType>(dds::Topic::kSslCommandYellow,
                                                                                 [this] { loop_.Wake(); })} {
    const Scene& s = world_.scene();
    world_.Snapshot(&snapshot_);
    published_feedback_ = snapshot_.robots;
    for (int t = 0; t < kTeamCount; ++t)
      command_links_.emplace_back(s.realism.command, StreamSeed(s.seed, CommandStreamName(t)));
    SetRealism(s.realism);
  }

  void Run(const std::function<bool()>& stop) {
    ReportStartup();
    field_writer_->Write(FieldToIdl(world_.scene(), cameras_.cameras()));
    loop_.Run(stop);
  }

  SimNodeStats Stats() const { return loop_.Stats(); }
  uint64_t Rejected(const std::string& kind) const { return loop_.Rejected(kind); }

 private:
  static ControlLoop::Timing LoopTiming(const Scene& s, int64_t step_ns) {
    return {s.physics.step, step_ns, s.rates.world_state_hz};
  }

  // --- ControlLoop::Node ---

  int64_t TimeNs() const override { return world_.time_ns(); }
  uint64_t Frame() const override { return world_.frame(); }

  void TakeCommands() override {
    for (int t = 0; t < kTeamCount; ++t) {
      if (!command_readers_[t]->Take(&command_inbox_)) continue;
      for (const idl::SslRobotCommand& c : command_inbox_) ApplyCommand(c, static_cast<Team>(t));
    }
  }

  uint64_t CommandsOverflowed() const override {
    return command_readers_[0]->Overflowed() + command_readers_[1]->Overflowed();
  }

  void Step() override {
    ApplyDueCommands();
    world_.Step();
  }

  ControlAnswer ApplyStepCommands(const idl::SimControl& req) override {
    for (const idl::SslRobotCommand& c : req.commands()) {
      Team team;
      if (!FromIdl(c.team(), &team)) return {idl::CONTROL_UNKNOWN_ENUM, "a command has an unknown team"};
      ApplyCommand(c, team);
    }
    return {};
  }

  ControlAnswer TeleportBall(const idl::SimControl& req) override {
    BallTeleport t;
    FromIdl(req.ball(), &t);
    const InputError e = world_.TeleportBall(t);
    if (e == InputError::kOk) return {};
    return {ControlErrorOf(e), fmt::format("ball teleport refused: {}", InputErrorName(e))};
  }

  ControlAnswer TeleportRobot(const idl::SimControl& req) override {
    RobotTeleport t;
    InputError e = FromIdl(req.robot(), &t);
    if (e == InputError::kOk) e = world_.TeleportRobot(t);
    if (e == InputError::kOk) return {};
    return {ControlErrorOf(e), fmt::format("robot teleport refused: {}", InputErrorName(e))};
  }

  // --- Inputs ---

  // False (and counted) if the command was refused.
  bool ApplyCommand(const idl::SslRobotCommand& in, Team topic_team) {
    RobotCommand c;
    InputError error = FromIdl(in, &c);
    if (error == InputError::kOk && c.team != topic_team) {
      loop_.Reject("command.team_mismatch",
                   fmt::format("a {} command on the {} command topic", TeamName(c.team), TeamName(topic_team)));
      return false;
    }
    if (error == InputError::kOk && world_.RobotIndex(c.team, c.id) < 0) error = InputError::kUnknownRobot;
    if (error == InputError::kOk) error = CheckCommand(c);
    if (error != InputError::kOk) {
      loop_.Reject(fmt::format("command.{}", InputErrorName(error)),
                   fmt::format("{} robot {}", TeamName(topic_team), static_cast<int>(in.id())));
      return false;
    }
    // Valid: now it travels the team's modelled radio link (which may lose it).
    const int t = static_cast<int>(c.team);
    command_stats_[t].Sent();
    const bool kick = c.kick != KickKind::kNone && c.kick_speed > 0.0;
    const std::optional<int64_t> due =
        kick ? command_links_[t].TransmitAcknowledged(world_.time_ns(), kKickRetryNs, kKickTries)
             : command_links_[t].Transmit(world_.time_ns());
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

  ControlAnswer ChangeRealism(const std::string& spec) override {
    // From the network: preset names and YAML text only, never file paths.
    const RealismLoadResult loaded = LoadRealism(spec, realism_dir_, /*allow_paths=*/false, realism_);
    if (!loaded.realism)
      return {idl::CONTROL_INVALID_REALISM, loaded.errors.empty() ? "invalid realism" : loaded.errors.front()};
    SetRealism(*loaded.realism);
    spdlog::info("sensor realism changed ({})", spec.size() < 40 ? spec : spec.substr(0, 40) + "...");
    return {};
  }

  void ResetWorld() override {
    world_.Reset();
    cameras_.Reset();
    for (int t = 0; t < kTeamCount; ++t) {
      command_links_[t].Reset(StreamSeed(world_.scene().seed, CommandStreamName(t)));
      pending_commands_[t].clear();
    }
    world_.Snapshot(&snapshot_);
    published_feedback_ = snapshot_.robots;
  }

  // --- Outputs ---

  void AfterStep() override {
    world_.Snapshot(&snapshot_);
    if (cameras_.Due(world_.time_ns())) cameras_.Capture(snapshot_);
    cameras_.Release(world_.time_ns(), &camera_frames_);
    if (!camera_frames_.empty()) {
      // Source timestamp: the wall time the simulation was at the capture.
      const int64_t wall_now = UnixNowNs();
      const TimeMode mode = loop_.mode();
      const double per_sim_ns = (mode == TimeMode::kRealtime || mode == TimeMode::kScaled) ? 1.0 / loop_.speed() : 0.0;
      for (const CameraFrame& f : camera_frames_) {
        ToIdl(f, &camera_sample_);
        const int64_t age = std::llround((world_.time_ns() - f.capture_time_ns) * per_sim_ns);
        camera_writer_->Write(camera_sample_, wall_now - age);
      }
    }
    if (world_.time_ns() >= next_stats_ns_) PublishStats();
    PublishFeedback();
  }

  void PublishState() override {
    world_.Snapshot(&snapshot_);
    ToIdl(snapshot_, &state_sample_);
    state_writer_->Write(state_sample_);
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
    spdlog::info("publishing {} and {} on change, {}, {} every second of sim time", name(dds::Topic::kSslFeedbackBlue),
                 name(dds::Topic::kSslFeedbackYellow), name(dds::Topic::kControlReply), name(dds::Topic::kStats));
    const CameraRealism& c = realism_.camera;
    spdlog::info(
        "sensor realism: camera noise {:.1f} mm / {:.3f} rad, vanish {:.1f}%/{:.1f}%, occlusion {}, "
        "delay {:.1f} ms + link {:.1f} ms, link loss {:.1f}%{}; command link {:.1f} ms, loss {:.1f}%{}",
        c.robot_position_stddev * 1e3, c.robot_orientation_stddev, c.robot_vanish * 100, c.ball_vanish * 100,
        c.ball_occlusion ? "on" : "off", c.processing_delay * 1e3, c.link.latency * 1e3, c.link.loss * 100,
        c.link.burst.enabled ? " (bursts)" : "", realism_.command.latency * 1e3, realism_.command.loss * 100,
        realism_.command.burst.enabled ? " (bursts)" : "");
    spdlog::info("subscribing {}, {}, {}; command timeout {} s", name(dds::Topic::kSslCommandBlue),
                 name(dds::Topic::kSslCommandYellow), name(dds::Topic::kControl), s.rates.command_timeout);
    loop_.ReportTimeMode();
  }

  void ReportStatus() const override {
    const WorldHealth& h = world_.health();
    spdlog::info("t={:.1f}s frame={} rtf={:.2f} refused={} containment={} recoveries={}", world_.time_ns() * 1e-9,
                 world_.frame(), loop_.real_time_factor(), loop_.rejected(), h.containment_corrections,
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
  dds::Participant participant_;
  ControlLoop loop_;  // before the readers: their callbacks wake it
  std::unique_ptr<dds::Writer<idl::WorldStatePubSubType>> state_writer_;
  std::unique_ptr<dds::Writer<idl::SslFieldPubSubType>> field_writer_;
  std::unique_ptr<dds::Writer<idl::CameraFramePubSubType>> camera_writer_;
  std::unique_ptr<dds::Writer<idl::SslRobotFeedbackPubSubType>> feedback_writers_[kTeamCount];
  std::unique_ptr<dds::Writer<idl::SensorStatsPubSubType>> stats_writer_;
  std::unique_ptr<dds::Reader<idl::SslRobotCommandPubSubType>> command_readers_[kTeamCount];

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
};

SimNode::SimNode(Scene scene, SimNodeOptions options)
    : impl_(std::make_unique<Impl>(std::move(scene), std::move(options))) {}
SimNode::~SimNode() = default;
void SimNode::Run(const std::function<bool()>& stop) { impl_->Run(stop); }
SimNodeStats SimNode::Stats() const { return impl_->Stats(); }
uint64_t SimNode::Rejected(const std::string& kind) const { return impl_->Rejected(kind); }

}  // namespace turf
