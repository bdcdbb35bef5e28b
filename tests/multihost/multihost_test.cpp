// turf across two hosts, for real: two network namespaces joined by a veth
// pair (support/netns.h). turf-sim runs in one, the SSL bridges and a test
// client that speaks grSim and SSL-Vision in the other; the only way between
// them is the link. Every test checks the full path: a grSim command sent in
// the bridge host moves a robot in the vision stream received there.
// Needs root (skipped otherwise, with the reason).
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <thread>

#include "participants/launcher/security_init.h"
#include "tests/multihost/support/match.h"
#include "tests/multihost/support/netns.h"
#include "tests/multihost/support/ssl_client.h"
#include "tests/test_domain.h"

namespace turf::test {
namespace {

using namespace std::chrono_literals;

class MultiHost : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string why = TwoHosts::Unavailable();
    if (!why.empty()) GTEST_SKIP() << why;
    hosts = std::make_unique<TwoHosts>();
    ASSERT_TRUE(hosts->error().empty()) << hosts->error();
    prefix = "mh" + std::to_string(getpid());
  }

  // The team's sockets, made inside the bridge host.
  std::unique_ptr<VisionClient> Vision(int port) {
    return hosts->InNamespace(hosts->bridge_ns(), [&] { return std::make_unique<VisionClient>("127.0.0.1", port); });
  }
  std::unique_ptr<UdpSocket> Team() {
    return hosts->InNamespace(hosts->bridge_ns(), [] { return std::make_unique<UdpSocket>(); });
  }

  // The full path across the link: a grSim command sent in the bridge host moves a robot in the vision stream
  // received there.
  void DriveAcrossTheLink(const MatchSetup& setup) {
    Match match(setup);
    auto vision_client = Vision(match.vision_port);
    auto team = Team();
    ASSERT_TRUE(vision_client->ok() && team->ok());
    auto sim = match.Sim();
    auto grsim = match.Grsim();
    auto vision = match.Vision();
    const auto start = SteadyClock::now();
    // Deadlines, not paces: with DDS Security every pair of processes authenticates first (key exchange and
    // signatures), which a loaded machine can stretch past 15 s. And on a loaded machine Fast DDS 2.9 sometimes
    // never completes one pair's authentication (README, "Access control": measured, such a bridge waited for
    // turf-sim over 150 s): a bridge still waiting after 25 s is restarted once, as the README tells an operator
    // to do, and the test says so.
    int restarted = 0;
    if (!vision_client->WaitForStream(4, 25s)) {
      vision = match.Vision("restarted");
      ++restarted;
      ASSERT_TRUE(vision_client->WaitForStream(4, 45s)) << vision->Log() << sim->Log();
    }
    const auto first = std::chrono::duration_cast<std::chrono::milliseconds>(SteadyClock::now() - start);
    RecordProperty("vision_after_start_ms", static_cast<int>(first.count()));
    const auto matched = [&] { return grsim->Log().find("turf-sim is listening") != std::string::npos; };
    if (!DrainUntil(*vision_client, matched, 25s)) {
      grsim = match.Grsim("restarted");
      ++restarted;
      ASSERT_TRUE(DrainUntil(*vision_client, matched, 45s)) << grsim->Log() << sim->Log();
    }
    RecordProperty("bridges_restarted", restarted);
    if (restarted > 0)
      std::printf("%d bridge(s) restarted: their DDS authentication with turf-sim never ended\n", restarted);
    const auto moved = DriveBlueRobot(*team, "127.0.0.1", match.grsim_port, *vision_client, 3, -3.0, 2.0, 1000ms);
    ASSERT_TRUE(moved.has_value()) << grsim->Log() << vision->Log();
    EXPECT_GT(*moved, 0.5) << grsim->Log();
    EXPECT_TRUE(sim->Running() && grsim->Running() && vision->Running());
  }

  // Reads vision until `done` holds (true) or `timeout` passes (false).
  static bool DrainUntil(VisionClient& vision, const std::function<bool()>& done, std::chrono::milliseconds timeout) {
    const auto end = SteadyClock::now() + timeout;
    while (!done()) {
      if (SteadyClock::now() > end) return false;
      vision.Drain(50ms);
    }
    return true;
  }

