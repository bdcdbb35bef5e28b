#include "participants/simspark_bridge/world_link.h"

#include <turf/idl/ClockPubSubTypes.h>
#include <turf/idl/JointsPubSubTypes.h>
#include <turf/idl/SimControlPubSubTypes.h>

#include <fmt/format.h>

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

}  // namespace

class WorldLink::Impl {
 public:
  // `own` null: on `bus`, which outlives the link.
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

  // Polls until done() or the deadline; false on timeout or stop.
  bool WaitFor(const std::function<bool()>& done, Clock::time_point deadline,
               const std::function<bool()>& stop = nullptr) {
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
    // Asked again every 0.5 s: when turf-sim has just started, a request or
    // reply can miss an endpoint it has not discovered yet. The request is idempotent.
    dds::ControlOutcome answer;
    while (Clock::now() < deadline && !(stop && stop())) {
      const auto wait = std::chrono::duration_cast<std::chrono::milliseconds>(
          std::min(deadline - Clock::now(), Clock::duration(std::chrono::milliseconds(500))));
      answer = control_.Call(lockstep, wait, stop);
      if (answer.reply) break;
    }
    if (!answer.reply) {
      *error = "turf-sim did not answer the switch to lockstep (" + answer.Describe() + ")";
      return std::nullopt;
    }
    if (!answer.ok()) {
      *error = "turf-sim refused lockstep: " + answer.reply->reason();
      return std::nullopt;
    }
    frame_ = answer.reply->frame();
    Scene scene;
    scene.name = scene_info_->name();
    for (const idl::RobotDescription& r : scene_info_->robots()) scene.robots.push_back(r.robot());
    // Where every robot stands now.
    auto current = [&] { return step_s_ > 0 && Complete(scene.robots, frame_); };
    if (!WaitFor(current, deadline, stop)) {
      *error =
          fmt::format("turf-sim did not publish the state of its {} robots at frame {}", scene.robots.size(), frame_);
      return std::nullopt;
    }
    for (const idl::LinkState& links : state_now_->links()) {
      const idl::LinkPose& torso = links.links().at(0);
      simspark::RobotMove park;
      park.robot = links.robot();
      park.position = E3(torso.position());
      park.orientation = Eigen::Quaterniond(torso.orientation().w(), torso.orientation().x(), torso.orientation().y(),
                                            torso.orientation().z());
      scene.park.push_back(park);
    }
    robots_ = scene.robots;
    return scene;
  }

  std::optional<simspark::WorldSnapshot> Cycle(const simspark::WorldRequests& requests, uint32_t steps,
                                               std::chrono::milliseconds timeout, const std::function<bool()>& stop,
                                               std::string* error, std::vector<std::string>* warnings) {
    // Moves are answered before the step; their refusals are reported when
    // the step is done (late ones next cycle).
    auto warn = [this](std::string what) {
      return [this, what = std::move(what)](const dds::ControlOutcome& o) {
        if (!o.ok()) move_warnings_.push_back(what + ": " + o.Describe());
      };
    };
    for (const simspark::RobotMove& m : requests.moves) {
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
      ball.ball().position(V3(requests.ball->position));
      ball.ball().velocity(V3(requests.ball->velocity));
      control_.Send(std::move(ball), timeout, warn("ball"));
    }
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
    const uint64_t id = control_.Send(std::move(step), timeout);
    const auto deadline = Clock::now() + timeout;
    // The world after the step usually arrives before the step's reply (turf-sim
    // writes robots/state first): take it at the expected frame at once; the
    // reply's frame counts when someone else stepped too (a viewer's step).
    const uint64_t expected = frame_ + steps;
    std::optional<dds::ControlOutcome> answer;
    auto done = [&] {
      if (Complete(robots_, expected)) return true;
      answer = control_.Peek(id);
      return answer && (!answer->reply || !answer->ok() || Complete(robots_, answer->reply->frame()));
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

  // The newest state is of `frame` and has every robot, whole.
  bool Complete(const std::vector<std::string>& robots, uint64_t frame) const {
    if (!state_now_ || state_now_->frame() != frame) return false;
    const idl::LeggedState& s = *state_now_;
    const size_t n = s.joints().size();
    if (n != robots.size() || s.imu().size() != n || s.force().size() != n || s.links().size() != n) return false;
    for (size_t i = 0; i < n; ++i) {
      if (s.joints()[i].robot() != robots[i] || s.links()[i].links().empty()) return false;
    }
    return true;
  }

  simspark::WorldSnapshot Snapshot() const {
    const idl::LeggedState& s = *state_now_;
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

  double step_s() const { return step_s_; }
  uint64_t Overflowed() const { return control_.Overflowed() + state_->Overflowed(); }

 private:
  static constexpr const char* kClient = "turf-simspark-bridge";

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
  std::vector<std::string> move_warnings_;  // refused moves, reported with the next step
  std::vector<std::string> robots_;
  uint64_t frame_ = 0;
  double step_s_ = 0.0;
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
