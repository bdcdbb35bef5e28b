// `turf log diff`: two recordings compared sample by sample: the same samples under other prefixes are the same;
// a changed byte, a missing tail and a skipped topic are reported as they are.
#include <gtest/gtest.h>

#include <string>

#include "codecs/mcap/writer.h"
#include "participants/launcher/log_diff.h"

namespace turf::launch {
namespace {

// 50 world states and clocks (sim time 10 ms apart); `change` alters world state #change's byte 3 (-1: none);
// `count` world states only.
std::string Recording(const std::string& prefix, int change = -1, int count = 50, uint64_t clock_salt = 0) {
  mcap::StringSink sink;
  mcap::Writer w(&sink, {});
  const uint16_t world = w.AddChannel(0, prefix + "/world_state", "cdr");
  const uint16_t clock = w.AddChannel(0, prefix + "/clock", "cdr");
  for (int i = 0; i < 50; ++i) {
    const uint64_t sim = 10'000'000ull * static_cast<uint64_t>(i + 1);
    std::string data = "world state " + std::to_string(i);
    if (i == change) data[3] ^= 1;
    if (i < count) w.Write(world, static_cast<uint32_t>(i), 1000 + static_cast<uint64_t>(i), sim, data);
    w.Write(clock, static_cast<uint32_t>(i), 1000 + static_cast<uint64_t>(i), sim,
            "clock " + std::to_string(static_cast<uint64_t>(i) + clock_salt));
  }
  w.Close();
  return sink.bytes();
}

LogDiff Diff(const std::string& a, const std::string& b, std::set<std::string> skip = {},
             uint64_t until_ns = UINT64_MAX) {
  DiffOptions options;
  options.skip = std::move(skip);
  options.until_ns = until_ns;
  return DiffRecordings(mcap::StringSource(a), mcap::StringSource(b), options);
}

TEST(LogDiff, TheSameSamplesUnderAnotherPrefixAreTheSame) {
  const LogDiff d = Diff(Recording("turf"), Recording("other"));
  EXPECT_TRUE(d.same) << d.report;
  EXPECT_EQ(d.report, "same: 100 samples on 2 topics\n");
}

TEST(LogDiff, NamesTheFirstDifferingSampleAndByte) {
  const LogDiff d = Diff(Recording("turf"), Recording("turf", 7));
  EXPECT_FALSE(d.same);
  EXPECT_EQ(d.report,
            "first difference: world_state sample #7 (sim time 0.080000 s): 13 bytes in A, 13 in B, first differing "
            "byte at offset 3\n");
}

TEST(LogDiff, TheEarliestDifferenceBySimTimeAcrossTopics) {
  // The clocks differ from sample #0 on, world state #7: the clock is reported.
  const LogDiff d = Diff(Recording("turf"), Recording("turf", 7, 50, 1000));
  EXPECT_NE(d.report.find("first difference: clock sample #0 (sim time 0.010000 s)"), std::string::npos) << d.report;
  // Skipping the clock (its run epoch differs between runs) leaves the world state.
  const LogDiff skipped = Diff(Recording("turf"), Recording("turf", 7, 50, 1000), {"clock"});
  EXPECT_NE(skipped.report.find("world_state sample #7"), std::string::npos) << skipped.report;
}

TEST(LogDiff, AMissingTailIsNamed) {
  const LogDiff d = Diff(Recording("turf"), Recording("turf", -1, 40));
  EXPECT_FALSE(d.same);
  EXPECT_EQ(d.report,
            "first difference: world_state sample #40 (sim time 0.410000 s): B ends after 40 samples, A has 50\n");
}

TEST(LogDiff, UntilLeavesOutTheLaterSamples) {
  EXPECT_FALSE(Diff(Recording("turf"), Recording("turf", -1, 40)).same);
  EXPECT_TRUE(Diff(Recording("turf"), Recording("turf", -1, 40), {}, 400'000'000).same);
  EXPECT_FALSE(Diff(Recording("turf"), Recording("turf", -1, 40), {}, 410'000'000).same);
}

TEST(LogDiff, ADamagedFileIsComparedUpToTheDamage) {
  const std::string whole = Recording("turf");
  const LogDiff d = Diff(whole, whole.substr(0, whole.size() - 100));
  EXPECT_EQ(d.damage_b.error, mcap::ReadError::kTruncated);
  EXPECT_NE(d.report.find("B: compared up to truncated at offset"), std::string::npos) << d.report;
}

}  // namespace
}  // namespace turf::launch
