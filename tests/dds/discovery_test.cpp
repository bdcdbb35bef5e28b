// Discovery of other participants' writers (dds::Participant::OtherWriters and its listener, issue 20): two
// participants on one domain and prefix each see the other's world_state writer, named by host, pid and program,
// and never their own; a listener hears writers come and go.
#include <gtest/gtest.h>
#include <turf/idl/ClockPubSubTypes.h>
#include <turf/idl/WorldStatePubSubTypes.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "dds/participant.h"
#include "tests/test_domain.h"

namespace turf {
namespace {

using namespace std::chrono_literals;
using Writers = std::vector<dds::RemoteWriter>;

constexpr auto kDiscoveryDeadline = 15s;

dds::ParticipantOptions Options(const std::string& name, const std::string& prefix) {
  dds::ParticipantOptions o;
  o.domain = test::TestDomain(17);
  o.prefix = prefix;
  o.name = name;
  o.qos_file = TURF_SOURCE_DIR "/configs/qos/turf_qos.xml";
  return o;
}

std::string UniquePrefix(const char* what) {
  static int counter = 0;
  return std::string(what) + std::to_string(getpid()) + "_" + std::to_string(++counter);
}

Writers WaitForCount(const dds::Participant& p, dds::Topic topic, size_t n) {
  return p.WaitForOtherWriters(
      topic, [n](const Writers& w) { return w.size() >= n; }, std::chrono::steady_clock::now() + kDiscoveryDeadline);
}

std::string HostName() {
  char name[256] = {};
  gethostname(name, sizeof(name) - 1);
  return name;
}

TEST(Discovery, TwoParticipantsSeeEachOthersWorldStateWriterWithHostAndPid) {
  const std::string prefix = UniquePrefix("disc");
  dds::Participant a(Options("sim-a", prefix));
  dds::Participant b(Options("sim-b", prefix));
  auto writer_a = a.MakeWriter(dds::Topic::kWorldState);
  auto writer_b = b.MakeWriter(dds::Topic::kWorldState);

  const Writers seen_by_a = WaitForCount(a, dds::Topic::kWorldState, 1);
  const Writers seen_by_b = WaitForCount(b, dds::Topic::kWorldState, 1);
  ASSERT_EQ(seen_by_a.size(), 1u) << "a never saw b's writer";
  ASSERT_EQ(seen_by_b.size(), 1u) << "b never saw a's writer";

  // Each sees the other, never itself.
  const dds::RemoteWriter& from_b = seen_by_a[0];
  EXPECT_EQ(from_b.topic, prefix + "/world_state");
  EXPECT_EQ(from_b.participant.guid_prefix, b.Self().guid_prefix);
  EXPECT_EQ(from_b.participant.name, "sim-b");
  EXPECT_EQ(from_b.participant.host, HostName());
  EXPECT_EQ(from_b.participant.pid, getpid());
  EXPECT_EQ(from_b.participant.program, program_invocation_short_name);
  EXPECT_GT(from_b.participant.started_unix_ns, 0);
  EXPECT_EQ(from_b.participant.started_unix_ns, b.Self().started_unix_ns);
  EXPECT_EQ(seen_by_b[0].participant.guid_prefix, a.Self().guid_prefix);
  EXPECT_EQ(seen_by_b[0].participant.name, "sim-a");
  EXPECT_NE(a.Self().guid_prefix, b.Self().guid_prefix);

  // The name in a log line carries the pid and host.
  const std::string named = from_b.participant.Describe();
  EXPECT_NE(named.find("pid " + std::to_string(getpid())), std::string::npos) << named;
  EXPECT_NE(named.find("host " + HostName()), std::string::npos) << named;
  EXPECT_NE(named.find("'sim-b'"), std::string::npos) << named;

  // Only topics of the prefix are kept: b's clock writer shows under clock, not under world_state.
  auto clock_b = b.MakeWriter(dds::Topic::kClock);
  ASSERT_EQ(WaitForCount(a, dds::Topic::kClock, 1).size(), 1u);
  EXPECT_EQ(a.OtherWriters(dds::Topic::kWorldState).size(), 1u);
  EXPECT_GE(a.OtherWritersSeen(), 2u);
}

TEST(Discovery, AnotherPrefixsWritersAreNotListed) {
  const std::string prefix = UniquePrefix("discp");
  dds::Participant a(Options("sim-a", prefix));
  dds::Participant other(Options("sim-other", prefix + "x"));
  dds::Participant b(Options("sim-b", prefix));
  // Written in this order: once a has seen b's writer, it has had the same chance to see the other prefix's.
  auto writer_other = other.MakeWriter(dds::Topic::kWorldState);
  auto writer_b = b.MakeWriter(dds::Topic::kWorldState);
  auto has_b = [](const Writers& writers) {
    for (const dds::RemoteWriter& w : writers)
      if (w.participant.name == "sim-b") return true;
    return false;
  };
  const Writers seen =
      a.WaitForOtherWriters(dds::Topic::kWorldState, has_b, std::chrono::steady_clock::now() + kDiscoveryDeadline);
  ASSERT_TRUE(has_b(seen));
  ASSERT_EQ(seen.size(), 1u) << seen.back().participant.Describe();
  EXPECT_EQ(other.OtherWriters(dds::Topic::kWorldState).size(), 0u);
}

// Events a listener heard, for the test thread to wait on.
class Heard {
 public:
  void Add(dds::WriterEvent event, const dds::RemoteWriter& writer) {
    std::lock_guard<std::mutex> lock(mutex_);
    events_.emplace_back(event, writer);
    changed_.notify_all();
  }
  // The events once there are `n` (or fewer, after 15 s).
  std::vector<std::pair<dds::WriterEvent, dds::RemoteWriter>> WaitFor(size_t n) {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait_for(lock, kDiscoveryDeadline, [&] { return events_.size() >= n; });
    return events_;
  }

 private:
  std::mutex mutex_;
  std::condition_variable changed_;
  std::vector<std::pair<dds::WriterEvent, dds::RemoteWriter>> events_;
};

TEST(Discovery, AListenerHearsAWriterAppearAndGo) {
  const std::string prefix = UniquePrefix("discl");
  dds::Participant a(Options("sim-a", prefix));
  Heard heard;
  const uint64_t id = a.AddWriterListener([&](dds::WriterEvent e, const dds::RemoteWriter& w) { heard.Add(e, w); });
  {
    dds::Participant b(Options("sim-b", prefix));
    auto writer_b = b.MakeWriter(dds::Topic::kWorldState);
    const auto appeared = heard.WaitFor(1);
    ASSERT_EQ(appeared.size(), 1u);
    EXPECT_EQ(appeared[0].first, dds::WriterEvent::kAppeared);
    EXPECT_EQ(appeared[0].second.topic, prefix + "/world_state");
    EXPECT_EQ(appeared[0].second.participant.guid_prefix, b.Self().guid_prefix);
  }  // b leaves: its writer goes (told by b as it is deleted, not by its lease)
  const auto both = heard.WaitFor(2);
  ASSERT_EQ(both.size(), 2u);
  EXPECT_EQ(both[1].first, dds::WriterEvent::kGone);
  EXPECT_EQ(both[1].second.guid, both[0].second.guid);
  EXPECT_TRUE(a.OtherWriters(dds::Topic::kWorldState).empty());
  a.RemoveWriterListener(id);
}

}  // namespace
}  // namespace turf
