// turf-sim's legged node in process: joint state / IMU / force out, joint commands in, refusals counted,
// pause/step/reset and lockstep. On a MemoryBus; the sensor topics also over DDS.
#include <gtest/gtest.h>
#include <turf/idl/ClockPubSubTypes.h>
#include <turf/idl/JointsPubSubTypes.h>
#include <turf/idl/SensorStatsPubSubTypes.h>
#include <turf/idl/SimControlPubSubTypes.h>
#include <turf/idl/WorldStatePubSubTypes.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <thread>

#include "dds/control_client.h"
#include "dds/participant.h"
#include "idl/values.h"
#include "loader/legged_scene_yaml.h"
#include "loader/realism_yaml.h"
#include "participants/sim/sim_node.h"
#include "tests/sim/sim_harness.h"
#include "tests/support/newest.h"

namespace turf {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

using test::TestTransport;
using test::Transport;

TestTransport Net(Transport kind, const char* name = "sim") { return TestTransport(kind, name, "legged", 7); }

LeggedScene SimSparkScene(const SensorRealism& realism = {}) {
  LeggedSceneLoadResult r = LoadLeggedSceneFile(TURF_SOURCE_DIR "/configs/scenes/simspark_3d.yaml");
  if (!r.scene) throw std::runtime_error(r.errors.front());
  r.scene->realism = realism;
  return std::move(*r.scene);
}

// turf-sim on the SimSpark scene.
class NodeUnderTest : public test::SimUnderTest {
 public:
  NodeUnderTest(const TestTransport& net, TimeMode mode, const SensorRealism& realism = {})
      : SimUnderTest(SimSparkScene(realism), net, mode) {}
};

class Client {
 public:
  explicit Client(const TestTransport& net)
      : participant_(net.ClientBus(&own_, "client")),
        command_(participant_.MakeWriter(dds::Topic::kRobotJointCommand)),
        control_(participant_, "test") {}

  bool WaitMatched() {
    const auto end = Clock::now() + 10s;  // discovery is slower on a busy machine
    while (Clock::now() < end) {
      Poll();
      if (command_->Matched() > 0 && control_.ServerMatched() && joints.count("nao_1") && imu_now_.count("nao_1") &&
          force_now_.count("nao_1"))
        return true;
      std::this_thread::sleep_for(5ms);
    }
    return false;
  }
  // Commands and control matched, the frame-0 IMU sample in (for links that
  // delay joint states past the start).
  bool WaitControlMatched() {
    return WaitFor([&] { return command_->Matched() > 0 && control_.ServerMatched() && imu_now_.count("nao_1"); });
  }
  void Poll() { test::PollAll(joints, imu_now_, force_now_, links, world, scene); }
  // Polls until `done` holds, or 5 s.
  bool WaitFor(const std::function<bool()>& done) {
    const auto end = Clock::now() + 5s;
    while (Clock::now() < end) {
      Poll();
      if (done()) return true;
      std::this_thread::sleep_for(2ms);
    }
    return false;
  }
  std::optional<idl::SimControlReply> Control(idl::ControlOp op, uint32_t steps = 0) {
    idl::SimControl req;
    req.op(op);
    req.step_count(steps);
    return Control(req);
  }
  // Through dds::ControlClient: the reply (OK or refused), or nullopt if none came in 5 s.
  std::optional<idl::SimControlReply> Control(idl::SimControl req) {
    if (req.op() == idl::OP_SET_TIME_MODE) req.time_mode(idl::TIME_LOCKSTEP);
    return control_.Call(std::move(req), 5s).reply;
  }
  void Command(const std::string& robot, const std::string& joint, idl::JointMode mode, double value) {
    idl::JointCommand c;
    c.robot(robot);
    idl::JointTarget t;
    t.name(joint);
    t.mode(mode);
    t.value(value);
    t.kp(-1);
    t.kd(-1);
    c.joints().push_back(t);
    command_->Write(c);
  }
  double Angle(const std::string& robot, const std::string& joint) {
    const idl::JointState& s = joints.at(robot);
    for (size_t i = 0; i < s.name().size(); ++i)
      if (s.name()[i] == joint) return s.position()[i];
    return NAN;
  }

