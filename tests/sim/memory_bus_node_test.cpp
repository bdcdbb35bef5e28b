// turf-sim's node on a dds::MemoryBus, driven by dds::ControlClient on the same bus: no DDS domain, no
// discovery, no sleeps. The node runs in lockstep on a thread with a stop flag; the test waits for conditions
// with deadlines (the client's blocking Call, or an Inbox woken by its reader's on_data).
#include <gtest/gtest.h>
#include <turf/idl/Clock.h>
#include <turf/idl/Joints.h>
#include <turf/idl/SimControl.h>
#include <turf/idl/SslRobot.h>
#include <turf/idl/WorldState.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "dds/control_client.h"
#include "dds/memory_bus.h"
#include "loader/legged_scene_yaml.h"
#include "participants/sim/control_loop.h"
#include "participants/sim/sim_node.h"
#include "tests/core/test_scenes.h"
#include "tests/sim/sim_harness.h"
#include "tests/support/wake_wait.h"

namespace turf {
namespace {

using namespace std::chrono_literals;
using SteadyClock = std::chrono::steady_clock;

constexpr auto kDeadline = 20s;  // generous: a deadline, not a pace

// Every sample of one topic, collected as it arrives; a test waits for a condition on them with a deadline.
template <class PubSub>
class Inbox {
 public:
  using Sample = dds::SampleOf<PubSub>;
  Inbox(dds::Bus& bus, const dds::TopicDef<PubSub>& topic) : reader_(bus.MakeReader(topic, [this] { wake_.Wake(); })) {}

  // Waits until `done(every sample so far)` holds; false if it did not by the deadline.
  bool WaitFor(const std::function<bool(const std::vector<Sample>&)>& done) {
    return wake_.Until(SteadyClock::now() + kDeadline, [&] {
      std::vector<Sample> got;
      if (reader_->Take(&got)) samples_.insert(samples_.end(), got.begin(), got.end());
      return done(samples_);
    });
  }
  // The samples taken by the last WaitFor.
  const std::vector<Sample>& samples() const { return samples_; }

