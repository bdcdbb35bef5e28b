// turf-sim --rcssservermj as a real process: an RCSSServerMJ agent served by turf-sim itself (as fast as it
// answers), stopping cleanly on SIGTERM. (The front-end next to the node in one process: front_end_test.cpp.)
#include <gtest/gtest.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <optional>
#include <regex>
#include <string>
#include <thread>

#include "tests/simspark/agent_client.h"
#include "tests/support/process.h"
#include "tests/test_domain.h"

namespace turf::test {
namespace {

using namespace std::chrono_literals;

double Now(const std::string& perception) {
  std::smatch m;
  return std::regex_search(perception, m, std::regex(R"(^\(time \(now ([-0-9.]+)\)\))")) ? std::stod(m[1]) : NAN;
}

TEST(RcssServerMjInTurfSim, AnAgentsRoundsStepTurfSimAndItStopsCleanly) {
  const int agent_port = FreePort(SOCK_STREAM), monitor_port = FreePort(SOCK_STREAM);
  Process sim("rcssservermj_in_sim",
              {Built("participants/sim/turf-sim"), "--scene",
               std::string(TURF_SOURCE_DIR) + "/configs/scenes/rcssservermj_fifa.yaml", "--lockstep", "--rcssservermj",
               "--rcssservermj-agent-port", std::to_string(agent_port), "--rcssservermj-monitor-port",
               std::to_string(monitor_port), "--rcssservermj-no-realtime", "--domain", std::to_string(TestDomain(23)),
               "--prefix", "mjinsim" + std::to_string(getpid())});
  AgentClient agent;
  const auto end = std::chrono::steady_clock::now() + 60s;  // loading 22 T1s takes seconds on a loaded machine
  while (!agent.Connect(static_cast<uint16_t>(agent_port)) && std::chrono::steady_clock::now() < end)
    std::this_thread::sleep_for(50ms);  // until turf-sim listens
  ASSERT_GE(agent.fd(), 0) << sim.Log();
  ASSERT_TRUE(agent.Send("(init T1 teamBlue 1)"));
  std::optional<std::string> m = agent.Receive(60s);
  ASSERT_TRUE(m.has_value()) << sim.Log();
  double before = Now(*m);
  for (int i = 0; i < 3; ++i) {
    ASSERT_TRUE(agent.Send("(syn)"));
    m = agent.Receive(20s);
    ASSERT_TRUE(m.has_value()) << sim.Log();
    EXPECT_NEAR(Now(*m) - before, 0.02, 1e-6) << *m;
    before = Now(*m);
  }
  EXPECT_NE(sim.Log().find("RCSSServerMJ agents: TCP 127.0.0.1:" + std::to_string(agent_port)), std::string::npos)
      << sim.Log();
  agent.Close();
  const int status = sim.Stop();
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << sim.Log();
}

}  // namespace
}  // namespace turf::test
