#include "participants/sim/legged_node.h"

#include <spdlog/spdlog.h>
#include <turf/idl/JointsPubSubTypes.h>
#include <turf/idl/WorldStatePubSubTypes.h>

#include <cmath>

#include "core/legged/legged_sensors.h"
#include "core/legged/legged_world.h"
#include "dds/participant.h"
#include "loader/realism_yaml.h"
#include "participants/sim/control_loop.h"

namespace turf {

namespace {

constexpr double kMaxPlacement = 100.0;  // m from the origin, any axis
constexpr double kMaxBallSpeed = 50.0;   // m/s

idl::Vec3 V3(const std::array<double, 3>& a) {
  idl::Vec3 v;
  v.x(a[0]);
  v.y(a[1]);
  v.z(a[2]);
  return v;
}

idl::Quat Q4(const std::array<double, 4>& a) {
  idl::Quat q;
  q.w(a[0]);
  q.x(a[1]);
  q.y(a[2]);
  q.z(a[3]);
  return q;
}

std::array<double, 3> A3(const idl::Vec3& v) { return {v.x(), v.y(), v.z()}; }

idl::GeomShape ToIdl(LeggedGeom::Shape shape) {
  switch (shape) {
    case LeggedGeom::Shape::kBox:
      return idl::GEOM_BOX;
    case LeggedGeom::Shape::kSphere:
      return idl::GEOM_SPHERE;
    case LeggedGeom::Shape::kCapsule:
      return idl::GEOM_CAPSULE;
    case LeggedGeom::Shape::kCylinder:
      return idl::GEOM_CYLINDER;
    case LeggedGeom::Shape::kEllipsoid:
      return idl::GEOM_ELLIPSOID;
    case LeggedGeom::Shape::kOther:
      break;
  }
  return idl::GEOM_OTHER;
}

// The world's state as the per-robot samples (reusing out's storage).
void FillState(const LeggedWorldState& state, idl::LeggedState* out) {
  const size_t n = state.robots.size();
  out->sim_time_ns(state.time_ns);
  out->frame(state.frame);
  out->joints().resize(n);
  out->imu().resize(n);
  out->force().resize(n);
  out->links().resize(n);
  for (size_t i = 0; i < n; ++i) {
    const LeggedRobotState& r = state.robots[i];
    idl::JointState& joints = out->joints()[i];
    joints.robot(r.name);
    joints.id(r.id);
    joints.sim_time_ns(state.time_ns);
    joints.frame(state.frame);
    joints.name(r.joint_names);
    joints.position(r.joint_positions);
    joints.velocity(r.joint_velocities);
    joints.effort(r.joint_efforts);

    idl::ImuState& imu = out->imu()[i];
    imu.robot(r.name);
    imu.sim_time_ns(state.time_ns);
    imu.valid(r.has_imu);
    imu.orientation(Q4(r.orientation));
    imu.angular_velocity(V3(r.gyro));
    imu.linear_acceleration(V3(r.accelerometer));
    imu.base_position(V3(r.base_position));
    imu.base_orientation(Q4(r.base_orientation));

    idl::ForceState& force = out->force()[i];
    force.robot(r.name);
    force.sim_time_ns(state.time_ns);
    force.sensors().resize(r.forces.size());
    for (size_t f = 0; f < r.forces.size(); ++f) {
      idl::ForceReading& reading = force.sensors()[f];
      reading.name(r.forces[f].name);
      reading.values(r.forces[f].values);
      reading.contact(r.forces[f].contact);
      reading.force(V3(r.forces[f].force));
      reading.point(V3(r.forces[f].point));
    }

    idl::LinkState& links = out->links()[i];
    links.robot(r.name);
    links.sim_time_ns(state.time_ns);
    links.frame(state.frame);
    links.links().resize(r.links.size());
    for (size_t l = 0; l < r.links.size(); ++l) {
      links.links()[l].name(r.links[l].name);
      links.links()[l].position(V3(r.links[l].position));
      links.links()[l].orientation(Q4(r.links[l].orientation));
    }
  }
  out->has_ball(state.has_ball);
  out->ball_position(V3(state.ball_position));
  out->ball_velocity(V3(state.ball_velocity));
}

bool FromIdl(const idl::JointTarget& in, JointCommand* out) {
  out->joint = in.name();
  switch (in.mode()) {
    case idl::JOINT_VELOCITY:
      out->mode = JointMode::kVelocity;
      break;
    case idl::JOINT_POSITION:
      out->mode = JointMode::kPosition;
      break;
    case idl::JOINT_TORQUE:
      out->mode = JointMode::kTorque;
      break;
    default:
      return false;
  }
  out->value = in.value();
  out->kp = in.kp();
  out->kd = in.kd();
  return true;
}

}  // namespace

class LeggedNode::Impl final : private ControlLoop::Node {
 public:
  Impl(LeggedScene scene, SimNodeOptions options)
      : options_(std::move(options)),
        world_(std::move(scene)),
        participant_({options_.domain, options_.name, options_.prefix, options_.qos_file}),
        loop_(participant_, options_, LoopTiming(world_.scene(), world_.step_ns()), *this),
        joint_writer_(participant_.MakeWriter<idl::JointStatePubSubType>(dds::Topic::kRobotJointState)),
        imu_writer_(participant_.MakeWriter<idl::ImuStatePubSubType>(dds::Topic::kRobotImu)),
        force_writer_(participant_.MakeWriter<idl::ForceStatePubSubType>(dds::Topic::kRobotForce)),
        links_writer_(participant_.MakeWriter<idl::LinkStatePubSubType>(dds::Topic::kRobotLinks)),
        state_writer_(participant_.MakeWriter<idl::LeggedStatePubSubType>(dds::Topic::kRobotsState)),
        world_writer_(participant_.MakeWriter<idl::WorldStatePubSubType>(dds::Topic::kWorldState)),
        scene_writer_(participant_.MakeWriter<idl::LeggedSceneInfoPubSubType>(dds::Topic::kLeggedScene)),
        command_reader_(participant_.MakeReader<idl::JointCommandPubSubType>(dds::Topic::kRobotJointCommand,
                                                                             [this] { loop_.Wake(); })),
        realism_(world_.scene().realism),
        sensors_(world_.scene().seed, RobotNames(world_.scene())) {}

