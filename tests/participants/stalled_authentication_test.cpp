// A bridge restarts itself when one of its DDS authentications stalls while it waits for turf-sim, and only then
// (participants/common/stalled_authentication.h). Pure: the participant's counts are given.
#include "participants/common/stalled_authentication.h"

#include <gtest/gtest.h>

#include "participants/common/process.h"

namespace turf {
namespace {

dds::Authentications Stalled(uint64_t n) {
  dds::Authentications a;
  a.stalled = n;
  return a;
}

// Each case runs in its own process state: RequestRestart is process-wide, so these run in one test in order.
TEST(StalledAuthenticationRestart, OnlyAStallToldWhileWaitingRestarts) {
  StalledAuthenticationRestart restart;
  // Waiting, nothing stalled: no restart.
  EXPECT_FALSE(restart.Check(Stalled(0), /*waiting=*/true));
  // turf-sim is there; a stall told now (another peer's) is not the bridge's problem, nor later.
  EXPECT_FALSE(restart.Check(Stalled(1), /*waiting=*/false));
  EXPECT_FALSE(restart.Check(Stalled(1), /*waiting=*/true));
  EXPECT_FALSE(RestartRequested());
  EXPECT_FALSE(StopRequested());
  // Waiting again (turf-sim gone), and a new stall is told: restart.
  EXPECT_TRUE(restart.Check(Stalled(2), /*waiting=*/true));
  EXPECT_TRUE(RestartRequested());
  EXPECT_TRUE(StopRequested());
  // Told once per stall.
  EXPECT_FALSE(restart.Check(Stalled(2), /*waiting=*/true));
}

}  // namespace
}  // namespace turf
