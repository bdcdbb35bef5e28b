// Faults during a match, with real processes on this host's loopback: a bridge
// or turf-sim killed with SIGKILL and started again, and bridges started
// before turf-sim. The team's view (grSim in, SSL-Vision out) must come back
// by itself, and the processes that kept running must not need a restart.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
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

// A division B match on this host's loopback, with a team's vision client and
// grSim socket; each test starts the processes it needs.
struct LoopbackMatch {
  explicit LoopbackMatch(const char* what)
      : match({TestDomain(), std::string("fault_") + what + std::to_string(getpid()), nullptr, {}, "ssl_div_b"}),
        client("127.0.0.1", match.vision_port) {}

  // How far (m) blue 1 drives in 0.6 s at 1 m/s seen by vision; 0 if it could not.
  double Drive() {
    return DriveBlueRobot(team, "127.0.0.1", match.grsim_port, client, 1, -3.0, 2.0, 600ms).value_or(0);
  }

  // turf-sim, then the bridges; true once vision streams both cameras and geometry.
  bool StartAll() {
    sim = match.Sim();
    grsim = match.Grsim();
    vision = match.Vision();
    return client.WaitForStream(2, kStreamTimeout);
  }

  // No detection for 200 ms, after 1 s for those in flight.
  ::testing::AssertionResult VisionStopped() {
    client.Drain(1000ms);
    const int during = client.detections;
    client.Drain(200ms);
    if (client.detections == during) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << client.detections - during << " detections after the stop";
  }

  Match match;
  VisionClient client;
  UdpSocket team;
  std::unique_ptr<Process> sim, grsim, vision;
};

// Records how long vision took to resume, in the test's XML and its output.
void ReportResumed(const char* property, const char* after, std::chrono::milliseconds resumed) {
  testing::Test::RecordProperty(property, static_cast<int>(resumed.count()));
  std::printf("vision resumed %lld ms after %s\n", static_cast<long long>(resumed.count()), after);
}

// Lines at warning level or worse that a process logged after `from` bytes of its log.
int Complaints(const Process& p, size_t from = 0) {
  const std::string log = p.Log().substr(from);
  const std::regex bad(R"(\[(warning|error|critical)\])");
  return static_cast<int>(std::distance(std::sregex_iterator(log.begin(), log.end(), bad), std::sregex_iterator()));
}

// kill -9 both bridges mid-match and start them again: vision resumes within
// 2 s of the restart, commands work, and turf-sim logs nothing worse than info.
TEST(Faults, BridgeKilledAndRestartedResumesWithinTwoSeconds) {
  LoopbackMatch m("bridge");
  ASSERT_TRUE(m.StartAll()) << m.vision->Log();
  ASSERT_GT(m.Drive(), 0.2);

  const size_t sim_log_before = m.sim->Log().size();
  m.vision->Kill();
  m.grsim->Kill();
  EXPECT_TRUE(m.VisionStopped()) << "a killed vision bridge still sends";

  m.vision = m.match.Vision("_restarted");
  m.grsim = m.match.Grsim("_restarted");
  const auto resumed = m.client.UntilDetection(15s);
  ASSERT_TRUE(resumed.has_value()) << m.vision->Log();
  ReportResumed("vision_after_bridge_restart_ms", "the bridge restarted", *resumed);
  // Known cause when this fails at 2-4 s: the new bridge takes over the dead
  // one's participant id, and with Fast DDS's shared-memory transport it first
  // waits out the dead one's SHM port while turf-sim keeps writing to the stale
  // segment. A UDPv4-only participant profile (and a 0.5 s lease announcement,
  // which bounds a lost discovery reply) brings this to ~0.1 s.
  EXPECT_LE(resumed->count(), 2000) << m.vision->Log();
  EXPECT_GT(m.Drive(), 0.2) << m.grsim->Log();
  EXPECT_TRUE(m.sim->Running());
  EXPECT_EQ(Complaints(*m.sim, sim_log_before), 0) << m.sim->Log().substr(sim_log_before);
}

// kill -9 turf-sim mid-match and start it again: the running bridges resume by
// themselves (same processes), and commands reach the new turf-sim.
TEST(Faults, SimKilledAndRestartedBridgesResumeWithoutRestart) {
  LoopbackMatch m("sim");
  ASSERT_TRUE(m.StartAll()) << m.vision->Log();

  m.sim->Kill();
  EXPECT_TRUE(m.VisionStopped()) << "vision kept flowing without turf-sim";

  m.sim = m.match.Sim("_restarted");
  const auto resumed = m.client.UntilDetection(10s);
  ASSERT_TRUE(resumed.has_value()) << m.vision->Log() << m.sim->Log();
  ReportResumed("vision_after_sim_restart_ms", "turf-sim restarted", *resumed);
  EXPECT_GT(m.Drive(), 0.2) << m.grsim->Log();
  EXPECT_TRUE(m.grsim->Running() && m.vision->Running());
}

// Bridges started first wait quietly (no packets, no warnings) and work once
// turf-sim appears.
TEST(Faults, BridgesStartedBeforeSimWaitQuietlyThenWork) {
  LoopbackMatch m("order");
  auto grsim = m.match.Grsim();
  auto vision = m.match.Vision();
  m.client.Drain(2000ms);
  EXPECT_EQ(m.client.detections, 0);
  EXPECT_FALSE(m.client.geometry);
  EXPECT_TRUE(grsim->Running() && vision->Running());
  EXPECT_EQ(Complaints(*grsim) + Complaints(*vision), 0) << grsim->Log() << vision->Log();

  auto sim = m.match.Sim();
  const auto start = SteadyClock::now();
  ASSERT_TRUE(m.client.WaitForStream(2, kStreamTimeout)) << vision->Log();
  RecordProperty(
      "vision_after_sim_start_ms",
      static_cast<int>(std::chrono::duration_cast<std::chrono::milliseconds>(SteadyClock::now() - start).count()));
  EXPECT_GT(m.Drive(), 0.2) << grsim->Log();
  EXPECT_EQ(Complaints(*grsim) + Complaints(*vision), 0) << grsim->Log() << vision->Log();
}

}  // namespace
}  // namespace turf::test
