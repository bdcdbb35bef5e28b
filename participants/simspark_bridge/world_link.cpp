#include "participants/simspark_bridge/world_link.h"

#include <turf/idl/ClockPubSubTypes.h>
#include <turf/idl/JointsPubSubTypes.h>
#include <turf/idl/SimControlPubSubTypes.h>
#include <turf/idl/WorldStatePubSubTypes.h>

#include <fmt/format.h>

#include <map>

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

// What turf-sim published for one robot, gathered until all parts carry the
// cycle's frame.
struct RobotParts {
  std::optional<idl::JointState> joints;
  std::optional<idl::ImuState> imu;
  std::optional<idl::ForceState> force;
  std::optional<idl::LinkState> links;
};

}  // namespace

class WorldLink::Impl {
 public:
  explicit Impl(const dds::ParticipantOptions& options)
      : participant_(options),
        control_(participant_.MakeWriter<idl::SimControlPubSubType>(dds::Topic::kControl)),
        reply_(participant_.MakeReader<idl::SimControlReplyPubSubType>(dds::Topic::kControlReply, Wake())),
        scene_(participant_.MakeReader<idl::LeggedSceneInfoPubSubType>(dds::Topic::kLeggedScene, Wake())),
        clock_(participant_.MakeReader<idl::ClockPubSubType>(dds::Topic::kClock, Wake())),
        joints_(participant_.MakeReader<idl::JointStatePubSubType>(dds::Topic::kRobotJointState, Wake())),
        imu_(participant_.MakeReader<idl::ImuStatePubSubType>(dds::Topic::kRobotImu, Wake())),
        force_(participant_.MakeReader<idl::ForceStatePubSubType>(dds::Topic::kRobotForce, Wake())),
        links_(participant_.MakeReader<idl::LinkStatePubSubType>(dds::Topic::kRobotLinks, Wake())),
        world_(participant_.MakeReader<idl::WorldStatePubSubType>(dds::Topic::kWorldState, Wake())) {}

  std::function<void()> Wake() {
    return [this] { wakeup_.Notify(); };
  }

  std::string TopicName(dds::Topic t) const { return participant_.TopicName(t); }

