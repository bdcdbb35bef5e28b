// In-process harness for turf-sim's node: the node on a thread and a client, over a TestTransport: a private DDS
// domain and topic prefix (each a participant of its own) or one dds::MemoryBus they share (no DDS domain, no
// discovery: what most node tests use; the DDS adapter keeps a few tests of its own in each file).
#pragma once

#include <gtest/gtest.h>
#include <turf/idl/ClockPubSubTypes.h>
#include <turf/idl/SensorStatsPubSubTypes.h>
#include <turf/idl/SimControlPubSubTypes.h>
#include <turf/idl/SslRobotPubSubTypes.h>
#include <turf/idl/SslVisionPubSubTypes.h>
#include <turf/idl/WorldStatePubSubTypes.h>
#include <unistd.h>
#include "tests/test_domain.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <thread>

#include "dds/control_client.h"
#include "dds/memory_bus.h"
#include "dds/participant.h"
#include "participants/sim/sim_node.h"
#include "tests/core/test_scenes.h"

namespace turf::test {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

// A domain from the process id (salted: test programs that run side by side
// stay apart) and a prefix of its own for every call.
inline dds::ParticipantOptions UniqueDds(const char* name, const char* prefix = "test", int domain_salt = 0) {
  static int g_test_counter = 0;
  ++g_test_counter;
  dds::ParticipantOptions o;
  o.domain = TestDomain(domain_salt);
  o.prefix = prefix + std::to_string(getpid()) + "_" + std::to_string(g_test_counter);
  o.name = name;
  o.qos_file = TURF_SOURCE_DIR "/configs/qos/turf_qos.xml";
  return o;
}

enum class Transport { kMemory, kDds };

// Test names: .../memory, .../dds.
inline std::string TransportName(const ::testing::TestParamInfo<Transport>& info) {
  return info.param == Transport::kMemory ? "memory" : "dds";
}

// Where a test's node and its clients meet: a private DDS domain and prefix, or one MemoryBus. Cheap to copy (the
// copies share the bus).
class TestTransport {
 public:
  // `name`, `prefix` and `salt` as UniqueDds takes them (the DDS domain and prefix; the bus's prefix).
  explicit TestTransport(Transport kind, const char* name = "sim", const char* prefix = "test", int salt = 0)
      : dds_(UniqueDds(name, prefix, salt)) {
    if (kind == Transport::kMemory) bus_ = std::make_shared<dds::MemoryBus>(dds_.prefix);
  }
  bool memory() const { return bus_ != nullptr; }
  const dds::ParticipantOptions& dds() const { return dds_; }
  dds::MemoryBus& bus() const { return *bus_; }
  // A client's bus: the shared MemoryBus, or a DDS participant of its own named `name`, made in `own`.
  dds::Bus& ClientBus(std::unique_ptr<dds::Participant>* own, const char* name) const {
    if (bus_) return *bus_;
    dds::ParticipantOptions o = dds_;
    o.name = name;
    *own = std::make_unique<dds::Participant>(o);
    return **own;
  }

 private:
  dds::ParticipantOptions dds_;
  std::shared_ptr<dds::MemoryBus> bus_;
};

// turf-sim's node on a thread of its own, for an SSL Scene or a LeggedScene.
class SimUnderTest {
 public:
  template <typename SceneKind>
  SimUnderTest(SceneKind scene, const dds::ParticipantOptions& dds, TimeMode mode, double speed = 1.0) {
    Start(std::make_unique<SimNode>(std::move(scene), Options(dds, mode, speed)));
  }
  // On a bus the test made (a dds::MemoryBus: no DDS domain).
  template <typename SceneKind>
  SimUnderTest(SceneKind scene, dds::Bus& bus, TimeMode mode, double speed = 1.0) {
    Start(std::make_unique<SimNode>(std::move(scene), Options({}, mode, speed), bus));
  }
  template <typename SceneKind>
  SimUnderTest(SceneKind scene, const TestTransport& net, TimeMode mode, double speed = 1.0) {
    if (net.memory()) {
      Start(std::make_unique<SimNode>(std::move(scene), Options({}, mode, speed), net.bus()));
    } else {
      Start(std::make_unique<SimNode>(std::move(scene), Options(net.dds(), mode, speed)));
    }
  }
  ~SimUnderTest() {
    stop_ = true;
    thread_.join();
  }
  SimNode& node() { return *node_; }

