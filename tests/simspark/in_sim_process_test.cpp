// turf-sim --simspark as a real process: SimSpark agents served by turf-sim itself (sync mode), stopping cleanly
// on SIGTERM. (The same front-end against the node in one process: tests/sim/sim_host_test.cpp.)
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "tests/simspark/front_end_in_sim.h"

namespace turf::test {
namespace {

using namespace std::chrono_literals;

TEST(SimSparkInTurfSim, AnAgentsSyncCyclesStepTurfSimAndItStopsCleanly) {
  FrontEndInSim turf("simspark", "simspark_match.yaml", "sync", 17);
  Process& sim = turf.sim;
  AgentClient agent;
  ASSERT_TRUE(turf.Connect(agent)) << sim.Log();
  agent.Send("(scene rsg/agent/nao/nao_hetero.rsg 0)");
  ASSERT_TRUE(agent.Receive(15s).has_value()) << sim.Log();
  for (int i = 1; i < 5; ++i) ASSERT_TRUE(agent.Receive(10s).has_value()) << "grace cycle " << i;
  std::vector<double> times;
  for (int i = 0; i < 3; ++i) {
    agent.Send("(syn)");
    const std::optional<std::string> m = agent.Receive(10s);
    ASSERT_TRUE(m.has_value()) << sim.Log();
    times.push_back(PerceptionTime(*m));
  }
  EXPECT_NEAR(times[1] - times[0], 0.02, 1e-6);
  EXPECT_NEAR(times[2] - times[1], 0.02, 1e-6);
  EXPECT_NE(sim.Log().find("agents: TCP 127.0.0.1:" + std::to_string(turf.agent_port)), std::string::npos) << sim.Log();
  agent.Close();
  const int status = sim.Stop();
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << sim.Log();
}

}  // namespace
}  // namespace turf::test