  void Drain() {
    if (reply_->Take(&reply_in_))
      for (auto& r : reply_in_)
        if (r.client() == kClient) replies_[r.request_id()] = r;
    if (scene_->Take(&scene_in_)) scene_info_ = scene_in_.back();
    if (clock_->Take(&clock_in_)) step_s_ = clock_in_.back().step_s();
    if (joints_->Take(&joints_in_))
      for (auto& s : joints_in_) parts_[s.robot()].joints = std::move(s);
    if (imu_->Take(&imu_in_))
      for (auto& s : imu_in_) parts_[s.robot()].imu = std::move(s);
    if (force_->Take(&force_in_))
      for (auto& s : force_in_) parts_[s.robot()].force = std::move(s);
    if (links_->Take(&links_in_))
      for (auto& s : links_in_) parts_[s.robot()].links = std::move(s);
    if (world_->Take(&world_in_)) world_state_ = world_in_.back();
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

  uint64_t Send(idl::SimControl request) {
    request.client(kClient);
    request.request_id(++request_id_);
    control_->Write(request);
    return request_id_;
  }

  std::optional<Scene> Attach(std::chrono::milliseconds timeout, const std::function<bool()>& stop,
                              std::string* error) {
    const auto deadline = Clock::now() + timeout;
    if (!WaitFor([this] { return scene_info_.has_value() && control_->Matched() > 0 && reply_->Matched() > 0; },
                 deadline, stop)) {
      *error = "no legged scene from turf-sim (is it running a `kind: legged` scene on this domain and prefix?)";
      return std::nullopt;
    }
    idl::SimControl lockstep;
    lockstep.op(idl::OP_SET_TIME_MODE);
    lockstep.time_mode(idl::TIME_LOCKSTEP);
    const uint64_t id = Send(lockstep);
    if (!WaitFor([&] { return replies_.count(id) > 0; }, deadline, stop)) {
      *error = "turf-sim did not answer the switch to lockstep";
      return std::nullopt;
    }
    if (replies_[id].result() != idl::RESULT_OK) {
      *error = "turf-sim refused lockstep: " + replies_[id].reason();
      return std::nullopt;
    }
    frame_ = replies_[id].frame();
    Scene scene;
    scene.name = scene_info_->name();
    for (const idl::RobotDescription& r : scene_info_->robots()) scene.robots.push_back(r.robot());
    // Where every robot stands now: its links at the current frame.
    auto all_links = [&] {
      for (const std::string& r : scene.robots) {
        auto it = parts_.find(r);
        if (it == parts_.end() || !it->second.links || it->second.links->frame() != frame_) return false;
      }
      return step_s_ > 0;
    };
    if (!WaitFor(all_links, deadline, stop)) {
      *error = fmt::format("turf-sim did not publish every robot's links at frame {} ({} of {} robots seen, step {} s)",
                           frame_, parts_.size(), scene.robots.size(), step_s_);
      return std::nullopt;
    }
    for (const std::string& r : scene.robots) {
      const idl::LinkPose& torso = parts_[r].links->links().at(0);
      simspark::RobotMove park;
      park.robot = r;
      park.position = E3(torso.position());
      park.orientation = Eigen::Quaterniond(torso.orientation().w(), torso.orientation().x(), torso.orientation().y(),
                                            torso.orientation().z());
      scene.park.push_back(park);
    }
    robots_ = scene.robots;
    return scene;
  }

  std::optional<simspark::WorldSnapshot> Cycle(const simspark::WorldRequests& requests, uint32_t steps,
                                               std::chrono::milliseconds timeout, std::string* error,
                                               std::vector<std::string>* warnings) {
    std::vector<std::pair<uint64_t, std::string>> moves;
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
      moves.emplace_back(Send(move), "move " + m.robot);
    }
    if (requests.ball) {
      idl::SimControl ball;
      ball.op(idl::OP_TELEPORT_BALL);
      ball.ball().position(V3(requests.ball->position));
      ball.ball().velocity(V3(requests.ball->velocity));
      moves.emplace_back(Send(ball), "ball");
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
    const uint64_t id = Send(step);
    const auto deadline = Clock::now() + timeout;
    if (!WaitFor([&] { return replies_.count(id) > 0; }, deadline)) {
      *error = "turf-sim did not answer the step";
      return std::nullopt;
    }
    for (const auto& [move_id, what] : moves) {
      auto it = replies_.find(move_id);
      if (it != replies_.end() && it->second.result() != idl::RESULT_OK)
        warnings->push_back(what + ": " + it->second.reason());
    }
    const idl::SimControlReply reply = replies_[id];
    replies_.clear();
    if (reply.result() != idl::RESULT_OK) {
      *error = "turf-sim refused the step: " + reply.reason();
      return std::nullopt;
    }
    frame_ = reply.frame();
    auto complete = [&] {
      if (!world_state_ || world_state_->frame() != frame_) return false;
      for (const std::string& r : robots_) {
        auto it = parts_.find(r);
        if (it == parts_.end()) return false;
        const RobotParts& p = it->second;
        if (!p.joints || !p.imu || !p.force || !p.links || p.joints->frame() != frame_ || p.links->frame() != frame_ ||
            p.imu->sim_time_ns() != reply.sim_time_ns() || p.force->sim_time_ns() != reply.sim_time_ns())
          return false;
      }
      return true;
    };
    if (!WaitFor(complete, deadline)) {
      *error = "turf-sim did not publish the world after the step";
      return std::nullopt;
    }
    return Snapshot(reply.sim_time_ns());
  }

  simspark::WorldSnapshot Snapshot(int64_t time_ns) const {
    simspark::WorldSnapshot w;
    w.time = time_ns * 1e-9;
    w.ball = E3(world_state_->ball().position());
    w.ball_velocity = E3(world_state_->ball().velocity());
    for (const std::string& name : robots_) {
      const RobotParts& p = parts_.at(name);
      simspark::RobotSnapshot r;
      r.name = name;
      r.joint_names = p.joints->name();
      r.joint_positions = p.joints->position();
      r.gyro = A3(p.imu->angular_velocity());
      r.accelerometer = A3(p.imu->linear_acceleration());
      for (const idl::ForceReading& f : p.force->sensors())
        r.feet.push_back({f.name(), f.contact(), A3(f.point()), A3(f.force())});
      for (const idl::LinkPose& l : p.links->links()) {
        r.links.push_back(
            {l.name(), E3(l.position()),
             Eigen::Quaterniond(l.orientation().w(), l.orientation().x(), l.orientation().y(), l.orientation().z())});
      }
      w.robots.push_back(std::move(r));
    }
    return w;
  }

  double step_s() const { return step_s_; }
  uint64_t Overflowed() const {
    return reply_->Overflowed() + joints_->Overflowed() + imu_->Overflowed() + force_->Overflowed() +
           links_->Overflowed() + world_->Overflowed();
  }

 private:
  static constexpr const char* kClient = "turf-simspark-bridge";

  Wakeup wakeup_;
  dds::Participant participant_;
  std::unique_ptr<dds::Writer<idl::SimControlPubSubType>> control_;
  std::unique_ptr<dds::Reader<idl::SimControlReplyPubSubType>> reply_;
  std::unique_ptr<dds::Reader<idl::LeggedSceneInfoPubSubType>> scene_;
  std::unique_ptr<dds::Reader<idl::ClockPubSubType>> clock_;
  std::unique_ptr<dds::Reader<idl::JointStatePubSubType>> joints_;
  std::unique_ptr<dds::Reader<idl::ImuStatePubSubType>> imu_;
  std::unique_ptr<dds::Reader<idl::ForceStatePubSubType>> force_;
  std::unique_ptr<dds::Reader<idl::LinkStatePubSubType>> links_;
  std::unique_ptr<dds::Reader<idl::WorldStatePubSubType>> world_;

  std::vector<idl::SimControlReply> reply_in_;
  std::vector<idl::LeggedSceneInfo> scene_in_;
  std::vector<idl::Clock> clock_in_;
  std::vector<idl::JointState> joints_in_;
  std::vector<idl::ImuState> imu_in_;
  std::vector<idl::ForceState> force_in_;
  std::vector<idl::LinkState> links_in_;
  std::vector<idl::WorldState> world_in_;

  std::optional<idl::LeggedSceneInfo> scene_info_;
  std::optional<idl::WorldState> world_state_;
  std::map<std::string, RobotParts> parts_;
  std::map<uint64_t, idl::SimControlReply> replies_;
  std::vector<std::string> robots_;
  uint64_t request_id_ = 0;
  uint64_t frame_ = 0;
  double step_s_ = 0.0;
};

WorldLink::WorldLink(const dds::ParticipantOptions& options) : impl_(std::make_unique<Impl>(options)) {}
WorldLink::~WorldLink() = default;
std::string WorldLink::TopicName(dds::Topic topic) const { return impl_->TopicName(topic); }
std::optional<WorldLink::Scene> WorldLink::Attach(std::chrono::milliseconds timeout, const std::function<bool()>& stop,
                                                  std::string* error) {
  return impl_->Attach(timeout, stop, error);
}
std::optional<simspark::WorldSnapshot> WorldLink::Cycle(const simspark::WorldRequests& requests, uint32_t steps,
                                                        std::chrono::milliseconds timeout, std::string* error,
                                                        std::vector<std::string>* warnings) {
  return impl_->Cycle(requests, steps, timeout, error, warnings);
}
double WorldLink::step_s() const { return impl_->step_s(); }
uint64_t WorldLink::Overflowed() const { return impl_->Overflowed(); }

}  // namespace turf