  void Run(const std::function<bool()>& stop) {
    ReportStartup();
    PublishSceneInfo();
    loop_.Run(stop);
  }

  SimNodeStats Stats() const { return loop_.Stats(); }
  uint64_t Rejected(const std::string& kind) const { return loop_.Rejected(kind); }

 private:
  static std::vector<std::string> RobotNames(const LeggedScene& s) {
    std::vector<std::string> names;
    for (const LeggedRobot& r : s.robots) names.push_back(r.name);
    return names;
  }

  static ControlLoop::Timing LoopTiming(const LeggedScene& s, int64_t step_ns) {
    return {s.physics.step, step_ns, s.rates.joint_state_hz};
  }

  // --- ControlLoop::Node ---

  int64_t TimeNs() const override { return world_.time_ns(); }
  uint64_t Frame() const override { return world_.frame(); }

  void TakeCommands() override {
    if (command_reader_->Take(&command_inbox_)) {
      for (const idl::JointCommand& c : command_inbox_) ApplyCommand(c);
    }
  }

  uint64_t CommandsOverflowed() const override { return command_reader_->Overflowed(); }
  void Step() override { world_.Step(); }
  void AfterStep() override {}

  ControlAnswer ApplyStepCommands(const idl::SimControl& req) override {
    if (!req.commands().empty())
      return {idl::CONTROL_NOT_ALLOWED, "legged robots take joint_commands, not SSL commands"};
    // All of the step's joint commands or none.
    for (const idl::JointCommand& c : req.joint_commands()) {
      const JointCommandError e = CheckCommand(c, &checked_);
      if (e != JointCommandError::kOk)
        return {ControlErrorOf(e), fmt::format("joint command for '{}': {}", c.robot(), JointCommandErrorName(e))};
    }
    for (const idl::JointCommand& c : req.joint_commands()) {
      CheckCommand(c, &checked_);
      for (const JointCommand& j : checked_) world_.SetJointCommand(world_.RobotIndex(c.robot()), j);
    }
    return {};
  }

