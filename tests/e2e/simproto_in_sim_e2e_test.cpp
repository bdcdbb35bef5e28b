// turf-sim --simproto as a real process: the SSL simulation protocol served by turf-sim itself (its sync port
// steps it in lockstep and answers with the step's detections), a separate turf-simproto-bridge on other ports
// working next to it over DDS, and both stopping cleanly on SIGTERM.
#include "tests/e2e/ssl_match.h"
#include "tests/support/bridge_args.h"

namespace turf::test {
namespace {

// One sync request of 1/60 s commanding blue 0; the response, or nullopt after 5 s without one.
std::optional<wire::simulation::SimulationSyncResponse> Sync(Udp& team, int port) {
  wire::simulation::SimulationSyncRequest request;
  request.set_sim_step(1.0f / 60.0f);
  auto* c = request.mutable_robot_control()->add_robot_commands();
  c->set_id(0);
  auto* v = c->mutable_move_command()->mutable_local_velocity();
  v->set_forward(0.5f);
  v->set_left(0);
  v->set_angular(0);
  team.Send(request.SerializeAsString(), port);
  const auto end = Clock::now() + 5s;
  while (Clock::now() < end)
    if (auto bytes = team.Receive()) {
      wire::simulation::SimulationSyncResponse response;
      if (response.ParseFromString(*bytes)) return response;
    }
  return std::nullopt;
}

// Command() once the process listens: a datagram sent before it bound its port is lost, so ask again (20 s at most).
std::optional<wire::simulation::SimulatorResponse> CommandOnceUp(Udp& team,
                                                                 const wire::simulation::SimulatorCommand& cmd,
                                                                 int port) {
  const auto end = Clock::now() + 20s;
  std::optional<wire::simulation::SimulatorResponse> r;
  while (!r && Clock::now() < end) r = Command(team, cmd, static_cast<uint16_t>(port));
  return r;
}

TEST(SimprotoInTurfSim, TheSyncPortStepsTurfSimAndTheSeparateBridgeStillWorks) {
  const int domain = TestDomain(71);
  const std::string prefix = "e2einsim" + std::to_string(getpid());
  const int control_port = FreePort(), sync_port = FreePort(), bridge_control_port = FreePort();
  const std::vector<std::string> dds = {"--domain", std::to_string(domain), "--prefix", prefix};
  std::vector<std::string> sim_args = {Built("participants/sim/turf-sim"),
                                       "--scene",
                                       std::string(TURF_SOURCE_DIR) + "/configs/scenes/ssl_div_a.yaml",
                                       "--realism",
                                       "ideal",
                                       "--lockstep",
                                       "--simproto",
                                       "--simproto-control-port",
                                       std::to_string(control_port),
                                       "--simproto-blue-port",
                                       "0",
                                       "--simproto-yellow-port",
                                       "0",
                                       "--simproto-sync-port",
                                       std::to_string(sync_port),
                                       "--simproto-sync"};
  sim_args.insert(sim_args.end(), dds.begin(), dds.end());
  Process sim(prefix + "_sim", sim_args);
  Process bridge(prefix + "_bridge", SimprotoControlOnly(bridge_control_port, dds));
  Udp team;

  // A teleport through the separate bridge, over DDS (asked again until the bridge listens and has seen turf-sim).
  wire::simulation::SimulatorCommand teleport;
  teleport.mutable_control()->mutable_teleport_ball()->set_x(1.0f);
  teleport.mutable_control()->mutable_teleport_ball()->set_y(-0.5f);
  const auto teleported = CommandOnceUp(team, teleport, bridge_control_port);
  ASSERT_TRUE(teleported.has_value()) << bridge.Log();
  ASSERT_EQ(teleported->errors_size(), 0) << teleported->DebugString();
  // turf-sim's own control port answers too.
  wire::simulation::SimulatorCommand ping;
  ping.mutable_control();
  const auto pong = CommandOnceUp(team, ping, control_port);
  ASSERT_TRUE(pong.has_value()) << sim.Log();
  EXPECT_EQ(pong->errors_size(), 0) << pong->DebugString();

  // 12 sync requests of 1/60 s through turf-sim's own sync port: 200 ms, 12 camera frames of 4 cameras.
  int detections = 0;
  std::optional<double> ball_x;
  for (int i = 0; i < 12; ++i) {
    SCOPED_TRACE(i);
    const auto response = Sync(team, sync_port);
    ASSERT_TRUE(response.has_value()) << sim.Log();
    ASSERT_EQ(response->robot_control_response().errors_size(), 0) << response->DebugString();
    for (const wire::vision::SSL_DetectionFrame& frame : response->detection()) {
      ++detections;
      if (!ball_x && frame.balls_size() > 0) ball_x = frame.balls(0).x();
    }
  }
  EXPECT_EQ(detections, 12 * 4);
  ASSERT_TRUE(ball_x.has_value());
  EXPECT_NEAR(*ball_x, 1000.0, 20.0);  // mm: the separate bridge's teleport reached the same world

  const std::string log = sim.Log();
  EXPECT_NE(log.find("sync port 127.0.0.1:" + std::to_string(sync_port)), std::string::npos) << log;
  for (Process* p : {&bridge, &sim}) {
    const int status = p->Stop();
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << p->log_path() << ":\n" << p->Log();
  }
}

}  // namespace
}  // namespace turf::test