  // A division B match across the link, the team's sockets in the bridge host; its vision stream flows.
  struct Running {
    Running(MultiHost& t, const MatchSetup& setup)
        : match(setup),
          vision_client(t.Vision(match.vision_port)),
          team(t.Team()),
          sim(match.Sim()),
          grsim(match.Grsim()),
          vision(match.Vision()) {}
    Match match;
    std::unique_ptr<VisionClient> vision_client;
    std::unique_ptr<UdpSocket> team;
    std::unique_ptr<Process> sim, grsim, vision;
    // Drives blue robot 1 across the link; how far it moved (m) in the vision stream.
    std::optional<double> Drive() {
      return DriveBlueRobot(*team, "127.0.0.1", match.grsim_port, *vision_client, 1, -3.0, 2.0, 600ms);
    }
  };
  std::unique_ptr<Running> StartDivisionB() {
    auto r = std::make_unique<Running>(*this, MatchSetup{TestDomain(), prefix, hosts.get(), {}, "ssl_div_b"});
    EXPECT_TRUE(r->vision_client->WaitForStream(2, 15s)) << r->vision->Log();
    return r;
  }

  std::unique_ptr<TwoHosts> hosts;  // outlives the processes of the test body
  std::string prefix;
};

// Default (multicast) discovery across the link.
TEST_F(MultiHost, GrsimCommandMovesRobotInVisionAcrossTheLink) {
  DriveAcrossTheLink({TestDomain(), prefix, hosts.get(), {}, "ssl_div_a"});
}

// The same with DDS Security on (issue 19): every process authenticated with its own identity, the traffic on the
// link encrypted.
TEST_F(MultiHost, GrsimCommandMovesRobotInVisionAcrossTheLinkWithSecurityOn) {
  launch::SecurityInitOptions o;
  o.dir = LogDir() + "/multihost_security_" + std::to_string(getpid());
  o.prefix = prefix;
  std::filesystem::remove_all(o.dir);
  const std::vector<std::string> errors = launch::InitSecurity(o);
  ASSERT_TRUE(errors.empty()) << errors.front();
  DriveAcrossTheLink({TestDomain(), prefix, hosts.get(), {}, "ssl_div_a", o.dir});
  std::filesystem::remove_all(o.dir);
}

// Multicast dropped on the link (nftables in both namespaces): nothing is
// found without a discovery server; with `turf launch --discovery-server` on
// both hosts (and --start-discovery-server on the sim host) the match runs.
TEST_F(MultiHost, DiscoveryServerWorksWithMulticastBlocked) {
  ASSERT_TRUE(hosts->BlockMulticast()) << hosts->error();
  const int domain = TestDomain();
  {
    Match plain({domain, prefix + "_plain", hosts.get(), {}, "ssl_div_a"});
    auto vision_client = Vision(plain.vision_port);
    auto sim = plain.Sim();
    auto vision = plain.Vision();
    EXPECT_FALSE(vision_client->UntilDetection(4s).has_value()) << "multicast discovery crossed a blocked link";
  }
  EXPECT_GT(hosts->DroppedMulticast(), 0) << "the nftables rules saw no multicast";

  // A profile as a team would write one; the bridges' UDP stays on 127.0.0.1.
  const int grsim_port = FreePort(), vision_port = FreePort();
  const std::string profile = LogDir() + "/" + prefix + ".yaml";
  std::ofstream(profile) << "name: multihost\n"
                         << "scene: " << TURF_SOURCE_DIR << "/configs/scenes/ssl_div_a.yaml\n"
                         << "realism: ideal\ndomain: " << domain << "\nprefix: " << prefix << "\n"
                         << "bridges:\n"
                         << "  grsim: {listen: 127.0.0.1, port: " << grsim_port << "}\n"
                         << "  vision: {address: 127.0.0.1, port: " << vision_port << "}\n";
  const std::string server = hosts->sim_ip() + ":11811";
  const std::string turf = Built("participants/launcher/turf");
  Process sim_host("launch_sim_host",
                   hosts->In(hosts->sim_ns(), {turf, "launch", profile, "--only", "sim", "--discovery-server", server,
                                               "--start-discovery-server"}));
  Process bridge_host(
      "launch_bridge_host",
      hosts->In(hosts->bridge_ns(), {turf, "launch", profile, "--only", "grsim,vision", "--discovery-server", server}));
  auto vision_client = Vision(vision_port);
  auto team = Team();
  const auto start = SteadyClock::now();
  ASSERT_TRUE(vision_client->WaitForStream(4, 15s)) << bridge_host.Log() << sim_host.Log();
  const auto first = std::chrono::duration_cast<std::chrono::milliseconds>(SteadyClock::now() - start);
  RecordProperty("vision_after_start_ms", static_cast<int>(first.count()));
  const auto moved = DriveBlueRobot(*team, "127.0.0.1", grsim_port, *vision_client, 3, -3.0, 2.0, 1000ms);
  ASSERT_TRUE(moved.has_value());
  EXPECT_GT(*moved, 0.5) << bridge_host.Log();
  EXPECT_NE(sim_host.Log().find("ROS_DISCOVERY_SERVER=" + server), std::string::npos);
  // Both launches stop cleanly on SIGINT (Ctrl-C).
  for (Process* p : {&bridge_host, &sim_host}) {
    p->Signal(SIGINT);
    const auto status = p->Wait(10s);
    ASSERT_TRUE(status.has_value()) << p->Log();
    EXPECT_TRUE(WIFEXITED(*status) && WEXITSTATUS(*status) == 0) << p->Log();
  }
}

