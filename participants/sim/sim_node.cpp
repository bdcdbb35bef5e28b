#include "participants/sim/sim_node.h"

#include <spdlog/spdlog.h>
#include <turf/idl/SensorStatsPubSubTypes.h>
#include <turf/idl/SslRobotPubSubTypes.h>
#include <turf/idl/SslVisionPubSubTypes.h>
#include <turf/idl/WorldStatePubSubTypes.h>

#include <cmath>
#include <deque>

#include "dds/bus.h"
#include "kernel/ssl_kernel.h"
#include "loader/realism_yaml.h"
#include "participants/sim/control_loop.h"
#include "participants/sim/convert.h"
#include "participants/sim/kernel_node.h"
#include "participants/sim/ssl_publisher.h"
#include "participants/sim/stats_report.h"

namespace turf {

namespace {

int64_t UnixNowNs() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

class SslNode final : public KernelNode<SslKernel, SslPublisher> {
  static constexpr dds::TopicDef<idl::SslRobotCommandPubSubType> kCommandTopics[kTeamCount] = {
      dds::Topic::kSslCommandBlue, dds::Topic::kSslCommandYellow};

 public:
  SslNode(Scene scene, SimNodeOptions options, dds::Bus* bus)
      : KernelNode("ssl", std::move(scene), std::move(options), bus, LoopTiming),
        command_readers_{
            bus_.MakeReader<idl::SslRobotCommandPubSubType>(dds::Topic::kSslCommandBlue, [this] { loop_.Wake(); }),
            bus_.MakeReader<idl::SslRobotCommandPubSubType>(dds::Topic::kSslCommandYellow, [this] { loop_.Wake(); })} {}

  void Run(const std::function<bool()>& stop) override {
    ReportStartup();
    publisher_.PublishField(kernel_);
    loop_.Run(stop);
  }

 private:
  static ControlLoop::Timing LoopTiming(const SslKernel& k) {
    const Scene& s = k.scene();
    return {s.physics.step, k.world().step_ns(), s.rates.world_state_hz};
  }

  // --- ControlLoop::Node ---

  void TakeCommands() override {
    for (int t = 0; t < kTeamCount; ++t) {
      if (!command_readers_[t]->Take(&command_inbox_)) continue;
      for (const idl::SslRobotCommand& c : command_inbox_) {
        loop_.Took(kCommandTopics[t], c);
        ApplyCommand(c, static_cast<Team>(t));
      }
    }
  }

  std::string ApplyRecordedInput(const std::string& topic, const std::vector<uint8_t>& cdr) override {
    for (int t = 0; t < kTeamCount; ++t) {
      if (topic != kCommandTopics[t].info().suffix) continue;
      idl::SslRobotCommand c;
      if (!FromCdr<idl::SslRobotCommandPubSubType>(cdr.data(), cdr.size(), &c))
        return "a recorded " + topic + " sample is no SslRobotCommand";
      ApplyCommand(c, static_cast<Team>(t));
      return {};
    }
    return "an SSL scene takes no input on " + topic;
  }

  uint64_t CommandsOverflowed() const override {
    return command_readers_[0]->Overflowed() + command_readers_[1]->Overflowed();
  }

  // All or nothing, as the STEP's contract says (and the legged node's): every command is checked before any is
  // applied, and a STEP with one refused command is refused whole, naming it.
  ControlAnswer ApplyStepCommands(const idl::SimControl& req) override {
    std::vector<RobotCommand> commands(req.commands().size());
    for (size_t i = 0; i < commands.size(); ++i) {
      const idl::SslRobotCommand& in = req.commands()[i];
      Team team;
      if (!FromIdl(in.team(), &team))
        return {idl::CONTROL_UNKNOWN_ENUM, fmt::format("command {} of the STEP has an unknown team", i)};
      InputError e = FromIdl(in, &commands[i]);
      if (e == InputError::kOk) e = kernel_.CheckCommandInput(team, commands[i]);
      if (e != InputError::kOk)
        return {ControlErrorOf(e), fmt::format("command {} of the STEP ({} robot {}): {}", i, TeamName(team),
                                               static_cast<int>(in.id()), InputErrorName(e))};
    }
    for (const RobotCommand& c : commands) kernel_.Command(c.team, c);
    return {};
  }

  ControlAnswer TeleportBall(const idl::SimControl& req) override {
    BallTeleport t;
    FromIdl(req.ball(), &t);
    const InputError e = kernel_.TeleportBall(t);
    if (e == InputError::kOk) return {};
    return {ControlErrorOf(e), fmt::format("ball teleport refused: {}", InputErrorName(e))};
  }

  ControlAnswer TeleportRobot(const idl::SimControl& req) override {
    RobotTeleport t;
    InputError e = FromIdl(req.robot(), &t);
    if (e == InputError::kOk) e = kernel_.TeleportRobot(t);
    if (e == InputError::kOk) return {};
    return {ControlErrorOf(e), fmt::format("robot teleport refused: {}", InputErrorName(e))};
  }

  // --- Inputs ---

