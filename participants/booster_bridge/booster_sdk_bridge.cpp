#include "participants/booster_bridge/booster_sdk_bridge.h"

#include <spdlog/spdlog.h>
#include <turf/idl/BoosterLowLevelPubSubTypes.h>
#include <turf/idl/JointsPubSubTypes.h>

#include <atomic>
#include <cmath>
#include <mutex>

#include "codecs/booster/low_cmd.h"
#include "codecs/booster/low_state.h"
#include "codecs/booster/robots.h"
#include "dds/bus.h"
#include "dds/vendor_participant.h"
#include "participants/common/pd_target.h"
#include "participants/common/process.h"
#include "participants/common/wakeup.h"

namespace turf {

namespace bi = booster_interface::msg::dds_;

namespace {

constexpr int kMaxDdsDomain = 232;  // RTPS's port arithmetic with the default port parameters
constexpr const char* kLowState = "rt/low_state";
constexpr const char* kJointCtrl = "rt/joint_ctrl";
constexpr const char* kOdometer = "rt/odometer_state";
constexpr const char* kFallDown = "rt/fall_down";
constexpr double kFallenTilt = 60.0 * M_PI / 180.0;

int64_t WallNs() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

std::array<double, 4> Q(const idl::Quat& q) { return {q.w(), q.x(), q.y(), q.z()}; }

// The parts of turf's frame the SDK's LowState carries.
LeggedRobotState RobotOf(const idl::JointState& j, const idl::ImuState& imu) {
  LeggedRobotState r;
  r.name = j.robot();
  r.joint_names = j.name();
  r.joint_positions = j.position();
  r.joint_velocities = j.velocity();
  r.joint_efforts = j.effort();
  r.orientation = Q(imu.orientation());
  r.gyro = {imu.angular_velocity().x(), imu.angular_velocity().y(), imu.angular_velocity().z()};
  r.accelerometer = {imu.linear_acceleration().x(), imu.linear_acceleration().y(), imu.linear_acceleration().z()};
  return r;
}

double Yaw(const std::array<double, 4>& q) {
  return std::atan2(2 * (q[0] * q[3] + q[1] * q[2]), 1 - 2 * (q[2] * q[2] + q[3] * q[3]));
}

// Angle between the trunk's z axis and the vertical.
double Tilt(const std::array<double, 4>& q) {
  const double zz = 1 - 2 * (q[1] * q[1] + q[2] * q[2]);
  return std::acos(std::clamp(zz, -1.0, 1.0));
}

}  // namespace

class BoosterSdkBridge::Impl {
 public:
  Impl(BoosterSdkOptions options, dds::Bus& bus)
      : options_(options),
        state_reader_(bus.MakeReader(dds::Topic::kRobotsState, [this] { wake_.Notify(); })),
        command_writer_(bus.MakeWriter(dds::Topic::kRobotJointCommand)),
        rejects_("Booster SDK input", std::chrono::seconds(1)) {}

  void Run(const std::function<bool()>& stop) {
    while (!stop()) {
      wake_.WaitFor(std::chrono::milliseconds(50));
      if (!state_reader_->Take(&frames_)) continue;
      for (const idl::LeggedState& frame : frames_) Publish(frame);
    }
  }

  BoosterSdkStats Stats() const {
    BoosterSdkStats s;
    s.states = states_.load();
    s.commands = commands_.load();
    s.refused = rejects_.Total();
    s.refused_by_kind = rejects_.counts();
    return s;
  }

  std::vector<std::string> Robots() const {
    std::lock_guard<std::mutex> lock(robots_mutex_);
    std::vector<std::string> out;
    for (const auto& r : robots_)
      out.push_back(fmt::format("{} ({}) on domain {}", r->name, booster::ModelName(r->model), r->dds.domain()));
    return out;
  }

