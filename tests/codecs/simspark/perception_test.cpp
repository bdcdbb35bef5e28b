#include "codecs/simspark/perception.h"

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "codecs/simspark/nao_joints.h"
#include "codecs/simspark/sexpr.h"
#include "tests/codecs/simspark/golden_perception.h"

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
            "(hear left 0.02 self hello)"
            "(hear Probe 12.50 -35.12 pass@2)"
            "(GYR (n torso) (rt 0.01 0.07 0.46))"
            "(ACC (n torso) (a 0.00 0.00 9.81))"
            "(HJ (n hj1) (ax -1.02))"
            "(HJ (n laj3) (ax 45.00))"
            // no hj2 or llj6 here: See and FRP after the HJs
            "(See (B (pol 8.51 -0.21 -0.17)) (G1R (pol 15.20 4.00 3.00)) "
            "(P (team X) (id 1) (head (pol 2.00 1.00 -3.00)) (rfoot (pol 2.50 1.50 -20.00))) "
            "(L (pol 1.00 2.00 3.00) (pol 4.00 5.00 6.00)))"
            "(FRP (n lf) (c -0.04 0.06 -0.01) (f 1.12 -0.26 13.07))");
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

TEST(Perception, NoSeeOffVisionCycles) {
  Perception p;
  EXPECT_EQ(FormatPerception(p).find("See"), std::string::npos);
}

// The reference's SexpParser::PredicateToString writes '(' name ' ' params ')':
// with nothing visible the See predicate is still sent, as "(See )".
TEST(Perception, EmptySeeIsWrittenWithTheSpaceAfterTheName) {
  Perception p;
  p.see = SeeItems{};
  const std::string text = FormatPerception(p);
  EXPECT_EQ(text.substr(text.size() - 6), "(See )") << text;
  EXPECT_EQ(text.find("(See)"), std::string::npos) << text;
}

// The joints of a type-0 Nao in NaoJoints order, all at `deg`.
std::vector<std::pair<std::string, double>> AllJoints(int type, double deg) {
  std::vector<std::pair<std::string, double>> joints;
  for (const NaoJoint& j : NaoJoints(type)) joints.emplace_back(j.perceptor, deg);
  return joints;
}

// A fallen robot (no foot touching), after init, on a vision cycle, seeing
// nothing and hearing nothing: the whole message, in the reference's order.
TEST(Perception, FallenRobotThatSeesNothingGetsTheReferencesBytes) {
  Perception p;
  p.time = 12.34;
  p.game_time = 2.5;
  p.play_mode = PlayMode::kPlayOn;
  p.gyro_deg_s = {-0.5, 12.25, 0.0};
  p.acc = {0.12, -9.79, 0.31};
  p.joints_deg = AllJoints(0, 0.0);
  p.joints_deg[1].second = -45.0;  // hj2
  p.see = SeeItems{};
  EXPECT_EQ(FormatPerception(p), std::string("(time (now 12.34))"
                                             "(GS (sl 0) (sr 0) (t 2.50) (pm PlayOn))"
                                             "(GYR (n torso) (rt -0.50 12.25 0.00))"
                                             "(ACC (n torso) (a 0.12 -9.79 0.31))"
                                             "(HJ (n hj1) (ax 0.00))"
                                             "(HJ (n hj2) (ax -45.00))"
                                             "(See )") +
                                     test::kLimbJointsAtZero);
}

TEST(Perception, SeesNothingAndHearsNothingHasNoHearAndAnEmptySee) {
  Perception p;
  p.unum = 4;
  p.side = Side::kRight;
  p.joints_deg = {{"hj1", 1.0}, {"hj2", 2.0}, {"raj1", 3.0}};
  p.see = SeeItems{};
  EXPECT_EQ(FormatPerception(p),
            "(time (now 0.00))(GS (unum 4) (team right) (sl 0) (sr 0) (t 0.00) (pm BeforeKickOff))"
            "(GYR (n torso) (rt 0.00 0.00 0.00))(ACC (n torso) (a 0.00 0.00 0.00))"
            "(HJ (n hj1) (ax 1.00))(HJ (n hj2) (ax 2.00))(See )(HJ (n raj1) (ax 3.00))");
}

