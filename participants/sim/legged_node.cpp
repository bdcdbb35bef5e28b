#include "participants/sim/sim_node.h"

#include <spdlog/spdlog.h>
#include <turf/idl/JointsPubSubTypes.h>
#include <turf/idl/SensorStatsPubSubTypes.h>
#include <turf/idl/WorldStatePubSubTypes.h>

#include <cmath>

#include "dds/bus.h"
#include "kernel/legged_kernel.h"
#include "loader/realism_yaml.h"
#include "participants/sim/control_loop.h"
#include "participants/sim/legged_convert.h"
#include "participants/sim/stats_report.h"

namespace turf {

namespace {

class LeggedNode final : public SimNode::Impl, private ControlLoop::Node {
 public:
  LeggedNode(LeggedScene scene, SimNodeOptions options, dds::Bus* bus)
      : options_(std::move(options)),
        kernel_(std::move(scene)),
        own_bus_(bus != nullptr ? nullptr : MakeNodeParticipant(options_)),
        bus_(bus != nullptr ? *bus : *own_bus_),
        loop_(bus_, options_, LoopTiming(kernel_), *this),
        joint_writer_(bus_.MakeWriter<idl::JointStatePubSubType>(dds::Topic::kRobotJointState)),
        imu_writer_(bus_.MakeWriter<idl::ImuStatePubSubType>(dds::Topic::kRobotImu)),
        force_writer_(bus_.MakeWriter<idl::ForceStatePubSubType>(dds::Topic::kRobotForce)),
        links_writer_(bus_.MakeWriter<idl::LinkStatePubSubType>(dds::Topic::kRobotLinks)),
        state_writer_(bus_.MakeWriter<idl::LeggedStatePubSubType>(dds::Topic::kRobotsState)),
        world_writer_(bus_.MakeWriter<idl::WorldStatePubSubType>(dds::Topic::kWorldState)),
        scene_writer_(bus_.MakeWriter<idl::LeggedSceneInfoPubSubType>(dds::Topic::kLeggedScene)),
        stats_writer_(bus_.MakeWriter<idl::SensorStatsPubSubType>(dds::Topic::kStats)),
        command_reader_(
            bus_.MakeReader<idl::JointCommandPubSubType>(dds::Topic::kRobotJointCommand, [this] { loop_.Wake(); })) {}

  void Run(const std::function<bool()>& stop) override {
    ReportStartup();
    PublishSceneInfo();
    PublishReleased();  // the readings of frame 0
    loop_.Run(stop);
  }

  SimNodeStats Stats() const override { return loop_.Stats(); }
  uint64_t Rejected(const std::string& kind) const override { return loop_.Rejected(kind); }

 private:
  // The loop publishes the whole frame at every sensor frame.
  static ControlLoop::Timing LoopTiming(const LeggedKernel& k) {
    const double step = k.scene().physics.step;
    return {step, k.world().step_ns(), 1.0 / (step * static_cast<double>(k.sensor_every()))};
  }

  // --- ControlLoop::Node ---

  int64_t TimeNs() const override { return kernel_.time_ns(); }
  uint64_t Frame() const override { return kernel_.frame(); }

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
  void Step() override { kernel_.Step(); }

  void AfterStep() override {
    PublishReleased();
    if (kernel_.stats()) {
      stats_writer_->Write(StatsToIdl(*kernel_.stats()));
      last_stats_ = *kernel_.stats();
    }
  }

