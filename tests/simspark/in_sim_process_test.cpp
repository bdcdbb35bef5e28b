// turf-sim --simspark as a real process: SimSpark agents served by turf-sim itself (sync mode), stopping cleanly
// on SIGTERM. (The same front-end against the node in one process: tests/sim/sim_host_test.cpp.)
#include <gtest/gtest.h>

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "tests/simspark/front_end_in_sim.h"

namespace turf::test {
namespace {

using namespace std::chrono_literals;

TEST(SimSparkInTurfSim, AnAgentsSyncCyclesStepTurfSimAndItStopsCleanly) {
  FrontEndInSim turf("simspark", "simspark_match.yaml", "sync", 17);  // no --lockstep: the front-end implies it
  const std::optional<std::string> first = turf.Hello("(scene rsg/agent/nao/nao_hetero.rsg 0)", 15s);
  ASSERT_TRUE(first.has_value());
  // The world waits for the front-end from its first frame: the first perception is the first cycle's, whenever the
  // agent connects (it was one cycle later in 2 of 8 runs when turf-sim began in real time).
  EXPECT_DOUBLE_EQ(PerceptionTime(*first), 0.02) << *first;
  // The 5 grace cycles after scene run without (syn); then each (syn) is one cycle.
  for (int i = 1; i < 5; ++i) ASSERT_TRUE(turf.agent.Receive(10s).has_value()) << "grace cycle " << i;
  const std::vector<double> times = turf.SynRounds(3, 10s);
  ASSERT_EQ(times.size(), 3u);
  ExpectCyclesOf20ms(times);
  turf.ExpectAnnouncedAndCleanStop("agents");
}

}  // namespace
}  // namespace turf::test
