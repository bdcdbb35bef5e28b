#include "participants/simspark_bridge/world_link.h"

#include <fmt/format.h>

#include "participants/common/legged_lockstep.h"

namespace turf {

namespace {

Eigen::Vector3d E3(const idl::Vec3& v) { return {v.x(), v.y(), v.z()}; }
std::array<double, 3> A3(const idl::Vec3& v) { return {v.x(), v.y(), v.z()}; }

}  // namespace

class WorldLink::Impl {
 public:
  // `own` null: on `bus`, which outlives the link.
  Impl(std::unique_ptr<dds::Participant> own, dds::Bus& bus) : link_(std::move(own), bus, kClient, true) {}

  std::string TopicName(dds::Topic t) const { return link_.TopicName(t); }
  std::string DescribeBus() const { return link_.DescribeBus(); }

  std::optional<Scene> Attach(std::chrono::milliseconds timeout, const std::function<bool()>& stop,
                              std::string* error) {
    if (!link_.Attach(timeout, stop, error)) return std::nullopt;
    Scene scene;
    scene.name = link_.scene_info().name();
    for (const idl::RobotDescription& r : link_.scene_info().robots()) scene.robots.push_back(r.robot());
    for (const idl::LinkState& links : link_.state().links()) {
      const idl::LinkPose& torso = links.links().at(0);
      simspark::RobotMove park;
      park.robot = links.robot();
      park.position = E3(torso.position());
      park.orientation = Eigen::Quaterniond(torso.orientation().w(), torso.orientation().x(), torso.orientation().y(),
                                            torso.orientation().z());
      scene.park.push_back(park);
    }
    return scene;
  }

  std::optional<simspark::WorldSnapshot> Cycle(const simspark::WorldRequests& requests, uint32_t steps,
                                               std::chrono::milliseconds timeout, const std::function<bool()>& stop,
                                               std::string* error, std::vector<std::string>* warnings) {
    for (const simspark::RobotMove& m : requests.moves)
      link_.SendMove(m.robot, m.position, m.orientation, m.reset_joints, timeout);
    if (requests.ball) link_.SendBall(requests.ball->position, requests.ball->velocity, timeout);
    idl::SimControl step;
    step.op(idl::OP_STEP);
    step.step_count(steps);
    for (const auto& [robot, targets] : requests.joints) {
      idl::JointCommand c;
      c.robot(robot);
      for (const simspark::JointVelocity& v : targets) {
        idl::JointTarget t;
        t.name(v.joint);
        t.mode(idl::JOINT_VELOCITY);
        t.value(v.velocity);
        t.kp(-1);
        t.kd(-1);
        c.joints().push_back(t);
      }
      step.joint_commands().push_back(std::move(c));
    }
    if (!link_.Step(std::move(step), steps, timeout, stop, error, warnings)) return std::nullopt;
    return Snapshot();
  }

  simspark::WorldSnapshot Snapshot() const {
    const idl::LeggedState& s = link_.state();
    simspark::WorldSnapshot w;
    w.time = s.sim_time_ns() * 1e-9;
    w.ball = E3(s.ball_position());
    w.ball_velocity = E3(s.ball_velocity());
    for (size_t i = 0; i < s.joints().size(); ++i) {
      simspark::RobotSnapshot r;
      r.name = s.joints()[i].robot();
      r.joint_names = s.joints()[i].name();
      r.joint_positions = s.joints()[i].position();
      r.gyro = A3(s.imu()[i].angular_velocity());
      r.accelerometer = A3(s.imu()[i].linear_acceleration());
      for (const idl::ForceReading& f : s.force()[i].sensors())
        r.feet.push_back({f.name(), f.contact(), A3(f.point()), A3(f.force())});
      for (const idl::LinkPose& l : s.links()[i].links()) {
        r.links.push_back(
            {l.name(), E3(l.position()),
             Eigen::Quaterniond(l.orientation().w(), l.orientation().x(), l.orientation().y(), l.orientation().z())});
      }
      w.robots.push_back(std::move(r));
    }
    return w;
  }

  double step_s() const { return link_.step_s(); }
  uint64_t Overflowed() const { return link_.Overflowed(); }

 private:
  static constexpr const char* kClient = "turf-simspark-bridge";

  LeggedLockstep link_;
};

WorldLink::WorldLink(const dds::ParticipantOptions& options) {
  auto own = std::make_unique<dds::Participant>(options);
  dds::Bus& bus = *own;
  impl_ = std::make_unique<Impl>(std::move(own), bus);
}
WorldLink::WorldLink(dds::Bus& bus) : impl_(std::make_unique<Impl>(nullptr, bus)) {}
WorldLink::~WorldLink() = default;
std::string WorldLink::TopicName(dds::Topic topic) const { return impl_->TopicName(topic); }
std::string WorldLink::DescribeBus() const { return impl_->DescribeBus(); }
std::optional<WorldLink::Scene> WorldLink::Attach(std::chrono::milliseconds timeout, const std::function<bool()>& stop,
                                                  std::string* error) {
  return impl_->Attach(timeout, stop, error);
}
std::optional<simspark::WorldSnapshot> WorldLink::Cycle(const simspark::WorldRequests& requests, uint32_t steps,
                                                        std::chrono::milliseconds timeout,
                                                        const std::function<bool()>& stop, std::string* error,
                                                        std::vector<std::string>* warnings) {
  return impl_->Cycle(requests, steps, timeout, stop, error, warnings);
}
double WorldLink::step_s() const { return impl_->step_s(); }
uint64_t WorldLink::Overflowed() const { return impl_->Overflowed(); }

}  // namespace turf
