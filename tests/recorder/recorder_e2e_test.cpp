// turf-record with real processes on a private domain: a recording of turf-sim for 3 simulated seconds is read
// back (every table topic a channel with its IDL schema, world states and clocks in simulation-time order, CDR
// that deserializes to the sample it came from), and a recorder killed with SIGKILL leaves a file that reads up
// to its last complete chunk.
#include <fastdds/rtps/common/SerializedPayload.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <turf/idl/WorldStatePubSubTypes.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include "codecs/mcap/reader.h"
#include "dds/topics.h"
#include "participants/common/mcap_file.h"
#include "participants/launcher/log_diff.h"
#include "tests/support/process.h"
#include "tests/test_domain.h"

namespace turf::test {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

struct Recording {
  mcap::FileInfo info;
  mcap::Damage damage;
  std::map<std::string, std::vector<mcap::Message>> by_topic;
  std::vector<std::string> data;  // keeps the messages' bytes
};

Recording Read(const std::string& path) {
  Recording r;
  McapFileSource source(path);
  EXPECT_TRUE(source.ok()) << source.error();
  if (!source.ok()) return r;
  std::vector<std::pair<std::string, mcap::Message>> all;
  r.damage = mcap::Scan(source, {}, &r.info, [&](const mcap::Channel& c, const mcap::Message& m) {
    r.data.emplace_back(m.data);
    all.emplace_back(c.topic, m);
  });
  r.data.reserve(r.data.size());
  for (size_t i = 0; i < all.size(); ++i) {
    all[i].second.data = r.data[i];
    r.by_topic[all[i].first].push_back(all[i].second);
  }
  return r;
}

std::vector<std::string> Args(std::vector<std::string> args, int domain, const std::string& prefix) {
  args.insert(args.end(), {"--domain", std::to_string(domain), "--prefix", prefix});
  return args;
}

// Polls a child's file (no notification exists for it) until `done` or the deadline.
template <class Done>
bool WaitFor(Done done, std::chrono::seconds deadline = 30s) {
  const auto end = Clock::now() + deadline;
  while (!done()) {
    if (Clock::now() > end) return false;
    std::this_thread::sleep_for(100ms);  // polling a file, not waiting for an event
  }
  return true;
}

// Records turf-sim (realistic sensors, no commands) on its own prefix until the recording holds `seconds` of sim
// time, then stops the recorder (SIGINT) before turf-sim, so no sample is cut by turf-sim's exit; the file's path.
std::string RecordOneRun(int domain, const std::string& prefix, double seconds, std::string* log = nullptr) {
  const std::string file = LogDir() + "/" + prefix + ".mcap";
  Process recorder(prefix + "_record",
                   Args({Built("participants/recorder/turf-record"), file, "--chunk-interval", "0.2"}, domain, prefix));
  EXPECT_TRUE(WaitFor([&] { return recorder.Log().find("reads " + prefix + "/robots/state") != std::string::npos; }))
      << recorder.Log();
  Process sim(prefix + "_sim", Args({Built("participants/sim/turf-sim"), "--realism", "realistic"}, domain, prefix));
  const uint64_t end_ns = static_cast<uint64_t>(seconds * 1e9);
  EXPECT_TRUE(WaitFor(
      [&] {
        const Recording r = Read(file);
        const auto it = r.by_topic.find(prefix + "/world_state");
        return it != r.by_topic.end() && !it->second.empty() && it->second.back().publish_time >= end_ns;
      },
      60s))
      << recorder.Log();
  recorder.Signal(SIGINT);
  const std::optional<int> status = recorder.Wait(20s);
  EXPECT_TRUE(status && WIFEXITED(*status) && WEXITSTATUS(*status) == 0) << recorder.Log();
  if (log != nullptr) *log = recorder.Log();
  return file;
}

TEST(RecorderE2e, RecordsEveryTopicOfTurfSimInSimTimeOrder) {
  const int domain = TestDomain(41);
  std::string log;
  const std::string file = RecordOneRun(domain, "rec" + std::to_string(getpid()), 3.0, &log);
  const std::string prefix = "rec" + std::to_string(getpid());
  const Recording r = Read(file);
  ASSERT_TRUE(r.damage.ok()) << r.damage.Describe();
  EXPECT_EQ(r.info.channels.size(), dds::kTopicCount);
  for (const auto& [id, c] : r.info.channels) {
    EXPECT_EQ(c.message_encoding, "cdr");
    const mcap::Schema& s = r.info.schemas.at(c.schema_id);
    EXPECT_EQ(s.encoding, "omgidl");
    EXPECT_EQ(s.name.rfind("turf::idl::", 0), 0u) << s.name;
    EXPECT_NE(s.data.find("struct " + s.name.substr(11)), std::string::npos) << s.name;
    EXPECT_EQ(c.metadata.at("dds_type"), s.name);
  }
  // 100 Hz of sim time for at least 3 s; the recorder was reading before turf-sim started.
  const std::vector<mcap::Message>& world = r.by_topic.at(prefix + "/world_state");
  const std::vector<mcap::Message>& clock = r.by_topic.at(prefix + "/clock");
  EXPECT_LE(world.front().publish_time, 10'000'000u);  // turf-sim's first (sim time 0 or 10 ms)
  EXPECT_GE(world.size(), 300u);
  EXPECT_EQ(world.size(), (world.back().publish_time - world.front().publish_time) / 10'000'000 + 1);  // none lost
  EXPECT_GE(clock.size() + 2, world.size());
  EXPECT_GE(r.by_topic.at(prefix + "/ssl/camera").size(), 4u * 170u);  // 4 cameras at 60 Hz, some lost (realistic)
  EXPECT_EQ(r.by_topic.at(prefix + "/ssl/field").size(), 1u);
  for (const auto* topic : {&world, &clock}) {
    for (size_t i = 1; i < topic->size(); ++i) {
      EXPECT_GT((*topic)[i].publish_time, (*topic)[i - 1].publish_time) << i;
      EXPECT_GE((*topic)[i].log_time, (*topic)[i - 1].log_time) << i;
      EXPECT_EQ((*topic)[i].sequence, (*topic)[i - 1].sequence + 1);
    }
  }
  // A message is the sample's CDR (encapsulation header first), and its publish_time the sample's sim time.
  idl::WorldStatePubSubType type;
  for (const mcap::Message& m : world) {
    ASSERT_GE(m.data.size(), 4u);
    EXPECT_EQ(std::memcmp(m.data.data(), "\x00\x01\x00\x00", 4), 0);
    eprosima::fastrtps::rtps::SerializedPayload_t payload(static_cast<uint32_t>(m.data.size()));
    std::memcpy(payload.data, m.data.data(), m.data.size());
    payload.length = static_cast<uint32_t>(m.data.size());
    idl::WorldState state;
    ASSERT_TRUE(type.deserialize(&payload, &state));
    EXPECT_EQ(static_cast<uint64_t>(state.sim_time_ns()), m.publish_time);
    EXPECT_FALSE(state.robots().empty());
  }
  EXPECT_NE(log.find("closed: "), std::string::npos) << log;
}

TEST(RecorderE2e, AKilledRecorderLeavesAFileReadableUpToItsLastChunk) {
  const int domain = TestDomain(42);
  const std::string prefix = "reckill" + std::to_string(getpid());
  const std::string file = LogDir() + "/" + prefix + ".mcap";
  Process recorder(prefix + "_record", Args({Built("participants/recorder/turf-record"), file, "--chunk-interval",
                                             "0.1", "--compression", "none", "--topics", "world_state,clock"},
                                            domain, prefix));
  ASSERT_TRUE(WaitFor([&] { return recorder.Log().find("reads " + prefix + "/clock") != std::string::npos; }))
      << recorder.Log();
  Process sim(prefix + "_sim", Args({Built("participants/sim/turf-sim"), "--realism", "ideal"}, domain, prefix));
  uint64_t chunks_before = 0;
  ASSERT_TRUE(WaitFor([&] {
    chunks_before = Read(file).info.statistics.chunk_count;
    return chunks_before >= 5;
  })) << recorder.Log();
  recorder.Kill();
  recorder.Wait(20s);
  const Recording r = Read(file);
  EXPECT_EQ(r.damage.error, mcap::ReadError::kTruncated) << r.damage.Describe();
  EXPECT_GE(r.info.statistics.chunk_count, chunks_before);
  EXPECT_EQ(r.damage.offset, r.info.read_up_to);
  EXPECT_EQ(r.info.channels.size(), 2u);  // --topics world_state,clock
  const std::vector<mcap::Message>& world = r.by_topic.at(prefix + "/world_state");
  ASSERT_FALSE(world.empty());
  for (size_t i = 1; i < world.size(); ++i) EXPECT_GT(world[i].publish_time, world[i - 1].publish_time);
  // turf log info says what the file holds and where it ends (exit status 1: damaged).
  Process info(prefix + "_info", {Built("participants/launcher/turf"), "log", "info", file});
  const std::optional<int> status = info.Wait(20s);
  ASSERT_TRUE(status && WIFEXITED(*status));
  EXPECT_EQ(WEXITSTATUS(*status), 1) << info.Log();
  EXPECT_NE(info.Log().find("truncated at offset"), std::string::npos) << info.Log();
}

// The same scene and seed run twice give the same recorded samples on every topic but the clock (its run epoch
// and measured speed are wall-clock values): the check re-simulation builds on.
TEST(RecorderE2e, TwoRunsOfOneSceneRecordTheSameSamples) {
  const int domain = TestDomain(45);
  const std::string a = RecordOneRun(domain, "recA" + std::to_string(getpid()), 2.0);
  const std::string b = RecordOneRun(domain, "recB" + std::to_string(getpid()), 2.0);
  McapFileSource fa(a), fb(b);
  // Up to 2 s (the recorders stopped at 2 s or a little later; a sample of another topic may still be on its way).
  launch::DiffOptions options;
  options.skip = {"clock"};
  options.until_ns = 1'900'000'000;
  const launch::LogDiff diff = launch::DiffRecordings(fa, fb, options);
  EXPECT_TRUE(diff.same) << diff.report;
  EXPECT_TRUE(diff.damage_a.ok() && diff.damage_b.ok()) << diff.report;
  // And the check can fail: the clock differs.
  options.skip.clear();
  EXPECT_FALSE(launch::DiffRecordings(fa, fb, options).same);
}

}  // namespace
}  // namespace turf::test
