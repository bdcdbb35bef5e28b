#include "participants/sim/legged_node.h"

#include <spdlog/spdlog.h>
#include <turf/idl/ClockPubSubTypes.h>
#include <turf/idl/JointsPubSubTypes.h>
#include <turf/idl/SimControlPubSubTypes.h>
#include <turf/idl/WorldStatePubSubTypes.h>

#include <atomic>
#include <cmath>
#include <deque>
#include <mutex>
#include <thread>

#include "core/legged/legged_world.h"
#include "dds/participant.h"
#include "participants/common/process.h"
#include "participants/common/wakeup.h"
#include "participants/sim/pacer.h"

namespace turf {

namespace {

constexpr double kMaxSpeed = 1000.0;
constexpr uint32_t kMaxStepRequest = 1000000;
constexpr double kMaxPlacement = 100.0;  // m from the origin, any axis
constexpr double kMaxBallSpeed = 50.0;   // m/s

struct PendingStep {
  uint64_t done_at_frame;
  idl::SimControl request;
};

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

class LeggedNode::Impl {
 public:
  Impl(LeggedScene scene, SimNodeOptions options)
      : options_(std::move(options)),
        world_(std::move(scene)),
        participant_({options_.domain, options_.name, options_.prefix, options_.qos_file}),
        clock_writer_(participant_.MakeWriter<idl::ClockPubSubType>(dds::Topic::kClock)),
        joint_writer_(participant_.MakeWriter<idl::JointStatePubSubType>(dds::Topic::kRobotJointState)),
        imu_writer_(participant_.MakeWriter<idl::ImuStatePubSubType>(dds::Topic::kRobotImu)),
        force_writer_(participant_.MakeWriter<idl::ForceStatePubSubType>(dds::Topic::kRobotForce)),
        links_writer_(participant_.MakeWriter<idl::LinkStatePubSubType>(dds::Topic::kRobotLinks)),
        world_writer_(participant_.MakeWriter<idl::WorldStatePubSubType>(dds::Topic::kWorldState)),
        scene_writer_(participant_.MakeWriter<idl::LeggedSceneInfoPubSubType>(dds::Topic::kLeggedScene)),
        reply_writer_(participant_.MakeWriter<idl::SimControlReplyPubSubType>(dds::Topic::kControlReply)),
        command_reader_(participant_.MakeReader<idl::JointCommandPubSubType>(dds::Topic::kRobotJointCommand,
                                                                             [this] { wakeup_.Notify(); })),
        control_reader_(
            participant_.MakeReader<idl::SimControlPubSubType>(dds::Topic::kControl, [this] { wakeup_.Notify(); })),
        rejects_("input") {
    mode_ = options_.mode;
    speed_ = options_.mode == TimeMode::kScaled ? options_.speed : 1.0;
    paused_ = options_.start_paused;
    const LeggedScene& s = world_.scene();
    state_every_ = std::max<int64_t>(1, std::llround(1.0 / (s.rates.joint_state_hz * s.physics.step)));
  }

  void Run(const std::function<bool()>& stop) {
    ReportStartup();
    PublishSceneInfo();
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
    if (pacer_.CatchUp(now, deadline, world_.time_ns())) return;
    if (deadline > now) std::this_thread::sleep_until(deadline);
  }

  void Reject(const std::string& kind, const std::string& detail) {
    std::lock_guard<std::mutex> lock(rejects_mutex_);
    rejects_.Reject(kind, detail);
    rejected_.store(rejects_.Total());
  }

  void HandleInputs() {
    if (command_reader_->Take(&command_inbox_)) {
      for (const idl::JointCommand& c : command_inbox_) ApplyCommand(c);
    }
    if (control_reader_->Take(&control_inbox_)) {
      for (const idl::SimControl& c : control_inbox_) HandleControl(c);
    }
    const uint64_t overflow = command_reader_->Overflowed() + control_reader_->Overflowed();
    if (overflow > reported_overflow_) {
      Reject("queue_overflow",
             fmt::format("{} samples arrived faster than the loop could take them", overflow - reported_overflow_));
      reported_overflow_ = overflow;
    }
  }

