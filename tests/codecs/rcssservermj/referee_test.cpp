// The referee (shared/protocols/rcssservermj.md, "Play modes" and rule books; turf's decisions in referee.h):
// kick-off, goals, out of bounds (kick-in, corner, goal kick), halves.
#include <gtest/gtest.h>

#include "kernel/rcssservermj/referee.h"

namespace turf::rcssservermj {
namespace {

constexpr double kDt = 0.02;
constexpr double kR = 0.11;

struct RefereeFixture : ::testing::Test {
  Referee ref{*FindRuleBook("fifa"), *FindField("fifa"), kR};
  std::optional<Eigen::Vector3d> Step(const Eigen::Vector3d& ball, std::optional<Side> toucher = std::nullopt) {
    return ref.Update(kDt, ball, toucher);
  }
  void KickOffAndPlay(Side side) {
    ref.KickOff(side);
    const auto centre = Step({0, 0, kR});
    ASSERT_TRUE(centre);
    ASSERT_EQ(*centre, Eigen::Vector3d(0, 0, kR));  // the ball to the centre
    Step({0.3, 0, kR}, side);                       // kicked: play on
    ASSERT_EQ(ref.play_mode(), PlayMode::kPlayOn);
  }
};

TEST_F(RefereeFixture, SidesAndNames) {
  EXPECT_EQ(ref.Join("a"), Side::kLeft);
  EXPECT_EQ(ref.Join("b"), Side::kRight);
  EXPECT_EQ(ref.Join("a"), Side::kLeft);
  EXPECT_EQ(ref.Join("c"), std::nullopt);
  EXPECT_EQ(std::string(PlayModeName(PlayMode::kCornerKickLeft)), "corner_kick_left");
  EXPECT_EQ(ParsePlayMode("Goal_Right"), PlayMode::kGoalRight);
  EXPECT_EQ(ParsePlayMode("goal_right"), std::nullopt);
}

TEST_F(RefereeFixture, TimeStandsBeforeKickOff) {
  for (int i = 0; i < 100; ++i) Step({0, 0, kR});
  EXPECT_EQ(ref.play_mode(), PlayMode::kBeforeKickOff);
  EXPECT_EQ(ref.play_time(), 0.0);
  EXPECT_TRUE(ref.BeamAllowed());
}

TEST_F(RefereeFixture, GoalThenKickOffOfTheOtherSide) {
  KickOffAndPlay(Side::kLeft);
  Step({52.5 + kR - 0.01, 0, kR});  // on the line, not wholly over it
  EXPECT_EQ(ref.play_mode(), PlayMode::kPlayOn);
  Step({52.5 + kR + 0.01, 1.0, kR});
  EXPECT_EQ(ref.play_mode(), PlayMode::kGoalLeft);
  EXPECT_EQ(ref.score(Side::kLeft), 1);
  EXPECT_TRUE(ref.BeamAllowed());
  std::optional<Eigen::Vector3d> place;
  for (int i = 0; i < 150 && !place; ++i) place = Step({53, 1, kR});  // 3 s pause
  ASSERT_TRUE(place);
  EXPECT_EQ(*place, Eigen::Vector3d(0, 0, kR));
  EXPECT_EQ(ref.play_mode(), PlayMode::kKickOffRight);
}

TEST_F(RefereeFixture, OverTheBarOrBesideThePostIsNoGoal) {
  KickOffAndPlay(Side::kRight);
  const auto place = Step({-53, 0.5, 2.6}, Side::kLeft);  // over the bar, the defenders touched it last
  EXPECT_EQ(ref.play_mode(), PlayMode::kCornerKickRight);
  ASSERT_TRUE(place);
  EXPECT_EQ(*place, Eigen::Vector3d(-52.5, 34, kR));
  EXPECT_EQ(ref.score(Side::kRight), 0);
}

TEST_F(RefereeFixture, GoalKickWhenTheAttackersTouchedItLast) {
  KickOffAndPlay(Side::kLeft);
  const auto place = Step({53, -5, kR}, Side::kLeft);
  ASSERT_TRUE(place);
  EXPECT_EQ(ref.play_mode(), PlayMode::kGoalKickRight);
  EXPECT_EQ(*place, Eigen::Vector3d(47, 0, kR));
}

TEST_F(RefereeFixture, KickInForTheTeamThatDidNotTouchLast) {
  KickOffAndPlay(Side::kLeft);
  const auto place = Step({10, -34.2, kR}, Side::kLeft);
  ASSERT_TRUE(place);
  EXPECT_EQ(ref.play_mode(), PlayMode::kKickInRight);
  EXPECT_EQ(*place, Eigen::Vector3d(10, -34, kR));
  Step(*place);
  Step(*place + Eigen::Vector3d(0.2, 0, 0), Side::kRight);
  EXPECT_EQ(ref.play_mode(), PlayMode::kPlayOn);
}

TEST_F(RefereeFixture, RestartTurnsToPlayOnAfterTheExclusiveTime) {
  ref.KickOff(Side::kLeft);
  for (int i = 0; i < 749; ++i) Step({0, 0, kR});
  EXPECT_EQ(ref.play_mode(), PlayMode::kKickOffLeft);
  Step({0, 0, kR});
  Step({0, 0, kR});
  EXPECT_EQ(ref.play_mode(), PlayMode::kPlayOn);
}

TEST(Referee, HalvesOfTheSsim2025RuleBook) {
  Referee ref(*FindRuleBook("ssim_2025"), *FindField("fifa"), kR);
  ref.KickOff(Side::kLeft);
  ref.Update(kDt, {0, 0, kR}, std::nullopt);
  ref.DropBall();
  int cycles = 1;
  while (ref.play_mode() == PlayMode::kPlayOn && cycles < 20000) {
    ref.Update(kDt, {0, 0, kR}, std::nullopt);
    ++cycles;
  }
  EXPECT_EQ(ref.play_mode(), PlayMode::kBeforeKickOff);
  EXPECT_EQ(ref.half(), 2);
  EXPECT_NEAR(ref.play_time(), 300.0, 1e-9);
  ref.KickOff(Side::kRight);
  ref.Update(kDt, {0, 0, kR}, std::nullopt);
  ref.DropBall();
  while (ref.play_mode() == PlayMode::kPlayOn) ref.Update(kDt, {0, 0, kR}, std::nullopt);
  EXPECT_EQ(ref.play_mode(), PlayMode::kGameOver);
  EXPECT_NEAR(ref.play_time(), 600.0, 1e-9);
  ASSERT_NE(FindRuleBook("fifa"), nullptr);
  EXPECT_EQ(FindRuleBook("fifa")->half_s, 45 * 60);
}

}  // namespace
}  // namespace turf::rcssservermj