// The link goes down for 3 s and comes back: vision resumes and commands move
// robots again, with every process as it was.
TEST_F(MultiHost, LinkDownForThreeSecondsBothSidesRecover) {
  const std::unique_ptr<Running> m = StartDivisionB();
  ASSERT_FALSE(HasFailure());
  VisionClient* vision_client = m->vision_client.get();
  const auto before = m->Drive();
  ASSERT_TRUE(before.has_value());
  ASSERT_GT(*before, 0.2);

  ASSERT_TRUE(hosts->SetLink(false)) << hosts->error();
  const auto down = SteadyClock::now();
  vision_client->Drain(3000ms);
  ASSERT_TRUE(hosts->SetLink(true)) << hosts->error();
  // The stream really stopped: the link is the only way.
  ASSERT_TRUE(vision_client->last_detection.has_value());
  EXPECT_LT(*vision_client->last_detection - down, 300ms);

  const auto resumed = vision_client->UntilDetection(10s);
  ASSERT_TRUE(resumed.has_value()) << m->vision->Log();
  RecordProperty("vision_after_link_up_ms", static_cast<int>(resumed->count()));
  std::printf("vision resumed %lld ms after the link came back\n", static_cast<long long>(resumed->count()));
  const auto after = m->Drive();
  ASSERT_TRUE(after.has_value());
  EXPECT_GT(*after, 0.2) << m->grsim->Log();
  EXPECT_TRUE(m->sim->Running() && m->grsim->Running() && m->vision->Running());
}

// A lossy link (venue Wi-Fi, a busy switch): 5 % of the UDP packets crossing it are lost each way. DDS repairs
// what it can, so vision keeps flowing (no camera misses more than 30 frames in a row, half a second) and grSim
// commands still move robots.
TEST_F(MultiHost, FivePercentLossOnTheLinkVisionAndCommandsKeepFlowing) {
  const std::unique_ptr<Running> m = StartDivisionB();
  ASSERT_FALSE(HasFailure());
  VisionClient* vision_client = m->vision_client.get();
  ASSERT_TRUE(hosts->DropUdp(5)) << hosts->error();
  vision_client->ResetGaps();
  const int before = vision_client->detections;
  vision_client->Drain(5000ms);
  const long dropped = hosts->DroppedUdp();
  RecordProperty("longest_gap_frames", static_cast<int>(vision_client->longest_gap));
  std::printf("5%% loss: %ld packets dropped, %d detections, longest gap %u frames\n", dropped,
              vision_client->detections - before, vision_client->longest_gap);
  EXPECT_GT(dropped, 0) << "the loss rule dropped nothing: the test tested nothing";
  EXPECT_GT(vision_client->detections - before, 0) << m->vision->Log();
  EXPECT_LE(vision_client->longest_gap, 30u) << m->vision->Log();
  const auto moved = m->Drive();
  ASSERT_TRUE(moved.has_value());
  EXPECT_GT(*moved, 0.2) << m->grsim->Log();
  EXPECT_TRUE(m->sim->Running() && m->grsim->Running() && m->vision->Running());
}

}  // namespace
}  // namespace turf::test
