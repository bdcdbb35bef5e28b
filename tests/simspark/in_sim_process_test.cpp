// turf-sim --simspark as a real process: SimSpark agents served by turf-sim itself (sync mode), stopping cleanly
// on SIGTERM. (The same front-end against the node in one process: tests/sim/sim_host_test.cpp.)
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
#include <vector>

#include "tests/simspark/agent_client.h"
#include "tests/support/process.h"
#include "tests/test_domain.h"

namespace turf::test {
namespace {

using namespace std::chrono_literals;

double Now(const std::string& perception) {
  std::smatch m;
  return std::regex_search(perception, m, std::regex(R"(\(time \(now ([-0-9.]+)\)\))")) ? std::stod(m[1]) : NAN;
}

TEST(SimSparkInTurfSim, AnAgentsSyncCyclesStepTurfSimAndItStopsCleanly) {
  const int agent_port = FreePort(SOCK_STREAM), monitor_port = FreePort(SOCK_STREAM);
  Process sim("simspark_in_sim",
              {Built("participants/sim/turf-sim"), "--scene",
               std::string(TURF_SOURCE_DIR) + "/configs/scenes/simspark_match.yaml", "--lockstep", "--simspark",
               "--simspark-agent-port", std::to_string(agent_port), "--simspark-monitor-port",
               std::to_string(monitor_port), "--simspark-sync", "--domain", std::to_string(TestDomain(17)), "--prefix",
               "simsparkinsim" + std::to_string(getpid())});
  AgentClient agent;
  const auto end = std::chrono::steady_clock::now() + 60s;  // loading 22 Naos takes seconds on a loaded machine
  while (!agent.Connect(static_cast<uint16_t>(agent_port)) && std::chrono::steady_clock::now() < end)
    std::this_thread::sleep_for(50ms);  // until turf-sim listens
  ASSERT_GE(agent.fd(), 0) << sim.Log();
  agent.Send("(scene rsg/agent/nao/nao_hetero.rsg 0)");
  ASSERT_TRUE(agent.Receive(15s).has_value()) << sim.Log();
  for (int i = 1; i < 5; ++i) ASSERT_TRUE(agent.Receive(10s).has_value()) << "grace cycle " << i;
  std::vector<double> times;
  for (int i = 0; i < 3; ++i) {
    agent.Send("(syn)");
    const std::optional<std::string> m = agent.Receive(10s);
    ASSERT_TRUE(m.has_value()) << sim.Log();
    times.push_back(Now(*m));
  }
  EXPECT_NEAR(times[1] - times[0], 0.02, 1e-6);
  EXPECT_NEAR(times[2] - times[1], 0.02, 1e-6);
  EXPECT_NE(sim.Log().find("agents: TCP 127.0.0.1:" + std::to_string(agent_port)), std::string::npos) << sim.Log();
  agent.Close();
  const int status = sim.Stop();
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << sim.Log();
}

}  // namespace
}  // namespace turf::test
