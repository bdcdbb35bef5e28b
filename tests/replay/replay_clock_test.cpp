// Replay pacing: the recorded receive times at a speed, from the first message on.
#include <gtest/gtest.h>

#include "participants/replay/replay_clock.h"

namespace turf {
namespace {

using namespace std::chrono_literals;

TEST(ReplayClock, RealTimeScaledAndMax) {
  const auto start = std::chrono::steady_clock::time_point(100s);
  ReplayClock real(1.0, start), fast(4.0, start), max(0.0, start);
  EXPECT_EQ(real.Due(5'000'000'000), start);  // the first message fixes the origin
  EXPECT_EQ(real.Due(6'000'000'000), start + 1s);
  EXPECT_EQ(real.Due(4'000'000'000), start);  // out of order: due at once
  EXPECT_EQ(fast.Due(5'000'000'000), start);
  EXPECT_EQ(fast.Due(7'000'000'000), start + 500ms);
  EXPECT_EQ(max.Due(5'000'000'000), start);
  EXPECT_EQ(max.Due(9'000'000'000), start);
}

// A file's log times are untrusted: the largest gap at the slowest speed is due within the clock's range (a
// nanosecond count past int64 was a conversion out of range, in practice due at once).
TEST(ReplayClock, AGapOfCenturiesIsDueAfterTheLongestWait) {
  const auto start = std::chrono::steady_clock::time_point(100s);
  ReplayClock clock(1e-3, start);
  EXPECT_EQ(clock.Due(0), start);
  const auto longest = std::chrono::nanoseconds(static_cast<int64_t>(kMaxReplayWaitNs));
  EXPECT_EQ(clock.Due(uint64_t{1} << 63), start + longest);
  EXPECT_EQ(clock.Due(~uint64_t{0}), start + longest);
  EXPECT_EQ(clock.Due(1'000'000), start + 1s);  // the pace below the limit is the speed's
}

TEST(ReplayClock, AnOriginAfterTheFirstMessage) {
  const auto start = std::chrono::steady_clock::time_point(100s);
  ReplayClock clock(2.0, start);
  clock.SetOrigin(10'000'000'000);
  EXPECT_EQ(clock.Due(9'000'000'000), start);
  EXPECT_EQ(clock.Due(12'000'000'000), start + 1s);
}

TEST(ReplayClock, APauseMovesEveryLaterMessageOnByItsLength) {
  const auto start = std::chrono::steady_clock::time_point(100s);
  ReplayClock clock(1.0, start);
  EXPECT_EQ(clock.Due(1'000'000'000), start);
  EXPECT_EQ(clock.Due(3'000'000'000), start + 2s);
  clock.Pause(start + 1s);
  EXPECT_TRUE(clock.paused());
  clock.Pause(start + 2s);  // a second pause changes nothing
  clock.Resume(start + 5s);
  EXPECT_FALSE(clock.paused());
  EXPECT_EQ(clock.Due(3'000'000'000), start + 6s);  // paused 4 s
  clock.Resume(start + 9s);                         // not paused: nothing
  EXPECT_EQ(clock.Due(3'000'000'000), start + 6s);
}

TEST(ReplayClock, RebaseMakesAMessageDueNowAtANewSpeed) {
  const auto start = std::chrono::steady_clock::time_point(100s);
  ReplayClock clock(1.0, start);
  EXPECT_EQ(clock.Due(1'000'000'000), start);
  clock.Rebase(8'000'000'000, 4.0, start + 3s);  // a seek to 8 s (recorded), now at 4x
  EXPECT_EQ(clock.speed(), 4.0);
  EXPECT_EQ(clock.Due(8'000'000'000), start + 3s);
  EXPECT_EQ(clock.Due(12'000'000'000), start + 4s);
  clock.Pause(start + 3s);
  clock.Rebase(2'000'000'000, 1.0, start + 10s);  // rebased while paused: the pause counts from the rebase
  clock.Resume(start + 12s);
  EXPECT_EQ(clock.Due(2'000'000'000), start + 12s);
  EXPECT_EQ(clock.Due(3'000'000'000), start + 13s);
}

}  // namespace
}  // namespace turf