 private:
  struct Robot {
    Robot(std::string n, booster::BoosterModel m, int domain)
        : name(std::move(n)), model(m), dds(domain, "turf-sim/booster/" + name) {}
    std::string name;
    booster::BoosterModel model;
    dds::VendorParticipant dds;
    std::unique_ptr<dds::VendorParticipant::Writer<bi::LowState_PubSubType>> low_state;
    std::unique_ptr<dds::VendorParticipant::Writer<bi::Odometer_PubSubType>> odometer;
    std::unique_ptr<dds::VendorParticipant::Writer<bi::FallDownState_PubSubType>> fall_down;
    std::unique_ptr<dds::VendorParticipant::RawReader> joint_ctrl;
    bool have_start = false;
    std::array<double, 3> start{};  // x, y, yaw of the base at the first frame
    bi::LowState_ sample;
  };

  // The first frame names the robots: every T1 and K1 gets its domain, writers and reader.
  void Discover(const idl::LeggedState& frame) {
    std::lock_guard<std::mutex> lock(robots_mutex_);
    discovered_ = true;
    int domain = options_.domain;
    for (const idl::JointState& j : frame.joints()) {
      const auto model = booster::IdentifyRobot(j.name());
      if (!model) continue;
      if (domain > kMaxDdsDomain) {  // Fast DDS would exit the process (its port numbers overflow)
        spdlog::error(
            "Booster SDK: robot {} is not served: its DDS domain would be {}, past {} (give --booster-sdk "
            "a lower first domain)",
            j.robot(), domain, kMaxDdsDomain);
        continue;
      }
      if (domain == options_.turf_domain)
        spdlog::warn(
            "Booster SDK: robot {}'s DDS domain {} is turf's own: a program there can also write turf's "
            "topics (its control and every robot's joint commands); give --booster-sdk a domain apart where "
            "robot programs are not trusted (README, Access control)",
            j.robot(), domain);
      auto r = std::make_unique<Robot>(j.robot(), *model, domain++);
      r->low_state = r->dds.MakeWriter<bi::LowState_PubSubType>(kLowState);
      r->odometer = r->dds.MakeWriter<bi::Odometer_PubSubType>(kOdometer);
      r->fall_down = r->dds.MakeWriter<bi::FallDownState_PubSubType>(kFallDown);
      Robot* robot = r.get();
      r->joint_ctrl = r->dds.MakeReader<bi::LowCmd_PubSubType>(
          kJointCtrl, [this, robot](const bi::LowCmd_& cmd, int64_t source_ns) { Command(*robot, cmd, source_ns); });
      spdlog::info(
          "Booster SDK: robot {} ({}) on DDS domain {}: publishing {} ({}), {} ({}), {} ({}); subscribing {} ({})",
          robot->name, booster::ModelName(robot->model), robot->dds.domain(), kLowState,
          bi::LowState_PubSubType().getName(), kOdometer, bi::Odometer_PubSubType().getName(), kFallDown,
          bi::FallDownState_PubSubType().getName(), kJointCtrl, bi::LowCmd_PubSubType().getName());
      robots_.push_back(std::move(r));
    }
    if (robots_.empty()) spdlog::warn("Booster SDK: the scene has no T1 or K1; nothing to serve");
  }

  void Publish(const idl::LeggedState& frame) {
    if (!discovered_) Discover(frame);
    for (const auto& r : robots_) {
      const idl::JointState* joints = nullptr;
      const idl::ImuState* imu = nullptr;
      for (const idl::JointState& j : frame.joints())
        if (j.robot() == r->name) joints = &j;
      for (const idl::ImuState& i : frame.imu())
        if (i.robot() == r->name) imu = &i;
      if (joints == nullptr || imu == nullptr) continue;
      booster::EncodeLowState(RobotOf(*joints, *imu), &r->sample);
      r->low_state->Write(r->sample);
      PublishBase(*r, *imu);
      ++states_;
    }
  }

