// turf-sim and turf-hlvs-bridge as real processes over DDS (UDP): an HLVS client gets Welcome and measurements every
// 8 ms of simulated time, then both stop cleanly on SIGTERM. (The bridge next to the node in one process:
// hlvs_bridge_test.cpp.)
#include <gtest/gtest.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <thread>

#include "tests/hlvs/hlvs_client.h"
#include "tests/support/process.h"
#include "tests/test_domain.h"

namespace turf::test {
namespace {

using namespace std::chrono_literals;

TEST(HlvsBridgeProcess, AClientIsServedOverDdsAndBothStopCleanly) {
  // Red player 2 has a port but no robot in the scene.
  const int red = FreePort(SOCK_STREAM), red2 = FreePort(SOCK_STREAM), blue = FreePort(SOCK_STREAM);
  const std::string domain = std::to_string(TestDomain(29)), prefix = "hlvsproc" + std::to_string(getpid());
  Process sim("hlvs_sim",
              {Built("participants/sim/turf-sim"), "--scene",
               std::string(TURF_SOURCE_DIR) + "/configs/scenes/hlvs.yaml", "--domain", domain, "--prefix", prefix});
  Process bridge("hlvs_bridge",
                 {Built("participants/hlvs_bridge/turf-hlvs-bridge"), "--listen", "127.0.0.1", "--red-ports",
                  std::to_string(red) + "," + std::to_string(red2), "--blue-ports", std::to_string(blue),
                  "--realtime-factor", "0", "--domain", domain, "--prefix", prefix});
  HlvsClient client;
  std::string greeting;
  const auto end = std::chrono::steady_clock::now() + 60s;
  while (greeting != std::string("Welcome\0", 8) && std::chrono::steady_clock::now() < end) {
    // Refused (or closed) until the bridge has attached to turf-sim: the sample client also tries again.
    if (client.Connect(static_cast<uint16_t>(red))) greeting = client.Greeting(5s);
    if (greeting != std::string("Welcome\0", 8)) std::this_thread::sleep_for(200ms);
  }
  ASSERT_EQ(greeting, std::string("Welcome\0", 8)) << bridge.Log() << sim.Log();
  auto m = client.Receive(20s);
  ASSERT_TRUE(m.has_value()) << bridge.Log();
  for (int i = 0; i < 10; ++i) {
    auto next = client.Receive(20s);
    ASSERT_TRUE(next.has_value()) << bridge.Log();
    EXPECT_EQ(next->time(), m->time() + 8);
    m = next;
  }
  EXPECT_NE(bridge.Log().find("robot 'red_1' (K1) on TCP 127.0.0.1:" + std::to_string(red)), std::string::npos)
      << bridge.Log();
  EXPECT_NE(bridge.Log().find("red player 2: no robot 'red_2' in the scene; TCP 127.0.0.1:" + std::to_string(red2) +
                              " refuses its clients"),
            std::string::npos)
      << bridge.Log();
  client.Close();
  const int bridge_status = bridge.Stop();
  EXPECT_TRUE(WIFEXITED(bridge_status) && WEXITSTATUS(bridge_status) == 0) << bridge.Log();
  const int sim_status = sim.Stop();
  EXPECT_TRUE(WIFEXITED(sim_status) && WEXITSTATUS(sim_status) == 0) << sim.Log();
}

}  // namespace
}  // namespace turf::test