  // Refused commands are counted and logged per kind.
  void ApplyCommand(const idl::SslRobotCommand& in, Team topic_team) {
    RobotCommand c;
    InputError error = FromIdl(in, &c);
    if (error == InputError::kOk) error = kernel_.Command(topic_team, c);
    if (error == InputError::kTeamMismatch) {
      loop_.Reject("command.team_mismatch",
                   fmt::format("a {} command on the {} command topic", TeamName(c.team), TeamName(topic_team)));
    } else if (error != InputError::kOk) {
      loop_.Reject(fmt::format("command.{}", InputErrorName(error)),
                   fmt::format("{} robot {}", TeamName(topic_team), static_cast<int>(in.id())));
    }
  }

  void ResetWorld() override { kernel_.Reset(); }

  // --- Outputs ---

  void AfterStep() override {
    // Camera frames' source timestamp: the wall time the simulation was at the capture.
    const bool frames = !kernel_.camera_frames().empty();
    const TimeMode mode = loop_.mode();
    const double per_sim_ns = (mode == TimeMode::kRealtime || mode == TimeMode::kScaled) ? 1.0 / loop_.speed() : 0.0;
    publisher_.AfterStep(kernel_, frames ? UnixNowNs() : 0, per_sim_ns);
  }

  void ReportStartup() const {
    const Scene& s = kernel_.scene();
    int on_field[2] = {0, 0};
    for (const RobotSnapshot& r : kernel_.state().robots) on_field[static_cast<int>(r.team)] += r.on_field;
    spdlog::info(
        "scene '{}': division {}, {} blue + {} yellow robots on the field ({} ids a team), step {} ms, seed {}", s.name,
        s.field.division == Division::kA ? "A" : "B", on_field[0], on_field[1], s.robots_per_team, s.physics.step * 1e3,
        s.seed);
    spdlog::info("{}", bus_.Describe());
    auto name = [this](dds::Topic t) { return bus_.TopicName(t); };
    spdlog::info("publishing {} and {} at {:.0f} Hz of sim time", name(dds::Topic::kWorldState),
                 name(dds::Topic::kClock), s.rates.world_state_hz);
    spdlog::info("publishing {} ({} cameras at {:.0f} Hz), {} (latched)", name(dds::Topic::kSslCamera),
                 kernel_.cameras().size(), s.cameras.rate_hz, name(dds::Topic::kSslField));
    spdlog::info("publishing {} and {} on change, {}, {} every second of sim time", name(dds::Topic::kSslFeedbackBlue),
                 name(dds::Topic::kSslFeedbackYellow), name(dds::Topic::kControlReply), name(dds::Topic::kStats));
    const SensorRealism& realism = kernel_.realism();
    const CameraRealism& c = realism.camera;
    spdlog::info(
        "sensor realism: camera noise {:.1f} mm / {:.3f} rad, vanish {:.1f}%/{:.1f}%, occlusion {}, "
        "delay {:.1f} ms + link {:.1f} ms, link loss {:.1f}%{}; command link {:.1f} ms, loss {:.1f}%{}",
        c.robot_position_stddev * 1e3, c.robot_orientation_stddev, c.robot_vanish * 100, c.ball_vanish * 100,
        c.ball_occlusion ? "on" : "off", c.processing_delay * 1e3, c.link.latency * 1e3, c.link.loss * 100,
        c.link.burst.enabled ? " (bursts)" : "", realism.command.latency * 1e3, realism.command.loss * 100,
        realism.command.burst.enabled ? " (bursts)" : "");
    spdlog::info("subscribing {}, {}, {}; command timeout {} s", name(dds::Topic::kSslCommandBlue),
                 name(dds::Topic::kSslCommandYellow), name(dds::Topic::kControl), s.rates.command_timeout);
    loop_.ReportTimeMode();
  }

  void ReportStatus() const override {
    const WorldHealth& h = kernel_.world().health();
    ReportStatusWith(fmt::format("containment={} recoveries={} solver_capped_steps={}", h.containment_corrections,
                                 h.instability_recoveries, h.solver_capped_steps));
  }

  std::unique_ptr<dds::Reader<idl::SslRobotCommandPubSubType>> command_readers_[kTeamCount];

  std::vector<idl::SslRobotCommand> command_inbox_;
};

}  // namespace

std::unique_ptr<SimNode::Impl> MakeSslNode(Scene scene, SimNodeOptions options, dds::Bus* bus) {
  return std::make_unique<SslNode>(std::move(scene), std::move(options), bus);
}

SimNode::SimNode(Scene scene, SimNodeOptions options)
    : impl_(MakeSslNode(std::move(scene), std::move(options), nullptr)) {}
SimNode::SimNode(LeggedScene scene, SimNodeOptions options)
    : impl_(MakeLeggedNode(std::move(scene), std::move(options), nullptr)) {}
SimNode::SimNode(Scene scene, SimNodeOptions options, dds::Bus& bus)
    : impl_(MakeSslNode(std::move(scene), std::move(options), &bus)) {}
SimNode::SimNode(LeggedScene scene, SimNodeOptions options, dds::Bus& bus)
    : impl_(MakeLeggedNode(std::move(scene), std::move(options), &bus)) {}
SimNode::~SimNode() = default;
void SimNode::Run(const std::function<bool()>& stop) { impl_->Run(stop); }
SimNodeStats SimNode::Stats() const { return impl_->Stats(); }
uint64_t SimNode::Rejected(const std::string& kind) const { return impl_->Rejected(kind); }

}  // namespace turf
