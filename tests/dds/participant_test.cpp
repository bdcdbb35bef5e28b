// The topic table against DDS: every constant's type registers the type name in its row, every topic gets a
// writer and a reader with its QoS profile, and a participant's start-up lines list what it writes and reads.
#include <gtest/gtest.h>
#include <spdlog/spdlog.h>
#include <turf/idl/ClockPubSubTypes.h>
#include <turf/idl/JointsPubSubTypes.h>
#include <turf/idl/SensorStatsPubSubTypes.h>
#include <turf/idl/SimControlPubSubTypes.h>
#include <turf/idl/SimRecordPubSubTypes.h>
#include <turf/idl/SslRobotPubSubTypes.h>
#include <turf/idl/SslVisionPubSubTypes.h>
#include <turf/idl/WorldStatePubSubTypes.h>
#include <unistd.h>
#include <fastdds/dds/topic/TypeSupport.hpp>

#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include "dds/participant.h"
#include "tests/support/captured_log.h"
#include "tests/test_domain.h"

namespace turf {
namespace {

template <class PubSub>
void ExpectRegisteredName(const dds::TopicDef<PubSub>& topic) {
  PubSub type;
  EXPECT_STREQ(type.getName(), topic.info().dds_type) << topic.info().constant;
  EXPECT_EQ(eprosima::fastdds::dds::TypeSupport(new PubSub()).get_type_name(), topic.info().dds_type)
      << topic.info().constant;
}

TEST(TopicTypes, EveryTopicsTypeRegistersTheNameInItsRow) {
  std::apply([](const auto&... topic) { (ExpectRegisteredName(topic), ...); }, dds::kTypedTopics);
}

dds::ParticipantOptions Options(const char* name) {
  static int g_counter = 0;
  dds::ParticipantOptions o;
  o.domain = test::TestDomain();
  o.prefix = "dds" + std::to_string(getpid()) + "_" + std::to_string(++g_counter);
  o.name = name;
  o.qos_file = TURF_SOURCE_DIR "/configs/qos/turf_qos.xml";
  return o;
}

TEST(ParticipantTopics, ListsWhatItWritesAndReadsOnceEach) {
  test::CapturedLog log(spdlog::level::debug);
  {
    dds::Participant participant(Options("topics_list"));
    const std::string p = participant.options().prefix;
    auto clock = participant.MakeWriter(dds::Topic::kClock);
    auto state = participant.MakeReader<idl::WorldStatePubSubType>(dds::Topic::kWorldState);
    auto state_again = participant.MakeReader(dds::Topic::kWorldState, [] {});
    auto control = participant.MakeReader(dds::Topic::kControl);
    const std::vector<std::string> expected = {
        "writes " + p + "/clock (turf::idl::Clock, QoS profile turf.state)",
        "reads " + p + "/world_state (turf::idl::WorldState, QoS profile turf.state)",
        "reads " + p + "/control (turf::idl::SimControl, QoS profile turf.control)",
    };
    EXPECT_EQ(participant.TopicLines(), expected);
    ASSERT_EQ(participant.Endpoints().size(), 3u);
    EXPECT_EQ(participant.Endpoints()[1].first, dds::Endpoint::kReader);
    EXPECT_EQ(participant.Endpoints()[1].second, dds::Topic::kWorldState);

    // Each creation is logged at debug as it happens (the second world_state reader too); LogTopics() gives
    // the list at info.
    const std::string created = log.Text();
    EXPECT_NE(created.find("debug " + expected[0] + "\n"), std::string::npos) << created;
    EXPECT_NE(created.find("debug " + expected[1] + "\n"), std::string::npos) << created;
    EXPECT_NE(created.find("debug " + expected[2] + "\n"), std::string::npos) << created;
    EXPECT_EQ(created.find("info "), std::string::npos) << created;
    participant.LogTopics();
    const std::string listed = log.Text().substr(created.size());
    EXPECT_EQ(listed, "info " + expected[0] + "\ninfo " + expected[1] + "\ninfo " + expected[2] + "\n");
  }
}

// Every row: a writer and a reader of its type, with its QoS profile found in the QoS file (the participant
// warns when a profile is missing).
TEST(ParticipantTopics, EveryTopicGetsAWriterAndAReaderWithItsProfile) {
  test::CapturedLog log(spdlog::level::debug);
  dds::Participant participant(Options("topics_all"));
  std::apply(
      [&participant](const auto&... topic) {
        auto check = [&participant](const auto& t) {
          auto writer = participant.MakeWriter(t);
          auto reader = participant.MakeReader(t);
          EXPECT_NE(writer, nullptr);
          EXPECT_NE(reader, nullptr);
        };
        (check(topic), ...);
      },
      dds::kTypedTopics);
  EXPECT_EQ(participant.Endpoints().size(), 2 * dds::kTopicCount);
  EXPECT_EQ(log.Text().find("warn"), std::string::npos) << log.Text();
  EXPECT_EQ(log.Text().find("error"), std::string::npos) << log.Text();
}

// Polls `done` until it holds, up to 20 s (discovery and delivery over UDP on a loaded machine).
bool Eventually(const std::function<bool()>& done) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (!done()) {
    if (std::chrono::steady_clock::now() > end) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return true;
}

// Takes what `reader` holds and appends the request ids to `ids`.
void TakeIds(dds::Reader<idl::SimControlPubSubType>& reader, std::vector<uint64_t>* ids) {
  std::vector<idl::SimControl> got;
  if (reader.Take(&got))
    for (const idl::SimControl& c : got) ids->push_back(c.request_id());
}

// A reliable volatile topic (control) over DDS: its writer offers TRANSIENT_LOCAL (Fast DDS 2.9's deadlock kept out,
// dds/participant.cpp: Offered), yet a reader that matches late gets nothing written before it matched.
TEST(ParticipantTopics, AReaderOfAVolatileTopicGetsNothingWrittenBeforeItMatched) {
  const dds::ParticipantOptions options = Options("volatile_writer");
  dds::ParticipantOptions reader_options = options;
  reader_options.name = "volatile_reader";
  dds::Participant writing(options);
  dds::Participant reading(reader_options);
  auto writer = writing.MakeWriter(dds::Topic::kControl);
  auto early = reading.MakeReader(dds::Topic::kControl);
  ASSERT_TRUE(Eventually([&] { return writer->Matched() == 1 && early->Matched() == 1; }));
  idl::SimControl request;
  for (uint64_t id = 1; id <= 3; ++id) {
    request.request_id(id);
    ASSERT_TRUE(writer->Write(request));
  }
  std::vector<uint64_t> early_ids;
  ASSERT_TRUE(Eventually([&] {
    TakeIds(*early, &early_ids);
    return early_ids.size() >= 3;
  }));
  EXPECT_EQ(early_ids, (std::vector<uint64_t>{1, 2, 3}));

  auto late = reading.MakeReader(dds::Topic::kControl);
  ASSERT_TRUE(Eventually([&] { return writer->Matched() == 2 && late->Matched() == 1; }));
  request.request_id(4);
  ASSERT_TRUE(writer->Write(request));
  std::vector<uint64_t> late_ids;
  ASSERT_TRUE(Eventually([&] {
    TakeIds(*late, &late_ids);
    return !late_ids.empty() && late_ids.back() == 4;
  })) << late_ids.size()
      << " samples";
  EXPECT_EQ(late_ids, (std::vector<uint64_t>{4}));
}

}  // namespace
}  // namespace turf
