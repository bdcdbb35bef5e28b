// Faults during a match, with real processes on this host's loopback: a bridge
// or turf-sim killed with SIGKILL and started again, and bridges started
// before turf-sim. The team's view (grSim in, SSL-Vision out) must come back
// by itself, and the processes that kept running must not need a restart.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <memory>
#include <regex>
#include <string>

#include "tests/multihost/support/match.h"
#include "tests/multihost/support/ssl_client.h"
#include "tests/test_domain.h"

namespace turf::test {
namespace {

using namespace std::chrono_literals;

constexpr auto kStreamTimeout = 15s;

std::string Prefix(const char* what) { return std::string("fault_") + what + std::to_string(getpid()); }

// Lines at warning level or worse that a process logged after `from` bytes of its log.
int Complaints(const Process& p, size_t from = 0) {
  const std::string log = p.Log().substr(from);
  const std::regex bad(R"(\[(warning|error|critical)\])");
  return static_cast<int>(std::distance(std::sregex_iterator(log.begin(), log.end(), bad), std::sregex_iterator()));
}

// kill -9 both bridges mid-match and start them again: vision resumes within
// 2 s of the restart, commands work, and turf-sim logs nothing worse than info.
TEST(Faults, BridgeKilledAndRestartedResumesWithinTwoSeconds) {
  Match match({TestDomain(), Prefix("bridge"), nullptr, {}, "ssl_div_b"});
  VisionClient client("127.0.0.1", match.vision_port);
  UdpSocket team;
  auto sim = match.Sim();
  auto grsim = match.Grsim();
  auto vision = match.Vision();
  ASSERT_TRUE(client.WaitForStream(2, kStreamTimeout)) << vision->Log();
  ASSERT_GT(DriveBlueRobot(team, "127.0.0.1", match.grsim_port, client, 1, -3.0, 2.0, 600ms).value_or(0), 0.2);

  const size_t sim_log_before = sim->Log().size();
  vision->Kill();
  grsim->Kill();
  client.Drain(1000ms);
  const int during = client.detections;
  client.Drain(200ms);
  EXPECT_EQ(client.detections, during) << "a killed vision bridge still sends";

  vision = match.Vision("_restarted");
  grsim = match.Grsim("_restarted");
  const auto resumed = client.UntilDetection(15s);
  ASSERT_TRUE(resumed.has_value()) << vision->Log();
  RecordProperty("vision_after_bridge_restart_ms", static_cast<int>(resumed->count()));
  std::printf("vision resumed %lld ms after the bridge restarted\n", static_cast<long long>(resumed->count()));
  // Known cause when this fails at 2-4 s: the new bridge takes over the dead
  // one's participant id, and with Fast DDS's shared-memory transport it first
  // waits out the dead one's SHM port while turf-sim keeps writing to the stale
  // segment. A UDPv4-only participant profile (and a 0.5 s lease announcement,
  // which bounds a lost discovery reply) brings this to ~0.1 s.
  EXPECT_LE(resumed->count(), 2000) << vision->Log();
  EXPECT_GT(DriveBlueRobot(team, "127.0.0.1", match.grsim_port, client, 1, -3.0, 2.0, 600ms).value_or(0), 0.2)
      << grsim->Log();
  EXPECT_TRUE(sim->Running());
  EXPECT_EQ(Complaints(*sim, sim_log_before), 0) << sim->Log().substr(sim_log_before);
}

// kill -9 turf-sim mid-match and start it again: the running bridges resume by
// themselves (same processes), and commands reach the new turf-sim.
TEST(Faults, SimKilledAndRestartedBridgesResumeWithoutRestart) {
  Match match({TestDomain(), Prefix("sim"), nullptr, {}, "ssl_div_b"});
  VisionClient client("127.0.0.1", match.vision_port);
  UdpSocket team;
  auto sim = match.Sim();
  auto grsim = match.Grsim();
  auto vision = match.Vision();
  ASSERT_TRUE(client.WaitForStream(2, kStreamTimeout)) << vision->Log();

  sim->Kill();
  client.Drain(1000ms);
  const int during = client.detections;
  client.Drain(200ms);
  EXPECT_EQ(client.detections, during) << "vision kept flowing without turf-sim";

  sim = match.Sim("_restarted");
  const auto resumed = client.UntilDetection(10s);
  ASSERT_TRUE(resumed.has_value()) << vision->Log() << sim->Log();
  RecordProperty("vision_after_sim_restart_ms", static_cast<int>(resumed->count()));
  std::printf("vision resumed %lld ms after turf-sim restarted\n", static_cast<long long>(resumed->count()));
  EXPECT_GT(DriveBlueRobot(team, "127.0.0.1", match.grsim_port, client, 1, -3.0, 2.0, 600ms).value_or(0), 0.2)
      << grsim->Log();
  EXPECT_TRUE(grsim->Running() && vision->Running());
}

// Bridges started first wait quietly (no packets, no warnings) and work once
// turf-sim appears.
TEST(Faults, BridgesStartedBeforeSimWaitQuietlyThenWork) {
  Match match({TestDomain(), Prefix("order"), nullptr, {}, "ssl_div_b"});
  VisionClient client("127.0.0.1", match.vision_port);
  UdpSocket team;
  auto grsim = match.Grsim();
  auto vision = match.Vision();
  client.Drain(2000ms);
  EXPECT_EQ(client.detections, 0);
  EXPECT_FALSE(client.geometry);
  EXPECT_TRUE(grsim->Running() && vision->Running());
  EXPECT_EQ(Complaints(*grsim) + Complaints(*vision), 0) << grsim->Log() << vision->Log();

  auto sim = match.Sim();
  const auto start = SteadyClock::now();
  ASSERT_TRUE(client.WaitForStream(2, kStreamTimeout)) << vision->Log();
  RecordProperty(
      "vision_after_sim_start_ms",
      static_cast<int>(std::chrono::duration_cast<std::chrono::milliseconds>(SteadyClock::now() - start).count()));
  EXPECT_GT(DriveBlueRobot(team, "127.0.0.1", match.grsim_port, client, 1, -3.0, 2.0, 600ms).value_or(0), 0.2)
      << grsim->Log();
  EXPECT_EQ(Complaints(*grsim) + Complaints(*vision), 0) << grsim->Log() << vision->Log();
}

}  // namespace
}  // namespace turf::test