 private:
  static SimNodeOptions Options(const dds::ParticipantOptions& dds, TimeMode mode, double speed) {
    SimNodeOptions o;
    o.domain = dds.domain;
    o.prefix = dds.prefix.empty() ? o.prefix : dds.prefix;
    o.qos_file = dds.qos_file.empty() ? o.qos_file : dds.qos_file;
    o.mode = mode;
    o.speed = speed;
    return o;
  }
  void Start(std::unique_ptr<SimNode> node) {
    node_ = std::move(node);
    thread_ = std::thread([this] { node_->Run([this] { return stop_.load(); }); });
  }

  std::unique_ptr<SimNode> node_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

// What a team stack or a test harness would be: a plain participant of turf's topics.
class Client {
 public:
  explicit Client(const dds::ParticipantOptions& o) : Client(Named(o), nullptr) {}
  explicit Client(const TestTransport& net) : Client(net.dds(), &net) {}

 private:
  Client(const dds::ParticipantOptions& o, const TestTransport* net)
      : participant_(net != nullptr ? net->ClientBus(&own_, "client") : Own(o)),
        blue_(participant_.MakeWriter<idl::SslRobotCommandPubSubType>(dds::Topic::kSslCommandBlue)),
        yellow_(participant_.MakeWriter<idl::SslRobotCommandPubSubType>(dds::Topic::kSslCommandYellow)),
        control_(participant_, "test"),
        state_(participant_.MakeReader<idl::WorldStatePubSubType>(dds::Topic::kWorldState)),
        clock_(participant_.MakeReader<idl::ClockPubSubType>(dds::Topic::kClock)),
        camera_(participant_.MakeReader<idl::CameraFramePubSubType>(dds::Topic::kSslCamera)),
        field_(participant_.MakeReader<idl::SslFieldPubSubType>(dds::Topic::kSslField)),
        stats_(participant_.MakeReader<idl::SensorStatsPubSubType>(dds::Topic::kStats)),
        all_frames_(participant_.MakeReader<idl::CameraFramePubSubType>(dds::Topic::kSslCamera)) {}

 public:
  // Polls until `done` holds, or the timeout.
  bool WaitFor(const std::function<bool()>& done, std::chrono::milliseconds timeout = 5s) {
    const auto end = Clock::now() + timeout;
    while (Clock::now() < end) {
      Poll();
      if (done()) return true;
      std::this_thread::sleep_for(2ms);
    }
    return false;
  }
  // Polls until `done` holds for the newest world state, or the timeout.
  bool WaitState(const std::function<bool(const idl::WorldState&)>& done, std::chrono::milliseconds timeout = 5s) {
    return WaitFor([&] { return has_state_ && done(state_now_); }, timeout);
  }
  // Polls until `done` holds for the newest clock sample, or the timeout.
  bool WaitClock(const std::function<bool(const idl::Clock&)>& done, std::chrono::milliseconds timeout = 5s) {
    return WaitFor([&] { return has_clock_ && done(clock_now_); }, timeout);
  }
  static constexpr bool kNoState = false;
  // Until turf-sim is matched and (unless `state` is kNoState) a world state has arrived. Discovery is slower on a
  // busy machine: a generous (but bounded) wait.
  bool WaitMatched(bool state = true, std::chrono::milliseconds timeout = 10s) {
    const auto end = Clock::now() + timeout;
    while (Clock::now() < end) {
      if (blue_->Matched() > 0 && yellow_->Matched() > 0 && control_.ServerMatched() && state_->Matched() > 0 &&
          all_frames_->Matched() > 0)
        return !state || WaitState([](const idl::WorldState&) { return true; });
      std::this_thread::sleep_for(5ms);
    }
    return false;
  }
  // Sends a control request through dds::ControlClient and waits for its
  // reply (OK or refused); nullopt if none came by the timeout.
  std::optional<idl::SimControlReply> Control(idl::SimControl req, std::chrono::milliseconds timeout = 5s) {
    return control_.Call(std::move(req), timeout).reply;
  }
  void Command(const idl::SslRobotCommand& c) { (c.team() == idl::TEAM_BLUE ? blue_ : yellow_)->Write(c); }
  void CommandOnTopic(Team topic, const idl::SslRobotCommand& c) { (topic == Team::kBlue ? blue_ : yellow_)->Write(c); }