  ControlAnswer TeleportBall(const idl::SimControl& req) override { return PlaceBall(req.ball()); }
  ControlAnswer TeleportRobot(const idl::SimControl& req) override { return PlaceRobot(req.legged()); }
  ControlAnswer ChangeRealism(const std::string& spec) override {
    // From the network: preset names and YAML text only, never file paths.
    const RealismLoadResult loaded = LoadRealism(spec, DefaultRealismDir(), /*allow_paths=*/false, realism_);
    if (!loaded.realism)
      return {idl::CONTROL_INVALID_REALISM, loaded.errors.empty() ? "invalid realism" : loaded.errors.front()};
    realism_ = *loaded.realism;
    spdlog::info("sensor realism changed ({})", spec.size() < 40 ? spec : spec.substr(0, 40) + "...");
    return {};
  }
  void ResetWorld() override {
    world_.Reset();
    sensors_.Reset();
  }

  // --- Inputs ---

  // A sample is checked whole first: a refused one changes no joint.
  void ApplyCommand(const idl::JointCommand& in) {
    const JointCommandError error = CheckCommand(in, &checked_);
    if (error != JointCommandError::kOk) {
      loop_.Reject(fmt::format("joint_command.{}", JointCommandErrorName(error)),
                   fmt::format("robot '{}', {} joints", in.robot(), in.joints().size()));
      return;
    }
    for (const JointCommand& c : checked_) world_.SetJointCommand(world_.RobotIndex(in.robot()), c);
  }

  JointCommandError CheckCommand(const idl::JointCommand& in, std::vector<JointCommand>* commands) const {
    const int robot = world_.RobotIndex(in.robot());
    if (robot < 0) return JointCommandError::kUnknownRobot;
    commands->resize(in.joints().size());
    for (size_t i = 0; i < commands->size(); ++i) {
      if (!FromIdl(in.joints()[i], &(*commands)[i])) return JointCommandError::kOutOfRange;
    }
    return world_.CheckJointCommands(robot, *commands);
  }

  // OP_TELEPORT_ROBOT: a legged robot's root body.
  ControlAnswer PlaceRobot(const idl::LeggedTeleport& t) {
    RobotPlacement p;
    p.position = A3(t.position());
    p.orientation = {t.orientation().w(), t.orientation().x(), t.orientation().y(), t.orientation().z()};
    p.reset_joints = t.reset_joints();
    for (int k = 0; k < 3; ++k) {
      if (std::abs(p.position[k]) > kMaxPlacement)
        return {idl::CONTROL_OUT_OF_RANGE, fmt::format("position beyond {} m", kMaxPlacement)};
    }
    const PlacementError e = world_.PlaceRobot(world_.RobotIndex(t.robot()), p);
    if (e == PlacementError::kOk) return {};
    return {ControlErrorOf(e), fmt::format("robot '{}': {}", t.robot(), PlacementErrorName(e))};
  }

  ControlAnswer PlaceBall(const idl::BallTeleport& b) {
    const std::array<double, 3> position = A3(b.position());
    const std::array<double, 3> velocity = A3(b.velocity());
    for (int k = 0; k < 3; ++k) {
      if (std::abs(position[k]) > kMaxPlacement)
        return {idl::CONTROL_OUT_OF_RANGE, fmt::format("position beyond {} m", kMaxPlacement)};
      if (std::abs(velocity[k]) > kMaxBallSpeed)
        return {idl::CONTROL_OUT_OF_RANGE, fmt::format("velocity beyond {} m/s", kMaxBallSpeed)};
    }
    const PlacementError e = world_.PlaceBall(position, velocity);
    if (e == PlacementError::kOk) return {};
    return {ControlErrorOf(e), fmt::format("ball: {}", PlacementErrorName(e))};
  }

