// Perception messages (shared/protocols/rcssservermj.md, "Perception message"): the facts' example byte for byte,
// the number format (truncation toward zero, Python's float repr), the order, See's grammar.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "codecs/rcssservermj/perception.h"

namespace turf::rcssservermj {
namespace {

TEST(MjNumbers, PythonRepr) {
  EXPECT_EQ(PythonFloat(0.0), "0.0");
  EXPECT_EQ(PythonFloat(-0.0), "-0.0");
  EXPECT_EQ(PythonFloat(1.5), "1.5");
  EXPECT_EQ(PythonFloat(12.34), "12.34");
  EXPECT_EQ(PythonFloat(37.0), "37.0");
  EXPECT_EQ(PythonFloat(-5.0), "-5.0");
  EXPECT_EQ(PythonFloat(0.1), "0.1");
  EXPECT_EQ(PythonFloat(0.001), "0.001");
  EXPECT_EQ(PythonFloat(0.0001), "0.0001");
  EXPECT_EQ(PythonFloat(0.00001), "1e-05");
  EXPECT_EQ(PythonFloat(1.5e-7), "1.5e-07");
  EXPECT_EQ(PythonFloat(1e15), "1000000000000000.0");
  EXPECT_EQ(PythonFloat(1e16), "1e+16");
  EXPECT_EQ(PythonFloat(1.2345e20), "1.2345e+20");
  EXPECT_EQ(PythonFloat(123456.0), "123456.0");
  EXPECT_EQ(PythonFloat(std::numeric_limits<double>::quiet_NaN()), "0.0");
}

TEST(MjNumbers, TruncatedTowardZeroNotRounded) {
  std::string out;
  AppendNumber(&out, 0.70710678, 3);
  EXPECT_EQ(out, "0.707");
  out.clear();
  AppendNumber(&out, -0.70790, 3);
  EXPECT_EQ(out, "-0.707");
  out.clear();
  AppendNumber(&out, 1.229, 2);
  EXPECT_EQ(out, "1.22");
  out.clear();
  AppendNumber(&out, -0.004, 2);  // toward zero keeps the sign: -0.0
  EXPECT_EQ(out, "-0.0");
  out.clear();
  AppendNumber(&out, 9.81, 2);
  EXPECT_EQ(out, "9.81");
}

// Every cycle's time reads k * 0.02 exactly, although 0.58 * 100 is 57.99999999999999 in binary.
// AppendNumber's fast path writes what the general one (PythonFloat of Truncate) does, over signs, zeros, magnitudes
// from 1e-5 to 1e16 and the decimals the perceptions use.
TEST(MjNumbers, AppendNumberEqualsPythonFloatOfTruncate) {
  std::mt19937_64 rng(14);
  std::uniform_real_distribution<double> mantissa(-10.0, 10.0);
  std::uniform_int_distribution<int> exponent(-6, 16);
  std::vector<double> values = {0.0,   -0.0,       0.001,    -0.001, 0.0009,     -0.0009, 0.58,  0.29, 1.0, -1.0,
                                100.0, 123.456789, 999.9995, 1e14,   9.99999e14, 1e15,    -1e15, 1e16, NAN, INFINITY};
  for (int i = 0; i < 200000; ++i) values.push_back(mantissa(rng) * std::pow(10.0, exponent(rng)));
  for (int k = 0; k < 5000; ++k) values.push_back(k * 0.02);  // cycle times
  for (double v : values) {
    for (int decimals : {0, 1, 2, 3, 4}) {
      std::string fast;
      AppendNumber(&fast, v, decimals);
      ASSERT_EQ(fast, PythonFloat(Truncate(v, decimals))) << v << " with " << decimals << " decimals";
    }
  }
}

TEST(MjNumbers, CycleTimesKeepTheirLastDigit) {
  for (int64_t k = 0; k <= 500000; ++k) {
    const double decimal = static_cast<double>(2 * k) / 100.0;  // the double nearest to k * 0.02
    const double from_ns =
        static_cast<double>(k * 20000000) * 1e-9;  // the world's nanoseconds, as the front-end reads them
    for (const double t : {decimal, from_ns}) {
      std::string out;
      AppendNumber(&out, t, 2);
      ASSERT_EQ(out, PythonFloat(decimal)) << k;
    }
  }
}

// The facts' example (T1, shortened to two joints), written from the values it shows.
TEST(MjPerception, TheFactsExampleByteForByte) {
  MjPerception p;
  p.time = 1.2249;
  p.game.play_mode = "BeforeKickOff";
  p.game.team_left = "teamBlue";
  p.has_robot = true;
  p.quat = {std::sqrt(0.5), 0.0, 0.0, -std::sqrt(0.5)};
  p.pos = {-5.0, 37.0, 0.6735};
  p.gyro = {0.0, 0.0, 0.0};
  p.acc = {0.0, 0.0, 9.8049};
  p.joints = {{"q_hj1", 0.0, 0.0}, {"q_hj2", 0.0, 0.0}};
  EXPECT_EQ(FormatPerception(p),
            "(time (now 1.22))(GS (t 0.0)(pm BeforeKickOff)(tl teamBlue)(sl 0)(sr 0))"
            "(quat (n torso_quat) (q 0.707 0.0 0.0 -0.707))(pos (n torso_pos) (p -5.0 37.0 0.673))"
            "(GYR (n torso_gyro) (rt 0.0 0.0 0.0))(ACC (n torso_acc) (a 0.0 0.0 9.8))"
            "(HJ (n q_hj1)(ax 0.0)(vx 0.0))(HJ (n q_hj2)(ax 0.0)(vx 0.0))");
}

TEST(MjPerception, UnitsDegreesForGyroAndJoints) {
  MjPerception p;
  p.game.play_mode = "PlayOn";
  p.game.team_left = "a";
  p.game.team_right = "b";
  p.game.score_left = 2;
  p.game.score_right = 1;
  p.game.play_time = 61.5;
  p.has_robot = true;
  p.gyro = {M_PI, 0, -M_PI / 2};
  p.joints = {{"q_llj4", M_PI / 4, -M_PI}};
  const std::string text = FormatPerception(p);
  EXPECT_NE(text.find("(GS (t 61.5)(pm PlayOn)(tl a)(tr b)(sl 2)(sr 1))"), std::string::npos) << text;
  EXPECT_NE(text.find("(rt 180.0 0.0 -90.0)"), std::string::npos) << text;
  EXPECT_NE(text.find("(HJ (n q_llj4)(ax 45.0)(vx -180.0))"), std::string::npos) << text;
}

TEST(MjPerception, SeeGrammar) {
  MjPerception p;
  p.game.play_mode = "PlayOn";
  p.has_robot = true;
  SeeItems see;
  see.markers = {{"l_luf", {10.256, 30.119, -5.5}}, {"B", {1.0, 0.0, -20.0}}};
  see.players = {{"teamBlue", 2, {{"head", {3.0, 1.0, 2.0}}, {"rfoot", {3.5, 1.5, -20.0}}}}};
  p.see = see;
  const std::string text = FormatPerception(p);
  const std::string expected =
      "(See (l_luf (pol 10.25 30.11 -5.5))(B (pol 1.0 0.0 -20.0))"
      "(P (team teamBlue)(id 2)(head (pol 3.0 1.0 2.0))(rfoot (pol 3.5 1.5 -20.0))))";
  ASSERT_GE(text.size(), expected.size());
  EXPECT_EQ(text.substr(text.size() - expected.size()), expected);
}

TEST(MjPerception, WithoutARobotOnlyTimeAndGameState) {
  MjPerception p;
  p.time = 0.02;
  p.game.play_mode = "BeforeKickOff";
  EXPECT_EQ(FormatPerception(p), "(time (now 0.02))(GS (t 0.0)(pm BeforeKickOff)(sl 0)(sr 0))");
}

}  // namespace
}  // namespace turf::rcssservermj
