#include "participants/sim/sim_node.h"

#include <spdlog/spdlog.h>
#include <turf/idl/JointsPubSubTypes.h>
#include <turf/idl/SensorStatsPubSubTypes.h>
#include <turf/idl/WorldStatePubSubTypes.h>

#include <cmath>

#include "dds/bus.h"
#include "kernel/legged_kernel.h"
#include "loader/realism_yaml.h"
#include "participants/common/process.h"
#include "participants/sim/control_loop.h"
#include "participants/sim/kernel_node.h"
#include "participants/sim/legged_convert.h"
#include "participants/sim/legged_publisher.h"
#include "participants/sim/stats_report.h"

namespace turf {

namespace {

class LeggedNode final : public KernelNode<LeggedKernel, LeggedPublisher> {
 public:
  LeggedNode(LeggedScene scene, SimNodeOptions options, dds::Bus* bus)
      : KernelNode("legged", std::move(scene), std::move(options), bus, LoopTiming),
        command_reader_(
            bus_.MakeReader<idl::JointCommandPubSubType>(dds::Topic::kRobotJointCommand, [this] { loop_.Wake(); })) {}

  void Run(const std::function<bool()>& stop) override {
    ReportStartup();
    publisher_.PublishSceneInfo(kernel_);
    publisher_.PublishReleased(kernel_);  // the readings of frame 0
    loop_.Run(stop);
  }

 private:
  // The loop publishes the whole frame at every sensor frame.
  static ControlLoop::Timing LoopTiming(const LeggedKernel& k) {
    const double step = k.scene().physics.step;
    return {step, k.world().step_ns(), 1.0 / (step * static_cast<double>(k.sensor_every()))};
  }

  // --- ControlLoop::Node ---

  void TakeCommands() override {
    if (command_reader_->Take(&command_inbox_)) {
      for (const idl::JointCommand& c : command_inbox_) {
        loop_.Took(dds::Topic::kRobotJointCommand, c);
        ApplyCommand(c);
      }
    }
  }

  std::string ApplyRecordedInput(const std::string& topic, const std::vector<uint8_t>& cdr) override {
    if (topic != dds::Topic::kRobotJointCommand.info().suffix) return "a legged scene takes no input on " + topic;
    idl::JointCommand c;
    if (!FromCdr<idl::JointCommandPubSubType>(cdr.data(), cdr.size(), &c))
      return "a recorded " + topic + " sample is no JointCommand";
    ApplyCommand(c);
    return {};
  }

  uint64_t CommandsOverflowed() const override { return command_reader_->Overflowed(); }
  void AfterStep() override { publisher_.AfterStep(kernel_); }

  ControlAnswer ApplyStepCommands(const idl::SimControl& req) override {
    if (!req.commands().empty())
      return {idl::CONTROL_NOT_ALLOWED, "legged robots take joint_commands, not SSL commands"};
    // All of the step's joint commands or none; each converted and checked once.
    const auto& commands = req.joint_commands();
    if (commands.size() > static_cast<size_t>(kernel_.world().RobotCount()))
      return {idl::CONTROL_TOO_MANY, fmt::format("{} joint commands for {} robots: at most one each", commands.size(),
                                                 kernel_.world().RobotCount())};
    if (step_checked_.size() < commands.size()) step_checked_.resize(commands.size());
    for (size_t i = 0; i < commands.size(); ++i) {
      const JointCommandError e = CheckCommand(commands[i], &step_checked_[i]);
      if (e != JointCommandError::kOk)
        return {ControlErrorOf(e),
                fmt::format("joint command for '{}': {}", Clipped(commands[i].robot()), JointCommandErrorName(e))};
    }
    for (size_t i = 0; i < commands.size(); ++i)
      kernel_.SetJointCommands(kernel_.world().RobotIndex(commands[i].robot()), step_checked_[i]);
    return {};
  }

  ControlAnswer TeleportBall(const idl::SimControl& req) override {
    const Error e = kernel_.PlaceBall(A3(req.ball().position()), A3(req.ball().velocity()));
    if (e == Error::kOk) return {};
    return {ControlErrorOf(e), fmt::format("ball: {} (positions within {} m, speeds within {} m/s)", ErrorName(e),
                                           kMaxLeggedPlacement, kMaxLeggedBallSpeed)};
  }

  ControlAnswer TeleportRobot(const idl::SimControl& req) override {
    const idl::LeggedTeleport& t = req.legged();
    RobotPlacement p;
    p.position = A3(t.position());
    p.orientation = {t.orientation().w(), t.orientation().x(), t.orientation().y(), t.orientation().z()};
    p.reset_joints = t.reset_joints();
    const Error e = kernel_.PlaceRobot(kernel_.world().RobotIndex(t.robot()), p);
    if (e == Error::kOk) return {};
    return {ControlErrorOf(e), fmt::format("robot '{}': {}", Clipped(t.robot()), ErrorName(e))};
  }