  void PublishBase(Robot& r, const idl::ImuState& imu) {
    const std::array<double, 4> q = Q(imu.base_orientation());
    const double x = imu.base_position().x(), y = imu.base_position().y(), yaw = Yaw(q);
    if (!r.have_start) {
      r.start = {x, y, yaw};
      r.have_start = true;
    }
    // In the start frame: rotate the displacement by -yaw0.
    const double c = std::cos(r.start[2]), s = std::sin(r.start[2]);
    const double dx = x - r.start[0], dy = y - r.start[1];
    bi::Odometer_ odo;
    odo.x(static_cast<float>(c * dx + s * dy));
    odo.y(static_cast<float>(-s * dx + c * dy));
    odo.theta(static_cast<float>(std::remainder(yaw - r.start[2], 2 * M_PI)));
    r.odometer->Write(odo);
    bi::FallDownState_ fall;
    fall.fall_down_state(Tilt(q) > kFallenTilt ? bi::HAS_FALLEN : bi::IS_READY);
    fall.is_recovery_available(false);
    r.fall_down->Write(fall);
  }

  // On a Fast DDS thread.
  void Command(const Robot& r, const bi::LowCmd_& cmd, int64_t source_ns) {
    const int64_t age_ns = WallNs() - source_ns;
    const int64_t timeout_ns = std::chrono::nanoseconds(options_.command_timeout).count();
    if (age_ns > timeout_ns) {
      rejects_.Reject("joint_ctrl.stale", fmt::format("robot {}: a command {} ms old", r.name, age_ns / 1'000'000));
      return;
    }
    // Dated ahead by more than the same margin (a sender's clock, or stamps chosen to pass the check above).
    if (age_ns < -timeout_ns) {
      rejects_.Reject("joint_ctrl.future",
                      fmt::format("robot {}: a command dated {} ms ahead", r.name, -age_ns / 1'000'000));
      return;
    }
    const booster::LowCmdDecode d = booster::DecodeLowCmd(cmd, r.model);
    if (d.error != Error::kOk) {
      rejects_.Reject(fmt::format("joint_ctrl.{}", ErrorName(d.error)), fmt::format("robot {}: {}", r.name, d.detail));
      return;
    }
    if (d.parallel && !warned_parallel_.exchange(true))
      spdlog::warn(
          "Booster SDK: robot {}: cmd_type PARALLEL is taken as SERIAL (turf's ankles are pitch and roll "
          "joints; no model has the crank linkage)",
          r.name);
    idl::JointCommand out;
    out.robot(r.name);
    out.joints().reserve(d.commands.size());
    for (const JointCommand& c : d.commands)
      out.joints().push_back(PdTarget(c.joint, c.value, c.dq, c.kp, c.kd, c.tau));
    std::lock_guard<std::mutex> lock(command_mutex_);
    command_writer_->Write(out);
    ++commands_;
  }

  BoosterSdkOptions options_;
  Wakeup wake_;
  std::unique_ptr<dds::Reader<idl::LeggedStatePubSubType>> state_reader_;
  std::unique_ptr<dds::Writer<idl::JointCommandPubSubType>> command_writer_;
  std::mutex command_mutex_;  // the Fast DDS threads of several robots' readers share the writer
  RejectLog rejects_;
  std::vector<idl::LeggedState> frames_;
  mutable std::mutex robots_mutex_;
  std::vector<std::unique_ptr<Robot>> robots_;  // fixed after Discover
  bool discovered_ = false;
  std::atomic<uint64_t> states_{0};
  std::atomic<uint64_t> commands_{0};
  std::atomic<bool> warned_parallel_{false};
};

BoosterSdkBridge::BoosterSdkBridge(BoosterSdkOptions options, dds::Bus& bus)
    : impl_(std::make_unique<Impl>(options, bus)) {}
BoosterSdkBridge::~BoosterSdkBridge() = default;
void BoosterSdkBridge::Run(const std::function<bool()>& stop) { impl_->Run(stop); }
BoosterSdkStats BoosterSdkBridge::Stats() const { return impl_->Stats(); }
std::vector<std::string> BoosterSdkBridge::Robots() const { return impl_->Robots(); }

}  // namespace turf
