// The topic table (dds/topics.h) and what derives from it without DDS: the typed constants, the rows, the
// README's topic table and the log lines.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

#include "dds/camera_topics.h"
#include "dds/topics.h"
#include "tests/support/source_files.h"

namespace turf {
namespace {

template <class Def>
using CarriedType = typename std::remove_cv_t<Def>::PubSubType;

// A topic constant carries its type; no topic converts to, or can be built as, a topic of another type.
static_assert(std::is_same_v<CarriedType<decltype(dds::Topic::kWorldState)>, idl::WorldStatePubSubType>);
static_assert(std::is_same_v<CarriedType<decltype(dds::Topic::kSslCommandBlue)>, idl::SslRobotCommandPubSubType>);
static_assert(!std::is_convertible_v<const dds::TopicDef<idl::WorldStatePubSubType>&,
                                     const dds::TopicDef<idl::SslRobotCommandPubSubType>&>);
static_assert(!std::is_constructible_v<dds::TopicDef<idl::WorldStatePubSubType>, dds::TopicId>);
static_assert(!std::is_constructible_v<dds::TopicDef<idl::WorldStatePubSubType>, dds::Topic>);
// ... and is a plain value at run time.
static_assert(std::is_convertible_v<decltype(dds::Topic::kWorldState), dds::Topic>);
static_assert(dds::Topic::kWorldState.id() == dds::TopicId::kWorldState);
static_assert(dds::Topic(dds::Topic::kClock) != dds::Topic(dds::Topic::kWorldState));
static_assert(std::tuple_size_v<std::remove_cv_t<decltype(dds::kTypedTopics)>> == dds::kTopicCount);

TEST(Topics, EveryConstantIsItsOwnRowOfTheTable) {
  ASSERT_EQ(dds::kAllTopics.size(), dds::kTopicCount);
  for (size_t i = 0; i < dds::kTopicCount; ++i) {
    const dds::Topic topic = dds::kAllTopics[i];
    EXPECT_EQ(static_cast<size_t>(topic.id()), i);
    EXPECT_EQ(&topic.info(), &dds::kTopics[i]);
    EXPECT_EQ(&dds::Info(topic), &dds::kTopics[i]);
  }
  size_t i = 0;
  auto expect_row = [&i](const dds::Topic& topic) {
    EXPECT_EQ(static_cast<size_t>(topic.id()), i) << topic.info().constant;
    ++i;
  };
  std::apply([&expect_row](const auto&... topic) { (expect_row(topic), ...); }, dds::kTypedTopics);
  EXPECT_EQ(i, dds::kTopicCount);
  EXPECT_STREQ(dds::Topic::kSslField.info().suffix, "ssl/field");
  EXPECT_STREQ(dds::Topic::kSslField.info().constant, "kSslField");
  EXPECT_STREQ(dds::Topic::kSslField.info().type, "SslField");
  EXPECT_STREQ(dds::Topic::kSslField.info().dds_type, "turf::idl::SslField");
  EXPECT_EQ(dds::Topic::kSslField.info().direction, dds::Direction::kLatched);
}

TEST(Topics, RowsAreCompleteAndNamesUnique) {
  std::set<std::string> constants, names;
  for (const dds::TopicInfo& info : dds::kTopics) {
    SCOPED_TRACE(info.constant);
    EXPECT_TRUE(constants.insert(info.constant).second);
    EXPECT_TRUE(names.insert(info.suffix).second);
    EXPECT_EQ(std::string(info.constant).rfind('k', 0), 0u);
    EXPECT_NE(std::string(info.suffix), "");
    EXPECT_EQ(std::string(info.suffix).find_first_of(" |`"), std::string::npos);
    EXPECT_EQ(std::string(info.profile).rfind("turf.", 0), 0u);
    EXPECT_EQ(std::string(info.dds_type), std::string("turf::idl::") + info.type);
    EXPECT_NE(std::string(info.what), "");
    EXPECT_EQ(std::string(info.what).find('|'), std::string::npos) << "a '|' would split the README table's cell";
  }
}

// Every profile the table names is in the QoS file, for writers and readers. (dds_participant_tests also
// creates every topic's writer and reader and checks that Fast DDS found the profiles.)
TEST(Topics, EveryProfileIsInTheQosFile) {
  const std::string qos = test::SourceFile("configs/qos/turf_qos.xml");
  ASSERT_FALSE(qos.empty());
  for (const dds::TopicInfo& info : dds::kTopics) {
    for (const char* kind : {"data_writer", "data_reader"}) {
      const std::string tag = std::string("<") + kind + " profile_name=\"" + info.profile + "\"";
      EXPECT_NE(qos.find(tag), std::string::npos) << info.constant << ": no " << tag;
    }
  }
}

TEST(Topics, NamesAndLogLinesComeFromTheTable) {
  EXPECT_EQ(dds::TopicName("turf", dds::Topic::kSslCommandBlue), "turf/ssl/command/blue");
  EXPECT_EQ(dds::TopicName("", dds::Topic::kClock), "clock");
  EXPECT_EQ(dds::EndpointLine("m1", dds::Topic::kWorldState, dds::Endpoint::kWriter),
            "writes m1/world_state (turf::idl::WorldState, QoS profile turf.state)");
  EXPECT_EQ(dds::EndpointLine("turf", dds::Topic::kControl, dds::Endpoint::kReader),
            "reads turf/control (turf::idl::SimControl, QoS profile turf.control)");
}

TEST(Topics, MarkdownHasOneRowPerTopic) {
  const std::string md = dds::TopicsMarkdown();
  std::istringstream lines(md);
  std::string line;
  std::vector<std::string> rows;
  while (std::getline(lines, line)) rows.push_back(line);
  ASSERT_EQ(rows.size(), dds::kTopicCount + dds::kCameraTopicCount + 3);  // header, rule, ..., cameras/control
  EXPECT_EQ(rows[0], "| topic | type | direction | QoS profile | when, what |");
  for (size_t i = 0; i < dds::kTopicCount; ++i) {
    const dds::TopicInfo& info = dds::kTopics[i];
    EXPECT_EQ(rows[i + 2].rfind(std::string("| `") + info.suffix + "` | `" + info.type + "` | ", 0), 0u) << rows[i + 2];
    EXPECT_EQ(std::count(rows[i + 2].begin(), rows[i + 2].end(), '|'), 6) << rows[i + 2];
  }
  EXPECT_NE(md.find("| `ssl/field` | `SslField` | published, latched | `turf.field` | "), std::string::npos);
  EXPECT_NE(md.find("| `control` | `SimControl` | subscribed | `turf.control` | "), std::string::npos);
  EXPECT_EQ(rows.back().rfind("| `<prefix>/cameras/control` | `turf::idl::CameraControl` | read by turf-render | ", 0),
            0u)
      << rows.back();
  EXPECT_NE(md.find("| `rt/<prefix>/<robot>/<camera>/image_raw` | `sensor_msgs::msg::dds_::Image_` | published by "
                    "turf-render | best effort, volatile, keep last 1 | "),
            std::string::npos);
}

TEST(Topics, CameraTopicsAreNamedAsRos2NamesThem) {
  EXPECT_EQ(dds::CameraTopicName("turf", "t1", "camera", dds::CameraTopic::kImage), "rt/turf/t1/camera/image_raw");
  EXPECT_EQ(dds::CameraTopicName("", "nao", "top", dds::CameraTopic::kCameraInfo), "rt/nao/top/camera_info");
  EXPECT_EQ(dds::CameraTopicName("m", "k1", "camera", dds::CameraTopic::kCompressed),
            "rt/m/k1/camera/image_raw/compressed");
  EXPECT_EQ(dds::CameraTopicPattern("turf", dds::CameraTopic::kImage), "rt/turf/*/*/image_raw");
}

// README.md's topic table is the generated one: the text between the markers must equal TopicsMarkdown().
// To update it, paste the expected text this test prints.
TEST(Topics, ReadmeTableIsTheGeneratedOne) {
  EXPECT_TRUE(test::ReadmeSectionIs("<!-- topic-table: generated from dds/topics.h by dds::TopicsMarkdown() -->\n",
                                    "<!-- /topic-table -->", dds::TopicsMarkdown()));
}

}  // namespace
}  // namespace turf