// ForceResistancePerceptor: no predicate without contact; with contact the FRP
// comes right before the hinge of its body (rf before rlj6, toe rf1 before rlj7).
TEST(Perception, FrpOnlyWhileTouchingAndBeforeItsFootsHinge) {
  Perception p;
  p.joints_deg = AllJoints(4, 0.0);
  std::string text = FormatPerception(p);
  EXPECT_EQ(text.find("FRP"), std::string::npos) << text;
  p.forces.push_back({"rf", {0.01, 0.02, -0.01}, {0.0, 0.0, 22.5}});
  p.forces.push_back({"lf1", {0.0, 0.0, 0.0}, {1.0, 2.0, 3.0}});
  text = FormatPerception(p);
  EXPECT_NE(text.find("(HJ (n rlj5) (ax 0.00))(FRP (n rf) (c 0.01 0.02 -0.01) (f 0.00 0.00 22.50))"
                      "(HJ (n rlj6) (ax 0.00))(HJ (n rlj7) (ax 0.00))(HJ (n llj1)"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("(HJ (n llj6) (ax 0.00))(FRP (n lf1) (c 0.00 0.00 0.00) (f 1.00 2.00 3.00))"
                      "(HJ (n llj7) (ax 0.00))"),
            std::string::npos)
      << text;
  EXPECT_EQ(text.substr(text.size() - 23), "(HJ (n llj7) (ax 0.00))") << text;
}

// HearPerceptor writes its own message, then the teammate's, then the opponent's, between GS and GYR.
TEST(Perception, HearComesRightAfterGs) {
  Perception p;
  p.heard.push_back({"A", 1.0, true, 0.0, "mine"});
  p.heard.push_back({"B", 1.0, false, 90.0, "theirs"});
  const std::string text = FormatPerception(p);
  EXPECT_NE(text.find("(pm BeforeKickOff))(hear A 1.00 self mine)(hear B 1.00 90.00 theirs)(GYR"), std::string::npos)
      << text;
}

// The reference's numbers are floats: a double just below a tie that rounds to
// the tie as a float is printed as the float is.
TEST(Perception, NumbersAreRoundedAsFloats) {
  Perception p;
  p.joints_deg = {{"hj1", 0.375 - 1e-12}};
  char as_double[32];
  std::snprintf(as_double, sizeof(as_double), "%.2f", 0.375 - 1e-12);
  ASSERT_STREQ(as_double, "0.37");
  EXPECT_NE(FormatPerception(p).find("(HJ (n hj1) (ax 0.38))"), std::string::npos) << FormatPerception(p);
  p.joints_deg = {{"hj1", -1e300}};  // beyond float: saturates at the largest float, still a number
  EXPECT_NE(FormatPerception(p).find("(HJ (n hj1) (ax -340282346638528859811704183484516925440.00))"),
            std::string::npos)
      << FormatPerception(p);
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
  const SExpr& see_expr = parse.exprs[parse.exprs.size() - 3];  // no hj2 or llj6: See, then the two FRPs
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

namespace turf::simspark {
namespace {

// A strict reader of the reference's output grammar (SexpParser::Generate):
//   message   = predicate+                       (nothing between predicates)
//   predicate = "(" atom " " [element (" " element)*] ")"
//   element   = atom | list
//   list      = "(" atom (" " element)+ ")"    (a tag and at least one parameter)
//   atom      = 1+ of 0x21..0x7E but "(" ")"; a number is an int or fixed with 2 decimals
// It stops at the first difference and says where, as a strict agent would die there.
class StrictReader {
 public:
  explicit StrictReader(std::string_view text) : text_(text) {}

  std::string Check() {
    if (text_.empty()) return "empty message";
    while (at_ < text_.size() && error_.empty()) Predicate();
    return error_;
  }

 private:
  bool Fail(const std::string& what) {
    if (error_.empty()) error_ = what + " at " + std::to_string(at_) + " in " + std::string(text_);
    return false;
  }
  bool Eat(char c) {
    if (at_ < text_.size() && text_[at_] == c) {
      ++at_;
      return true;
    }
    return Fail(std::string("expected '") + c + "'");
  }
  bool Peek(char c) const { return at_ < text_.size() && text_[at_] == c; }

  bool Atom() {
    const size_t begin = at_;
    while (at_ < text_.size() && text_[at_] > 0x20 && text_[at_] < 0x7F && text_[at_] != '(' && text_[at_] != ')')
      ++at_;
    if (at_ == begin) return Fail("expected an atom");
    const std::string_view atom = text_.substr(begin, at_ - begin);
    if (std::isdigit(static_cast<unsigned char>(atom[0])) || atom[0] == '-') {
      size_t k = atom[0] == '-' ? 1 : 0;
      const size_t digits = k;
      while (k < atom.size() && std::isdigit(static_cast<unsigned char>(atom[k]))) ++k;
      const bool whole = k > digits;
      const bool integer = whole && k == atom.size();
      const bool fixed2 = whole && k + 3 == atom.size() && atom[k] == '.' &&
                          std::isdigit(static_cast<unsigned char>(atom[k + 1])) &&
                          std::isdigit(static_cast<unsigned char>(atom[k + 2]));
      if (!integer && !fixed2) return Fail("not an int or a 2-decimal number: " + std::string(atom));
    }
    return true;
  }

  bool Element() { return Peek('(') ? List() : Atom(); }

  bool List() {
    if (!Eat('(') || !Atom()) return false;
    if (!Peek(' ')) return Fail("a sub-list without parameters");
    while (Peek(' ')) {
      ++at_;
      if (!Element()) return false;
    }
    return Eat(')');
  }

  bool Predicate() {
    if (!Eat('(') || !Atom() || !Eat(' ')) return false;
    if (Peek(')')) return Eat(')');  // no parameters: "(See )"
    if (!Element()) return false;
    while (Peek(' ')) {
      ++at_;
      if (!Element()) return false;
    }
    return Eat(')');
  }

  std::string_view text_;
  size_t at_ = 0;
  std::string error_;
};

TEST(PerceptionStrictReader, AcceptsTheReferencesShapesAndRefusesOthers) {
  EXPECT_EQ(StrictReader("(time (now 1.00))(See )(hear A 1.00 self x)").Check(), "");
  EXPECT_NE(StrictReader("(time (now 1.00))(See)").Check(), "");  // what turf used to send
  EXPECT_NE(StrictReader("(See (B))").Check(), "");
  EXPECT_NE(StrictReader("(See  (B (pol 1.00 2.00 3.00)))").Check(), "");
  EXPECT_NE(StrictReader("(GS (t 1.5))").Check(), "");
  EXPECT_NE(StrictReader("(GS (t 1.50)) ").Check(), "");
  EXPECT_NE(StrictReader("(GS (t 1.50)").Check(), "");
}

// For random world states, every perception reads with the strict reader and
// keeps the reference's order (time, GS, hear*, GYR, ACC, then the body).
TEST(PerceptionProperty, RandomPerceptionsReadStrictlyInTheReferencesOrder) {
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const auto chance = [&](double p) { return unit(rng) < p; };
  const auto number = [&]() -> double {
    const double pick = unit(rng);
    if (pick < 0.02) return std::nan("");
    if (pick < 0.04) return (chance(0.5) ? 1 : -1) * std::numeric_limits<double>::infinity();
    if (pick < 0.06) return (chance(0.5) ? 1 : -1) * 1e300;
    if (pick < 0.10) return -0.001 * unit(rng);                             // "-0.00"
    if (pick < 0.15) return std::round(unit(rng) * 2000.0) / 1000.0 - 1.0;  // near-ties
    return (unit(rng) - 0.5) * std::pow(10.0, std::floor(unit(rng) * 6));
  };
  const auto name = [&]() {
    std::string n;
    const int length = 1 + static_cast<int>(unit(rng) * 8);
    for (int i = 0; i < length; ++i) n.push_back(static_cast<char>('A' + static_cast<int>(unit(rng) * 26)));
    return n;
  };
  const auto pol = [&]() { return Polar{number(), number(), number()}; };
  for (int round = 0; round < 3000; ++round) {
    Perception p;
    const int type = static_cast<int>(unit(rng) * kNaoTypes);
    p.time = number();
    if (chance(0.2)) p.unum = static_cast<int>(unit(rng) * 12);
    if (chance(0.2)) p.side = chance(0.5) ? Side::kLeft : Side::kRight;
    p.score_left = static_cast<int>(unit(rng) * 20);
    p.score_right = static_cast<int>(unit(rng) * 20);
    p.game_time = number();
    p.play_mode = static_cast<PlayMode>(static_cast<int>(unit(rng) * 21));
    p.gyro_deg_s = {number(), number(), number()};
    p.acc = {number(), number(), number()};
    if (!chance(0.1)) {
      for (const NaoJoint& j : NaoJoints(type))
        if (!chance(0.05)) p.joints_deg.emplace_back(j.perceptor, number());
    }
    for (const char* foot : {"lf", "rf", "lf1", "rf1"}) {
      if (std::string(foot).size() == 3 && type != 4) continue;
      if (chance(0.5)) p.forces.push_back({foot, {number(), number(), number()}, {number(), number(), number()}});
    }
    if (chance(0.4)) {
      SeeItems see;
      for (int i = static_cast<int>(unit(rng) * 4); i > 0; --i) see.objects.push_back({name(), pol()});
      for (int i = static_cast<int>(unit(rng) * 3); i > 0; --i) {
        SeePlayer player{name(), 1 + static_cast<int>(unit(rng) * 11), {}};
        for (int k = 1 + static_cast<int>(unit(rng) * 5); k > 0; --k) player.parts.push_back({name(), pol()});
        see.players.push_back(player);
      }
      for (int i = static_cast<int>(unit(rng) * 3); i > 0; --i) see.lines.push_back({pol(), pol()});
      p.see = see;
    }
    for (int i = static_cast<int>(unit(rng) * 4); i > 0; --i)
      p.heard.push_back({name(), number(), chance(0.3), number(), name()});

    const std::string text = FormatPerception(p);
    const std::string error = StrictReader(text).Check();
    ASSERT_EQ(error, "") << "round " << round;

    const SExprParse parse = ParseSExprs(text);
    ASSERT_EQ(parse.error, SExprError::kOk) << text;
    std::vector<std::string> names;
    std::vector<std::string> subjects;  // HJ and FRP: their (n ...); others: ""
    for (const SExpr& e : parse.exprs) {
      names.push_back(e.items[0].atom);
      const SExpr* n = e.Child("n");
      subjects.push_back(n != nullptr && (names.back() == "HJ" || names.back() == "FRP") ? n->items[1].atom : "");
    }
    const size_t hears = p.heard.size();
    ASSERT_EQ(names.size(), 4 + hears + p.joints_deg.size() + p.forces.size() + (p.see ? 1 : 0)) << text;
    EXPECT_EQ(names[0], "time");
    EXPECT_EQ(names[1], "GS");
    for (size_t i = 0; i < hears; ++i) EXPECT_EQ(names[2 + i], "hear") << text;
    EXPECT_EQ(names[2 + hears], "GYR");
    EXPECT_EQ(names[3 + hears], "ACC");
    for (size_t i = 4 + hears; i < names.size(); ++i) {
      if (names[i] == "See" && i > 0 && subjects[i - 1] == "hj2") continue;
      if (names[i] == "FRP" && i + 1 < names.size() && names[i + 1] == "HJ") {
        const std::string& foot = subjects[i];
        const std::string hinge = foot.substr(0, 1) + (foot.size() == 3 ? "lj7" : "lj6");
        EXPECT_EQ(subjects[i + 1], hinge) << text;
      }
      if (subjects[i] == "hj2" && p.see) {
        EXPECT_EQ(names[i + 1], "See") << text;
      }
    }
  }
}

}  // namespace
}  // namespace turf::simspark
