// turf-sim --rcssservermj as a real process: an RCSSServerMJ agent served by turf-sim itself (as fast as it
// answers), stopping cleanly on SIGTERM. (The front-end next to the node in one process: front_end_test.cpp.)
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <chrono>
#include <optional>
#include <string>

#include "tests/simspark/front_end_in_sim.h"

namespace turf::test {
namespace {

using namespace std::chrono_literals;

TEST(RcssServerMjInTurfSim, AnAgentsRoundsStepTurfSimAndItStopsCleanly) {
  FrontEndInSim turf("rcssservermj", "rcssservermj_fifa.yaml", "no-realtime", 23);
  Process& sim = turf.sim;
  AgentClient agent;
  ASSERT_TRUE(turf.Connect(agent)) << sim.Log();
  ASSERT_TRUE(agent.Send("(init T1 teamBlue 1)"));
  std::optional<std::string> m = agent.Receive(60s);
  ASSERT_TRUE(m.has_value()) << sim.Log();
  double before = PerceptionTime(*m);
  for (int i = 0; i < 3; ++i) {
    ASSERT_TRUE(agent.Send("(syn)"));
    m = agent.Receive(20s);
    ASSERT_TRUE(m.has_value()) << sim.Log();
    EXPECT_NEAR(PerceptionTime(*m) - before, 0.02, 1e-6) << *m;
    before = PerceptionTime(*m);
  }
  EXPECT_NE(sim.Log().find("RCSSServerMJ agents: TCP 127.0.0.1:" + std::to_string(turf.agent_port)), std::string::npos)
      << sim.Log();
  agent.Close();
  const int status = sim.Stop();
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << sim.Log();
}

}  // namespace
}  // namespace turf::test
