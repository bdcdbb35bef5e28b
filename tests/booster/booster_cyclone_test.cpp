// The Booster SDK's rt/low_state across DDS vendors: turf (Fast DDS) publishes it for a T1, and a reader built with
// Debian's Cyclone DDS from the same IDL (cyclone_low_state_reader.c) receives it with the right contents. turf-sim
// runs in lockstep on a memory bus and is stepped until the reader has exited (deadline 30 s).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <optional>
#include <thread>

#include "tests/booster/booster_rig.h"
#include "tests/support/process.h"
#include "tests/test_domain.h"

namespace turf {
namespace {

using namespace std::chrono_literals;

TEST(BoosterCyclone, ACycloneDdsReaderReceivesTurfsLowState) {
  const int domain = test::TestDomain(31);
  test::BoosterRig rig(test::IdealT1Stand(), domain);
  // Settle on the feet (1 s), then serve until the reader has one sample.
  ASSERT_TRUE(rig.Step(200).ok());
  test::Process reader("cyclone_low_state_reader", {TURF_CYCLONE_READER, std::to_string(domain), "30"});
  std::optional<int> status;
  const auto deadline = std::chrono::steady_clock::now() + 40s;
  while (!status && std::chrono::steady_clock::now() < deadline) {
    ASSERT_TRUE(rig.Step(4).ok());  // 20 ms: a few sensor frames
    status = reader.Wait(1ms);
  }
  ASSERT_TRUE(status.has_value()) << "the Cyclone DDS reader did not finish: " << reader.Log();
  ASSERT_TRUE(WIFEXITED(*status) && WEXITSTATUS(*status) == 0) << reader.Log();
  unsigned serial = 0, parallel = 0;
  float head = 0, acc_z = 0;
  ASSERT_EQ(std::sscanf(reader.Log().c_str(), "joints %u %u head_pitch %f acc_z %f", &serial, &parallel, &head, &acc_z),
            4)
      << reader.Log();
  EXPECT_EQ(serial, 23u);
  EXPECT_EQ(parallel, 23u);
  EXPECT_NEAR(acc_z, 9.81, 0.3);  // standing
  EXPECT_LT(std::abs(head), 0.5);
}

}  // namespace
}  // namespace turf