  void Poll() {
    if (state_->Take(&states_)) {
      state_now_ = states_.back();
      has_state_ = true;
    }
    std::vector<idl::Clock> clocks;
    if (clock_->Take(&clocks)) {
      clock_now_ = clocks.back();
      has_clock_ = true;
    }
    std::vector<idl::CameraFrame> frames;
    if (camera_->Take(&frames))
      for (auto& f : frames) cameras_[f.camera_id()] = f;
    std::vector<idl::SslField> fields;
    if (field_->Take(&fields)) field_now_ = fields.back();
    std::vector<idl::SensorStats> stats;
    if (stats_->Take(&stats)) stats_now_ = stats.back();
    std::vector<idl::CameraFrame> all;
    if (all_frames_->Take(&all)) frame_log_.insert(frame_log_.end(), all.begin(), all.end());
  }
  const std::optional<idl::SensorStats>& stats() const { return stats_now_; }
  int CameraDeadlinesMissed() const { return all_frames_->DeadlinesMissed(); }
  // Every camera frame received, in arrival order.
  const std::vector<idl::CameraFrame>& frame_log() const { return frame_log_; }
  const idl::WorldState& state() const { return state_now_; }
  const idl::Clock& clock() const { return clock_now_; }
  std::map<uint32_t, idl::CameraFrame>& cameras() { return cameras_; }
  const std::optional<idl::SslField>& field() const { return field_now_; }

 private:
  static dds::ParticipantOptions Named(dds::ParticipantOptions o) {
    o.name = "client";
    return o;
  }
  dds::Bus& Own(const dds::ParticipantOptions& o) {
    own_ = std::make_unique<dds::Participant>(o);
    return *own_;
  }
  std::unique_ptr<dds::Participant> own_;  // on DDS: the client's participant
  dds::Bus& participant_;
  std::unique_ptr<dds::Writer<idl::SslRobotCommandPubSubType>> blue_, yellow_;
  dds::ControlClient control_;
  std::unique_ptr<dds::Reader<idl::WorldStatePubSubType>> state_;
  std::unique_ptr<dds::Reader<idl::ClockPubSubType>> clock_;
  std::unique_ptr<dds::Reader<idl::CameraFramePubSubType>> camera_;
  std::unique_ptr<dds::Reader<idl::SslFieldPubSubType>> field_;
  std::unique_ptr<dds::Reader<idl::SensorStatsPubSubType>> stats_;
  std::unique_ptr<dds::Reader<idl::CameraFramePubSubType>> all_frames_;
  std::optional<idl::SensorStats> stats_now_;
  std::vector<idl::CameraFrame> frame_log_;
  std::vector<idl::WorldState> states_;
  idl::WorldState state_now_;
  bool has_state_ = false;
  idl::Clock clock_now_;
  bool has_clock_ = false;
  std::map<uint32_t, idl::CameraFrame> cameras_;
  std::optional<idl::SslField> field_now_;
};

inline idl::SslRobotCommand LocalVelocity(idl::Team team, int id, double forward, double left, double angular) {
  idl::SslRobotCommand c;
  c.team(team);
  c.id(static_cast<uint8_t>(id));
  c.move(idl::MOVE_LOCAL_VELOCITY);
  idl::Vec3 v;
  v.x(forward);
  v.y(left);
  v.z(angular);
  c.velocity(v);
  return c;
}

inline const idl::RobotState* FindRobot(const idl::WorldState& s, idl::Team team, int id) {
  for (const auto& r : s.robots())
    if (r.team() == team && r.id() == id) return &r;
  return nullptr;
}

// A reply that came and says OK; otherwise a failure that says why
// (ASSERT_TRUE(Ok(client.Control(...))) never dereferences a missing reply).
inline ::testing::AssertionResult Ok(const std::optional<idl::SimControlReply>& reply) {
  if (!reply) return ::testing::AssertionFailure() << "no reply from turf-sim";
  if (reply->result() != idl::RESULT_OK) return ::testing::AssertionFailure() << "refused: " << reply->reason();
  return ::testing::AssertionSuccess();
}

inline idl::SimControl Op(idl::ControlOp op) {
  idl::SimControl c;
  c.op(op);
  return c;
}

inline idl::SimControl StepRequest(uint32_t count) {
  idl::SimControl c = Op(idl::OP_STEP);
  c.step_count(count);
  return c;
}

}  // namespace turf::test