 private:
  test::WakeWait wake_;
  std::vector<Sample> samples_;
  std::unique_ptr<dds::Reader<PubSub>> reader_;
};

TEST(MemoryBusNode, ServerIsMatchedAtOnceAndStepsReplyAtTheFrameReached) {
  dds::MemoryBus bus("mem");
  Inbox<idl::WorldStatePubSubType> states(bus, dds::Topic::kWorldState);
  Inbox<idl::ClockPubSubType> clocks(bus, dds::Topic::kClock);
  test::SimUnderTest sim(test::OneRobot(), bus, TimeMode::kLockstep);
  dds::ControlClient client(bus, "test");
  EXPECT_TRUE(client.ServerMatched());  // no discovery to wait for

  dds::ControlOutcome outcome = client.Call(test::StepRequest(5), kDeadline);
  ASSERT_TRUE(outcome.ok()) << outcome.Describe();
  EXPECT_EQ(outcome.reply->frame(), 5u);
  EXPECT_EQ(outcome.reply->op(), idl::OP_STEP);
  // The state of the frame a STEP finishes is written before its reply.
  ASSERT_TRUE(states.WaitFor([](const auto& s) { return !s.empty() && s.back().frame() == 5u; }));
  ASSERT_TRUE(clocks.WaitFor([](const auto& c) { return !c.empty() && c.back().frame() == 5u; }));
  EXPECT_EQ(clocks.samples().back().mode(), idl::TIME_LOCKSTEP);
  EXPECT_EQ(clocks.samples().back().sim_time_ns(), outcome.reply->sim_time_ns());

  outcome = client.Call(test::StepRequest(3), kDeadline);
  ASSERT_TRUE(outcome.ok()) << outcome.Describe();
  EXPECT_EQ(outcome.reply->frame(), 8u);
  EXPECT_EQ(sim.node().Stats().frame, 8u);
  // Lockstep: nothing steps between requests.
  ASSERT_TRUE(states.WaitFor([](const auto& s) { return s.back().frame() == 8u; }));
  for (const idl::WorldState& s : states.samples()) EXPECT_LE(s.frame(), 8u);
}

// An in-process front-end's STEP in lockstep runs in its own thread, inside the write: the reply is there when
// Send returns, with no hop to the loop's thread (which may be in one of its idle passes: the write waits for it).
TEST(MemoryBusNode, ALockstepStepOnTheMemoryBusIsServedInTheWritersThread) {
  dds::MemoryBus bus("mem");
  test::SimUnderTest sim(test::OneRobot(), bus, TimeMode::kLockstep);
  dds::ControlClient client(bus, "test");
  ASSERT_TRUE(client.Call(test::StepRequest(1), kDeadline).ok());  // the loop runs

  int served_in_send = 0;
  uint64_t frame = 1;
  for (int i = 0; i < 50; ++i) {
    const uint64_t id = client.Send(test::StepRequest(2), kDeadline);
    std::optional<dds::ControlOutcome> outcome = client.TryTake(id);
    if (outcome) {
      ++served_in_send;
    } else {
      outcome = client.Wait(id);
    }
    ASSERT_TRUE(outcome->ok()) << outcome->Describe();
    frame += 2;
    EXPECT_EQ(outcome->reply->frame(), frame);
  }
  EXPECT_EQ(served_in_send, 50);
  EXPECT_EQ(sim.node().Stats().frame, frame);
}

TEST(MemoryBusNode, ATeleportMovesTheBallOnWorldState) {
  dds::MemoryBus bus("mem");
  Inbox<idl::WorldStatePubSubType> states(bus, dds::Topic::kWorldState);
  test::SimUnderTest sim(test::OneRobot(), bus, TimeMode::kLockstep);
  dds::ControlClient client(bus, "test");

  idl::SimControl teleport = test::Op(idl::OP_TELEPORT_BALL);
  teleport.ball().position().x(1.0);
  teleport.ball().position().y(-2.0);
  const dds::ControlOutcome outcome = client.Call(teleport, kDeadline);
  ASSERT_TRUE(outcome.ok()) << outcome.Describe();
  EXPECT_EQ(outcome.reply->frame(), 0u);  // lockstep: no step taken
  ASSERT_TRUE(states.WaitFor([](const auto& s) {
    return !s.empty() && std::abs(s.back().ball().position().x() - 1.0) < 1e-6 &&
           std::abs(s.back().ball().position().y() + 2.0) < 1e-6;
  }));
  EXPECT_EQ(states.samples().back().frame(), 0u);
}

TEST(MemoryBusNode, RefusalsReturnTheirControlError) {
  dds::MemoryBus bus("mem");
  test::SimUnderTest sim(test::OneRobot(), bus, TimeMode::kLockstep);
  dds::ControlClient client(bus, "test");

  idl::SimControl teleport = test::Op(idl::OP_TELEPORT_BALL);
  teleport.ball().position().x(NAN);
  dds::ControlOutcome outcome = client.Call(teleport, kDeadline);
  EXPECT_EQ(outcome.error, dds::ControlCallError::kRefused) << outcome.Describe();
  EXPECT_EQ(outcome.code(), idl::CONTROL_NOT_FINITE);
  EXPECT_EQ(outcome.reply->result(), idl::RESULT_REJECTED);

  outcome = client.Call(test::StepRequest(0), kDeadline);
  EXPECT_EQ(outcome.error, dds::ControlCallError::kRefused) << outcome.Describe();
  EXPECT_EQ(outcome.code(), idl::CONTROL_OUT_OF_RANGE);
  EXPECT_EQ(sim.node().Rejected("control"), 2u);

  // A command with a NaN speed on the blue topic: refused by the node when it takes its inputs.
  auto blue = bus.MakeWriter(dds::Topic::kSslCommandBlue);
  EXPECT_EQ(blue->Matched(), 1);
  idl::SslRobotCommand command;
  command.team(idl::TEAM_BLUE);
  command.id(0);
  command.move(idl::MOVE_LOCAL_VELOCITY);
  command.velocity().x(NAN);
  blue->Write(command);
  outcome = client.Call(test::StepRequest(1), kDeadline);  // commands are taken before control requests
  ASSERT_TRUE(outcome.ok()) << outcome.Describe();
  EXPECT_EQ(sim.node().Rejected("command.not_finite"), 1u);
}

// A request whose client name is oversized gets no reply (its name would be echoed) and is counted; a refused
// request publishes no world state (a flood of them was a flood of states); an accepted one does.
TEST(MemoryBusNode, OversizedClientNamesAreNotAnsweredAndRefusalsPublishNoState) {
  dds::MemoryBus bus("mem");
  Inbox<idl::WorldStatePubSubType> states(bus, dds::Topic::kWorldState);
  Inbox<idl::SimControlReplyPubSubType> replies(bus, dds::Topic::kControlReply);
  test::SimUnderTest sim(test::OneRobot(), bus, TimeMode::kLockstep);
  dds::ControlClient client(bus, "test");
  auto raw = bus.MakeWriter(dds::Topic::kControl);
  idl::SimControl pause = test::Op(idl::OP_PAUSE);
  pause.client(std::string(ControlLoop::kMaxClientName + 1, 'c'));
  pause.request_id(1);
  raw->Write(pause);
  // An accepted request's state is written before its reply: the count after it is settled.
  ASSERT_TRUE(client.Call(test::Op(idl::OP_RESUME), kDeadline).ok());
  ASSERT_TRUE(states.WaitFor([](const auto& s) { return !s.empty(); }));
  const size_t before = states.samples().size();
  for (int i = 0; i < 20; ++i)
    EXPECT_EQ(client.Call(test::Op(idl::OP_SEEK), kDeadline).code(), idl::CONTROL_NOT_ALLOWED);
  ASSERT_TRUE(client.Call(test::Op(idl::OP_PAUSE), kDeadline).ok());
  ASSERT_TRUE(states.WaitFor([&](const auto& s) { return s.size() > before; }));
  EXPECT_EQ(states.samples().size(), before + 1) << "a refused request published a world state";
  ASSERT_TRUE(replies.WaitFor([](const auto& r) { return r.size() >= 22; }));
  for (const idl::SimControlReply& r : replies.samples()) EXPECT_EQ(r.client(), "test");
  EXPECT_EQ(sim.node().Rejected("control.too_large"), 1u);
}

LeggedScene SimSparkScene() {
  LeggedSceneLoadResult r = LoadLeggedSceneFile(TURF_SOURCE_DIR "/configs/scenes/simspark_3d.yaml");
  if (!r.scene) throw std::runtime_error(r.errors.front());
  r.scene->realism = {};
  return std::move(*r.scene);
}

TEST(MemoryBusNode, ALeggedSceneStepsAndPublishesJointStates) {
  dds::MemoryBus bus("mem");
  Inbox<idl::JointStatePubSubType> joints(bus, dds::Topic::kRobotJointState);
  test::SimUnderTest sim(SimSparkScene(), bus, TimeMode::kLockstep);
  dds::ControlClient client(bus, "test");

  const dds::ControlOutcome outcome = client.Call(test::StepRequest(50), kDeadline);  // 0.1 s
  ASSERT_TRUE(outcome.ok()) << outcome.Describe();
  EXPECT_EQ(outcome.reply->frame(), 50u);
  const int64_t reached_ns = outcome.reply->sim_time_ns();
  ASSERT_TRUE(joints.WaitFor([&](const auto& all) {
    std::set<std::string> robots;
    for (const idl::JointState& j : all)
      if (j.sim_time_ns() >= reached_ns - 20'000'000) robots.insert(j.robot());
    return robots.size() == 2;
  }));
  std::map<std::string, int64_t> last_ns;
  for (const idl::JointState& j : joints.samples()) {
    EXPECT_EQ(j.name().size(), 22u) << j.robot();
    EXPECT_EQ(j.position().size(), 22u) << j.robot();
    EXPECT_LE(j.sim_time_ns(), reached_ns);
    EXPECT_GE(j.sim_time_ns(), last_ns[j.robot()]) << "in order per robot";
    last_ns[j.robot()] = j.sim_time_ns();
  }

  // One entry per joint at most, on the topic and in a STEP: more is too_many and changes nothing.
  idl::JointCommand many;
  many.robot(joints.samples().back().robot());
  for (int i = 0; i < 1000; ++i) {
    idl::JointTarget t;
    t.name("hj1");
    t.mode(idl::JOINT_VELOCITY);
    many.joints().push_back(t);
  }
  idl::SimControl step = test::StepRequest(1);
  step.joint_commands().push_back(many);
  const dds::ControlOutcome refused = client.Call(step, kDeadline);
  EXPECT_EQ(refused.code(), idl::CONTROL_TOO_MANY) << refused.Describe();
  auto writer = bus.MakeWriter(dds::Topic::kRobotJointCommand);
  writer->Write(many);
  ASSERT_TRUE(client.Call(test::StepRequest(1), kDeadline).ok());  // commands are taken before the step
  EXPECT_EQ(sim.node().Rejected("joint_command.too_many"), 1u);

  // The scene description is latched: a reader made now still gets it.
  Inbox<idl::LeggedSceneInfoPubSubType> scene(bus, dds::Topic::kLeggedScene);
  ASSERT_TRUE(scene.WaitFor([](const auto& s) { return !s.empty(); }));
  EXPECT_EQ(scene.samples().size(), 1u);
  EXPECT_EQ(scene.samples()[0].robots().size(), 2u);
}

// The generic joint-command topic carries the PD motor mode (JOINT_PD: q, dq, kp, kd, tau); a sample with a
// non-finite dq or a tau beyond the joint's effort limit is refused whole and counted, and moves nothing.
TEST(MemoryBusNode, JointPdCommandsOnTheTopicDriveABoosterT1) {
  LeggedSceneLoadResult r = LoadLeggedSceneFile(TURF_SOURCE_DIR "/configs/scenes/t1_stand.yaml");
  ASSERT_TRUE(r.scene) << r.errors.front();
  r.scene->realism = {};
  dds::MemoryBus bus("mem");
  Inbox<idl::JointStatePubSubType> joints(bus, dds::Topic::kRobotJointState);
  test::SimUnderTest sim(std::move(*r.scene), bus, TimeMode::kLockstep);
  dds::ControlClient client(bus, "test");
  auto writer = bus.MakeWriter(dds::Topic::kRobotJointCommand);
  auto target = [](double q, double dq, double tau) {
    idl::JointTarget t;
    t.name("AAHead_yaw");
    t.mode(idl::JOINT_PD);
    t.value(q);
    t.kp(5);
    t.kd(0.1);
    t.dq(dq);
    t.tau(tau);
    return t;
  };
  idl::JointCommand bad;
  bad.robot("t1");
  bad.joints().push_back(target(-0.5, NAN, 0));
  writer->Write(bad);
  bad.joints()[0] = target(-0.5, 0, 2000);  // beyond the PD guard (kMaxPdTau); a tau above the 7 N m limit is a command
  writer->Write(bad);
  idl::JointCommand good;
  good.robot("t1");
  good.joints().push_back(target(0.5, 0, 0.2));
  writer->Write(good);
  const dds::ControlOutcome outcome = client.Call(test::StepRequest(400), kDeadline);  // 2 s
  ASSERT_TRUE(outcome.ok()) << outcome.Describe();
  EXPECT_EQ(sim.node().Rejected("joint_command.not_finite"), 1u);
  EXPECT_EQ(sim.node().Rejected("joint_command.out_of_range"), 1u);
  const int64_t reached_ns = outcome.reply->sim_time_ns();
  ASSERT_TRUE(joints.WaitFor([&](const auto& all) { return !all.empty() && all.back().sim_time_ns() == reached_ns; }));
  const idl::JointState& last = joints.samples().back();
  ASSERT_EQ(last.name().size(), 23u);
  EXPECT_EQ(last.name()[0], "AAHead_yaw");
  // kp 5 with 0.2 N m feed-forward (and the joint's 0.1 N m friction): close to 0.5 + 0.2 / 5 rad.
  EXPECT_NEAR(last.position()[0], 0.54, 0.03);
}

}  // namespace
}  // namespace turf