  void ResetWorld() override {
    kernel_.Reset();
    publisher_.PublishReleased(kernel_);
  }

  // --- Inputs ---

  // A sample is checked whole first: a refused one changes no joint.
  void ApplyCommand(const idl::JointCommand& in) {
    JointCommandError error = CheckCommand(in, &checked_);
    if (error == JointCommandError::kOk)
      error = kernel_.SetJointCommands(kernel_.world().RobotIndex(in.robot()), checked_);
    if (error != JointCommandError::kOk) {
      loop_.Reject(fmt::format("joint_command.{}", JointCommandErrorName(error)),
                   fmt::format("robot '{}', {} joints", in.robot(), in.joints().size()));
    }
  }

  JointCommandError CheckCommand(const idl::JointCommand& in, std::vector<JointCommand>* commands) const {
    const int robot = kernel_.world().RobotIndex(in.robot());
    if (robot < 0) return JointCommandError::kUnknownRobot;
    // Before anything is converted or kept: one entry per joint at most.
    if (in.joints().size() > static_cast<size_t>(kernel_.world().JointCount(robot))) return JointCommandError::kTooMany;
    commands->resize(in.joints().size());
    for (size_t i = 0; i < commands->size(); ++i) {
      if (!FromIdl(in.joints()[i], &(*commands)[i])) return JointCommandError::kOutOfRange;
    }
    return kernel_.world().CheckJointCommands(robot, *commands);
  }

  // --- Outputs ---

  void ReportStartup() const {
    const LeggedScene& s = kernel_.scene();
    spdlog::info("legged scene '{}': {} robots, step {} ms, field {}, seed {}", s.name, s.robots.size(),
                 s.physics.step * 1e3, s.field.enabled ? "RoboCup 3D" : "none", s.seed);
    for (const LeggedRobotState& r : kernel_.world().State().robots)
      spdlog::info("  robot '{}' (id {}): {} joints, {} force sensors{}", r.name, r.id, r.joint_names.size(),
                   r.forces.size(), r.has_imu ? ", IMU" : "");
    spdlog::info("{}", bus_.Describe());
    auto name = [this](dds::Topic t) { return bus_.TopicName(t); };
    const bool ball = kernel_.world().State().has_ball;  // world_state carries only the ball
    spdlog::info(
        "publishing {}, {}, {} per robot through their modelled links, at {:.0f} Hz of sim time; {} (all in one "
        "sample), {}, {}{} at the same rate; {}, {} every second of sim time, {} (latched)",
        name(dds::Topic::kRobotJointState), name(dds::Topic::kRobotImu), name(dds::Topic::kRobotForce),
        s.rates.joint_state_hz, name(dds::Topic::kRobotsState), name(dds::Topic::kRobotLinks), name(dds::Topic::kClock),
        ball ? " and " + name(dds::Topic::kWorldState) + " (the ball)" : std::string(), name(dds::Topic::kControlReply),
        name(dds::Topic::kStats), name(dds::Topic::kLeggedScene));
    const SensorRealism& r = kernel_.realism();
    spdlog::info(
        "sensor realism: encoders {:.4f} rad steps, noise {:.4f} rad; IMU gyro noise {:.4f} rad/s, accel noise {:.3f} "
        "m/s^2; links joints {:.1f} ms loss {:.1f}%, IMU {:.1f} ms loss {:.1f}%, touch {:.1f} ms loss {:.1f}%",
        r.encoder.resolution, r.encoder.noise_stddev, r.imu.gyro_noise_stddev, r.imu.accel_noise_stddev,
        r.encoder.link.latency * 1e3, r.encoder.link.loss * 100, r.imu.link.latency * 1e3, r.imu.link.loss * 100,
        r.touch.link.latency * 1e3, r.touch.link.loss * 100);
    spdlog::info("subscribing {}, {}", name(dds::Topic::kRobotJointCommand), name(dds::Topic::kControl));
    loop_.ReportTimeMode();
  }

  void ReportStatus() const override {
    const LeggedHealth& h = kernel_.world().health();
    ReportStatusWith(
        fmt::format("recoveries={} solver_capped_steps={}", h.instability_recoveries, h.solver_capped_steps));
  }

  std::unique_ptr<dds::Reader<idl::JointCommandPubSubType>> command_reader_;

  std::vector<JointCommand> checked_;
  std::vector<std::vector<JointCommand>> step_checked_;  // a STEP's joint commands, checked
  std::vector<idl::JointCommand> command_inbox_;
};

}  // namespace

std::unique_ptr<SimNode::Impl> MakeLeggedNode(LeggedScene scene, SimNodeOptions options, dds::Bus* bus) {
  return std::make_unique<LeggedNode>(std::move(scene), std::move(options), bus);
}

}  // namespace turf