  void PublishState() override {
    world_.State(&state_);
    sensors_.Apply(realism_, &state_);
    FillState(state_, &frame_sample_);
    // The whole frame first: a lockstep driver (the SimSpark bridge) waits for it.
    state_writer_->Write(frame_sample_);
    for (size_t i = 0; i < state_.robots.size(); ++i) {
      joint_writer_->Write(frame_sample_.joints()[i]);
      imu_writer_->Write(frame_sample_.imu()[i]);
      force_writer_->Write(frame_sample_.force()[i]);
      links_writer_->Write(frame_sample_.links()[i]);
    }
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
    const LeggedScene& s = world_.scene();
    idl::LeggedSceneInfo info;
    info.name(s.name);
    info.has_field(s.field.enabled);
    info.field_length(s.field.length);
    info.field_width(s.field.width);
    info.goal_width(s.field.goal_width);
    info.goal_depth(s.field.goal_depth);
    info.goal_height(s.field.goal_height);
    info.ball_radius(s.field.ball_radius);
    for (int i = 0; i < world_.RobotCount(); ++i) {
      idl::RobotDescription robot;
      robot.robot(s.robots[i].name);
      robot.id(s.robots[i].id);
      robot.model(s.robots[i].model);
      for (const LeggedGeom& g : world_.RobotGeoms(i)) {
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
    const LeggedScene& s = world_.scene();
    spdlog::info("legged scene '{}': {} robots, step {} ms, field {}, seed {}", s.name, s.robots.size(),
                 s.physics.step * 1e3, s.field.enabled ? "RoboCup 3D" : "none", s.seed);
    for (const LeggedRobotState& r : world_.State().robots)
      spdlog::info("  robot '{}' (id {}): {} joints, {} force sensors{}", r.name, r.id, r.joint_names.size(),
                   r.forces.size(), r.has_imu ? ", IMU" : "");
    spdlog::info("DDS domain {}, QoS profiles {}", options_.domain, participant_.options().qos_file);
    auto name = [this](dds::Topic t) { return participant_.TopicName(t); };
    spdlog::info(
        "publishing {}, {}, {}, {}, {} (all four in one sample), {} and {} at {:.0f} Hz of sim time; {}, {} "
        "(latched)",
        name(dds::Topic::kRobotJointState), name(dds::Topic::kRobotImu), name(dds::Topic::kRobotForce),
        name(dds::Topic::kRobotLinks), name(dds::Topic::kRobotsState), name(dds::Topic::kWorldState),
        name(dds::Topic::kClock), s.rates.joint_state_hz, name(dds::Topic::kControlReply),
        name(dds::Topic::kLeggedScene));
    spdlog::info("subscribing {}, {}", name(dds::Topic::kRobotJointCommand), name(dds::Topic::kControl));
    loop_.ReportTimeMode();
  }

  void ReportStatus() const override {
    spdlog::info("t={:.1f}s frame={} rtf={:.2f} refused={} recoveries={}", world_.time_ns() * 1e-9, world_.frame(),
                 loop_.real_time_factor(), loop_.rejected(), world_.health().instability_recoveries);
  }

  SimNodeOptions options_;
  LeggedWorld world_;
  dds::Participant participant_;
  ControlLoop loop_;  // before the readers: their callbacks wake it
  std::unique_ptr<dds::Writer<idl::JointStatePubSubType>> joint_writer_;
  std::unique_ptr<dds::Writer<idl::ImuStatePubSubType>> imu_writer_;
  std::unique_ptr<dds::Writer<idl::ForceStatePubSubType>> force_writer_;
  std::unique_ptr<dds::Writer<idl::LinkStatePubSubType>> links_writer_;
  std::unique_ptr<dds::Writer<idl::LeggedStatePubSubType>> state_writer_;
  std::unique_ptr<dds::Writer<idl::WorldStatePubSubType>> world_writer_;
  std::unique_ptr<dds::Writer<idl::LeggedSceneInfoPubSubType>> scene_writer_;
  std::unique_ptr<dds::Reader<idl::JointCommandPubSubType>> command_reader_;

  LeggedWorldState state_;
  idl::LeggedState frame_sample_;
  SensorRealism realism_;
  LeggedSensors sensors_;
  std::vector<JointCommand> checked_;
  std::vector<idl::JointCommand> command_inbox_;
};

LeggedNode::LeggedNode(LeggedScene scene, SimNodeOptions options)
    : impl_(std::make_unique<Impl>(std::move(scene), std::move(options))) {}
LeggedNode::~LeggedNode() = default;
void LeggedNode::Run(const std::function<bool()>& stop) { impl_->Run(stop); }
SimNodeStats LeggedNode::Stats() const { return impl_->Stats(); }
uint64_t LeggedNode::Rejected(const std::string& kind) const { return impl_->Rejected(kind); }

}  // namespace turf
