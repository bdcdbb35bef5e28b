// The agent's messages (shared/protocols/rcssservermj.md, "Actions"): init, motor (degrees in, radians out), beam,
// say, syn; refusals are named and never applied.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "codecs/rcssservermj/actions.h"
#include "codecs/rcssservermj/robots.h"
#include "tests/support/issues.h"

namespace turf::rcssservermj {
namespace {

const MjRobotModel& T1() { return *FindModel("T1"); }

TEST(MjInit, TakesTheFactsExample) {
  InitAction init;
  ASSERT_EQ(ParseInit("(init T1 teamBlue 2)", &init), Error::kOk);
  EXPECT_EQ(init.model, "T1");
  EXPECT_EQ(init.team, "teamBlue");
  EXPECT_EQ(init.player_no, 2);
}

TEST(MjInit, PlayerNumberIsAbsoluteModuloHundred) {
  InitAction init;
  ASSERT_EQ(ParseInit("(init K1 a -123)", &init), Error::kOk);
  EXPECT_EQ(init.player_no, 23);
}

TEST(MjInit, RefusesAnythingElse) {
  InitAction init;
  EXPECT_EQ(ParseInit("(init T1 teamBlue)", &init), Error::kBadArguments);
  EXPECT_EQ(ParseInit("(init T1 teamBlue 2 3)", &init), Error::kBadArguments);
  EXPECT_EQ(ParseInit("(init T1 teamBlue 2.5)", &init), Error::kBadArguments);
  EXPECT_EQ(ParseInit("(init T1 (x) 2)", &init), Error::kBadArguments);
  EXPECT_EQ(ParseInit("(init T1 a 2)(syn)", &init), Error::kBadArguments);
  EXPECT_EQ(ParseInit("(scene rsg/agent/nao/nao.rsg)", &init), Error::kBadArguments);
  EXPECT_EQ(ParseInit("(init T1 a 2", &init), Error::kParse);
  EXPECT_EQ(ParseInit("", &init), Error::kBadArguments);
}

TEST(MjActions, MotorDegreesBecomeRadians) {
  const ActionMessage m = ParseActions("(he1 12.42 0 0.9 0 0)(lle4 90 -180 50 1.5 -2)", T1());
  ASSERT_TRUE(m.issues.empty());
  ASSERT_EQ(m.motors.size(), 2u);
  EXPECT_EQ(m.motors[0].joint, EffectorIndex(T1(), "he1"));
  EXPECT_NEAR(m.motors[0].q, 12.42 * M_PI / 180, 1e-12);
  EXPECT_DOUBLE_EQ(m.motors[0].kp, 0.9);
  EXPECT_EQ(std::string(T1().joints[m.motors[1].joint].joint), "Left_Knee_Pitch");
  EXPECT_NEAR(m.motors[1].q, M_PI / 2, 1e-12);
  EXPECT_NEAR(m.motors[1].dq, -M_PI, 1e-12);
  EXPECT_DOUBLE_EQ(m.motors[1].kd, 1.5);
  EXPECT_DOUBLE_EQ(m.motors[1].tau, -2);
}

TEST(MjActions, RefusesBadMotorCommandsByName) {
  const ActionMessage m = ParseActions(
      "(he1 nan 0 1 1 0)(he1 0 inf 1 1 0)(he1 1e9 0 1 1 0)(he1 0 0 -1 1 0)(he1 0 0 1 1e6 0)(te9 0 0 1 1 0)"
      "(he1 0 0 1 1 x)(he2 10 0 1 1 0)",
      T1());
  ASSERT_EQ(m.motors.size(), 1u);  // only the last
  EXPECT_EQ(m.motors[0].joint, 1);
  EXPECT_EQ(test::ErrorsOf(m.issues),
            (std::vector<Error>{Error::kNotFinite, Error::kNotFinite, Error::kOutOfRange, Error::kOutOfRange,
                                Error::kOutOfRange, Error::kUnknownEffector, Error::kBadArguments}));
}

TEST(MjActions, TheWaistIsAT1EffectorOnly) {
  EXPECT_TRUE(ParseActions("(te1 5 0 1 1 0)", T1()).issues.empty());
  const ActionMessage k1 = ParseActions("(te1 5 0 1 1 0)", *FindModel("K1"));
  ASSERT_EQ(k1.issues.size(), 1u);
  EXPECT_EQ(k1.issues[0].error, Error::kUnknownEffector);
}

TEST(MjActions, BeamSaySyn) {
  const ActionMessage m = ParseActions("(beam -3 1.5 90)(say hello there)(syn)", T1());
  ASSERT_TRUE(m.issues.empty());
  ASSERT_TRUE(m.beam);
  EXPECT_DOUBLE_EQ(m.beam->x, -3);
  EXPECT_DOUBLE_EQ(m.beam->y, 1.5);
  EXPECT_DOUBLE_EQ(m.beam->theta_deg, 90);
  EXPECT_TRUE(m.say);
  EXPECT_TRUE(m.syn);
  EXPECT_EQ(ParseActions("(beam 1 2)", T1()).issues.at(0).error, Error::kBadArguments);
  EXPECT_EQ(ParseActions("(beam 1 nan 0)", T1()).issues.at(0).error, Error::kNotFinite);
  EXPECT_FALSE(ParseActions("(beam 1 nan 0)", T1()).beam);
  // turf-sim's limit of a legged placement (core/legged/placement_limits.h) is the beam's: refused where it arrives.
  EXPECT_TRUE(ParseActions("(beam -100 100 720)", T1()).beam);
  EXPECT_EQ(ParseActions("(beam 100.5 0 0)", T1()).issues.at(0).error, Error::kOutOfRange);
  EXPECT_EQ(ParseActions("(beam 0 -100.5 0)", T1()).issues.at(0).error, Error::kOutOfRange);
}

TEST(MjActions, UnparsableMessageAppliesNothing) {
  const ActionMessage m = ParseActions("(he1 1 0 1 1 0)(syn", T1());
  EXPECT_TRUE(m.motors.empty());
  EXPECT_FALSE(m.syn);
  ASSERT_EQ(m.issues.size(), 1u);
  EXPECT_EQ(m.issues[0].error, Error::kParse);
}

TEST(MjRobots, TablesMatchTheFacts) {
  EXPECT_EQ(FindModel("T1")->joints.size(), 23u);
  EXPECT_EQ(FindModel("K1")->joints.size(), 22u);
  EXPECT_EQ(FindModel("t1"), nullptr);  // case sensitive
  EXPECT_EQ(FindModel("ant"), nullptr);
  // HJ order: hj1, hj2, laj1-4, raj1-4, tj1, llj1-6, rlj1-6; effector = perceptor with e for j, no q_.
  const char* order[] = {"q_hj1",  "q_hj2",  "q_laj1", "q_laj2", "q_laj3", "q_laj4", "q_raj1", "q_raj2",
                         "q_raj3", "q_raj4", "q_tj1",  "q_llj1", "q_llj2", "q_llj3", "q_llj4", "q_llj5",
                         "q_llj6", "q_rlj1", "q_rlj2", "q_rlj3", "q_rlj4", "q_rlj5", "q_rlj6"};
  for (size_t i = 0; i < 23; ++i) {
    const MjJoint& j = FindModel("T1")->joints[i];
    EXPECT_STREQ(j.perceptor, order[i]);
    std::string effector = std::string(order[i]).substr(2);
    effector[effector.size() - 2] = 'e';
    EXPECT_EQ(effector, j.effector);
    EXPECT_LT(j.lo_deg, j.hi_deg);
    EXPECT_GT(j.torque, 0);
  }
}

}  // namespace
}  // namespace turf::rcssservermj
