// turf-sim with the SSL simulation protocol served in its own process (participants/sim/sim_host.h, turf-sim
// --simproto): the node on a FanoutBus over DDS and an in-memory bus, the front-end on the in-memory bus. A team
// talks real UDP on 127.0.0.1; a remote DDS participant on the test's private domain watches turf-sim as any other
// process would. Waits are for conditions, with deadlines.
#include <gtest/gtest.h>
#include <turf/idl/ClockPubSubTypes.h>
#include <turf/idl/SslVisionPubSubTypes.h>
#include <turf/idl/WorldStatePubSubTypes.h>

#include <chrono>
#include <cmath>
#include <functional>
#include <optional>
#include <regex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "codecs/proto/ssl_simulation.pb.h"
#include "dds/participant.h"
#include "loader/legged_scene_yaml.h"
#include "participants/common/udp.h"
#include "participants/sim/sim_host.h"
#include "participants/sim/sim_node.h"
#include "tests/codecs/ssl_simulation/test_util.h"
#include "tests/core/test_scenes.h"
#include "tests/simspark/agent_client.h"
#include "tests/support/in_process.h"
#include "tests/support/process.h"
#include "tests/support/wake_wait.h"
#include "tests/support/world_observer.h"

namespace turf {
namespace {

using namespace std::chrono_literals;
using SteadyClock = std::chrono::steady_clock;
namespace ws = wire::simulation;

uint16_t FreePort() { return static_cast<uint16_t>(test::FreePort()); }

// A team on UDP: one socket, request and answer.
class Team {
 public:
  template <class Request, class Response>
  bool Ask(uint16_t port, const Request& request, Response* response, std::chrono::milliseconds timeout = 5s) {
    std::vector<uint8_t> bytes(request.ByteSizeLong());
    request.SerializeToArray(bytes.data(), static_cast<int>(bytes.size()));
    const std::optional<UdpEndpoint> to = MakeEndpoint("127.0.0.1", port);
    std::string error;
    if (!to || !socket_.SendTo(bytes, *to, &error)) {
      ADD_FAILURE() << "cannot send: " << error;
      return false;
    }
    const std::optional<Datagram> d = socket_.Receive(65536, timeout);
    return d && response->ParseFromArray(d->bytes.data(), static_cast<int>(d->bytes.size()));
  }

