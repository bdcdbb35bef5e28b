// dds/held_samples.h, without DDS: what a durable writer keeps while no reader is matched and writes when one
// matches. One ring for an unkeyed topic; one per instance for a keyed one, flushed in writing order, with the
// writer's instance limit. Then over Fast DDS on a private domain: a reader that matches late gets, per robot,
// the joint states a keyed writer would have kept (the last `depth` of each), and no others.
#include <gtest/gtest.h>
#include <turf/idl/JointsPubSubTypes.h>
#include <unistd.h>

#include <chrono>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "dds/held_samples.h"
#include "dds/participant.h"
#include "tests/support/wake_wait.h"
#include "tests/test_domain.h"

namespace turf {
namespace {

struct Sample {
  int robot = 0;
  int value = 0;
};

// What the writer was given to write: (robot, value, source time).
struct Written {
  std::vector<std::pair<int, int>> samples;
  std::vector<int64_t> source_ns;
  dds::HeldSamples::WriteFn Fn() {
    return [this](const void* s, std::optional<int64_t> ns) {
      const auto* sample = static_cast<const Sample*>(s);
      samples.emplace_back(sample->robot, sample->value);
      source_ns.push_back(ns.value_or(-1));
    };
  }
};

void Put(dds::HeldSamples& held, Sample sample, std::optional<int64_t> source_ns, Written& out) {
  held.Write(&sample, source_ns, out.Fn());
}

dds::KeyedHeldSamplesOf<Sample>::Key KeyOf(const Sample& s) {
  dds::KeyedHeldSamplesOf<Sample>::Key key{};
  key[0] = static_cast<uint8_t>(s.robot);
  return key;
}

// Closed (its writer is being deleted): a match that comes now writes nothing into the emptied history.
TEST(HeldSamples, AMatchAfterCloseWritesNothing) {
  dds::HeldSamplesOf<Sample> held(3);
  Written out;
  Put(held, {0, 1}, 100, out);
  held.Close();
  held.SetMatched(1, out.Fn());
  EXPECT_TRUE(out.samples.empty());
}

TEST(HeldSamples, UnkeyedKeepsTheLastDepthUntilAReaderMatchesThenPassesThrough) {
  dds::HeldSamplesOf<Sample> held(3);
  Written out;
  for (int v = 1; v <= 5; ++v) Put(held, {0, v}, v * 100, out);
  EXPECT_TRUE(out.samples.empty());
  held.SetMatched(1, out.Fn());
  EXPECT_EQ(out.samples, (std::vector<std::pair<int, int>>{{0, 3}, {0, 4}, {0, 5}}));
  EXPECT_EQ(out.source_ns, (std::vector<int64_t>{300, 400, 500}));  // each keeps its own source time
  Put(held, {0, 6}, std::nullopt, out);
  ASSERT_EQ(out.samples.size(), 4u);
  EXPECT_EQ(out.samples.back(), std::make_pair(0, 6));
  EXPECT_EQ(out.source_ns.back(), -1);  // written as given
  // The reader leaves: held again, and a second match writes only what came since.
  held.SetMatched(0, out.Fn());
  Put(held, {0, 7}, 700, out);
  EXPECT_EQ(out.samples.size(), 4u);
  held.SetMatched(2, out.Fn());
  ASSERT_EQ(out.samples.size(), 5u);
  EXPECT_EQ(out.samples.back(), std::make_pair(0, 7));
  held.SetMatched(2, out.Fn());
  EXPECT_EQ(out.samples.size(), 5u);  // nothing held twice
}

TEST(HeldSamples, KeyedKeepsTheLastDepthOfEachInstanceAndFlushesInWritingOrder) {
  dds::KeyedHeldSamplesOf<Sample> held(2, 8, KeyOf);
  Written out;
  // robot 1: 10, 11, 12; robot 2: 20, 21; robot 3: 30, interleaved.
  const std::vector<Sample> order = {{1, 10}, {2, 20}, {1, 11}, {3, 30}, {2, 21}, {1, 12}};
  int64_t ns = 0;
  for (const Sample& s : order) Put(held, s, ++ns, out);
  EXPECT_TRUE(out.samples.empty());
  held.SetMatched(1, out.Fn());
  EXPECT_EQ(out.samples, (std::vector<std::pair<int, int>>{{2, 20}, {1, 11}, {3, 30}, {2, 21}, {1, 12}}));
  EXPECT_EQ(out.source_ns, (std::vector<int64_t>{2, 3, 4, 5, 6}));
}

// Beyond the limit the writer's own history takes over: what was held goes out first, in order, then the sample.
TEST(HeldSamples, KeyedWritesEverythingWhenAnInstanceIsBeyondTheWritersLimit) {
  dds::KeyedHeldSamplesOf<Sample> held(4, 2, KeyOf);
  Written out;
  Put(held, {1, 10}, 1, out);
  Put(held, {2, 20}, 2, out);
  EXPECT_TRUE(out.samples.empty());
  Put(held, {3, 30}, 3, out);  // a third instance: over the limit of 2
  EXPECT_EQ(out.samples, (std::vector<std::pair<int, int>>{{1, 10}, {2, 20}, {3, 30}}));
  Put(held, {1, 11}, 4, out);  // a known instance is held again
  EXPECT_EQ(out.samples.size(), 3u);
  held.SetMatched(1, out.Fn());
  EXPECT_EQ(out.samples.size(), 4u);
  EXPECT_EQ(out.samples.back(), std::make_pair(1, 11));
}

dds::ParticipantOptions Options(const char* name, const std::string& prefix) {
  dds::ParticipantOptions o;
  o.domain = test::TestDomain();
  o.prefix = prefix;
  o.name = name;
  o.qos_file = TURF_SOURCE_DIR "/configs/qos/turf_qos.xml";
  return o;
}

// turf.state keeps 8 samples per instance (configs/qos/turf_qos.xml).
TEST(HeldSamplesOverDds, ALateReaderGetsTheLastDepthJointStatesOfEachRobot) {
  constexpr int kDepth = 8, kWrites = 12;
  const std::string prefix = "held" + std::to_string(getpid());
  dds::Participant sim(Options("held_writer", prefix));
  auto writer = sim.MakeWriter(dds::Topic::kRobotJointState);
  for (int frame = 1; frame <= kWrites; ++frame) {
    for (const char* robot : {"nao_1", "nao_2", "nao_3"}) {
      idl::JointState s;
      s.robot(robot);
      s.frame(static_cast<uint64_t>(frame));
      ASSERT_TRUE(writer->Write(s));
    }
  }
  dds::Participant viewer(Options("held_reader", prefix));
  test::WakeWait wake;
  auto reader = viewer.MakeReader(dds::Topic::kRobotJointState, [&wake] { wake.Wake(); });
  std::map<std::string, std::vector<uint64_t>> frames;
  const bool all = wake.Until(std::chrono::steady_clock::now() + std::chrono::seconds(20), [&] {
    std::vector<idl::JointState> got;
    if (reader->Take(&got))
      for (const idl::JointState& s : got) frames[s.robot()].push_back(s.frame());
    size_t n = 0;
    for (const auto& [robot, f] : frames) n += f.size();
    return n >= 3 * kDepth;
  });
  ASSERT_TRUE(all) << "the late reader got " << frames.size() << " robots' samples";
  std::vector<uint64_t> expected;
  for (int frame = kWrites - kDepth + 1; frame <= kWrites; ++frame) expected.push_back(static_cast<uint64_t>(frame));
  for (const char* robot : {"nao_1", "nao_2", "nao_3"}) EXPECT_EQ(frames[robot], expected) << robot;
  // Live samples follow the held ones.
  idl::JointState next;
  next.robot("nao_2");
  next.frame(kWrites + 1);
  ASSERT_TRUE(writer->Write(next));
  ASSERT_TRUE(wake.Until(std::chrono::steady_clock::now() + std::chrono::seconds(20), [&] {
    std::vector<idl::JointState> got;
    if (reader->Take(&got))
      for (const idl::JointState& s : got) frames[s.robot()].push_back(s.frame());
    return frames["nao_2"].size() == kDepth + 1;
  }));
  EXPECT_EQ(frames["nao_2"].back(), static_cast<uint64_t>(kWrites + 1));
}

}  // namespace
}  // namespace turf
