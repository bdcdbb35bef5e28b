#include "participants/rcssservermj_bridge/legged_link.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "participants/common/legged_lockstep.h"

namespace turf {

namespace {

Eigen::Vector3d E3(const idl::Vec3& v) { return {v.x(), v.y(), v.z()}; }
std::array<double, 3> A3(const idl::Vec3& v) { return {v.x(), v.y(), v.z()}; }
Eigen::Quaterniond EQ(const idl::Quat& q) { return Eigen::Quaterniond(q.w(), q.x(), q.y(), q.z()); }

}  // namespace

std::string ModelOfLabel(const std::string& label) {
  std::string stem = std::filesystem::path(label).stem().string();
  std::transform(stem.begin(), stem.end(), stem.begin(), [](unsigned char c) { return std::toupper(c); });
  return stem;
}

class MjLeggedLink::Impl {
 public:
  Impl(std::unique_ptr<dds::Participant> own, dds::Bus& bus) : link_(std::move(own), bus, kClient, false) {}

  std::string TopicName(dds::Topic t) const { return link_.TopicName(t); }
  std::string DescribeBus() const { return link_.DescribeBus(); }

  std::optional<Scene> Attach(std::chrono::milliseconds timeout, const std::function<bool()>& stop,
                              std::string* error) {
    if (!link_.Attach(timeout, stop, error)) return std::nullopt;
    const idl::LeggedSceneInfo& info = link_.scene_info();
    Scene scene;
    scene.name = info.name();
    scene.has_field = info.has_field();
    scene.field_length = info.field_length();
    scene.field_width = info.field_width();
    std::vector<std::string> robots;
    for (const idl::RobotDescription& r : info.robots()) robots.push_back(r.robot());
    for (size_t i = 0; i < robots.size(); ++i) {
      const idl::LinkPose& torso = link_.state().links()[i].links().at(0);
      rcssservermj::RobotMove park{robots[i], E3(torso.position()), EQ(torso.orientation()), true};
      scene.robots.push_back({robots[i], ModelOfLabel(info.robots()[i].model()), park});
    }
    return scene;
  }

  std::optional<rcssservermj::MjWorldSnapshot> Cycle(const rcssservermj::WorldRequests& requests, uint32_t steps,
                                                     std::chrono::milliseconds timeout,
                                                     const std::function<bool()>& stop, std::string* error,
                                                     std::vector<std::string>* warnings) {
    for (const rcssservermj::RobotMove& m : requests.moves)
      link_.SendMove(m.robot, m.position, m.orientation, m.reset_joints, timeout);
    if (requests.ball) link_.SendBall(*requests.ball, Eigen::Vector3d::Zero(), timeout);
    idl::SimControl step;
    step.op(idl::OP_STEP);
    step.step_count(steps);
    for (const auto& [robot, targets] : requests.joints) {
      idl::JointCommand c;
      c.robot(robot);
      for (const rcssservermj::PdCommand& t : targets) c.joints().push_back(ToJointTarget(t));
      step.joint_commands().push_back(std::move(c));
    }
    if (!link_.Step(std::move(step), steps, timeout, stop, error, warnings)) return std::nullopt;
    return Snapshot();
  }

  rcssservermj::MjWorldSnapshot Snapshot() const {
    const idl::LeggedState& s = link_.state();
    rcssservermj::MjWorldSnapshot w;
    w.time = static_cast<double>(s.sim_time_ns()) * 1e-9;
    w.ball = E3(s.ball_position());
    for (size_t i = 0; i < s.joints().size(); ++i) {
      rcssservermj::MjRobotSnapshot r;
      r.name = s.joints()[i].robot();
      r.joint_names = s.joints()[i].name();
      r.positions = s.joints()[i].position();
      r.velocities = s.joints()[i].velocity();
      r.gyro = A3(s.imu()[i].angular_velocity());
      r.acc = A3(s.imu()[i].linear_acceleration());
      for (const idl::LinkPose& l : s.links()[i].links())
        r.links.push_back({l.name(), E3(l.position()), EQ(l.orientation())});
      w.robots.push_back(std::move(r));
    }
    return w;
  }

  double step_s() const { return link_.step_s(); }

 private:
  static constexpr const char* kClient = "turf-rcssservermj-bridge";

  LeggedLockstep link_;
};

MjLeggedLink::MjLeggedLink(const dds::ParticipantOptions& options) {
  auto own = std::make_unique<dds::Participant>(options);
  dds::Bus& bus = *own;
  impl_ = std::make_unique<Impl>(std::move(own), bus);
}
MjLeggedLink::MjLeggedLink(dds::Bus& bus) : impl_(std::make_unique<Impl>(nullptr, bus)) {}
MjLeggedLink::~MjLeggedLink() = default;
std::string MjLeggedLink::TopicName(dds::Topic topic) const { return impl_->TopicName(topic); }
std::string MjLeggedLink::DescribeBus() const { return impl_->DescribeBus(); }
std::optional<MjLeggedLink::Scene> MjLeggedLink::Attach(std::chrono::milliseconds timeout,
                                                        const std::function<bool()>& stop, std::string* error) {
  return impl_->Attach(timeout, stop, error);
}
std::optional<rcssservermj::MjWorldSnapshot> MjLeggedLink::Cycle(const rcssservermj::WorldRequests& requests,
                                                                 uint32_t steps, std::chrono::milliseconds timeout,
                                                                 const std::function<bool()>& stop, std::string* error,
                                                                 std::vector<std::string>* warnings) {
  return impl_->Cycle(requests, steps, timeout, stop, error, warnings);
}
double MjLeggedLink::step_s() const { return impl_->step_s(); }

}  // namespace turf
