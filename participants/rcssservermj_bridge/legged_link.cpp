#include "participants/rcssservermj_bridge/legged_link.h"

#include <turf/idl/ClockPubSubTypes.h>
#include <turf/idl/JointsPubSubTypes.h>
#include <turf/idl/SimControlPubSubTypes.h>

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "dds/control_client.h"
#include "participants/common/wakeup.h"

namespace turf {

namespace {

using Clock = std::chrono::steady_clock;

idl::Vec3 V3(const Eigen::Vector3d& v) {
  idl::Vec3 out;
  out.x(v.x());
  out.y(v.y());
  out.z(v.z());
  return out;
}

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
  Impl(std::unique_ptr<dds::Participant> own, dds::Bus& bus)
      : own_(std::move(own)),
        bus_(bus),
        control_(bus_, kClient, Wake()),
        scene_(bus_.MakeReader<idl::LeggedSceneInfoPubSubType>(dds::Topic::kLeggedScene, Wake())),
        clock_(bus_.MakeReader<idl::ClockPubSubType>(dds::Topic::kClock, Wake())),
        state_(bus_.MakeReader<idl::LeggedStatePubSubType>(dds::Topic::kRobotsState, Wake())) {}

  std::function<void()> Wake() {
    return [this] { wakeup_.Notify(); };
  }
  std::string TopicName(dds::Topic t) const { return bus_.TopicName(t); }
  std::string DescribeBus() const { return bus_.Describe(); }

  void Drain() {
    if (scene_->Take(&scene_in_)) scene_info_ = scene_in_.back();
    if (clock_->Take(&clock_in_)) step_s_ = clock_in_.back().step_s();
    if (state_->Take(&state_in_)) state_now_ = std::move(state_in_.back());
  }

  bool WaitFor(const std::function<bool()>& done, Clock::time_point deadline, const std::function<bool()>& stop) {
    while (true) {
      Drain();
      if (done()) return true;
      if (Clock::now() >= deadline || (stop && stop())) return false;
      wakeup_.WaitUntil(std::min(deadline, Clock::now() + std::chrono::milliseconds(50)));
    }
  }

  std::optional<Scene> Attach(std::chrono::milliseconds timeout, const std::function<bool()>& stop,
                              std::string* error) {
    const auto deadline = Clock::now() + timeout;
    if (!WaitFor([this] { return scene_info_.has_value() && control_.ServerMatched(); }, deadline, stop)) {
      *error = "no legged scene from turf-sim (is it running a `kind: legged` scene on this domain and prefix?)";
      return std::nullopt;
    }
    idl::SimControl lockstep;
    lockstep.op(idl::OP_SET_TIME_MODE);
    lockstep.time_mode(idl::TIME_LOCKSTEP);
    dds::ControlOutcome answer;
    while (Clock::now() < deadline && !(stop && stop())) {  // idempotent; asked again while discovery settles
      const auto wait = std::chrono::duration_cast<std::chrono::milliseconds>(
          std::min(deadline - Clock::now(), Clock::duration(std::chrono::milliseconds(500))));
      answer = control_.Call(lockstep, wait, stop);
      if (answer.reply) break;
    }
    if (!answer.reply || !answer.ok()) {
      *error = "turf-sim did not switch to lockstep (" + answer.Describe() + ")";
      return std::nullopt;
    }
    frame_ = answer.reply->frame();
    Scene scene;
    scene.name = scene_info_->name();
    scene.has_field = scene_info_->has_field();
    scene.field_length = scene_info_->field_length();
    scene.field_width = scene_info_->field_width();
    for (const idl::RobotDescription& r : scene_info_->robots()) robots_.push_back(r.robot());
    if (!WaitFor([&] { return step_s_ > 0 && Complete(frame_); }, deadline, stop)) {
      *error = fmt::format("turf-sim did not publish the state of its {} robots at frame {}", robots_.size(), frame_);
      return std::nullopt;
    }
    for (size_t i = 0; i < robots_.size(); ++i) {
      const idl::LinkPose& torso = state_now_->links()[i].links().at(0);
      rcssservermj::RobotMove park{robots_[i], E3(torso.position()), EQ(torso.orientation()), true};
      scene.robots.push_back({robots_[i], ModelOfLabel(scene_info_->robots()[i].model()), park});
    }
    return scene;
  }

