// The DDS Security permissions table (dds/security_policy.h) and the documents drawn from it: only turf-sim
// publishes what turf-sim publishes, a team publishes only its own team's commands, the tournament profile keeps
// ground truth and control from the teams, observers publish nothing, every topic of the table is read by someone.
#include "dds/security_policy.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "dds/topics.h"
#include "tests/support/text.h"

namespace turf {
namespace {

using dds::SecurityProfile;

bool Has(const std::vector<std::string>& topics, dds::Topic topic) {
  return std::find(topics.begin(), topics.end(), topic.info().suffix) != topics.end();
}

std::vector<std::string> Publishers(dds::Topic topic, SecurityProfile profile) {
  std::vector<std::string> out;
  for (const std::string& name : dds::IdentityNames())
    if (Has(dds::GrantOf(name, profile).publish, topic)) out.push_back(name);
  return out;
}

TEST(SecurityPolicy, OnlyTurfSimPublishesWhatTurfSimPublishes) {
  for (SecurityProfile profile : {SecurityProfile::kLab, SecurityProfile::kTournament})
    for (const dds::TopicInfo& t : dds::kTopics) {
      if (t.direction == dds::Direction::kSubscribed) continue;
      std::vector<std::string> publishers;
      for (const std::string& name : dds::IdentityNames()) {
        const auto& p = dds::GrantOf(name, profile).publish;
        if (std::find(p.begin(), p.end(), t.suffix) != p.end()) publishers.push_back(name);
      }
      EXPECT_EQ(publishers, std::vector<std::string>{"sim"}) << t.suffix;
    }
}

TEST(SecurityPolicy, ATeamPublishesItsOwnCommandsOnly) {
  for (SecurityProfile profile : {SecurityProfile::kLab, SecurityProfile::kTournament}) {
    const dds::IdentityGrant blue = dds::GrantOf("blue", profile);
    const dds::IdentityGrant yellow = dds::GrantOf("yellow", profile);
    EXPECT_TRUE(Has(blue.publish, dds::Topic::kSslCommandBlue));
    EXPECT_FALSE(Has(blue.publish, dds::Topic::kSslCommandYellow));
    EXPECT_TRUE(Has(yellow.publish, dds::Topic::kSslCommandYellow));
    EXPECT_FALSE(Has(yellow.publish, dds::Topic::kSslCommandBlue));
    EXPECT_TRUE(Has(blue.subscribe, dds::Topic::kSslFeedbackBlue));
    EXPECT_FALSE(Has(blue.subscribe, dds::Topic::kSslFeedbackYellow));
    EXPECT_TRUE(Has(blue.subscribe, dds::Topic::kSslCamera));
  }
}

TEST(SecurityPolicy, InATournamentOnlyTheOperatorAndTheBridgesControlAndTeamsSeeNoGroundTruth) {
  const std::vector<std::string> controllers = Publishers(dds::Topic::kControl, SecurityProfile::kTournament);
  for (const std::string& name : controllers)
    EXPECT_TRUE(name == "operator" || name.find("-bridge") != std::string::npos) << name;
  EXPECT_NE(std::find(controllers.begin(), controllers.end(), "operator"), controllers.end());
  for (const char* team : {"blue", "yellow"}) {
    const dds::IdentityGrant g = dds::GrantOf(team, SecurityProfile::kTournament);
    EXPECT_FALSE(Has(g.subscribe, dds::Topic::kWorldState)) << team;
    EXPECT_FALSE(Has(g.subscribe, dds::Topic::kRobotsState)) << team;
    EXPECT_FALSE(Has(g.publish, dds::Topic::kControl)) << team;
    // In the lab they may.
    EXPECT_TRUE(Has(dds::GrantOf(team, SecurityProfile::kLab).publish, dds::Topic::kControl)) << team;
    EXPECT_TRUE(Has(dds::GrantOf(team, SecurityProfile::kLab).subscribe, dds::Topic::kWorldState)) << team;
  }
}

TEST(SecurityPolicy, ObserversPublishNothingAndEveryTopicIsReadBySomeone) {
  EXPECT_TRUE(dds::GrantOf("observer", SecurityProfile::kLab).publish.empty());
  for (dds::Topic t : dds::kAllTopics)
    EXPECT_TRUE(Has(dds::GrantOf("observer", SecurityProfile::kTournament).subscribe, t)) << t.info().suffix;
}

// turf-render alone publishes the camera topics (by pattern, rt/<prefix>/*/*/<kind>); every identity but turf-sim
// reads them, teams too in a tournament (they are what a robot sees).
TEST(SecurityPolicy, OnlyTheRendererPublishesCameraImagesAndEveryoneButTheSimReadsThem) {
  for (SecurityProfile profile : {SecurityProfile::kLab, SecurityProfile::kTournament})
    for (const std::string& name : dds::IdentityNames()) {
      const dds::IdentityGrant g = dds::GrantOf(name, profile);
      EXPECT_EQ(g.publish_cameras, name == "render") << name;
      EXPECT_EQ(g.subscribe_cameras, name != "render" && name != "sim") << name;
    }
  const std::string render =
      dds::PermissionsXml("render", SecurityProfile::kTournament, "m", "2026-01-01T00:00:00", "2027-01-01T00:00:00");
  const size_t publish = render.find("<publish>");
  ASSERT_NE(publish, std::string::npos);
  EXPECT_GT(render.find("<topic>rt/m/*/*/image_raw</topic>"), publish);
  EXPECT_NE(render.find("<topic>rt/m/*/*/camera_info</topic>"), std::string::npos);
  EXPECT_NE(render.find("<topic>m/robots/state</topic>"), std::string::npos);
  // Cameras switched at run time: the operator writes cameras/control, the renderer reads it.
  EXPECT_GT(render.find("<topic>m/cameras/control</topic>"), render.find("<subscribe>"));
  const std::string op =
      dds::PermissionsXml("operator", SecurityProfile::kLab, "m", "2026-01-01T00:00:00", "2027-01-01T00:00:00");
  const size_t cc = op.find("<topic>m/cameras/control</topic>");
  ASSERT_NE(cc, std::string::npos) << op;
  EXPECT_LT(cc, op.find("<subscribe>")) << "published" << op;
  const std::string blue =
      dds::PermissionsXml("blue", SecurityProfile::kTournament, "m", "2026-01-01T00:00:00", "2027-01-01T00:00:00");
  EXPECT_GT(blue.find("<topic>rt/m/*/*/image_raw/compressed</topic>"), blue.find("<subscribe>"));
}

TEST(SecurityPolicy, AnUnknownIdentityIsRefusedByName) {
  try {
    dds::GrantOf("referee", SecurityProfile::kLab);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'referee' is not a turf security identity"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("observer"), std::string::npos) << e.what();
  }
}

TEST(SecurityPolicy, PermissionsNameTheSubjectTheTopicsWithTheirPrefixAndDenyTheRest) {
  const std::string xml =
      dds::PermissionsXml("blue", SecurityProfile::kTournament, "match7", "2026-01-01T00:00:00", "2027-01-01T00:00:00");
  EXPECT_TRUE(test::ContainsAll(
      xml, {"<subject_name>CN=turf blue,O=turf</subject_name>", "<topic>match7/ssl/command/blue</topic>",
            "<not_after>2027-01-01T00:00:00</not_after>", "<default>DENY</default>"}));
  EXPECT_EQ(xml.find("match7/ssl/command/yellow"), std::string::npos) << xml;
  EXPECT_EQ(xml.find("match7/world_state"), std::string::npos) << xml;
}

TEST(SecurityPolicy, GovernanceEncryptsOrNotAndAlwaysControlsAccess) {
  const std::string on = dds::GovernanceXml(dds::Protection::kEncrypt);
  const std::string off = dds::GovernanceXml(dds::Protection::kNone);
  EXPECT_NE(on.find("<data_protection_kind>ENCRYPT</data_protection_kind>"), std::string::npos);
  EXPECT_NE(off.find("<data_protection_kind>NONE</data_protection_kind>"), std::string::npos);
  for (const std::string& g : {on, off}) {
    EXPECT_NE(g.find("<allow_unauthenticated_participants>false</allow_unauthenticated_participants>"),
              std::string::npos);
    EXPECT_NE(g.find("<enable_write_access_control>true</enable_write_access_control>"), std::string::npos);
    EXPECT_NE(g.find("<enable_read_access_control>true</enable_read_access_control>"), std::string::npos);
  }
}

}  // namespace
}  // namespace turf
