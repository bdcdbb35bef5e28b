// The IDL text a recording carries as each channel's schema: self-contained (every included file in place of its
// #include, once, before its user), for every type of the topic table.
#include <gtest/gtest.h>

#include "dds/topics.h"
#include "participants/recorder/idl_schema.h"
#include "tests/support/text.h"

namespace turf::record {
namespace {

using test::Occurrences;

TEST(IdlSchema, EveryTopicTypeHasASelfContainedSchema) {
  for (const dds::TopicInfo& t : dds::kTopics) {
    const std::string schema = IdlSchema(t.type);
    ASSERT_FALSE(schema.empty()) << t.type;
    EXPECT_EQ(Occurrences(schema, "#include"), 0u) << t.type;
    EXPECT_EQ(Occurrences(schema, "\n#"), 0u) << t.type << ": a preprocessor line is left\n" << schema;
    EXPECT_NE(schema[0], '#') << t.type;
    EXPECT_EQ(Occurrences(schema, std::string("struct ") + t.type + " "), 1u) << t.type << "\n" << schema;
  }
}

TEST(IdlSchema, IncludedFilesComeOnceAndFirst) {
  const std::string schema =
      IdlSchema("SimControl");  // includes Common, Clock, SslRobot, Joints (which include Common)
  EXPECT_EQ(Occurrences(schema, "// ---- Common.idl"), 1u);
  EXPECT_LT(schema.find("// ---- Common.idl"), schema.find("// ---- Clock.idl"));
  EXPECT_LT(schema.find("// ---- Joints.idl"), schema.find("// ---- SimControl.idl"));
  EXPECT_NE(schema.find("struct SimControlReply"), std::string::npos);
}

TEST(IdlSchema, APrefixOfANameIsNotTheName) { EXPECT_EQ(IdlSchema("Sim"), ""); }

}  // namespace
}  // namespace turf::record