  std::optional<rcssservermj::MjWorldSnapshot> Cycle(const rcssservermj::WorldRequests& requests, uint32_t steps,
                                                     std::chrono::milliseconds timeout,
                                                     const std::function<bool()>& stop, std::string* error,
                                                     std::vector<std::string>* warnings) {
    auto warn = [this](std::string what) {
      return [this, what = std::move(what)](const dds::ControlOutcome& o) {
        if (!o.ok()) move_warnings_.push_back(what + ": " + o.Describe());
      };
    };
    for (const rcssservermj::RobotMove& m : requests.moves) {
      idl::SimControl move;
      move.op(idl::OP_TELEPORT_ROBOT);
      move.legged().robot(m.robot);
      move.legged().position(V3(m.position));
      move.legged().orientation().w(m.orientation.w());
      move.legged().orientation().x(m.orientation.x());
      move.legged().orientation().y(m.orientation.y());
      move.legged().orientation().z(m.orientation.z());
      move.legged().reset_joints(m.reset_joints);
      control_.Send(std::move(move), timeout, warn("move " + m.robot));
    }
    if (requests.ball) {
      idl::SimControl ball;
      ball.op(idl::OP_TELEPORT_BALL);
      ball.ball().position(V3(*requests.ball));
      ball.ball().velocity(V3(Eigen::Vector3d::Zero()));
      control_.Send(std::move(ball), timeout, warn("ball"));
    }
    idl::SimControl step;
    step.op(idl::OP_STEP);
    step.step_count(steps);
    for (const auto& [robot, targets] : requests.joints) {
      idl::JointCommand c;
      c.robot(robot);
      for (const rcssservermj::PdCommand& t : targets) c.joints().push_back(ToJointTarget(t));
      step.joint_commands().push_back(std::move(c));
    }
    const uint64_t id = control_.Send(std::move(step), timeout);
    const auto deadline = Clock::now() + timeout;
    const uint64_t expected = frame_ + steps;
    std::optional<dds::ControlOutcome> answer;
    auto done = [&] {
      if (Complete(expected)) return true;
      answer = control_.Peek(id);
      return answer && (!answer->reply || !answer->ok() || Complete(answer->reply->frame()));
    };
    const bool finished = WaitFor(done, deadline, stop);
    control_.Forget(id);
    control_.Dispatch();
    warnings->insert(warnings->end(), move_warnings_.begin(), move_warnings_.end());
    move_warnings_.clear();
    if (!finished || (answer && !answer->reply)) {
      *error = "turf-sim did not answer the step" + (answer ? " (" + answer->Describe() + ")" : std::string());
      return std::nullopt;
    }
    if (answer && !answer->ok()) {
      *error = "turf-sim refused the step: " + answer->reply->reason();
      return std::nullopt;
    }
    frame_ = state_now_->frame();
    return Snapshot();
  }

  bool Complete(uint64_t frame) const {
    if (!state_now_ || state_now_->frame() != frame) return false;
    const idl::LeggedState& s = *state_now_;
    const size_t n = s.joints().size();
    if (n != robots_.size() || s.imu().size() != n || s.links().size() != n) return false;
    for (size_t i = 0; i < n; ++i)
      if (s.joints()[i].robot() != robots_[i] || s.links()[i].links().empty()) return false;
    return true;
  }

  rcssservermj::MjWorldSnapshot Snapshot() const {
    const idl::LeggedState& s = *state_now_;
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

  double step_s() const { return step_s_; }

 private:
  static constexpr const char* kClient = "turf-rcssservermj-bridge";

  Wakeup wakeup_;
  std::unique_ptr<dds::Participant> own_;
  dds::Bus& bus_;
  dds::ControlClient control_;
  std::unique_ptr<dds::Reader<idl::LeggedSceneInfoPubSubType>> scene_;
  std::unique_ptr<dds::Reader<idl::ClockPubSubType>> clock_;
  std::unique_ptr<dds::Reader<idl::LeggedStatePubSubType>> state_;
  std::vector<idl::LeggedSceneInfo> scene_in_;
  std::vector<idl::Clock> clock_in_;
  std::vector<idl::LeggedState> state_in_;
  std::optional<idl::LeggedSceneInfo> scene_info_;
  std::optional<idl::LeggedState> state_now_;
  std::vector<std::string> move_warnings_;
  std::vector<std::string> robots_;
  uint64_t frame_ = 0;
  double step_s_ = 0.0;
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