 private:
  std::unique_ptr<dds::Participant> own_;  // on DDS: the client's participant
  dds::Bus& participant_;
  std::unique_ptr<dds::Writer<idl::JointCommandPubSubType>> command_;
  dds::ControlClient control_;

 public:
  // The newest sample of each topic (of each robot), as of the last Poll.
  test::NewestByRobot<idl::JointStatePubSubType> joints{participant_, dds::Topic::kRobotJointState};
  test::NewestByRobot<idl::ImuStatePubSubType> imu_now_{participant_, dds::Topic::kRobotImu};
  test::NewestByRobot<idl::ForceStatePubSubType> force_now_{participant_, dds::Topic::kRobotForce};
  test::NewestByRobot<idl::LinkStatePubSubType> links{participant_, dds::Topic::kRobotLinks};
  test::Newest<idl::WorldStatePubSubType> world{participant_, dds::Topic::kWorldState};
  test::Newest<idl::LeggedSceneInfoPubSubType> scene{participant_, dds::Topic::kLeggedScene};
};

// turf-sim on the SimSpark scene and a client of it, on the test's transport (made by Start: the client first,
// so that its readers take the node's first samples on a MemoryBus too; the client goes first at the end).
class LeggedNode : public ::testing::TestWithParam<Transport> {
 protected:
  // True once the client has matched turf-sim (see Client::WaitMatched).
  bool Start(TimeMode mode) {
    client.emplace(net);
    sim.emplace(net, mode);
    return client->WaitMatched();
  }
  const TestTransport net = Net(GetParam());
  std::optional<NodeUnderTest> sim;
  std::optional<Client> client;
};
INSTANTIATE_TEST_SUITE_P(On, LeggedNode, ::testing::Values(Transport::kMemory), test::TransportName);

// The same, also over DDS.
class LeggedNodeAnyTransport : public LeggedNode {};
INSTANTIATE_TEST_SUITE_P(On, LeggedNodeAnyTransport, ::testing::Values(Transport::kMemory, Transport::kDds),
                         test::TransportName);

TEST_P(LeggedNodeAnyTransport, PublishesEveryRobotsJointsImuAndForces) {
  ASSERT_TRUE(Start(TimeMode::kFreeRunning));
  ASSERT_TRUE(client->WaitFor([&] {
    return client->joints.count("nao_2") && client->joints["nao_1"].sim_time_ns() > 500'000'000 &&
           client->force_now_.count("nao_1") && client->force_now_["nao_1"].sensors().size() == 2 &&
           client->force_now_["nao_1"].sensors()[0].values()[0] > 10.0;
  }));
  const idl::JointState& j = client->joints["nao_1"];
  EXPECT_EQ(j.name().size(), 22u);
  EXPECT_EQ(j.position().size(), 22u);
  EXPECT_EQ(j.id(), 1);
  const idl::ImuState& imu = client->imu_now_["nao_1"];
  EXPECT_TRUE(imu.valid());
  EXPECT_NEAR(imu.linear_acceleration().z(), 9.81, 0.5);
  EXPECT_NEAR(imu.base_position().x(), -14.2, 0.05);
  const idl::ForceReading& rf = client->force_now_["nao_1"].sensors()[0];
  EXPECT_EQ(rf.name(), "rf");
  EXPECT_TRUE(rf.contact());
  EXPECT_NEAR(rf.force().z(), 4.6071 * 9.81 / 2, 5.0);
  EXPECT_NEAR(rf.point().z(), -0.01, 0.003);
}

TEST_P(LeggedNode, JointCommandMovesTheJointAndBadOnesAreCounted) {
  ASSERT_TRUE(Start(TimeMode::kFreeRunning));
  client->Command("nao_2", "hj1", idl::JOINT_POSITION, 0.8);
  ASSERT_TRUE(client->WaitFor([&] { return std::abs(client->Angle("nao_2", "hj1") - 0.8) < 0.02; }));
  EXPECT_NEAR(client->Angle("nao_1", "hj1"), 0.0, 0.01);  // the other robot is untouched
  client->Command("nao_9", "hj1", idl::JOINT_VELOCITY, 1.0);
  client->Command("nao_1", "he1", idl::JOINT_VELOCITY, 1.0);
  client->Command("nao_1", "hj1", idl::JOINT_VELOCITY, NAN);
  client->Command("nao_1", "hj1", idl::JOINT_VELOCITY, 7.0);
  ASSERT_TRUE(client->WaitFor([&] { return sim->node().Stats().rejected >= 4; }));
  for (const char* kind : {"joint_command.unknown_robot", "joint_command.unknown_joint", "joint_command.not_finite",
                           "joint_command.out_of_range"})
    EXPECT_EQ(sim->node().Rejected(kind), 1u) << kind;
}

TEST_P(LeggedNode, LockstepStepsExactlyAndResetRestarts) {
  ASSERT_TRUE(Start(TimeMode::kLockstep));
  EXPECT_EQ(client->joints["nao_1"].frame(), 0u);
  client->Command("nao_1", "hj1", idl::JOINT_VELOCITY, 1.0);
  // The command is taken before the step request: a refused one written after
  // it on the same writer is counted only once both have been taken.
  client->Command("nao_1", "no_such_joint", idl::JOINT_VELOCITY, 1.0);
  ASSERT_TRUE(client->WaitFor([&] { return sim->node().Rejected("joint_command.unknown_joint") == 1; }));
  EXPECT_EQ(sim->node().Stats().rejected, 1u);
  EXPECT_EQ(sim->node().Stats().frame, 0u);
  const auto reply = client->Control(idl::OP_STEP, 250);  // 0.5 s
  ASSERT_TRUE(reply);
  EXPECT_EQ(reply->result(), idl::RESULT_OK);
  EXPECT_EQ(reply->frame(), 250u);
  ASSERT_TRUE(client->WaitFor([&] { return client->joints["nao_1"].frame() == 250u; }));
  EXPECT_NEAR(client->Angle("nao_1", "hj1"), 0.5, 0.03);
  // Lockstep: nothing moves without STEP. Later requests, each handled in a
  // turn of turf-sim's loop, are answered at the same frame.
  for (int i = 0; i < 5; ++i) {
    const auto probe = client->Control(idl::OP_RESUME);
    ASSERT_TRUE(probe);
    EXPECT_EQ(probe->result(), idl::RESULT_OK);
    EXPECT_EQ(probe->frame(), 250u);
  }
  EXPECT_EQ(sim->node().Stats().frame, 250u);
  const auto reset = client->Control(idl::OP_RESET);
  ASSERT_TRUE(reset);
  EXPECT_EQ(reset->frame(), 0u);
  ASSERT_TRUE(client->WaitFor([&] { return client->joints["nao_1"].frame() == 0u; }));
  EXPECT_NEAR(client->Angle("nao_1", "hj1"), 0.0, 1e-9);
}

// What the SimSpark bridge needs: joint commands inside STEP (atomic with the
// step), robots and ball moved by control requests, body poses, the scene.
TEST_P(LeggedNode, StepCarriesJointCommandsAndTeleportsMoveRobotsAndBall) {
  ASSERT_TRUE(Start(TimeMode::kLockstep));
  ASSERT_TRUE(client->WaitFor([&] { return client->scene.has_value() && client->links.count("nao_2"); }));
  ASSERT_EQ(client->scene->robots().size(), 2u);
  EXPECT_TRUE(client->scene->has_field());
  EXPECT_EQ(client->scene->field_length(), 30.0);
  EXPECT_GT(client->scene->robots()[0].geoms().size(), 10u);

  idl::SimControl step;
  step.op(idl::OP_STEP);
  step.step_count(250);  // 0.5 s
  idl::JointCommand c;
  c.robot("nao_1");
  idl::JointTarget t;
  t.name("hj1");
  t.mode(idl::JOINT_VELOCITY);
  t.value(1.0);
  c.joints().push_back(t);
  step.joint_commands().push_back(c);
  auto reply = client->Control(step);
  ASSERT_TRUE(reply);
  EXPECT_EQ(reply->result(), idl::RESULT_OK) << reply->reason();
  ASSERT_TRUE(client->WaitFor([&] { return client->joints["nao_1"].frame() == 250u; }));
  EXPECT_NEAR(client->Angle("nao_1", "hj1"), 0.5, 0.03);

  // A refused joint command refuses the whole step: no time passes.
  step.joint_commands()[0].joints()[0].value(NAN);
  reply = client->Control(step);
  ASSERT_TRUE(reply);
  EXPECT_EQ(reply->result(), idl::RESULT_REJECTED);
  EXPECT_EQ(reply->frame(), 250u);

  idl::SimControl move;
  move.op(idl::OP_TELEPORT_ROBOT);
  move.legged().robot("nao_2");
  move.legged().position(idl::V3(2.0, 3.0, 0.4));
  move.legged().orientation().w(1.0);
  reply = client->Control(move);
  ASSERT_TRUE(reply);
  EXPECT_EQ(reply->result(), idl::RESULT_OK) << reply->reason();
  idl::SimControl ball;
  ball.op(idl::OP_TELEPORT_BALL);
  ball.ball().position(idl::V3(1.0, -1.0, 0.042));
  reply = client->Control(ball);
  ASSERT_TRUE(reply);
  EXPECT_EQ(reply->result(), idl::RESULT_OK) << reply->reason();
  ASSERT_TRUE(client->WaitFor([&] {
    const auto& links = client->links["nao_2"].links();
    return !links.empty() && std::abs(links[0].position().x() - 2.0) < 1e-6 && client->world &&
           std::abs(client->world->ball().position().x() - 1.0) < 1e-6;
  }));
  EXPECT_EQ(client->links["nao_2"].links()[0].name(), "torso");
  EXPECT_NEAR(client->world->ball().position().y(), -1.0, 1e-6);

  move.legged().robot("nao_7");
  reply = client->Control(move);
  ASSERT_TRUE(reply);
  EXPECT_EQ(reply->result(), idl::RESULT_REJECTED);
  move.legged().robot("nao_2");
  move.legged().position(idl::V3(1e6, 0, 0));
  reply = client->Control(move);
  ASSERT_TRUE(reply);
  EXPECT_EQ(reply->result(), idl::RESULT_REJECTED);
  ball.ball().velocity(idl::V3(NAN, 0, 0));
  reply = client->Control(ball);
  ASSERT_TRUE(reply);
  EXPECT_EQ(reply->result(), idl::RESULT_REJECTED);
}

// Encoder realism changed at run time: published joint angles are quantised.
TEST_P(LeggedNode, SetRealismModelsTheEncoders) {
  ASSERT_TRUE(Start(TimeMode::kFreeRunning));
  client->Command("nao_1", "hj1", idl::JOINT_VELOCITY, 0.37);
  idl::SimControl req;
  req.op(idl::OP_SET_REALISM);
  idl::RealismValue resolution;
  resolution.parameter(idl::REALISM_ENCODER_RESOLUTION);
  resolution.value(0.05);
  req.realism_values({resolution});
  auto reply = client->Control(req);
  ASSERT_TRUE(reply);
  EXPECT_EQ(reply->result(), idl::RESULT_OK) << reply->reason();
  const uint64_t after = reply->frame();
  ASSERT_TRUE(client->WaitFor([&] { return client->joints["nao_1"].frame() > after + 10; }));
  for (double q : client->joints["nao_1"].position()) EXPECT_NEAR(q / 0.05, std::round(q / 0.05), 1e-9);
  req.realism_preset("/etc/passwd");  // never a path from the network
  reply = client->Control(req);
  ASSERT_TRUE(reply);
  EXPECT_EQ(reply->result(), idl::RESULT_REJECTED);
  EXPECT_EQ(reply->error(), idl::CONTROL_UNKNOWN_PRESET);
  req.realism_preset("");
  resolution.value(-1);
  req.realism_values({resolution});
  reply = client->Control(req);
  ASSERT_TRUE(reply);
  EXPECT_EQ(reply->result(), idl::RESULT_REJECTED);
  EXPECT_EQ(reply->error(), idl::CONTROL_OUT_OF_RANGE);
  EXPECT_NE(reply->reason().find("encoder.resolution"), std::string::npos) << reply->reason();
}

TEST_P(LeggedNode, PauseStopsTimeAndStepAdvancesIt) {
  ASSERT_TRUE(Start(TimeMode::kRealtime));
  const auto pause = client->Control(idl::OP_PAUSE);
  ASSERT_TRUE(pause);
  ASSERT_EQ(pause->result(), idl::RESULT_OK);
  const uint64_t frame = pause->frame();
  // Later requests, each handled in a turn of turf-sim's loop that would have
  // stepped if it could, are answered at the same frame.
  for (int i = 0; i < 5; ++i) {
    const auto probe = client->Control(idl::OP_PAUSE);
    ASSERT_TRUE(probe);
    EXPECT_EQ(probe->frame(), frame);
  }
  EXPECT_EQ(sim->node().Stats().frame, frame);
  const auto reply = client->Control(idl::OP_STEP, 10);
  ASSERT_TRUE(reply);
  EXPECT_EQ(reply->result(), idl::RESULT_OK);
  EXPECT_EQ(reply->frame(), frame + 10);
  const auto resume = client->Control(idl::OP_RESUME);
  ASSERT_TRUE(resume);
  EXPECT_EQ(resume->result(), idl::RESULT_OK);
  ASSERT_TRUE(client->WaitFor([&] { return sim->node().Stats().frame > frame + 50; }));
}

// The realistic preset's encoder and IMU noise, with ideal links (one joint
// sample per robot at every sensor frame, at once).
SensorRealism NoisyNoLinks() {
  RealismLoadResult r = LoadRealism("realistic");
  if (!r.realism) throw std::runtime_error("no realistic preset");
  r.realism->encoder.link = {};
  r.realism->imu.link = {};
  r.realism->touch.link = {};
  return *r.realism;
}

// nao_1's measured joint angles at each of `frames` sensor frames (10 steps
// each), stepping in lockstep; with `chatter`, every step is followed by
// control requests that make turf-sim publish its state again (a pause, a
// refused teleport), as a viewer or a bridge may send.
std::vector<std::vector<double>> NoisyAngles(Transport transport, int frames, bool chatter) {
  const TestTransport net = Net(transport);
  Client client(net);
  NodeUnderTest sim(net, TimeMode::kLockstep, NoisyNoLinks());
  EXPECT_TRUE(client.WaitMatched());
  std::vector<std::vector<double>> angles;
  for (int f = 1; f <= frames; ++f) {
    const auto reply = client.Control(idl::OP_STEP, 10);
    if (!reply || reply->result() != idl::RESULT_OK) return {};
    const uint64_t frame = 10u * f;
    if (!client.WaitFor([&] { return client.joints["nao_1"].frame() == frame; })) return {};
    angles.push_back(client.joints["nao_1"].position());
    if (!chatter) continue;
    EXPECT_TRUE(client.Control(idl::OP_PAUSE));
    idl::SimControl bad;
    bad.op(idl::OP_TELEPORT_BALL);
    bad.ball().position().x(NAN);
    const auto refused = client.Control(bad);
    EXPECT_TRUE(refused && refused->result() == idl::RESULT_REJECTED);
  }
  return angles;
}

// The determinism leak of the old node: it drew encoder noise at every state
// publication, so a viewer's requests changed every later reading.
TEST_P(LeggedNode, ControlRequestsDoNotChangeTheSensorNoise) {
  const auto quiet = NoisyAngles(GetParam(), 20, false);
  const auto chatty = NoisyAngles(GetParam(), 20, true);
  ASSERT_EQ(quiet.size(), 20u);
  ASSERT_EQ(chatty.size(), 20u);
  EXPECT_EQ(quiet, chatty);
  EXPECT_NE(quiet[3], quiet[4]);  // noisy readings of a robot standing still
}

// A joint-state link with 20 ms latency and 10 % loss, seen by a subscriber
// in lockstep: no sample arrives before the step that is 20 ms after its
// measurement, about a tenth never arrive, and the stats topic reports both.
TEST_P(LeggedNode, JointStatesArriveWithTheirLinksLatencyAndLoss) {
  SensorRealism realism;
  realism.encoder.link.latency = 0.020;
  realism.encoder.link.loss = 0.10;
  std::unique_ptr<dds::Participant> own;
  auto stats_reader = net.ClientBus(&own, "stats").MakeReader(dds::Topic::kStats);
  client.emplace(net);
  sim.emplace(net, TimeMode::kLockstep, realism);
  ASSERT_TRUE(client->WaitControlMatched());
  ASSERT_TRUE(client->WaitFor([&] { return stats_reader->Matched() > 0; }));

  constexpr int64_t kStepNs = 2'000'000;
  constexpr int kSteps = 2500;  // 5 s: 250 sensor frames of each robot
  std::set<std::pair<std::string, uint64_t>> received;
  for (int step = 1; step <= kSteps; ++step) {
    const auto reply = client->Control(idl::OP_STEP, 1);
    ASSERT_TRUE(reply && reply->result() == idl::RESULT_OK);
    // Whatever has arrived by now was released at or before this step.
    client->Poll();
    for (const auto& [robot, j] : client->joints) {
      if (!received.insert({robot, j.frame()}).second) continue;
      ASSERT_LE(j.sim_time_ns() + 20'000'000, static_cast<int64_t>(reply->sim_time_ns()))
          << robot << " frame " << j.frame() << " arrived early";
    }
  }
  // Every delivered sample arrives (reliable): wait for the last second's stats.
  std::vector<idl::SensorStats> windows;
  ASSERT_TRUE(client->WaitFor([&] {
    std::vector<idl::SensorStats> more;
    if (stats_reader->Take(&more)) windows.insert(windows.end(), more.begin(), more.end());
    return !windows.empty() && windows.back().sim_time_ns() >= 5'000'000'000 - kStepNs;
  }));
  uint64_t sent = 0, lost = 0;
  double latency = 0.0;
  for (const idl::SensorStats& w : windows) {
    for (const idl::StreamStats& s : w.streams()) {
      if (s.name() != "legged/nao_1/joint_state") continue;
      sent += s.sent();
      lost += s.lost();
      latency = s.latency_mean();
    }
  }
  ASSERT_GT(sent, 200u);
  EXPECT_NEAR(static_cast<double>(lost) / sent, 0.10, 0.05);
  EXPECT_NEAR(latency, 0.020, 1e-9);  // whole steps: no jitter
  // The subscriber's own count: about a tenth of nao_1's 250 frames missing.
  size_t nao_1 = 0;
  for (const auto& [robot, frame] : received) nao_1 += robot == "nao_1" && frame > 0 && frame <= 2480;
  EXPECT_NEAR(nao_1 / 248.0, 0.90, 0.06);
}

}  // namespace
}  // namespace turf
