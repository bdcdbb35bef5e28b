#include "bridges/simspark/perception.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "bridges/simspark/sexpr.h"

namespace turf::simspark {
namespace {

TEST(Perception, FormatFloatIsFixedWithTwoDecimals) {
  EXPECT_EQ(FormatFloat(0.0), "0.00");
  EXPECT_EQ(FormatFloat(1.0), "1.00");
  EXPECT_EQ(FormatFloat(9.806), "9.81");
  EXPECT_EQ(FormatFloat(-1.024), "-1.02");
  EXPECT_EQ(FormatFloat(-0.001), "-0.00");  // as the server prints it
  EXPECT_EQ(FormatFloat(123456.789), "123456.79");
  EXPECT_EQ(FormatFloat(std::nan("")), "0.00");
  EXPECT_EQ(FormatFloat(std::numeric_limits<double>::infinity()), "0.00");
  EXPECT_EQ(FormatFloat(-std::numeric_limits<double>::infinity()), "0.00");
  const std::string huge = FormatFloat(1e30);  // longer than any buffer guess: printed whole
  EXPECT_EQ(huge.size(), 34u);
  EXPECT_EQ(huge.substr(0, 2), "10");
  EXPECT_EQ(huge.substr(huge.size() - 3), ".00");
}

TEST(Perception, BeforeInitNoUnumOrTeam) {
  Perception p;
  EXPECT_EQ(FormatPerception(p),
            "(time (now 0.00))(GS (sl 0) (sr 0) (t 0.00) (pm BeforeKickOff))(GYR (n torso) (rt 0.00 0.00 0.00))"
            "(ACC (n torso) (a 0.00 0.00 0.00))");
}

TEST(Perception, TheSheetsExampleMessage) {
  Perception p;
  p.time = 1.34;
  p.unum = 7;
  p.side = Side::kLeft;
  p.gyro_deg_s = {0.01, 0.07, 0.46};
  p.acc = {0.0, 0.0, 9.81};
  p.joints_deg = {{"hj1", -1.02}, {"laj3", 45.0}};
  p.forces.push_back({"lf", {-0.04, 0.06, -0.01}, {1.12, -0.26, 13.07}});
  SeeItems see;
  see.objects.push_back({"B", {8.51, -0.21, -0.17}});
  see.objects.push_back({"G1R", {15.2, 4.0, 3.0}});
  see.players.push_back({"X", 1, {{"head", {2.0, 1.0, -3.0}}, {"rfoot", {2.5, 1.5, -20.0}}}});
  see.lines.push_back({{1.0, 2.0, 3.0}, {4.0, 5.0, 6.0}});
  p.see = see;
  p.heard.push_back({"left", 0.02, true, 0.0, "hello"});
  p.heard.push_back({"Probe", 12.5, false, -35.123, "pass@2"});
  EXPECT_EQ(FormatPerception(p),
            "(time (now 1.34))"
            "(GS (unum 7) (team left) (sl 0) (sr 0) (t 0.00) (pm BeforeKickOff))"
            "(GYR (n torso) (rt 0.01 0.07 0.46))"
            "(ACC (n torso) (a 0.00 0.00 9.81))"
            "(HJ (n hj1) (ax -1.02))"
            "(HJ (n laj3) (ax 45.00))"
            "(FRP (n lf) (c -0.04 0.06 -0.01) (f 1.12 -0.26 13.07))"
            "(See (B (pol 8.51 -0.21 -0.17)) (G1R (pol 15.20 4.00 3.00)) "
            "(P (team X) (id 1) (head (pol 2.00 1.00 -3.00)) (rfoot (pol 2.50 1.50 -20.00))) "
            "(L (pol 1.00 2.00 3.00) (pol 4.00 5.00 6.00)))"
            "(hear left 0.02 self hello)"
            "(hear Probe 12.50 -35.12 pass@2)");
}

TEST(Perception, GameStateFields) {
  Perception p;
  p.side = Side::kRight;
  p.score_left = 2;
  p.score_right = 11;
  p.game_time = 299.999;
  p.play_mode = PlayMode::kGoalRight;
  const std::string text = FormatPerception(p);
  EXPECT_NE(text.find("(GS (team right) (sl 2) (sr 11) (t 300.00) (pm Goal_Right))"), std::string::npos) << text;
  p.side.reset();
  p.unum = 11;
  p.play_mode = PlayMode::kPassLeft;
  EXPECT_NE(FormatPerception(p).find("(GS (unum 11) (sl 2) (sr 11) (t 300.00) (pm pass_left))"), std::string::npos);
}

TEST(Perception, EmptySeeOnVisionCycleOnly) {
  Perception p;
  EXPECT_EQ(FormatPerception(p).find("See"), std::string::npos);
  p.see = SeeItems{};
  const std::string text = FormatPerception(p);
  EXPECT_EQ(text.substr(text.size() - 5), "(See)");
}

TEST(Perception, NonFiniteValuesStayParseable) {
  Perception p;
  p.time = std::nan("");
  p.gyro_deg_s = {std::numeric_limits<double>::infinity(), 0, 0};
  EXPECT_EQ(FormatPerception(p).substr(0, 17), "(time (now 0.00))");
  EXPECT_NE(FormatPerception(p).find("(rt 0.00 0.00 0.00)"), std::string::npos);
}

TEST(Perception, AFullVisionCycleParsesBackWithinTheAgentLimits) {
  Perception p;
  p.unum = 3;
  p.side = Side::kLeft;
  for (int i = 0; i < 24; ++i) p.joints_deg.push_back({"j" + std::to_string(i), i * 1.5});
  p.forces.push_back({"lf", {}, {}});
  p.forces.push_back({"rf", {}, {}});
  SeeItems see;
  for (const char* label : {"B", "F1L", "F2L", "F1R", "F2R", "G1L", "G2L", "G1R", "G2R"})
    see.objects.push_back({label, {1, 2, 3}});
  for (int id = 1; id <= 22; ++id)
    see.players.push_back(
        {id <= 11 ? "A" : "B", id, {{"head", {}}, {"rlowerarm", {}}, {"llowerarm", {}}, {"rfoot", {}}, {"lfoot", {}}}});
  for (int i = 0; i < 21; ++i) see.lines.push_back({{}, {}});
  p.see = see;
  const SExprParse parse = ParseSExprs(FormatPerception(p));
  ASSERT_EQ(parse.error, SExprError::kOk);
  ASSERT_EQ(parse.exprs.size(), 1u + 1 + 2 + 24 + 2 + 1);
  const SExpr& gs = parse.exprs[1];
  ASSERT_TRUE(gs.IsCall("GS"));
  EXPECT_EQ(gs.Child("unum")->items[1].atom, "3");
  EXPECT_EQ(gs.Child("team")->items[1].atom, "left");
  const SExpr& see_expr = parse.exprs.back();
  ASSERT_TRUE(see_expr.IsCall("See"));
  EXPECT_EQ(see_expr.items.size(), 1u + 9 + 22 + 21);
  EXPECT_EQ(see_expr.items[10].Child("id")->items[1].atom, "1");
}

}  // namespace
}  // namespace turf::simspark

namespace turf::simspark {
namespace {

// The fast path agrees with printf("%.2f") (the reference's format), ties and
// near-ties included.
TEST(PerceptionFormatFloat, AgreesWithPrintfOnRandomAndTieValues) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> wide(-2000.0, 2000.0);
  std::vector<double> values = {0.0, -0.0, 0.125, -0.375, 2.675, 0.005, -0.004, 0.015, 1.005, 99.995, 1e11, -1e13};
  for (int i = 0; i < 100000; ++i) {
    const double v = wide(rng);
    values.push_back(v);
    values.push_back(std::round(v * 1000) / 1000);  // thousandths: many near-ties
  }
  int mismatches = 0;
  for (double v : values) {
    char expected[64];
    std::snprintf(expected, sizeof(expected), "%.2f", v);
    if (FormatFloat(v) != expected && ++mismatches < 5)
      ADD_FAILURE() << v << ": " << FormatFloat(v) << " vs " << expected;
  }
  EXPECT_EQ(mismatches, 0);
}

}  // namespace
}  // namespace turf::simspark