  // A sample is checked whole first: a refused one changes no joint.
  void ApplyCommand(const idl::JointCommand& in) {
    const JointCommandError error = CheckCommand(in, &checked_);
    if (error != JointCommandError::kOk) {
      Reject(fmt::format("joint_command.{}", JointCommandErrorName(error)),
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
  std::string PlaceRobot(const idl::LeggedTeleport& t) {
    RobotPlacement p;
    p.position = A3(t.position());
    p.orientation = {t.orientation().w(), t.orientation().x(), t.orientation().y(), t.orientation().z()};
    p.reset_joints = t.reset_joints();
    for (int k = 0; k < 3; ++k) {
      if (std::abs(p.position[k]) > kMaxPlacement) return fmt::format("position beyond {} m", kMaxPlacement);
    }
    const PlacementError e = world_.PlaceRobot(world_.RobotIndex(t.robot()), p);
    return e == PlacementError::kOk ? "" : fmt::format("robot '{}': {}", t.robot(), PlacementErrorName(e));
  }

  std::string PlaceBall(const idl::BallTeleport& b) {
    const std::array<double, 3> position = A3(b.position());
    const std::array<double, 3> velocity = A3(b.velocity());
    for (int k = 0; k < 3; ++k) {
      if (std::abs(position[k]) > kMaxPlacement) return fmt::format("position beyond {} m", kMaxPlacement);
      if (std::abs(velocity[k]) > kMaxBallSpeed) return fmt::format("velocity beyond {} m/s", kMaxBallSpeed);
    }
    const PlacementError e = world_.PlaceBall(position, velocity);
    return e == PlacementError::kOk ? "" : fmt::format("ball: {}", PlacementErrorName(e));
  }

  void HandleControl(const idl::SimControl& req) {
    std::string why;
    switch (req.op()) {
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
      case idl::OP_TELEPORT_BALL:
        why = PlaceBall(req.ball());
        break;
      case idl::OP_TELEPORT_ROBOT:
        why = PlaceRobot(req.legged());
        break;
      case idl::OP_SET_REALISM:
        why = "not supported in legged scenes yet";
        break;
      default:
        why = fmt::format("unknown op {}", static_cast<int>(req.op()));
        break;
    }
    if (!why.empty()) Reject("control", fmt::format("from '{}': {}", req.client(), why));
    Reply(req, why);
    PublishState();
  }

  std::string QueueSteps(const idl::SimControl& req) {
    if (!paused_ && mode_ != TimeMode::kLockstep) return "step needs a paused simulation or lockstep mode";
    if (req.step_count() == 0 || req.step_count() > kMaxStepRequest)
      return fmt::format("step_count must be 1..{}", kMaxStepRequest);
    if (!req.commands().empty()) return "legged robots take joint_commands, not SSL commands";
    // All of the step's joint commands or none.
    for (const idl::JointCommand& c : req.joint_commands()) {
      const JointCommandError e = CheckCommand(c, &checked_);
      if (e != JointCommandError::kOk)
        return fmt::format("joint command for '{}': {}", c.robot(), JointCommandErrorName(e));
    }
    for (const idl::JointCommand& c : req.joint_commands()) {
      CheckCommand(c, &checked_);
      for (const JointCommand& j : checked_) world_.SetJointCommand(world_.RobotIndex(c.robot()), j);
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
    pending_steps_ = 0;
    for (const PendingStep& p : pending_replies_) Reply(p.request, "cancelled by a reset");
    pending_replies_.clear();
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

  void AfterStep() {
    frame_.store(world_.frame());
    time_ns_.store(world_.time_ns());
    const bool steps_done = !pending_replies_.empty() && world_.frame() >= pending_replies_.front().done_at_frame;
    if (world_.frame() % state_every_ == 0 || steps_done) PublishState();
    while (!pending_replies_.empty() && world_.frame() >= pending_replies_.front().done_at_frame) {
      Reply(pending_replies_.front().request, "");
      pending_replies_.pop_front();
    }
  }

  void PublishState() {
    world_.State(&state_);
    for (const LeggedRobotState& r : state_.robots) {
      joint_sample_.robot(r.name);
      joint_sample_.id(r.id);
      joint_sample_.sim_time_ns(state_.time_ns);
      joint_sample_.frame(state_.frame);
      joint_sample_.name(r.joint_names);
      joint_sample_.position(r.joint_positions);
      joint_sample_.velocity(r.joint_velocities);
      joint_sample_.effort(r.joint_efforts);
      joint_writer_->Write(joint_sample_);

      idl::ImuState imu;
      imu.robot(r.name);
      imu.sim_time_ns(state_.time_ns);
      imu.valid(r.has_imu);
      imu.orientation(Q4(r.orientation));
      imu.angular_velocity(V3(r.gyro));
      imu.linear_acceleration(V3(r.accelerometer));
      imu.base_position(V3(r.base_position));
      imu.base_orientation(Q4(r.base_orientation));
      imu_writer_->Write(imu);

      idl::ForceState force;
      force.robot(r.name);
      force.sim_time_ns(state_.time_ns);
      for (const ForceReading& f : r.forces) {
        idl::ForceReading reading;
        reading.name(f.name);
        reading.values(f.values);
        reading.contact(f.contact);
        reading.force(V3(f.force));
        reading.point(V3(f.point));
        force.sensors().push_back(reading);
      }
      force_writer_->Write(force);

      links_sample_.robot(r.name);
      links_sample_.sim_time_ns(state_.time_ns);
      links_sample_.frame(state_.frame);
      links_sample_.links().resize(r.links.size());
      for (size_t i = 0; i < r.links.size(); ++i) {
        links_sample_.links()[i].name(r.links[i].name);
        links_sample_.links()[i].position(V3(r.links[i].position));
        links_sample_.links()[i].orientation(Q4(r.links[i].orientation));
      }
      links_writer_->Write(links_sample_);
    }
    if (state_.has_ball) {
      idl::WorldState world;
      world.sim_time_ns(state_.time_ns);
      world.frame(state_.frame);
      world.ball().position(V3(state_.ball_position));
      world.ball().velocity(V3(state_.ball_velocity));
      world_writer_->Write(world);
    }
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
    spdlog::info("publishing {}, {}, {}, {}, {} and {} at {:.0f} Hz of sim time; {}, {} (latched)",
                 name(dds::Topic::kRobotJointState), name(dds::Topic::kRobotImu), name(dds::Topic::kRobotForce),
                 name(dds::Topic::kRobotLinks), name(dds::Topic::kWorldState), name(dds::Topic::kClock),
                 s.rates.joint_state_hz, name(dds::Topic::kControlReply), name(dds::Topic::kLeggedScene));
    spdlog::info("subscribing {}, {}", name(dds::Topic::kRobotJointCommand), name(dds::Topic::kControl));
    spdlog::info("time: {}{}{}", TimeModeName(mode_), mode_ == TimeMode::kScaled ? fmt::format(" x{}", speed_) : "",
                 paused_ ? ", paused" : "");
  }

  void ReportStatus() const {
    spdlog::info("t={:.1f}s frame={} rtf={:.2f} refused={} recoveries={}", world_.time_ns() * 1e-9, world_.frame(),
                 pacer_.real_time_factor(), rejected_.load(), world_.health().instability_recoveries);
  }

  SimNodeOptions options_;
  LeggedWorld world_;
  Pacer pacer_;
  Wakeup wakeup_;
  dds::Participant participant_;
  std::unique_ptr<dds::Writer<idl::ClockPubSubType>> clock_writer_;
  std::unique_ptr<dds::Writer<idl::JointStatePubSubType>> joint_writer_;
  std::unique_ptr<dds::Writer<idl::ImuStatePubSubType>> imu_writer_;
  std::unique_ptr<dds::Writer<idl::ForceStatePubSubType>> force_writer_;
  std::unique_ptr<dds::Writer<idl::LinkStatePubSubType>> links_writer_;
  std::unique_ptr<dds::Writer<idl::WorldStatePubSubType>> world_writer_;
  std::unique_ptr<dds::Writer<idl::LeggedSceneInfoPubSubType>> scene_writer_;
  std::unique_ptr<dds::Writer<idl::SimControlReplyPubSubType>> reply_writer_;
  std::unique_ptr<dds::Reader<idl::JointCommandPubSubType>> command_reader_;
  std::unique_ptr<dds::Reader<idl::SimControlPubSubType>> control_reader_;

  TimeMode mode_ = TimeMode::kRealtime;
  double speed_ = 1.0;
  bool paused_ = false;
  int64_t state_every_ = 1;
  uint64_t pending_steps_ = 0;
  std::deque<PendingStep> pending_replies_;
  uint64_t reported_overflow_ = 0;

  LeggedWorldState state_;
  idl::JointState joint_sample_;
  idl::LinkState links_sample_;
  std::vector<JointCommand> checked_;
  std::vector<idl::JointCommand> command_inbox_;
  std::vector<idl::SimControl> control_inbox_;

  mutable std::mutex rejects_mutex_;
  RejectLog rejects_;
  std::atomic<uint64_t> rejected_{0};
  std::atomic<uint64_t> frame_{0};
  std::atomic<int64_t> time_ns_{0};
  std::atomic<double> rtf_{0.0};
};

LeggedNode::LeggedNode(LeggedScene scene, SimNodeOptions options)
    : impl_(std::make_unique<Impl>(std::move(scene), std::move(options))) {}
LeggedNode::~LeggedNode() = default;
void LeggedNode::Run(const std::function<bool()>& stop) { impl_->Run(stop); }
SimNodeStats LeggedNode::Stats() const { return impl_->Stats(); }
uint64_t LeggedNode::Rejected(const std::string& kind) const { return impl_->Rejected(kind); }

}  // namespace turf
