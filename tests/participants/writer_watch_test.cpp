// The checks turf-sim and the bridges share against two simulators on one domain and prefix
// (participants/common/writer_watch.h): which writer was there first, dead processes left out, and the report of a
// second writer naming both.
#include "participants/common/writer_watch.h"

#include <gtest/gtest.h>
#include <spdlog/spdlog.h>
#include <sys/wait.h>
#include <turf/idl/ClockPubSubTypes.h>
#include <turf/idl/WorldStatePubSubTypes.h>
#include <unistd.h>

#include <chrono>
#include <memory>
#include <mutex>
#include <string>

#include "tests/support/captured_log.h"
#include "tests/test_domain.h"

namespace turf {
namespace {

using namespace std::chrono_literals;

constexpr auto kDeadline = 15s;

using test::CapturedLog;

ParticipantOptions Options(const std::string& name, const std::string& prefix) {
  ParticipantOptions o;
  o.domain = test::TestDomain(23);
  o.prefix = prefix;
  o.name = name;
  o.qos_file = TURF_SOURCE_DIR "/configs/qos/turf_qos.xml";
  return o;
}

dds::ParticipantOptions DdsOptions(const std::string& name, const std::string& prefix) {
  const ParticipantOptions o = Options(name, prefix);
  return {o.domain, o.name, o.prefix, o.qos_file};
}

std::string UniquePrefix(const char* what) {
  static int counter = 0;
  return std::string(what) + std::to_string(getpid()) + "_" + std::to_string(++counter);
}

dds::PeerInfo Peer(int64_t started, const std::string& guid_prefix) {
  dds::PeerInfo p;
  p.host = "h";
  p.pid = 1;
  p.started_unix_ns = started;
  p.guid_prefix = guid_prefix;
  return p;
}

TEST(StartedEarlier, TheEarlierStartWinsTiesGoToTheSmallerGuidUnknownCountsAsEarlier) {
  EXPECT_TRUE(StartedEarlier(Peer(100, "b"), Peer(200, "a")));
  EXPECT_FALSE(StartedEarlier(Peer(200, "a"), Peer(100, "b")));
  EXPECT_TRUE(StartedEarlier(Peer(100, "a"), Peer(100, "b")));
  EXPECT_FALSE(StartedEarlier(Peer(100, "b"), Peer(100, "a")));
  EXPECT_TRUE(StartedEarlier(Peer(0, "z"), Peer(100, "a")));  // not a turf participant: it gives no way
}

TEST(WriterProcessGone, OnlyAProcessOfThisHostThatNoLongerRuns) {
  dds::Participant self(DdsOptions("self", UniquePrefix("gone")));
  const pid_t child = fork();
  if (child == 0) _exit(0);
  ASSERT_GT(child, 0);
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);  // reaped: the pid is free

  dds::RemoteWriter w;
  w.participant.host = self.Self().host;
  w.participant.pid = child;
  EXPECT_TRUE(WriterProcessGone(w, self.Self()));
  w.participant.pid = getpid();
  EXPECT_FALSE(WriterProcessGone(w, self.Self()));
  w.participant.pid = child;
  w.participant.host = self.Self().host + "-elsewhere";
  EXPECT_FALSE(WriterProcessGone(w, self.Self())) << "another host's pid says nothing here";
  w.participant.host = "";
  w.participant.pid = 0;
  EXPECT_FALSE(WriterProcessGone(w, self.Self())) << "a writer that does not say is assumed to run";
}

TEST(FindEarlierWriter, TheLaterParticipantFindsTheEarlierOneNotTheOtherWayRound) {
  const std::string prefix = UniquePrefix("earlier");
  dds::Participant first(DdsOptions("first", prefix));
  auto first_writer = first.MakeWriter(dds::Topic::kWorldState);
  dds::Participant second(DdsOptions("second", prefix));
  auto second_writer = second.MakeWriter(dds::Topic::kWorldState);

  const auto found = FindEarlierWriter(second, dds::Topic::kWorldState, kDeadline);
  ASSERT_TRUE(found.has_value()) << "the later participant did not find the earlier one's writer";
  EXPECT_EQ(found->participant.guid_prefix, first.Self().guid_prefix);
  const std::string line = RefusalLine(second, dds::Topic::kWorldState, *found);
  EXPECT_NE(line.find("pid " + std::to_string(getpid())), std::string::npos) << line;
  EXPECT_NE(line.find(prefix + "/world_state"), std::string::npos) << line;

  // The first one knows the second's writer, and does not give way to it.
  ASSERT_EQ(first
                .WaitForOtherWriters(
                    dds::Topic::kWorldState, [](const auto& w) { return !w.empty(); },
                    std::chrono::steady_clock::now() + kDeadline)
                .size(),
            1u);
  EXPECT_FALSE(FindEarlierWriter(first, dds::Topic::kWorldState, 0ms).has_value());
}

TEST(BridgeWriterWatch, ReportsASecondWriterOfWorldStateNamingBoth) {
  CapturedLog log;
  const std::string prefix = UniquePrefix("bridge");
  BridgeWriterWatch watch(Options("bridge", prefix));
  dds::Participant sim_a(DdsOptions("sim-a", prefix));
  auto writer_a = sim_a.MakeWriter(dds::Topic::kWorldState);
  // One simulator is what a bridge expects: no report once the watch has seen it.
  ASSERT_EQ(watch.participant()
                .WaitForOtherWriters(
                    dds::Topic::kWorldState, [](const auto& w) { return !w.empty(); },
                    std::chrono::steady_clock::now() + kDeadline)
                .size(),
            1u);

  dds::Participant sim_b(DdsOptions("sim-b", prefix));
  auto writer_b = sim_b.MakeWriter(dds::Topic::kWorldState);
  ASSERT_EQ(watch.watch().WaitForConflicts(1, kDeadline), 1u) << log.Text();
  const std::string text = log.Text();
  const std::string expected = "error 2 writers of " + prefix + "/world_state";
  const auto line_at = text.find(expected);
  ASSERT_NE(line_at, std::string::npos) << text;
  const std::string line = text.substr(line_at, text.find('\n', line_at) - line_at);
  EXPECT_NE(line.find("'sim-a' (pid " + std::to_string(getpid())), std::string::npos) << line;
  EXPECT_NE(line.find("'sim-b' (pid " + std::to_string(getpid())), std::string::npos) << line;
  EXPECT_NE(line.find("on host " + sim_a.Self().host), std::string::npos) << line;
}

TEST(WriterWatch, TurfSimReportsAnyOtherWriterOfItsWorldState) {
  CapturedLog log;
  const std::string prefix = UniquePrefix("own");
  dds::Participant sim(DdsOptions("sim", prefix));
  auto own = sim.MakeWriter(dds::Topic::kWorldState);
  WriterWatch watch(sim, {{dds::Topic::kWorldState}, /*own_writer=*/true});
  dds::Participant intruder(DdsOptions("intruder", prefix));
  auto writer = intruder.MakeWriter(dds::Topic::kWorldState);
  ASSERT_EQ(watch.WaitForConflicts(1, kDeadline), 1u) << log.Text();
  const std::string text = log.Text();
  EXPECT_NE(text.find("error another writer of " + prefix + "/world_state"), std::string::npos) << text;
  EXPECT_NE(text.find("'intruder' (pid " + std::to_string(getpid())), std::string::npos) << text;
}

}  // namespace
}  // namespace turf