 private:
  UdpSocket socket_ = test::BindLoopback();
};

// turf-sim (lockstep) with the in-process front-end on free loopback ports, on a thread.
struct Host {
  explicit Host(const dds::ParticipantOptions& dds) : host(Make(dds)) {}
  // The ports are picked free, released, then bound by the front-end: another process may take one in between,
  // so a failed bind picks new ones (a few times).
  std::unique_ptr<SimHost> Make(const dds::ParticipantOptions& dds) {
    for (int attempt = 1;; ++attempt) {
      try {
        return TryMake(dds);
      } catch (const std::runtime_error& e) {
        if (attempt == 5 || std::string(e.what()).find("cannot bind") == std::string::npos) throw;
      }
    }
  }
  std::unique_ptr<SimHost> TryMake(const dds::ParticipantOptions& dds) {
    SimNodeOptions node = test::OnDds<SimNodeOptions>(dds);
    node.mode = TimeMode::kLockstep;
    SimprotoBridgeOptions simproto;
    simproto.name = "turf-sim/simproto";
    simproto.listen = "127.0.0.1";
    simproto.control_port = control = FreePort();
    simproto.blue_port = blue = FreePort();
    simproto.yellow_port = yellow = FreePort();
    simproto.sync_port = sync = FreePort();
    simproto.sync = true;
    InProcessFrontEnds front_ends;
    front_ends.simproto = simproto;
    return std::make_unique<SimHost>(test::Teams(2), node, std::move(front_ends));
  }
  uint16_t control = 0, blue = 0, yellow = 0, sync = 0;
  test::OnThread<SimHost> host;
};

// Until the front-end has seen turf-sim: an empty control command is answered without errors.
bool WaitReady(Team& team, uint16_t control_port) {
  const auto end = SteadyClock::now() + 10s;
  while (SteadyClock::now() < end) {
    ws::SimulatorCommand ping;
    ping.mutable_control();
    ws::SimulatorResponse r;
    if (team.Ask(control_port, ping, &r, 1s) && r.errors_size() == 0) return true;
    std::this_thread::sleep_for(10ms);
  }
  return false;
}

TEST(SimHost, SyncRequestsOverUdpStepTheInProcessNodeAndARemoteParticipantSeesIt) {
  const dds::ParticipantOptions dds = test::UniqueDds("observer", "host", 41);
  Host h(dds);
  ASSERT_NE(h.host.node().simproto(), nullptr);
  test::WorldObserver remote(dds);
  Team team;
  ASSERT_TRUE(WaitReady(team, h.control));

  // A teleport through the control port, then 12 sync requests of 1/60 s with robot commands: 200 ms, exactly 100
  // physics steps of 2 ms.
  ws::SimulatorCommand teleport;
  teleport.mutable_control()->mutable_teleport_ball()->set_x(1.0f);
  teleport.mutable_control()->mutable_teleport_ball()->set_y(-0.5f);
  ws::SimulatorResponse teleported;
  ASSERT_TRUE(team.Ask(h.control, teleport, &teleported));
  EXPECT_EQ(teleported.errors_size(), 0) << teleported.DebugString();

  constexpr int kRequests = 12;
  int detections = 0;
  std::optional<double> first_ball_x;
  for (int i = 0; i < kRequests; ++i) {
    SCOPED_TRACE(i);
    ws::SimulationSyncRequest request;
    request.set_sim_step(1.0f / 60.0f);
    simproto::test::AddLocal(request.mutable_robot_control(), 0, 0.5f);   // blue 0
    simproto::test::AddLocal(request.mutable_robot_control(), 17, 0.5f);  // yellow 1
    ws::SimulationSyncResponse response;
    ASSERT_TRUE(team.Ask(h.sync, request, &response));
    EXPECT_EQ(response.robot_control_response().errors_size(), 0) << response.DebugString();
    EXPECT_EQ(response.robot_control_response().feedback_size(), 2);
    for (const auto& d : response.detection()) {
      ++detections;
      if (!first_ball_x && d.balls_size() > 0) first_ball_x = d.balls(0).x();
    }
  }
  EXPECT_EQ(detections, 12 * 4);  // 60 Hz for 200 ms, four cameras
  ASSERT_TRUE(first_ball_x.has_value());
  EXPECT_NEAR(*first_ball_x, 1000.0, 20.0);  // mm: the teleport took effect before the steps

  // The remote participant sees the same world over DDS: the frame the steps reached (each step request handled
  // once, though turf-sim listens on two buses) and the teleported ball.
  ASSERT_TRUE(remote.Wait([](const idl::WorldState& s, const idl::Clock&) { return s.frame() == 100u; }))
      << "frame " << remote.state().frame();
  EXPECT_NEAR(remote.state().ball().position().x(), 1.0, 0.02);
  EXPECT_EQ(h.host.node().node().Stats().frame, 100u);
  EXPECT_EQ(h.host.node().node().Stats().rejected, 0u);
  const SimprotoBridgeStats stats = h.host.node().simproto()->Stats();
  EXPECT_EQ(stats.rejected, 0u);
  EXPECT_EQ(stats.commands, 2u * kRequests);
}

// turf-sim holds back its durable DDS samples (world state, clock, replies) while no DDS reader is matched
// (dds/participant.cpp: a sync request does not pay for serialising them); a participant that joins afterwards, with
// the simulation standing still in lockstep, still gets the state and clock the last step reached and the field.
TEST(SimHost, ARemoteParticipantJoiningAfterSyncRequestsGetsTheLastStateClockAndField) {
  const dds::ParticipantOptions domain = test::UniqueDds("late", "host", 42);
  Host h(domain);
  Team team;
  ASSERT_TRUE(WaitReady(team, h.control));
  constexpr int kRequests = 6;  // 100 ms: 50 physics steps of 2 ms
  for (int i = 0; i < kRequests; ++i) {
    ws::SimulationSyncRequest request;
    request.set_sim_step(1.0f / 60.0f);
    simproto::test::AddLocal(request.mutable_robot_control(), 0, 0.5f);
    ws::SimulationSyncResponse response;
    ASSERT_TRUE(team.Ask(h.sync, request, &response));
    ASSERT_EQ(response.robot_control_response().errors_size(), 0) << response.DebugString();
  }
  ASSERT_EQ(h.host.node().node().Stats().frame, 50u);

  test::WorldObserver late(domain);
  EXPECT_TRUE(late.Wait([](const idl::WorldState& s, const idl::Clock& c) {
    return s.frame() == 50u && c.frame() == 50u;
  })) << "state frame "
      << late.state().frame() << ", clock frame " << late.clock().frame();
  EXPECT_EQ(late.clock().mode(), idl::TIME_LOCKSTEP);
  dds::Participant field_reader(domain);
  test::WakeWait woken;
  auto field = field_reader.MakeReader(dds::Topic::kSslField, [&] { woken.Wake(); });
  std::vector<idl::SslField> fields;
  EXPECT_TRUE(woken.Until(SteadyClock::now() + 15s, [&] { return field->Take(&fields); }));
  ASSERT_FALSE(fields.empty());
  EXPECT_EQ(fields.back().robots_per_team(), 2);
}

// A legged scene with SimSpark agents served in turf-sim's process (turf-sim --simspark): an agent in sync mode
// gets a perception per (syn) round, 20 ms apart, and a remote DDS participant sees turf-sim's clock advance.
TEST(SimHost, SimSparkAgentsInProcessStepTheLeggedNodeAndARemoteParticipantSeesIt) {
  const dds::ParticipantOptions dds = test::UniqueDds("observer", "hostspark", 43);
  LeggedSceneLoadResult scene = LoadLeggedSceneFile(TURF_SOURCE_DIR "/configs/scenes/simspark_match.yaml");
  ASSERT_TRUE(scene.scene.has_value());
  SimNodeOptions node = test::OnDds<SimNodeOptions>(dds);
  node.mode = TimeMode::kLockstep;
  SimSparkBridgeOptions simspark;
  simspark.listen = "127.0.0.1";
  simspark.agent_port = 0;  // any free port
  simspark.monitor_port = 0;
  simspark.sync_mode = true;
  InProcessFrontEnds front_ends;
  front_ends.simspark = simspark;
  test::OnThread<SimHost> host(std::make_unique<SimHost>(std::move(*scene.scene), node, std::move(front_ends)));
  ASSERT_NE(host.node().simspark(), nullptr);
  test::WorldObserver remote(dds);

  auto now = [](const std::string& m) {
    std::smatch match;
    return std::regex_search(m, match, std::regex(R"(\(time \(now ([-0-9.]+)\)\))")) ? std::stod(match[1]) : NAN;
  };
  test::AgentClient agent;
  ASSERT_TRUE(agent.Connect(host.node().simspark()->agent_port()));
  agent.Send("(scene rsg/agent/nao/nao_hetero.rsg 0)");
  ASSERT_TRUE(agent.Receive(10s).has_value()) << "no first perception";
  for (int i = 1; i < 5; ++i) ASSERT_TRUE(agent.Receive(10s).has_value()) << "grace cycle " << i;
  std::vector<double> times;
  for (int i = 0; i < 3; ++i) {
    agent.Send("(syn)");
    const std::optional<std::string> m = agent.Receive(10s);
    ASSERT_TRUE(m.has_value());
    times.push_back(now(*m));
  }
  EXPECT_NEAR(times[1] - times[0], 0.02, 1e-6);
  EXPECT_NEAR(times[2] - times[1], 0.02, 1e-6);
  // Over DDS, as any other process would see it: the clock at (at least) the last cycle's time.
  ASSERT_TRUE(remote.Wait([&](const idl::WorldState&, const idl::Clock& c) {
    return c.sim_time_ns() >= static_cast<int64_t>(std::llround(times.back() * 1e9)) - 1'000'000;
  }));
}

}  // namespace
}  // namespace turf
