// dds::VendorParticipant: the Booster SDK's topics under their exact names and types, between two participants.
#include "dds/vendor_participant.h"

#include <gtest/gtest.h>

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <optional>

#include "tests/test_domain.h"
#include "turf/idl/BoosterLowLevelPubSubTypes.h"

namespace turf::dds {
namespace {

namespace bi = booster_interface::msg::dds_;
using Clock = std::chrono::steady_clock;

TEST(VendorParticipant, ALowStateReachesAReaderOfTheSdksTopicAndType) {
  const int domain = test::TestDomain(17);
  VendorParticipant robot(domain, "robot");
  VendorParticipant program(domain, "program");
  std::mutex mutex;
  std::condition_variable arrived;
  std::optional<bi::LowState_> got;
  auto reader = program.MakeReader<bi::LowState_PubSubType>("rt/low_state", [&](const bi::LowState_& s, int64_t) {
    std::lock_guard<std::mutex> lock(mutex);
    got = s;
    arrived.notify_all();
  });
  auto writer = robot.MakeWriter<bi::LowState_PubSubType>("rt/low_state");
  bi::LowState_ sent;
  sent.imu_state().acc({0.f, 0.f, 9.81f});
  sent.motor_state_serial().resize(23);
  sent.motor_state_serial()[1].q(0.785f);
  // Best effort: write until one arrives (discovery takes a moment), within a deadline.
  const auto deadline = Clock::now() + std::chrono::seconds(20);
  std::unique_lock<std::mutex> lock(mutex);
  while (!got && Clock::now() < deadline) {
    lock.unlock();
    writer->Write(sent);
    lock.lock();
    arrived.wait_for(lock, std::chrono::milliseconds(50), [&] { return got.has_value(); });
  }
  ASSERT_TRUE(got.has_value()) << "no LowState within 20 s";
  EXPECT_EQ(*got, sent);
  EXPECT_GE(writer->Matched(), 1);
}

}  // namespace
}  // namespace turf::dds
