#include "codecs/simspark/effectors.h"

#include <gtest/gtest.h>

#include <initializer_list>
#include <optional>
#include <string>

namespace turf::simspark {
namespace {

std::vector<EffectorError> Errors(const AgentMessage& m) {
  std::vector<EffectorError> errors;
  for (const EffectorIssue& issue : m.issues) errors.push_back(issue.error);
  return errors;
}

// Each text is refused with `error` alone and sets no `effector`.
template <class Effector>
void ExpectRefused(std::initializer_list<const char*> texts, std::optional<Effector> AgentMessage::*effector,
                   EffectorError error) {
  for (const char* text : texts) {
    const AgentMessage m = ParseAgentMessage(text);
    EXPECT_FALSE(m.*effector) << text;
    EXPECT_EQ(Errors(m), std::vector<EffectorError>{error}) << text;
  }
}

bool NothingApplied(const AgentMessage& m) {
  return !m.scene && !m.init && !m.beam && m.hinges.empty() && !m.say && !m.syn && !m.pass;
}

TEST(Effectors, TypicalCycleMessage) {
  const AgentMessage m = ParseAgentMessage("(he1 0.50)(he2 -0.30)(syn)");
  EXPECT_TRUE(m.issues.empty());
  ASSERT_EQ(m.hinges.size(), 2u);
  EXPECT_EQ(m.hinges[0].effector, "he1");
  EXPECT_DOUBLE_EQ(m.hinges[0].velocity, 0.5);
  EXPECT_EQ(m.hinges[1].effector, "he2");
  EXPECT_DOUBLE_EQ(m.hinges[1].velocity, -0.3);
  EXPECT_TRUE(m.syn);
  EXPECT_FALSE(m.pass);
  EXPECT_FALSE(m.beam);
}

TEST(Effectors, AnyWhitespaceAndEmptyMessage) {
  const AgentMessage m = ParseAgentMessage(" ( rle4\t-2.5 )\n(\tsyn\r\n)");
  EXPECT_TRUE(m.issues.empty());
  ASSERT_EQ(m.hinges.size(), 1u);
  EXPECT_DOUBLE_EQ(m.hinges[0].velocity, -2.5);
  EXPECT_TRUE(m.syn);
  const AgentMessage empty = ParseAgentMessage("");
  EXPECT_TRUE(empty.issues.empty());
  EXPECT_TRUE(NothingApplied(empty));
}

TEST(Effectors, Scene) {
  AgentMessage m = ParseAgentMessage("(scene rsg/agent/nao/nao.rsg)");
  ASSERT_TRUE(m.scene);
  EXPECT_EQ(m.scene->path, "rsg/agent/nao/nao.rsg");
  EXPECT_EQ(m.scene->type, 0);
  m = ParseAgentMessage("(scene rsg/agent/nao/nao_hetero.rsg 3)");
  ASSERT_TRUE(m.scene);
  EXPECT_EQ(m.scene->path, "rsg/agent/nao/nao_hetero.rsg");
  EXPECT_EQ(m.scene->type, 3);
  EXPECT_EQ(ParseAgentMessage("(scene rsg/agent/nao/nao_hetero.rsg 4)").scene->type, 4);
}

TEST(Effectors, SceneErrors) {
  ExpectRefused({"(scene rsg/agent/nao/nao_hetero.rsg 5)", "(scene rsg/agent/nao/nao_hetero.rsg -1)"},
                &AgentMessage::scene, EffectorError::kBadRobotType);
  ExpectRefused({"(scene)", "(scene a.rsg 1.5)", "(scene a.rsg 1 2)", "(scene (a.rsg))", "(scene a.rsg x)"},
                &AgentMessage::scene, EffectorError::kBadArguments);
}

TEST(Effectors, Init) {
  AgentMessage m = ParseAgentMessage("(init (unum 1)(teamname FHO))");
  ASSERT_TRUE(m.init);
  EXPECT_EQ(m.init->unum, 1);
  EXPECT_EQ(m.init->team, "FHO");
  m = ParseAgentMessage("(init (teamname Probe) (unum 99))");
  ASSERT_TRUE(m.init);
  EXPECT_EQ(m.init->unum, 99);
  m = ParseAgentMessage("(init (teamname Probe))");  // unum missing = 0, lowest free
  ASSERT_TRUE(m.init);
  EXPECT_EQ(m.init->unum, 0);
  EXPECT_EQ(m.init->team, "Probe");
  EXPECT_TRUE(m.issues.empty());
}

TEST(Effectors, InitErrors) {
  ExpectRefused({"(init (unum 100)(teamname A))", "(init (unum -1)(teamname A))", "(init (unum 1.0)(teamname A))",
                 "(init (unum x)(teamname A))", "(init (unum 1))", "(init)", "(init (unum 1)(teamname A)(color red))",
                 "(init (unum 1)(teamname A B))", "(init (unum 1) teamname A)", "(init (unum 1)(teamname (A)))"},
                &AgentMessage::init, EffectorError::kBadArguments);
}

TEST(Effectors, Beam) {
  const AgentMessage m = ParseAgentMessage("(beam -5.0 1.5 90)");
  ASSERT_TRUE(m.beam);
  EXPECT_DOUBLE_EQ(m.beam->x, -5.0);
  EXPECT_DOUBLE_EQ(m.beam->y, 1.5);
  EXPECT_DOUBLE_EQ(m.beam->rot_deg, 90.0);
  EXPECT_TRUE(m.issues.empty());
}

TEST(Effectors, BeamErrors) {
  ExpectRefused({"(beam nan 0 0)", "(beam 0 inf 0)", "(beam 0 0 -1e999)"}, &AgentMessage::beam,
                EffectorError::kNotFinite);
  ExpectRefused({"(beam 1 2)", "(beam 1 2 3 4)", "(beam 1.0abc 2 3)", "(beam 1 (2) 3)", "(beam nan 0 x)"},
                &AgentMessage::beam, EffectorError::kBadArguments);
}

TEST(Effectors, Say) {
  AgentMessage m = ParseAgentMessage("(say helloworld)");
  ASSERT_TRUE(m.say);
  EXPECT_EQ(*m.say, "helloworld");
  const std::string twenty = "!\"#$%&'*+,-./0123~{}";
  ASSERT_EQ(twenty.size(), 20u);
  m = ParseAgentMessage("(say " + twenty + ")");
  ASSERT_TRUE(m.say);
  EXPECT_EQ(*m.say, twenty);
  EXPECT_TRUE(IsValidSayMessage("a"));
  EXPECT_FALSE(IsValidSayMessage(""));
  EXPECT_FALSE(IsValidSayMessage("a b"));
  EXPECT_FALSE(IsValidSayMessage("a(b"));
  EXPECT_FALSE(IsValidSayMessage("a)b"));
  EXPECT_FALSE(IsValidSayMessage("\xe9t\xe9"));
  EXPECT_FALSE(IsValidSayMessage(std::string(21, 'a')));
}

TEST(Effectors, SayErrors) {
  for (const std::string& text : {"(say " + std::string(21, 'a') + ")", std::string("(say hello world)"),
                                  std::string("(say)"), std::string("(say (hello))")}) {
    const AgentMessage m = ParseAgentMessage(text);
    EXPECT_FALSE(m.say) << text;
    EXPECT_EQ(Errors(m), std::vector<EffectorError>{EffectorError::kBadSay}) << text;
  }
}

TEST(Effectors, SynAndPass) {
  const AgentMessage m = ParseAgentMessage("(pass)(syn)");
  EXPECT_TRUE(m.pass);
  EXPECT_TRUE(m.syn);
  for (const char* text : {"(syn 1)", "(pass now)"}) {
    const AgentMessage bad = ParseAgentMessage(text);
    EXPECT_TRUE(NothingApplied(bad)) << text;
    EXPECT_EQ(Errors(bad), std::vector<EffectorError>{EffectorError::kBadArguments}) << text;
  }
}

TEST(Effectors, HingesOfEveryTypeAreAcceptedRawAndUnclamped) {
  const AgentMessage m = ParseAgentMessage("(lle7 1)(rae4 -100)(he1 1e2)(he1 +0.25)");
  EXPECT_TRUE(m.issues.empty());
  ASSERT_EQ(m.hinges.size(), 4u);
  EXPECT_EQ(m.hinges[0].effector, "lle7");  // only type 4 has it: the participant decides
  EXPECT_DOUBLE_EQ(m.hinges[1].velocity, -100.0);
  EXPECT_DOUBLE_EQ(m.hinges[2].velocity, 100.0);
  EXPECT_DOUBLE_EQ(m.hinges[3].velocity, 0.25);  // kept in order: the last for he1 wins
}

TEST(Effectors, HingeErrors) {
  AgentMessage m = ParseAgentMessage("(he1 nan)(he2 -inf)");
  EXPECT_TRUE(m.hinges.empty());
  EXPECT_EQ(Errors(m), (std::vector<EffectorError>{EffectorError::kNotFinite, EffectorError::kNotFinite}));
  m = ParseAgentMessage("(he1)(he1 1 2)(he1 fast)(he1 (1))");
  EXPECT_TRUE(m.hinges.empty());
  EXPECT_EQ(Errors(m), std::vector<EffectorError>(4, EffectorError::kBadArguments));
}

TEST(Effectors, UnknownEffectorsAreDroppedWithTheirName) {
  const AgentMessage m = ParseAgentMessage("(he3 1)(Beam 0 0 0)()((he1) 1)(rle8 0)");
  EXPECT_TRUE(NothingApplied(m));
  ASSERT_EQ(Errors(m), std::vector<EffectorError>(5, EffectorError::kUnknownEffector));
  EXPECT_EQ(m.issues[0].detail, "he3");
  EXPECT_EQ(m.issues[1].detail, "Beam");  // names are case-sensitive
  EXPECT_EQ(m.issues[4].detail, "rle8");
  const AgentMessage long_name = ParseAgentMessage("(" + std::string(200, 'x') + ")");
  ASSERT_EQ(long_name.issues.size(), 1u);
  EXPECT_LE(long_name.issues[0].detail.size(), 32u);
}

TEST(Effectors, EachPredicateStandsAlone) {
  const AgentMessage m = ParseAgentMessage("(foo)(he1 1)(beam nan 0 0)(say a b)(syn)(beam 1 2 3)");
  ASSERT_EQ(m.hinges.size(), 1u);
  EXPECT_TRUE(m.syn);
  ASSERT_TRUE(m.beam);
  EXPECT_DOUBLE_EQ(m.beam->x, 1.0);
  EXPECT_EQ(Errors(m), (std::vector<EffectorError>{EffectorError::kUnknownEffector, EffectorError::kNotFinite,
                                                   EffectorError::kBadSay}));
}

TEST(Effectors, UnparsablePayloadAppliesNothing) {
  for (const std::string& text : {std::string("(syn)(he1 1"), std::string("(syn))"), std::string("(syn) he1"),
                                  std::string("(syn)(say a\0)", 13), std::string(100000, '(')}) {
    const AgentMessage m = ParseAgentMessage(text);
    EXPECT_TRUE(NothingApplied(m));
    ASSERT_EQ(Errors(m), std::vector<EffectorError>{EffectorError::kParse});
  }
  EXPECT_EQ(ParseAgentMessage("(syn)(he1 1").issues[0].detail, "unbalanced_open at offset 11");
}

}  // namespace
}  // namespace turf::simspark
