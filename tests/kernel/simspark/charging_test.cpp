// rcssserver3d's charging judgement (kernel/simspark/charging.h) against the reference's rule as its code states it
// (SoccerRuleAspect::AnalyseChargingFouls with naosoccersim.rb's Charging* settings): who ran into whom.
#include "kernel/simspark/charging.h"

#include <gtest/gtest.h>

namespace turf::simspark {
namespace {

const Eigen::Vector3d kFarBall(8.0, 6.0, 0.042);

ChargingParty At(double x, double y, double vx = 0.0, double vy = 0.0) { return {{x, y, 0.35}, {vx, vy, 0.0}}; }

// Away from the ball (both farther than 1 m) only speed counts: 0.4 m/s or more, 0.2 m/s or more towards the
// collision.
TEST(ChargingJudgement, RunningIntoAStandingOpponentAwayFromTheBall) {
  const ChargingVerdict v = JudgeCollision({At(0, 0, 0.6), At(0.3, 0)}, {0.15, 0, 0.3}, kFarBall);
  EXPECT_TRUE(v.moving_into[0]);
  EXPECT_TRUE(v.charging[0]);
  EXPECT_FALSE(v.moving_into[1]) << "standing still";
  EXPECT_FALSE(v.charging[1]);
}

TEST(ChargingJudgement, TooSlowOrPassingByIsNoCharge) {
  EXPECT_FALSE(JudgeCollision({At(0, 0, 0.39), At(0.3, 0)}, {0.15, 0, 0.3}, kFarBall).charging[0]) << "0.39 m/s";
  // 0.5 m/s, but across: 0.5 sin(20 deg) = 0.17 m/s towards the collision.
  const double a = 70 * M_PI / 180;
  EXPECT_FALSE(JudgeCollision({At(0, 0, 0.5 * std::cos(a), 0.5 * std::sin(a)), At(0.3, 0)}, {0.15, 0, 0.3}, kFarBall)
                   .moving_into[0]);
  // Running away from the opponent it touches.
  EXPECT_FALSE(JudgeCollision({At(0, 0, -0.6), At(0.3, 0)}, {0.15, 0, 0.3}, kFarBall).charging[0]);
}

TEST(ChargingJudgement, BothRunningIntoEachOtherIsNoFoul) {
  const ChargingVerdict v = JudgeCollision({At(0, 0, 0.6), At(0.3, 0, -0.6)}, {0.15, 0, 0.3}, kFarBall);
  EXPECT_TRUE(v.moving_into[0]);
  EXPECT_TRUE(v.moving_into[1]);
  EXPECT_FALSE(v.charging[0]);
  EXPECT_FALSE(v.charging[1]);
}

// When neither heads away from the ball, the one farther from the ball charges if the other stands (slower than
// 0.4 m/s), or their angles to each other differ by more than 15 deg.
TEST(ChargingJudgement, NearTheBallTheOneFartherFromItChargesAStandingOpponent) {
  const Eigen::Vector3d ball(0.6, 0.0, 0.042);
  // Straight at the ball with a standing opponent in between (contact 0.45 m from the ball).
  const ChargingVerdict v = JudgeCollision({At(0, 0, 0.6), At(0.3, 0)}, {0.15, 0, 0.3}, ball);
  EXPECT_TRUE(v.charging[0]);
  EXPECT_FALSE(v.charging[1]);
  // Running into the back of an opponent who runs for the ball too: their angles to each other differ (0 and
  // 180 deg), so the one behind charges.
  const ChargingVerdict behind = JudgeCollision({At(0, 0, 0.6), At(0.3, 0, 0.6)}, {0.15, 0, 0.3}, ball);
  EXPECT_TRUE(behind.charging[0]);
  EXPECT_FALSE(behind.moving_into[1]) << "running away from the contact";
  // Their distances to the ball within 0.05 m (the ball 28 deg off its heading, as far from both): no charge.
  const Eigen::Vector3d between(0.15, 0.08, 0.042);
  EXPECT_FALSE(JudgeCollision({At(0, 0, 0.6), At(0.3, 0)}, {0.15, -0.05, 0.3}, between).moving_into[0]);
}

// Within 1 m of the ball, running into the opponent from aside (more towards it than the ball, 30 deg or more off
// the ball) charges.
TEST(ChargingJudgement, NearTheBallRunningAtTheOpponentCharges) {
  const Eigen::Vector3d ball(0.3, 0.5, 0.042);  // the opponent's ball, 0.5 m beyond it
  const ChargingVerdict v = JudgeCollision({At(0, 0, 0.6), At(0.3, 0)}, {0.15, 0, 0.3}, ball);
  EXPECT_TRUE(v.charging[0]);
  EXPECT_FALSE(v.charging[1]);
}

// Both running head-on for the ball between them (each less than 30 deg off it, as far from it as the other): no
// charge.
TEST(ChargingJudgement, BothRunningForTheBallBetweenThemIsNoCharge) {
  const ChargingVerdict v = JudgeCollision({At(0, 0, 0.6), At(0.3, 0, -0.6)}, {0.15, -0.06, 0.3}, {0.15, 0.05, 0.042});
  EXPECT_FALSE(v.moving_into[0]);
  EXPECT_FALSE(v.moving_into[1]);
}

// A contact within 0.1 m of the ball is a tussle for the ball: nobody charges. (31 deg off the ball and straight at
// the opponent: charging by the ball rule, but the contact is 0.09 m from the ball.)
TEST(ChargingJudgement, AContactAtTheBallIsNoFoul) {
  const ChargingVerdict v = JudgeCollision({At(0, 0, 0.6), At(0.3, 0)}, {0.15, 0, 0.3}, {0.15, 0.09, 0.042});
  EXPECT_TRUE(v.moving_into[0]);
  EXPECT_FALSE(v.charging[0]);
  EXPECT_TRUE(JudgeCollision({At(0, 0, 0.6), At(0.3, 0)}, {0.15, 0, 0.3}, {0.15, 0.11, 0.042}).charging[0])
      << "0.11 m from the ball";
}

}  // namespace
}  // namespace turf::simspark
