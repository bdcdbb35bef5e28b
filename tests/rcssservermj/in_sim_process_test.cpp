// turf-sim --rcssservermj as a real process: an RCSSServerMJ agent served by turf-sim itself (as fast as it
// answers), stopping cleanly on SIGTERM. (The front-end next to the node in one process: front_end_test.cpp.)
#include <gtest/gtest.h>

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "tests/simspark/front_end_in_sim.h"

namespace turf::test {
namespace {

using namespace std::chrono_literals;

TEST(RcssServerMjInTurfSim, AnAgentsRoundsStepTurfSimAndItStopsCleanly) {
  FrontEndInSim turf("rcssservermj", "rcssservermj_fifa.yaml", "no-realtime", 23);
  const std::optional<std::string> first = turf.Hello("(init T1 teamBlue 1)", 60s);
  ASSERT_TRUE(first.has_value());
  // Each round of actions is one cycle, from the perception that answered init on.
  std::vector<double> times = turf.SynRounds(3, 20s);
  times.insert(times.begin(), PerceptionTime(*first));
  ASSERT_EQ(times.size(), 4u);
  ExpectCyclesOf20ms(times);
  turf.ExpectAnnouncedAndCleanStop("RCSSServerMJ agents");
}

}  // namespace
}  // namespace turf::test
