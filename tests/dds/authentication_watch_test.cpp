// dds/authentication_watch.h, without DDS: which discovered participants are still authenticating, and which are
// overdue (each told once), with the time given.
#include "dds/authentication_watch.h"

#include <gtest/gtest.h>

#include <chrono>
#include <optional>
#include <string>

namespace turf::dds {
namespace {

using namespace std::chrono_literals;
using Clock = AuthenticationWatch::Clock;

PeerInfo Peer(const std::string& prefix) { return PeerInfo{"bridge", "lab-3", 42, "turf-vision-bridge", 1, prefix}; }

TEST(AuthenticationWatch, APeerPendingPastTheTimeoutIsToldOnce) {
  AuthenticationWatch watch(20s);
  const Clock::time_point t0{};
  watch.Discovered(Peer("a"), t0);
  watch.Discovered(Peer("b"), t0 + 5s);
  EXPECT_TRUE(watch.Overdue(t0 + 19s).empty());
  const auto overdue = watch.Overdue(t0 + 20s);
  ASSERT_EQ(overdue.size(), 1u);
  EXPECT_EQ(overdue[0].guid_prefix, "a");
  EXPECT_EQ(overdue[0].pid, 42);
  EXPECT_TRUE(watch.Overdue(t0 + 21s).empty());  // a: told already; b: 16 s
  ASSERT_EQ(watch.Overdue(t0 + 25s).size(), 1u);
  EXPECT_EQ(watch.Stalled(), 2u);
  EXPECT_EQ(watch.Pending(), 2u);  // still pending: told, not forgotten
}

TEST(AuthenticationWatch, AnEndedOrGoneAuthenticationIsNeverOverdue) {
  AuthenticationWatch watch(20s);
  const Clock::time_point t0{};
  watch.Discovered(Peer("authorized"), t0);
  watch.Discovered(Peer("left"), t0);
  watch.Discovered(Peer("stalled"), t0);
  const std::optional<PeerInfo> authorized = watch.Ended("authorized");
  ASSERT_TRUE(authorized);
  EXPECT_EQ(authorized->program, "turf-vision-bridge");  // as discovered: a refusal's warning names it
  watch.Gone("left");
  EXPECT_FALSE(watch.Ended("never-discovered"));  // not counted: it was not pending
  EXPECT_EQ(watch.Pending(), 1u);
  EXPECT_EQ(watch.Ended(), 1u);
  const auto overdue = watch.Overdue(t0 + 60s);
  ASSERT_EQ(overdue.size(), 1u);
  EXPECT_EQ(overdue[0].guid_prefix, "stalled");
}

// Announcements are not authenticated: made-up participants beyond the cap are not kept.
TEST(AuthenticationWatch, KeepsAtMostItsCapOfPendingParticipants) {
  AuthenticationWatch watch(1s);
  for (size_t i = 0; i < AuthenticationWatch::kMaxPending + 10; ++i)
    watch.Discovered(Peer("p" + std::to_string(i)), Clock::time_point{});
  EXPECT_EQ(watch.Pending(), AuthenticationWatch::kMaxPending);
}

}  // namespace
}  // namespace turf::dds