  ControlAnswer ApplyStepCommands(const idl::SimControl& req) override {
    if (!req.commands().empty())
      return {idl::CONTROL_NOT_ALLOWED, "legged robots take joint_commands, not SSL commands"};
    // All of the step's joint commands or none; each converted and checked once.
    const auto& commands = req.joint_commands();
    if (step_checked_.size() < commands.size()) step_checked_.resize(commands.size());
    for (size_t i = 0; i < commands.size(); ++i) {
      const JointCommandError e = CheckCommand(commands[i], &step_checked_[i]);
      if (e != JointCommandError::kOk)
        return {ControlErrorOf(e),
                fmt::format("joint command for '{}': {}", commands[i].robot(), JointCommandErrorName(e))};
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
    return {ControlErrorOf(e), fmt::format("robot '{}': {}", t.robot(), ErrorName(e))};
  }

  ControlAnswer ChangeRealism(const RealismChange& change) override {
    const RealismChangeResult changed = ApplyRealismChange(kernel_.realism(), change, DefaultRealismDir());
    if (!changed.ok()) return {ControlErrorOf(changed.error), changed.reason};
    if (std::string e = kernel_.SetRealism(changed.realism); !e.empty()) return {idl::CONTROL_INVALID_REALISM, e};
    spdlog::info("sensor realism changed ({})", DescribeRealismChange(change));
    return {};
  }

  void ResetWorld() override {
    kernel_.Reset();
    PublishReleased();
  }
  std::string SaveKernel() const override { return kernel_.Save(); }
  std::string RestoreKernel(std::string_view snapshot) override { return kernel_.Restore(snapshot); }
  std::string SceneIdentity() const override {
    return fmt::format("legged scene '{}' seed {}", kernel_.scene().name, kernel_.scene().seed);
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
    commands->resize(in.joints().size());
    for (size_t i = 0; i < commands->size(); ++i) {
      if (!FromIdl(in.joints()[i], &(*commands)[i])) return JointCommandError::kOutOfRange;
    }
    return kernel_.world().CheckJointCommands(robot, *commands);
  }

  // --- Outputs ---

  // The sensor streams' samples that arrived (their modelled links).
  void PublishReleased() {
    for (const LeggedSample& s : kernel_.released()) {
      switch (s.stream) {
        case LeggedStream::kJoints:
          FillJoints(s.robot_state, s.time_ns, s.frame, &joint_sample_);
          joint_writer_->Write(joint_sample_);
          break;
        case LeggedStream::kImu:
          FillImu(s.robot_state, s.time_ns, &imu_sample_);
          imu_writer_->Write(imu_sample_);
          break;
        default:
          FillForce(s.robot_state, s.time_ns, &force_sample_);
          force_writer_->Write(force_sample_);
          break;
      }
    }
  }

  // The whole frame (sensor noise of this frame, no link delay), body poses
  // and the ball: what bridges and viewers read.
  void PublishState() override {
    kernel_.Measure(&state_);
    FillState(state_, &frame_sample_);
    // The whole frame first: a lockstep driver (the SimSpark bridge) waits for it.
    state_writer_->Write(frame_sample_);
    for (const idl::LinkState& links : frame_sample_.links()) links_writer_->Write(links);
    if (state_.has_ball) {
      idl::WorldState world;
      world.sim_time_ns(state_.time_ns);
      world.frame(state_.frame);
      world.ball().position(V3(state_.ball_position));
      world.ball().velocity(V3(state_.ball_velocity));
      world_writer_->Write(world);
    }
  }

  void PublishSceneInfo() {
    const LeggedScene& s = kernel_.scene();
    idl::LeggedSceneInfo info;
    info.name(s.name);
    info.has_field(s.field.enabled);
    info.field_length(s.field.length);
    info.field_width(s.field.width);
    info.goal_width(s.field.goal_width);
    info.goal_depth(s.field.goal_depth);
    info.goal_height(s.field.goal_height);
    info.ball_radius(s.field.ball_radius);
    for (int i = 0; i < kernel_.world().RobotCount(); ++i) {
      idl::RobotDescription robot;
      robot.robot(s.robots[i].name);
      robot.id(s.robots[i].id);
      robot.model(s.robots[i].model);
      for (const LeggedGeom& g : kernel_.world().RobotGeoms(i)) {
        idl::RobotGeom geom;
        geom.body(g.body);
        geom.shape(ToIdl(g.shape));
        geom.size(V3(g.size));
        geom.position(V3(g.position));
        geom.orientation(Q4(g.orientation));
        robot.geoms().push_back(geom);
      }
      info.robots().push_back(robot);
    }
    scene_writer_->Write(info);
  }

  void ReportStartup() const {
    const LeggedScene& s = kernel_.scene();
    spdlog::info("legged scene '{}': {} robots, step {} ms, field {}, seed {}", s.name, s.robots.size(),
                 s.physics.step * 1e3, s.field.enabled ? "RoboCup 3D" : "none", s.seed);
    for (const LeggedRobotState& r : kernel_.world().State().robots)
      spdlog::info("  robot '{}' (id {}): {} joints, {} force sensors{}", r.name, r.id, r.joint_names.size(),
                   r.forces.size(), r.has_imu ? ", IMU" : "");
    spdlog::info("{}", bus_.Describe());
    auto name = [this](dds::Topic t) { return bus_.TopicName(t); };
    spdlog::info(
        "publishing {}, {}, {} per robot through their modelled links, at {:.0f} Hz of sim time; {} (all in one "
        "sample), {}, {} and {} at the same rate; {}, {} every second of sim time, {} (latched)",
        name(dds::Topic::kRobotJointState), name(dds::Topic::kRobotImu), name(dds::Topic::kRobotForce),
        s.rates.joint_state_hz, name(dds::Topic::kRobotsState), name(dds::Topic::kRobotLinks),
        name(dds::Topic::kWorldState), name(dds::Topic::kClock), name(dds::Topic::kControlReply),
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
    loop_.ReportStatusLine(fmt::format("recoveries={}", kernel_.world().health().instability_recoveries));
    ReportStreams(last_stats_);
  }

  SimNodeOptions options_;
  LeggedKernel kernel_;
  std::unique_ptr<dds::Bus> own_bus_;  // when the node makes its own participant
  dds::Bus& bus_;
  ControlLoop loop_;  // before the readers: their callbacks wake it
  std::unique_ptr<dds::Writer<idl::JointStatePubSubType>> joint_writer_;
  std::unique_ptr<dds::Writer<idl::ImuStatePubSubType>> imu_writer_;
  std::unique_ptr<dds::Writer<idl::ForceStatePubSubType>> force_writer_;
  std::unique_ptr<dds::Writer<idl::LinkStatePubSubType>> links_writer_;
  std::unique_ptr<dds::Writer<idl::LeggedStatePubSubType>> state_writer_;
  std::unique_ptr<dds::Writer<idl::WorldStatePubSubType>> world_writer_;
  std::unique_ptr<dds::Writer<idl::LeggedSceneInfoPubSubType>> scene_writer_;
  std::unique_ptr<dds::Writer<idl::SensorStatsPubSubType>> stats_writer_;
  std::unique_ptr<dds::Reader<idl::JointCommandPubSubType>> command_reader_;

  LeggedWorldState state_;
  idl::LeggedState frame_sample_;
  idl::JointState joint_sample_;
  idl::ImuState imu_sample_;
  idl::ForceState force_sample_;
  StreamReport last_stats_;
  std::vector<JointCommand> checked_;
  std::vector<std::vector<JointCommand>> step_checked_;  // a STEP's joint commands, checked
  std::vector<idl::JointCommand> command_inbox_;
};

}  // namespace

std::unique_ptr<SimNode::Impl> MakeLeggedNode(LeggedScene scene, SimNodeOptions options, dds::Bus* bus) {
  return std::make_unique<LeggedNode>(std::move(scene), std::move(options), bus);
}

}  // namespace turf
