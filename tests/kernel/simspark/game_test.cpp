#include "kernel/simspark/game.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "tests/support/state_round_trip.h"

namespace turf::simspark {
namespace {

constexpr double kDt = 0.02;
const Eigen::Vector3d kCentre(0, 0, 0.042);
const std::vector<Toucher> kNobody;
const std::vector<Toucher> kSomeone{{Side::kLeft, 1}};

// Runs cycles with the ball at `ball` until the play mode changes; returns the
// number of cycles (or `max` if it never does).
int CyclesUntilModeChange(Game* game, const Eigen::Vector3d& ball, int max, GameUpdate* last = nullptr) {
  const PlayMode start = game->play_mode();
  for (int i = 1; i <= max; ++i) {
    const GameUpdate u = game->Update(kDt, ball, kNobody);
    if (game->play_mode() != start) {
      if (last != nullptr) *last = u;
      return i;
    }
  }
  return max;
}

// The reference's paused flag (GameStateAspect::IsPaused): set at the start and by a cycle in BeforeKickOff or a
// goal, kept by offside, cleared by every other mode; in snapshots.
TEST(GamePaused, SetByBeforeKickOffAndGoalsKeptByOffsideClearedByTheRest) {
  Game game;
  ASSERT_TRUE(game.Init("Alpha", 1, 0).ok);
  EXPECT_TRUE(game.paused());
  const auto after = [&](PlayMode before, PlayMode mode) {
    game.SetPlayMode(before);
    game.Update(kDt, kCentre, kNobody);
    game.SetPlayMode(mode);
    game.Update(kDt, kCentre, kNobody);
    return game.paused();
  };
  for (PlayMode m : {PlayMode::kPlayOn, PlayMode::kKickOffLeft, PlayMode::kKickInRight, PlayMode::kCornerKickLeft,
                     PlayMode::kGoalKickRight, PlayMode::kFreeKickLeft, PlayMode::kDirectFreeKickRight,
                     PlayMode::kPassLeft, PlayMode::kGameOver})
    EXPECT_FALSE(after(PlayMode::kBeforeKickOff, m)) << PlayModeName(m);
  for (PlayMode m : {PlayMode::kBeforeKickOff, PlayMode::kGoalLeft, PlayMode::kGoalRight})
    EXPECT_TRUE(after(PlayMode::kPlayOn, m)) << PlayModeName(m);
  EXPECT_TRUE(after(PlayMode::kBeforeKickOff, PlayMode::kOffsideLeft)) << "offside keeps it";
  EXPECT_FALSE(after(PlayMode::kPlayOn, PlayMode::kOffsideRight)) << "offside keeps it";
  Game copy;
  ASSERT_EQ(test::RestoreAll(test::Saved(game), &copy), "");
  EXPECT_FALSE(copy.paused());
}

TEST(GameInit, FirstTeamLeftSecondRightThirdRejected) {
  Game game;
  InitResult a = game.Init("Alpha", 1, 0);
  ASSERT_TRUE(a.ok) << a.error;
  EXPECT_EQ(a.side, Side::kLeft);
  InitResult b = game.Init("Beta", 1, 0);
  ASSERT_TRUE(b.ok) << b.error;
  EXPECT_EQ(b.side, Side::kRight);
  InitResult a2 = game.Init("Alpha", 2, 1);
  ASSERT_TRUE(a2.ok);
  EXPECT_EQ(a2.side, Side::kLeft);
  InitResult c = game.Init("Gamma", 1, 0);
  EXPECT_FALSE(c.ok);
  EXPECT_FALSE(c.error.empty());
  EXPECT_EQ(game.TeamName(Side::kLeft), "Alpha");
  EXPECT_EQ(game.TeamName(Side::kRight), "Beta");
  EXPECT_FALSE(game.Init("", 3, 0).ok);
}

TEST(GameInit, UniformNumbersAutoAllocatedAndUnique) {
  Game game;
  EXPECT_EQ(game.Init("A", 0, 0).unum, 1);
  EXPECT_EQ(game.Init("A", 0, 1).unum, 2);
  EXPECT_EQ(game.Init("A", 5, 2).unum, 5);
  EXPECT_EQ(game.Init("A", 0, 0).unum, 3);
  EXPECT_FALSE(game.Init("A", 5, 1).ok);      // taken
  EXPECT_EQ(game.Init("A", 42, 1).unum, 42);  // any int is allowed
  game.Leave(Side::kLeft, 1, 0);
  EXPECT_EQ(game.Init("A", 0, 2).unum, 1);
  EXPECT_EQ(game.PlayerCount(Side::kLeft), 5);
  EXPECT_EQ(game.Init("B", 5, 0).unum, 5);  // numbers are per team
}

TEST(GameInit, TwelfthPlayerRejected) {
  GameRules rules;
  rules.check_composition = false;
  Game game(rules);
  for (int i = 0; i < 11; ++i) ASSERT_TRUE(game.Init("A", 0, 0).ok) << i;
  const InitResult twelfth = game.Init("A", 12, 0);
  EXPECT_FALSE(twelfth.ok);
  EXPECT_EQ(game.PlayerCount(Side::kLeft), 11);
  game.Leave(Side::kLeft, 4, 0);
  EXPECT_EQ(game.Init("A", 0, 0).unum, 4);
}

TEST(GameInit, AtMostSevenOfOneType) {
  Game game;
  for (int i = 0; i < 7; ++i) ASSERT_TRUE(game.Init("A", 0, 3).ok) << i;
  EXPECT_FALSE(game.Init("A", 0, 3).ok);
  EXPECT_TRUE(game.Init("A", 0, 4).ok);
  EXPECT_TRUE(game.Init("B", 0, 3).ok);  // per team
}

TEST(GameInit, AtMostNineOfTwoTypesAndThreeTypesInTheEnd) {
  Game game;
  for (int i = 0; i < 7; ++i) ASSERT_TRUE(game.Init("A", 0, 0).ok);
  for (int i = 0; i < 2; ++i) ASSERT_TRUE(game.Init("A", 0, 1).ok);
  EXPECT_FALSE(game.Init("A", 0, 1).ok);  // types 0 + 1 would be 10
  EXPECT_TRUE(game.Init("A", 0, 2).ok);
  EXPECT_TRUE(game.Init("A", 0, 2).ok);
  EXPECT_EQ(game.PlayerCount(Side::kLeft), 11);
  EXPECT_FALSE(game.Init("A", 0, 4).ok);  // full
}

TEST(GameInit, OnlyUnusedTypesWhenFreeSlotsNoLongerExceedMissingTypes) {
  GameRules rules;
  rules.max_players = 4;  // small team to reach the rule early
  Game game(rules);
  ASSERT_TRUE(game.Init("A", 0, 0).ok);  // 3 free, 2 missing
  ASSERT_TRUE(game.Init("A", 0, 0).ok);  // 2 free, 2 missing
  EXPECT_FALSE(game.Init("A", 0, 0).ok);
  ASSERT_TRUE(game.Init("A", 0, 1).ok);  // 1 free, 1 missing
  EXPECT_FALSE(game.Init("A", 0, 1).ok);
  EXPECT_FALSE(game.Init("A", 0, 0).ok);
  EXPECT_TRUE(game.Init("A", 0, 4).ok);
}

TEST(GameInit, RobotTypeRangeAndCompositionSwitch) {
  Game game;
  EXPECT_FALSE(game.Init("A", 0, 5).ok);
  EXPECT_FALSE(game.Init("A", 0, -1).ok);
  EXPECT_FALSE(game.TeamName(Side::kLeft).has_value());  // a rejected init registers nothing
  GameRules rules;
  rules.check_composition = false;
  Game lax(rules);
  for (int i = 0; i < 11; ++i) EXPECT_TRUE(lax.Init("A", 0, 0).ok);
}

TEST(GameInit, StartPoses) {
  Game game;
  const Pose2 l1 = game.StartPose(Side::kLeft, 1);
  EXPECT_NEAR(l1.x, -14.2, 1e-12);
  EXPECT_NEAR(l1.y, 9.2, 1e-12);
  EXPECT_EQ(l1.facing_deg, 0.0);
  const Pose2 l3 = game.StartPose(Side::kLeft, 3);
  EXPECT_NEAR(l3.y, 9.2 - 2.4, 1e-12);
  const Pose2 r1 = game.StartPose(Side::kRight, 1);
  EXPECT_NEAR(r1.x, 14.2, 1e-12);
  EXPECT_NEAR(r1.y, 9.2, 1e-12);
  EXPECT_EQ(r1.facing_deg, 180.0);
  const Pose2 l11 = game.StartPose(Side::kLeft, 11);
  EXPECT_NEAR(l11.y, 9.2 - 12.0, 1e-12);
  EXPECT_GE(game.StartPose(Side::kLeft, 42).y, -10.0);  // any unum lands on the field
}

TEST(GameBeam, AllowedOnlyBeforeKickOffAndAfterGoals) {
  Game game;
  EXPECT_TRUE(game.BeamAllowed());
  game.SetPlayMode(PlayMode::kGoalLeft);
  EXPECT_TRUE(game.BeamAllowed());
  game.SetPlayMode(PlayMode::kGoalRight);
  EXPECT_TRUE(game.BeamAllowed());
  for (PlayMode mode : {PlayMode::kPlayOn, PlayMode::kKickOffLeft, PlayMode::kKickInRight, PlayMode::kGameOver}) {
    game.SetPlayMode(mode);
    EXPECT_FALSE(game.BeamAllowed()) << PlayModeName(mode);
  }
}

TEST(GameBeam, TeamFrameMirroringAndClamps) {
  Game game;
  const Pose2 l = game.BeamPose(Side::kLeft, -5, 1.5, 30, nullptr);
  EXPECT_DOUBLE_EQ(l.x, -5);
  EXPECT_DOUBLE_EQ(l.y, 1.5);
  EXPECT_DOUBLE_EQ(l.facing_deg, 30);
  const Pose2 r = game.BeamPose(Side::kRight, -5, 1.5, 30, nullptr);
  EXPECT_DOUBLE_EQ(r.x, 5);
  EXPECT_DOUBLE_EQ(r.y, -1.5);
  EXPECT_DOUBLE_EQ(r.facing_deg, -150);
  const Pose2 r0 = game.BeamPose(Side::kRight, -3, 0, 0, nullptr);
  EXPECT_DOUBLE_EQ(r0.facing_deg, 180);                                 // faces the left goal
  const Pose2 clamped = game.BeamPose(Side::kLeft, 3, 12, 0, nullptr);  // no beaming into the opponent half
  EXPECT_DOUBLE_EQ(clamped.x, 0);
  EXPECT_DOUBLE_EQ(clamped.y, 10);
  const Pose2 far = game.BeamPose(Side::kRight, -20, -11, 0, nullptr);
  EXPECT_DOUBLE_EQ(far.x, 15);
  EXPECT_DOUBLE_EQ(far.y, 10);
}

TEST(GameBeam, NoiseWithinBoundsAndClampedAfter) {
  Game game;
  Rng rng(9);
  double max_dx = 0, max_drot = 0;
  for (int i = 0; i < 2000; ++i) {
    const Pose2 p = game.BeamPose(Side::kLeft, -5, 1.5, 0, &rng);
    EXPECT_LE(std::abs(p.x + 5), 0.05);
    EXPECT_LE(std::abs(p.y - 1.5), 0.05);
    EXPECT_LE(std::abs(p.facing_deg), 10.0);
    max_dx = std::max(max_dx, std::abs(p.x + 5));
    max_drot = std::max(max_drot, std::abs(p.facing_deg));
    const Pose2 edge = game.BeamPose(Side::kLeft, 0, 10, 0, &rng);
    EXPECT_LE(edge.x, 0.0);
    EXPECT_LE(edge.y, 10.0);
  }
  EXPECT_GT(max_dx, 0.045);
  EXPECT_GT(max_drot, 9.0);
  Rng a(4), b(4);
  EXPECT_EQ(game.BeamPose(Side::kRight, -2, 2, 45, &a).x, game.BeamPose(Side::kRight, -2, 2, 45, &b).x);
}

TEST(GameFlow, ClockStoppedBeforeKickOffAndBallHeldAtCentre) {
  Game game;
  GameUpdate u = game.Update(kDt, {3, 1, 0.042}, kNobody);
  EXPECT_FALSE(u.place_ball.has_value());  // nobody there yet
  ASSERT_TRUE(game.Init("A", 0, 0).ok);
  u = game.Update(kDt, {3, 1, 0.042}, kSomeone);
  EXPECT_TRUE(u.place_ball_at_centre);
  ASSERT_TRUE(u.place_ball.has_value());
  EXPECT_TRUE(u.place_ball->isApprox(kCentre));
  EXPECT_EQ(game.game_time(), 0.0);
  EXPECT_EQ(game.play_mode(), PlayMode::kBeforeKickOff);  // no automatic kick-off
}

TEST(GameFlow, KickOffToPlayOnAtFirstTouch) {
  Game game;
  game.KickOff(Side::kLeft, nullptr);
  EXPECT_EQ(game.play_mode(), PlayMode::kKickOffLeft);
  GameUpdate u = game.Update(kDt, kCentre, kNobody);
  EXPECT_TRUE(u.play_mode_changed);  // the trainer's change is reported once
  u = game.Update(kDt, kCentre, kNobody);
  EXPECT_FALSE(u.play_mode_changed);
  EXPECT_EQ(game.play_mode(), PlayMode::kKickOffLeft);
  EXPECT_NEAR(game.game_time(), 2 * kDt, 1e-6);  // the reference's float clock
  u = game.Update(kDt, kCentre, kSomeone);
  EXPECT_EQ(game.play_mode(), PlayMode::kPlayOn);
  EXPECT_TRUE(u.play_mode_changed);
  EXPECT_FALSE(u.place_ball.has_value());
}

TEST(GameFlow, KickOffUntouchedDropsBallAfterFifteenSeconds) {
  Game game;
  game.KickOff(Side::kRight, nullptr);
  GameUpdate last;
  const int cycles = CyclesUntilModeChange(&game, {0.3, 0.1, 0.042}, 2000, &last);
  EXPECT_NEAR(cycles, 750, 1);
  EXPECT_EQ(game.play_mode(), PlayMode::kPlayOn);
  EXPECT_TRUE(last.dropped_ball);
  ASSERT_TRUE(last.place_ball.has_value());
  EXPECT_NEAR(last.place_ball->x(), 0.3, 1e-12);
}

// rcssserver3d (SoccerRuleAspect::UpdateKickOff, naosoccersim.rb RuleDropBallTime
// 15): a kick-off nobody touches ends when its mode time is MORE than 15 s: a
// drop ball where the ball is and PlayOn, nobody's kick-off. dt = 0.25 s sums
// exactly: at 15.00 s it is still the kick-off, at 15.25 s PlayOn.
TEST(GameFlow, UntouchedKickOffBecomesPlayOnAfterMoreThanFifteenSecondsOfGameTime) {
  Game game;
  game.KickOff(Side::kLeft, nullptr);
  const Eigen::Vector3d ball(0.2, -0.1, 0.042);
  for (int i = 0; i < 60; ++i) {
    const GameUpdate u = game.Update(0.25, ball, kNobody);
    ASSERT_EQ(game.play_mode(), PlayMode::kKickOffLeft) << i;
    ASSERT_FALSE(u.place_ball.has_value());
  }
  EXPECT_EQ(game.mode_time(), 15.0);
  const GameUpdate u = game.Update(0.25, ball, kNobody);
  EXPECT_EQ(game.play_mode(), PlayMode::kPlayOn);
  EXPECT_TRUE(u.play_mode_changed);
  EXPECT_TRUE(u.dropped_ball);
  ASSERT_TRUE(u.place_ball.has_value());
  EXPECT_TRUE(u.place_ball->isApprox(ball));
  EXPECT_EQ(game.game_time(), 15.25);
}

// The same in 0.02 s cycles on the reference's float clock (TTime): 750 sums of 0.02f make 15.000154 s, more than
// 15, so the 750th cycle ends it (GS shows t 15.000 with PlayOn, as in rcssserver3d's traces).
TEST(GameFlow, UntouchedKickOffEndsOnTheCycleAtFifteenSecondsOnTheFloatClock) {
  Game game;
  game.KickOff(Side::kRight, nullptr);
  EXPECT_EQ(CyclesUntilModeChange(&game, kCentre, 2000), 750);
  EXPECT_NEAR(game.game_time(), 15.000154, 1e-6);
  EXPECT_EQ(game.play_mode(), PlayMode::kPlayOn);
}

// GameStateAspect::GetModeTime is game time since the mode began, so a
// trainer's time change moves the kick-off's deadline.
TEST(GameFlow, ModeTimeIsGameTimeSinceTheModeBegan) {
  Game game;
  game.KickOff(Side::kLeft, nullptr);
  game.Update(0.25, kCentre, kNobody);
  game.SetGameTime(14.9);
  EXPECT_NEAR(game.mode_time(), 14.9, 1e-5);
  game.Update(0.25, kCentre, kNobody);  // 15.15 s
  EXPECT_EQ(game.play_mode(), PlayMode::kPlayOn);
  // BeforeKickOff counts simulation time (the game clock stands).
  game.SetPlayMode(PlayMode::kBeforeKickOff);
  game.Update(0.25, kCentre, kNobody);
  EXPECT_EQ(game.mode_time(), 0.25);
}

// SoccerRuleAspect::Update runs CheckTime before the mode's rule: the cycle
// that reaches half time is no longer play.
TEST(GameFlow, HalfTimeEndsPlayBeforeTheGoalCheck) {
  Game game;
  ASSERT_TRUE(game.Init("A", 1, 0).ok);
  game.SetPlayMode(PlayMode::kPlayOn);
  game.SetGameTime(299.99);
  const GameUpdate u = game.Update(kDt, {15.1, 0, 0.042}, kNobody);
  EXPECT_FALSE(u.goal);
  EXPECT_EQ(game.score(Side::kLeft), 0);
  EXPECT_EQ(game.play_mode(), PlayMode::kBeforeKickOff);
  EXPECT_TRUE(u.place_ball_at_centre);
}

// UpdateGoal: mode time < 3 s waits; at 3 s the team scored on kicks off.
TEST(GameFlow, GoalKickOffAtThreeSecondsOfGameTime) {
  Game game;
  game.SetPlayMode(PlayMode::kPlayOn);
  ASSERT_TRUE(game.Update(0.25, {-15.1, 0, 0.042}, kNobody).goal);
  for (int i = 0; i < 11; ++i) game.Update(0.25, {-15.3, 0, 0.042}, kNobody);
  EXPECT_EQ(game.play_mode(), PlayMode::kGoalRight);
  game.Update(0.25, {-15.3, 0, 0.042}, kNobody);
  EXPECT_EQ(game.play_mode(), PlayMode::kKickOffLeft);
}

Game FourPlayers() {
  Game game;
  for (const char* team : {"A", "B"})
    for (int unum : {1, 2}) EXPECT_TRUE(game.Init(team, unum, 0).ok);
  return game;
}

const Toucher kLeft1{Side::kLeft, 1};
const Toucher kLeft2{Side::kLeft, 2};
const Toucher kRight1{Side::kRight, 1};

// CheckFreeKickTakerFoul / WasLastKickFromFreeKick: the kick-off's taker (more
// than 2 agents) touching the ball again 0.1 s or more after its kick, before
// anybody else: indirect free kick for the other team.
TEST(GameKicks, KickOffTakerTouchingTwiceGivesTheOtherTeamAFreeKick) {
  Game game = FourPlayers();
  game.KickOff(Side::kLeft, nullptr);
  const std::vector<Toucher> taker{kLeft1};
  game.Update(kDt, kCentre, taker);
  ASSERT_EQ(game.play_mode(), PlayMode::kPlayOn);
  // 0.02 .. 0.10 s: still the kick (the reference's float clock: 0.12f - 0.02f = 0.0999999940 < 0.1)
  for (int i = 0; i < 5; ++i) {
    game.Update(kDt, kCentre, taker);
    ASSERT_EQ(game.play_mode(), PlayMode::kPlayOn) << i;
  }
  const GameUpdate u = game.Update(kDt, kCentre, taker);  // 0.12 s
  EXPECT_EQ(game.play_mode(), PlayMode::kFreeKickRight);
  EXPECT_TRUE(u.play_mode_changed);
}

TEST(GameKicks, AnotherTouchEndsTheDoubleTouchCheck) {
  Game game = FourPlayers();
  game.KickOff(Side::kRight, nullptr);
  game.Update(kDt, kCentre, std::vector<Toucher>{kRight1});
  for (int i = 0; i < 10; ++i) game.Update(kDt, kCentre, kNobody);
  game.Update(kDt, kCentre, std::vector<Toucher>{kLeft2});
  for (int i = 0; i < 10; ++i) game.Update(kDt, kCentre, std::vector<Toucher>{kRight1});
  EXPECT_EQ(game.play_mode(), PlayMode::kPlayOn);
}

TEST(GameKicks, NoDoubleTouchRuleAtAKickOffWithTwoPlayers) {
  Game game;
  ASSERT_TRUE(game.Init("A", 1, 0).ok);
  ASSERT_TRUE(game.Init("B", 1, 0).ok);
  game.KickOff(Side::kLeft, nullptr);
  for (int i = 0; i < 20; ++i) game.Update(kDt, kCentre, std::vector<Toucher>{kLeft1});
  EXPECT_EQ(game.play_mode(), PlayMode::kPlayOn);
  game.SetPlayMode(PlayMode::kPlayOn);
  EXPECT_TRUE(game.Update(kDt, {15.1, 0, 0.042}, kNobody).goal);  // and the kick-off team may score
}

// CheckGoal: the kick-off team may not score before the other team touched the
// ball or it touched the ball outside the centre circle: goal kick instead,
// the ball 1 m in front of the goal line (AwardGoalKick, GoalKickDist).
TEST(GameKicks, KickOffTeamCannotScoreStraightFromTheKickOff) {
  Game game = FourPlayers();
  game.KickOff(Side::kLeft, nullptr);
  game.Update(kDt, kCentre, std::vector<Toucher>{kLeft1});
  game.Update(kDt, {1.0, 0, 0.042}, std::vector<Toucher>{kLeft2});  // inside the circle
  const GameUpdate u = game.Update(kDt, {15.1, 0, 0.042}, kNobody);
  EXPECT_FALSE(u.goal);
  EXPECT_EQ(game.score(Side::kLeft), 0);
  EXPECT_EQ(game.play_mode(), PlayMode::kGoalKickRight);
  EXPECT_FALSE(u.place_ball.has_value());  // the ball waits for the kick-in pause
  EXPECT_TRUE(game.free_kick_spot().isApprox(Eigen::Vector3d(14, 0, 0.042)));
}

TEST(GameKicks, KickOffTeamScoresOnceTheBallLeftTheCircleOrTheOtherTeamTouchedIt) {
  {
    Game game = FourPlayers();
    game.KickOff(Side::kLeft, nullptr);
    game.Update(kDt, kCentre, std::vector<Toucher>{kLeft1});
    game.Update(kDt, {2.5, 0, 0.042}, std::vector<Toucher>{kLeft2});
    EXPECT_TRUE(game.Update(kDt, {15.1, 0, 0.042}, kNobody).goal);
  }
  {
    Game game = FourPlayers();
    game.KickOff(Side::kLeft, nullptr);
    game.Update(kDt, kCentre, std::vector<Toucher>{kLeft1});
    game.Update(kDt, {0.5, 0, 0.042}, std::vector<Toucher>{kRight1});
    EXPECT_TRUE(game.Update(kDt, {15.1, 0, 0.042}, kNobody).goal);
  }
}

// UpdateKickIn & co.: untouched for more than 15 s -> drop ball, PlayOn.
TEST(GameKicks, UntouchedSetPieceBecomesPlayOnAfterMoreThanFifteenSeconds) {
  for (const PlayMode mode : {PlayMode::kKickInLeft, PlayMode::kCornerKickRight, PlayMode::kGoalKickLeft,
                              PlayMode::kFreeKickRight, PlayMode::kDirectFreeKickLeft}) {
    Game game;
    game.SetPlayMode(mode);
    for (int i = 0; i < 60; ++i) game.Update(0.25, {3, 9.958, 0.042}, kNobody);
    EXPECT_EQ(game.play_mode(), mode);
    const GameUpdate u = game.Update(0.25, {3, 9.958, 0.042}, kNobody);
    EXPECT_EQ(game.play_mode(), PlayMode::kPlayOn) << PlayModeName(mode);
    EXPECT_TRUE(u.dropped_ball);
  }
}

// A set piece's touch counts more than kick-in pause + 0.03 s into the mode.
TEST(GameKicks, SetPieceTouchCountsAfterPausePlusThirtyMilliseconds) {
  Game game;
  game.SetPlayMode(PlayMode::kKickInRight);
  for (int i = 0; i < 51; ++i) game.Update(kDt, kCentre, kNobody);  // 1.02 s
  game.Update(kDt, kCentre, std::vector<Toucher>{kRight1});         // 1.04 s
  EXPECT_EQ(game.play_mode(), PlayMode::kPlayOn);
  game.SetPlayMode(PlayMode::kKickInRight);
  for (int i = 0; i < 50; ++i) game.Update(kDt, kCentre, kNobody);
  game.Update(kDt, kCentre, std::vector<Toucher>{kRight1});  // 1.02 s: too early
  EXPECT_EQ(game.play_mode(), PlayMode::kKickInRight);
}

// UpdateGoalKick: after the touch, PlayOn once the ball is out of the box.
TEST(GameKicks, GoalKickPlaysOnWhenTheTouchedBallLeavesThePenaltyBox) {
  Game game;
  game.SetPlayMode(PlayMode::kGoalKickLeft);
  for (int i = 0; i < 60; ++i) game.Update(kDt, {-14, 0, 0.042}, kNobody);
  game.Update(kDt, {-14, 0, 0.042}, std::vector<Toucher>{kLeft1});
  EXPECT_EQ(game.play_mode(), PlayMode::kGoalKickLeft);
  game.Update(kDt, {-13.3, 0.5, 0.042}, kNobody);
  EXPECT_EQ(game.play_mode(), PlayMode::kGoalKickLeft);
  game.Update(kDt, {-13.1, 0.5, 0.042}, kNobody);
  EXPECT_EQ(game.play_mode(), PlayMode::kPlayOn);
}

// UpdatePassMode: PlayOn at a touch, before PassModeDuration.
TEST(GameKicks, PassModeEndsAtATouch) {
  Game game;
  game.SetPlayMode(PlayMode::kPassLeft);
  game.Update(kDt, kCentre, kNobody);
  EXPECT_EQ(game.play_mode(), PlayMode::kPassLeft);
  game.Update(kDt, kCentre, std::vector<Toucher>{kRight1});
  EXPECT_EQ(game.play_mode(), PlayMode::kPlayOn);
}

// UpdateOffside's body is compiled out: the mode lasts.
TEST(GameKicks, OffsideModeLastsUntilTheTrainerChangesIt) {
  Game game;
  game.SetPlayMode(PlayMode::kOffsideLeft);
  for (int i = 0; i < 1000; ++i) game.Update(kDt, kCentre, i % 2 == 0 ? kSomeone : kNobody);
  EXPECT_EQ(game.play_mode(), PlayMode::kOffsideLeft);
}

// GameStateAspect::KickOff(TI_NONE): half 2's first kick-off goes to the team
// that did not win half 1's coin toss.
TEST(GameFlow, SecondHalfKickOffGoesToTheOtherTeam) {
  for (uint64_t seed = 1; seed <= 8; ++seed) {
    Rng rng(seed);
    Game game;
    game.KickOff(std::nullopt, &rng);
    const PlayMode first = game.play_mode();
    game.SetGameTime(299.99);
    game.Update(kDt, kCentre, kNobody);
    ASSERT_EQ(game.half(), 2);
    game.KickOff(std::nullopt, &rng);
    EXPECT_NE(game.play_mode(), first) << seed;
  }
}

TEST(GameFlow, CoinTossPicksBothSides) {
  int left = 0;
  Rng rng(1);
  for (int i = 0; i < 200; ++i) {
    Game game;
    game.KickOff(std::nullopt, &rng);
    left += game.play_mode() == PlayMode::kKickOffLeft;
    EXPECT_TRUE(game.play_mode() == PlayMode::kKickOffLeft || game.play_mode() == PlayMode::kKickOffRight);
  }
  EXPECT_GT(left, 60);
  EXPECT_LT(left, 140);
}

TEST(GameFlow, GoalInTheRightGoalScoresForLeft) {
  Game game;
  game.SetPlayMode(PlayMode::kPlayOn);
  GameUpdate u = game.Update(kDt, {14.995, 0.5, 0.042}, kNobody);  // on the line
  EXPECT_FALSE(u.goal);
  // The goal's box begins a radius behind the line: the ball meets it once its centre is over the line.
  u = game.Update(kDt, {15.005, 0.5, 0.042}, kNobody);
  EXPECT_TRUE(u.goal);
  EXPECT_EQ(u.scored_by, Side::kLeft);
  EXPECT_EQ(game.play_mode(), PlayMode::kGoalLeft);
  EXPECT_EQ(game.score(Side::kLeft), 1);
  EXPECT_EQ(game.score(Side::kRight), 0);
  u = game.Update(kDt, {15.3, 0.5, 0.042}, kNobody);  // still in the goal: counted once
  EXPECT_FALSE(u.goal);
  EXPECT_EQ(game.score(Side::kLeft), 1);
}

// goal.rsg's box: a radius inside the posts, up to the bar; the ball counts when it meets it.
TEST(GameFlow, TheBallMeetsTheGoalsBox) {
  for (const auto& [ball, goal] :
       {std::pair{Eigen::Vector3d(15.3, 1.04, 0.042), true}, std::pair{Eigen::Vector3d(15.3, 1.06, 0.042), false},
        std::pair{Eigen::Vector3d(-15.3, 0.0, 0.83), true}, std::pair{Eigen::Vector3d(-15.3, 0.0, 0.85), false}}) {
    Game game;
    game.SetPlayMode(PlayMode::kPlayOn);
    EXPECT_EQ(game.Update(kDt, ball, kNobody).goal, goal) << ball.transpose();
  }
}

TEST(GameFlow, GoalInTheLeftGoalScoresForRight) {
  Game game;
  game.SetPlayMode(PlayMode::kPlayOn);
  const GameUpdate u = game.Update(kDt, {-15.2, -1.0, 0.7}, kNobody);
  EXPECT_TRUE(u.goal);
  EXPECT_EQ(u.scored_by, Side::kRight);
  EXPECT_EQ(game.play_mode(), PlayMode::kGoalRight);
  EXPECT_EQ(game.score(Side::kRight), 1);
}

TEST(GameFlow, WideOrHighIsNoGoal) {
  for (const Eigen::Vector3d& ball :
       {Eigen::Vector3d(15.2, 1.1, 0.042), Eigen::Vector3d(15.2, 0, 0.85), Eigen::Vector3d(-15.2, -1.06, 0.042)}) {
    Game game;
    game.SetPlayMode(PlayMode::kPlayOn);
    EXPECT_FALSE(game.Update(kDt, ball, kNobody).goal) << ball.transpose();
    EXPECT_EQ(game.play_mode(), PlayMode::kPlayOn);
  }
}

TEST(GameFlow, GoalPauseThenKickOffOfTheOtherTeam) {
  Game game;
  game.SetPlayMode(PlayMode::kPlayOn);
  ASSERT_TRUE(game.Update(kDt, {15.1, 0, 0.042}, kNobody).goal);
  GameUpdate last;
  const int cycles = CyclesUntilModeChange(&game, {15.3, 0, 0.042}, 1000, &last);
  EXPECT_NEAR(cycles, 150, 1);  // 3 s
  EXPECT_EQ(game.play_mode(), PlayMode::kKickOffRight);
  EXPECT_TRUE(last.place_ball_at_centre);
  EXPECT_TRUE(last.play_mode_changed);
  ASSERT_TRUE(last.place_ball.has_value());
  EXPECT_TRUE(last.place_ball->isApprox(kCentre));

  game.SetPlayMode(PlayMode::kPlayOn);
  ASSERT_TRUE(game.Update(kDt, {-15.1, 0, 0.042}, kNobody).goal);
  CyclesUntilModeChange(&game, {-15.3, 0, 0.042}, 1000);
  EXPECT_EQ(game.play_mode(), PlayMode::kKickOffLeft);
}

TEST(GameFlow, HalvesAndGameOver) {
  Game game;
  game.KickOff(Side::kLeft, nullptr);
  game.SetGameTime(299.99);
  game.Update(kDt, kCentre, kNobody);
  EXPECT_EQ(game.half(), 2);
  EXPECT_EQ(game.play_mode(), PlayMode::kBeforeKickOff);
  const double t = game.game_time();
  EXPECT_GE(t, 300.0);
  game.Update(kDt, kCentre, kNobody);
  EXPECT_EQ(game.game_time(), t);  // stopped
  game.KickOff(Side::kRight, nullptr);
  game.Update(kDt, kCentre, kSomeone);
  EXPECT_EQ(game.play_mode(), PlayMode::kPlayOn);
  EXPECT_GT(game.game_time(), t);  // the second half continues the clock
  game.SetGameTime(599.99);
  game.Update(kDt, kCentre, kNobody);
  EXPECT_EQ(game.play_mode(), PlayMode::kGameOver);
  const double end = game.game_time();
  game.Update(kDt, kCentre, kNobody);
  EXPECT_EQ(game.game_time(), end);
  EXPECT_EQ(game.half(), 2);
}

// Runs `cycles` cycles with the ball at `ball`, nobody touching; the last update.
GameUpdate RunCycles(Game* game, const Eigen::Vector3d& ball, int cycles) {
  GameUpdate u;
  for (int i = 0; i < cycles; ++i) u = game->Update(kDt, ball, kNobody);
  return u;
}

const Clearing* FindClearing(const GameUpdate& u, ClearingKind kind, Side team) {
  for (const Clearing& c : u.clearings)
    if (c.kind == kind && c.team == team) return &c;
  return nullptr;
}

// CheckBallLeftField / AwardKickIn: over a touch line, a kick-in for the other team than the last toucher's, on
// the line where the ball last was on the field. For the kick-in pause nothing; then the ball is held on the spot,
// the other team cleared from its 2 m circle every cycle, the taking team pushed 0.5 m off it once.
TEST(GameSetPieces, KickInForTheOtherTeamOnTheLineWhereTheBallLeft) {
  Game game = FourPlayers();
  game.SetPlayMode(PlayMode::kPlayOn);
  game.Update(kDt, {3, 5, 0.042}, std::vector<Toucher>{kLeft2});
  game.Update(kDt, {3.2, 9.9, 0.042}, kNobody);  // still on the field (within a radius and 1 mm)
  EXPECT_EQ(game.play_mode(), PlayMode::kPlayOn);
  GameUpdate u = game.Update(kDt, {3.3, 10.1, 0.042}, kNobody);
  EXPECT_EQ(game.play_mode(), PlayMode::kKickInRight);
  EXPECT_TRUE(game.free_kick_spot().isApprox(Eigen::Vector3d(3.2, 10 - 0.042, 0.042)));
  EXPECT_FALSE(u.place_ball.has_value());
  const Eigen::Vector3d out(3.5, 11, 0.042);
  int cycles = 0;
  for (; cycles < 100 && !u.place_ball; ++cycles) {
    u = game.Update(kDt, out, kNobody);
    if (!u.place_ball) ASSERT_TRUE(u.clearings.empty()) << cycles;
  }
  EXPECT_NEAR(cycles, 50, 1) << "1 s into the mode (on the float clock)";
  ASSERT_TRUE(u.place_ball.has_value());
  EXPECT_FALSE(u.dropped_ball);
  EXPECT_TRUE(u.place_ball->isApprox(game.free_kick_spot()));
  const Clearing* circle = FindClearing(u, ClearingKind::kCircle, Side::kLeft);
  ASSERT_NE(circle, nullptr);
  EXPECT_TRUE(circle->centre.isApprox(game.free_kick_spot()));
  EXPECT_DOUBLE_EQ(circle->radius, 2.0);
  EXPECT_DOUBLE_EQ(circle->distance, 2.5);
  const Clearing* repel = FindClearing(u, ClearingKind::kRepel, Side::kRight);
  ASSERT_NE(repel, nullptr);
  EXPECT_DOUBLE_EQ(repel->radius, 0.5);
  EXPECT_FALSE(repel->avoid_ball);
  u = game.Update(kDt, *u.place_ball, kNobody);
  EXPECT_TRUE(u.place_ball.has_value());  // held
  EXPECT_NE(FindClearing(u, ClearingKind::kCircle, Side::kLeft), nullptr);
  EXPECT_EQ(FindClearing(u, ClearingKind::kRepel, Side::kRight), nullptr);  // once
  u = game.Update(kDt, game.free_kick_spot(), std::vector<Toucher>{kRight1});
  EXPECT_EQ(game.play_mode(), PlayMode::kPlayOn);
  EXPECT_FALSE(u.place_ball.has_value());
}

// Over a goal line: a goal kick for the defenders when an attacker touched it last, a corner for the attackers
// when a defender did (AwardGoalKick: 1 m in front of the goal; AwardCornerKick: a radius in front of the line,
// (W + goal width) / 4 - r from the middle on the ball's side).
TEST(GameSetPieces, GoalKickOrCornerByWhoTouchedTheBallLast) {
  struct Case {
    Toucher last;
    Eigen::Vector3d out;
    PlayMode mode;
    Eigen::Vector3d spot;
  };
  const double corner_y = (20 + 2.1) / 4 - 0.042;
  for (const Case& c : {Case{kLeft1, {15.3, 3, 0.042}, PlayMode::kGoalKickRight, {14, 0, 0.042}},
                        Case{kRight1, {15.3, 3, 0.042}, PlayMode::kCornerKickLeft, {14.958, corner_y, 0.042}},
                        Case{kRight1, {-15.3, -4, 0.042}, PlayMode::kGoalKickLeft, {-14, 0, 0.042}},
                        Case{kLeft1, {-15.3, -4, 0.042}, PlayMode::kCornerKickRight, {-14.958, -corner_y, 0.042}}}) {
    Game game = FourPlayers();
    game.SetPlayMode(PlayMode::kPlayOn);
    game.Update(kDt, {0, 0, 0.042}, std::vector<Toucher>{c.last});
    game.Update(kDt, c.out, kNobody);
    EXPECT_EQ(game.play_mode(), c.mode) << PlayModeName(c.mode);
    EXPECT_TRUE(game.free_kick_spot().isApprox(c.spot)) << game.free_kick_spot().transpose();
    const GameUpdate u = RunCycles(&game, c.out, 52);  // the pause is 50 or 51 cycles on the float clock
    ASSERT_TRUE(u.place_ball.has_value()) << PlayModeName(c.mode);
    EXPECT_TRUE(u.place_ball->isApprox(c.spot));
  }
}

// With nobody having touched the ball, an out ball changes nothing (the reference has no team to blame).
TEST(GameSetPieces, OutBallNobodyTouchedChangesNothing) {
  Game game;
  game.SetPlayMode(PlayMode::kPlayOn);
  const GameUpdate u = RunCycles(&game, {3, 10.5, 0.042}, 100);
  EXPECT_EQ(game.play_mode(), PlayMode::kPlayOn);
  EXPECT_FALSE(u.place_ball.has_value());
}

// UpdateGoalKick: the other team is cleared from the taking team's penalty area, not from a circle.
TEST(GameSetPieces, GoalKickClearsThePenaltyAreaOfTheOtherTeam) {
  Game game = FourPlayers();
  game.SetPlayMode(PlayMode::kPlayOn);
  game.Update(kDt, {0, 0, 0.042}, std::vector<Toucher>{kRight1});
  game.Update(kDt, {-15.3, -4, 0.042}, kNobody);
  ASSERT_EQ(game.play_mode(), PlayMode::kGoalKickLeft);
  const GameUpdate u = RunCycles(&game, {-15.3, -4, 0.042}, 51);
  const Clearing* box = FindClearing(u, ClearingKind::kBox, Side::kRight);
  ASSERT_NE(box, nullptr);
  EXPECT_TRUE(box->box.min().isApprox(Eigen::Vector2d(-15, -1.95)));
  EXPECT_TRUE(box->box.max().isApprox(Eigen::Vector2d(-13.2, 1.95)));
  EXPECT_EQ(FindClearing(u, ClearingKind::kCircle, Side::kRight), nullptr);
}

// CheckGoal -> WasLastKickFromFreeKick: a goal whose last touch was an indirect kick (a kick-in) is a goal kick
// for the team scored on; an own goal straight from a direct kick (a corner) a corner for the other team; a goal
// straight from a direct kick counts.
TEST(GameSetPieces, NoGoalStraightFromAnIndirectKickNorAnOwnGoalFromADirectOne) {
  const auto take = [](PlayMode mode, const Toucher& taker, const Eigen::Vector3d& goal) {
    Game game = FourPlayers();
    game.Update(kDt, kCentre, std::vector<Toucher>{kRight1});  // a corner is held once anybody touched the ball
    game.SetPlayMode(mode);
    RunCycles(&game, {3, 0, 0.042}, 55);
    game.Update(kDt, game.free_kick_spot(), std::vector<Toucher>{taker});
    EXPECT_EQ(game.play_mode(), PlayMode::kPlayOn);
    RunCycles(&game, {8, 0, 0.042}, 100);  // 2 s later, nobody else touched it
    const GameUpdate u = game.Update(kDt, goal, kNobody);
    return std::make_pair(u.goal, game.play_mode());
  };
  EXPECT_EQ(take(PlayMode::kKickInLeft, kLeft1, {15.2, 0, 0.042}), std::make_pair(false, PlayMode::kGoalKickRight));
  EXPECT_EQ(take(PlayMode::kFreeKickLeft, kLeft1, {15.2, 0, 0.042}), std::make_pair(false, PlayMode::kGoalKickRight));
  EXPECT_EQ(take(PlayMode::kDirectFreeKickLeft, kLeft1, {15.2, 0, 0.042}), std::make_pair(true, PlayMode::kGoalLeft));
  EXPECT_EQ(take(PlayMode::kCornerKickLeft, kLeft1, {-15.2, 0, 0.042}),
            std::make_pair(false, PlayMode::kCornerKickRight));
}

// A free kick's spot in a penalty area goes to the area's front corner (UpdateFreeKick); the taker's second touch
// gives one where the ball last was on the field.
TEST(GameSetPieces, FreeKickSpotLeavesThePenaltyArea) {
  Game game = FourPlayers();
  game.KickOff(Side::kRight, nullptr);
  game.Update(kDt, kCentre, std::vector<Toucher>{kRight1});
  RunCycles(&game, {13.5, -0.5, 0.042}, 5);
  game.Update(kDt, {13.5, -0.5, 0.042}, std::vector<Toucher>{kRight1});  // 0.12 s after its kick
  ASSERT_EQ(game.play_mode(), PlayMode::kFreeKickLeft);
  EXPECT_TRUE(game.free_kick_spot().isApprox(Eigen::Vector3d(13.5, -0.5, 0.042)));
  const GameUpdate u = RunCycles(&game, {13.5, -0.5, 0.042}, 52);
  ASSERT_TRUE(u.place_ball.has_value());
  EXPECT_TRUE(u.place_ball->isApprox(Eigen::Vector3d(13.2, -1.95, 0.042))) << u.place_ball->transpose();
}

// The game's clearings at kick-offs (ClearPlayersBeforeKickOff) and before them (UpdateBeforeKickOff), and at a
// drop ball: which team, which area, in what order.
TEST(GameClearings, KickOffBeforeKickOffAndDropBall) {
  Game game = FourPlayers();
  GameUpdate u = game.Update(kDt, kCentre, kNobody);
  ASSERT_EQ(u.clearings.size(), 2u);  // BeforeKickOff: each team from the other's half
  for (const Clearing& c : u.clearings) {
    EXPECT_EQ(c.kind, ClearingKind::kBox);
    EXPECT_EQ(c.box.min().x(), c.team == Side::kLeft ? 0.0 : -25.0);
    EXPECT_EQ(c.box.max().x(), c.team == Side::kLeft ? 25.0 : 0.0);
  }
  game.KickOff(Side::kLeft, nullptr);
  u = game.Update(kDt, kCentre, kNobody);
  ASSERT_EQ(u.clearings.size(), 3u);
  EXPECT_EQ(u.clearings[0].kind, ClearingKind::kBox);  // the other team from the kick-off team's half
  EXPECT_EQ(u.clearings[0].team, Side::kRight);
  EXPECT_EQ(u.clearings[0].box.max().x(), 0.0);
  EXPECT_EQ(u.clearings[1].kind, ClearingKind::kCircle);  // and from the centre circle
  EXPECT_EQ(u.clearings[1].team, Side::kRight);
  EXPECT_EQ(u.clearings[2].kind, ClearingKind::kBox);  // the kick-off team from the other half
  EXPECT_EQ(u.clearings[2].team, Side::kLeft);
  EXPECT_EQ(u.clearings[2].box.min().x(), 0.0);
  EXPECT_DOUBLE_EQ(u.clearings[2].keep_in_circle, 2.0);
  u = game.DropBall({4, 2, 0.042});
  ASSERT_EQ(u.clearings.size(), 2u);
  EXPECT_NE(u.clearings[0].team, u.clearings[1].team);
  for (const Clearing& c : u.clearings) {
    EXPECT_EQ(c.kind, ClearingKind::kCircle);
    EXPECT_TRUE(c.centre.isApprox(Eigen::Vector3d(4, 2, 0.042)));
    EXPECT_TRUE(c.ball.isApprox(Eigen::Vector3d(4, 2, 0.042)));
  }
  // Both orders come up, drawn from the game's seed.
  int left_first = 0;
  for (uint64_t seed = 1; seed <= 40; ++seed) {
    Game g(GameRules{}, seed);
    ASSERT_TRUE(g.Init("A", 1, 0).ok);
    left_first += g.Update(kDt, kCentre, kNobody).clearings.front().team == Side::kLeft;
  }
  EXPECT_GT(left_first, 5);
  EXPECT_LT(left_first, 35);
}

TEST(GameFlow, DropPositionLeavesPenaltyAreas) {
  Game game;
  // The rule aspect's box is 1.8 deep and 3.9 wide (PenaltyWidth), edges included.
  EXPECT_TRUE(game.DropPosition({14, 0.5, 0.3}).isApprox(Eigen::Vector3d(13.2, 1.95, 0.3)));  // height kept
  EXPECT_TRUE(game.DropPosition({-14.5, -0.2, 0.042}).isApprox(Eigen::Vector3d(-13.2, -1.95, 0.042)));
  // Behind a goal line it stays (SoccerRuleAspect::DropBall does not limit x).
  EXPECT_TRUE(game.DropPosition({-15.5, -0.2, 0.042}).isApprox(Eigen::Vector3d(-15.5, -0.2, 0.042)));
  EXPECT_TRUE(game.DropPosition({13.2, 1.95, 0.042}).isApprox(Eigen::Vector3d(13.2, 1.95, 0.042)));
  EXPECT_TRUE(game.DropPosition({14, 0, 0.042}).isApprox(Eigen::Vector3d(13.2, 1.95, 0.042)));  // y = 0: +
  EXPECT_TRUE(game.DropPosition({5, -12, 0.042}).isApprox(Eigen::Vector3d(5, -9.958, 0.042)));
  EXPECT_TRUE(game.DropPosition({14, 2.5, 0.042}).isApprox(Eigen::Vector3d(14, 2.5, 0.042)));
}

TEST(GameTrainer, DropBallScoreTimeAndModes) {
  Game game;
  game.KickOff(Side::kLeft, nullptr);
  const GameUpdate u = game.DropBall({-14, 0, 0.042});  // at once, before the next step
  EXPECT_EQ(game.play_mode(), PlayMode::kPlayOn);
  ASSERT_TRUE(u.place_ball.has_value());
  EXPECT_TRUE(u.dropped_ball);
  EXPECT_TRUE(u.place_ball->isApprox(Eigen::Vector3d(-13.2, 1.95, 0.042)));
  EXPECT_TRUE(game.Update(kDt, *u.place_ball, kNobody).play_mode_changed) << "reported by the next update";
  game.SetScore(2, std::nullopt);
  game.SetScore(std::nullopt, 5);
  EXPECT_EQ(game.score(Side::kLeft), 2);
  EXPECT_EQ(game.score(Side::kRight), 5);
  game.SetGameTime(-4);
  EXPECT_EQ(game.game_time(), 0.0);
  game.SetPlayMode(PlayMode::kKickInLeft);
  game.Update(kDt, kCentre, kSomeone);  // within the kick-in pause: no change
  EXPECT_EQ(game.play_mode(), PlayMode::kKickInLeft);
  for (int i = 0; i < 60; ++i) game.Update(kDt, kCentre, kNobody);
  game.Update(kDt, kCentre, kSomeone);
  EXPECT_EQ(game.play_mode(), PlayMode::kPlayOn);
  game.Update(kDt, kCentre, kNobody);  // a touch since the pass mode began would end it at once
  game.SetPlayMode(PlayMode::kPassRight);
  EXPECT_NEAR(CyclesUntilModeChange(&game, kCentre, 1000), 200, 1);
  EXPECT_EQ(game.play_mode(), PlayMode::kPlayOn);
}

}  // namespace
}  // namespace turf::simspark

namespace turf::simspark {
namespace {

// A game some way into a match: teams, a kick-off, a touch, a score, a time.
Game GameInPlay() {
  Game game;
  EXPECT_TRUE(game.Init("Alpha", 1, 0).ok);
  EXPECT_TRUE(game.Init("Alpha", 2, 1).ok);
  EXPECT_TRUE(game.Init("Beta", 1, 2).ok);
  game.KickOff(Side::kLeft, nullptr);
  for (int i = 0; i < 10; ++i)
    game.Update(kDt, kCentre, i == 3 ? std::vector<Toucher>{{Side::kLeft, 1}} : std::vector<Toucher>{});
  game.SetScore(2, 1);
  game.SetGameTime(123.4);
  return game;
}

TEST(GameSnapshot, RoundTripKeepsModeScoreTimesAndTeams) {
  const Game played = GameInPlay();
  ASSERT_EQ(played.play_mode(), PlayMode::kPlayOn);
  const std::string bytes = test::Saved(played);
  Game game;
  ASSERT_EQ(test::RestoreAll(bytes, &game), "");
  EXPECT_EQ(game.play_mode(), PlayMode::kPlayOn);
  EXPECT_EQ(game.score(Side::kLeft), 2);
  EXPECT_EQ(game.score(Side::kRight), 1);
  EXPECT_DOUBLE_EQ(game.game_time(), static_cast<float>(123.4));
  EXPECT_DOUBLE_EQ(game.mode_time(), played.mode_time());
  EXPECT_EQ(game.half(), 1);
  EXPECT_EQ(game.TeamName(Side::kLeft), "Alpha");
  EXPECT_EQ(game.TeamName(Side::kRight), "Beta");
  EXPECT_EQ(game.PlayerCount(Side::kLeft), 2);
  EXPECT_EQ(test::Saved(game), bytes);
  // Both go on the same way: the taker's double touch, then the free kick's timeout.
  Game original = played;
  const std::vector<Toucher> taker{{Side::kLeft, 1}};
  for (int i = 0; i < 1000; ++i) {
    const GameUpdate a = original.Update(kDt, kCentre, i == 5 ? taker : std::vector<Toucher>{});
    const GameUpdate b = game.Update(kDt, kCentre, i == 5 ? taker : std::vector<Toucher>{});
    ASSERT_EQ(a.play_mode_changed, b.play_mode_changed) << i;
    ASSERT_EQ(a.place_ball.has_value(), b.place_ball.has_value()) << i;
  }
  EXPECT_EQ(test::Saved(game), test::Saved(original));
  // The taken team and number are kept: a third Alpha number 2 is refused.
  EXPECT_FALSE(game.Init("Alpha", 2, 0).ok);
}

TEST(GameSnapshot, TruncatedOrOutOfRangeChangesNothing) {
  const std::string bytes = test::Saved(GameInPlay());
  Game game;
  ASSERT_TRUE(game.Init("Gamma", 3, 0).ok);
  const std::string before = test::Saved(game);
  for (size_t cut = 0; cut < bytes.size(); ++cut) {
    StateReader in(std::string_view(bytes).substr(0, cut));
    game.Restore(in);
    ASSERT_FALSE(in.ok()) << cut;
    ASSERT_EQ(test::Saved(game), before) << cut;
  }
  // The play mode (right after the two teams) past the last one.
  std::string bad = bytes;
  // tag, then per team: has name, name (length, chars), player count, (unum, type) per player.
  const size_t mode_at = 4 + (1 + 8 + 5 + 8 + 2 * 8) + (1 + 8 + 4 + 8 + 1 * 8);
  const auto count = static_cast<int32_t>(PlayMode::kCount);
  std::memcpy(bad.data() + mode_at, &count, sizeof(count));
  StateReader in(bad);
  game.Restore(in);
  EXPECT_STREQ(in.error(), "enum value out of range");
  EXPECT_EQ(test::Saved(game), before);
}

// turf's rule (game.h): a side whose last player left is free for a new team;
// the reference keeps both names until it restarts.
TEST(GameTeams, ANameIsFreedWhenItsLastPlayerLeaves) {
  Game game;
  ASSERT_TRUE(game.Init("Squat1", 1, 0).ok);
  ASSERT_TRUE(game.Init("Squat2", 1, 0).ok);
  ASSERT_TRUE(game.Init("Squat1", 2, 1).ok);
  EXPECT_FALSE(game.Init("Real", 1, 0).ok);  // both sides taken
  game.Leave(Side::kLeft, 1, 0);
  EXPECT_EQ(game.TeamName(Side::kLeft), "Squat1");  // one player is still in
  EXPECT_FALSE(game.Init("Real", 1, 0).ok);
  game.Leave(Side::kLeft, 2, 1);
  EXPECT_FALSE(game.TeamName(Side::kLeft).has_value());
  const InitResult real = game.Init("Real", 1, 0);
  ASSERT_TRUE(real.ok) << real.error;
  EXPECT_EQ(real.side, Side::kLeft);
  EXPECT_EQ(game.TeamName(Side::kRight), "Squat2");
}

TEST(GameTeams, ResetTeamFreesTheSideAndItsPlayers) {
  Game game;
  ASSERT_TRUE(game.Init("Squat1", 1, 0).ok);
  ASSERT_TRUE(game.Init("Squat2", 1, 0).ok);
  game.ResetTeam(Side::kRight);
  EXPECT_FALSE(game.TeamName(Side::kRight).has_value());
  EXPECT_EQ(game.PlayerCount(Side::kRight), 0);
  const InitResult real = game.Init("Real", 1, 0);
  ASSERT_TRUE(real.ok) << real.error;
  EXPECT_EQ(real.side, Side::kRight);
  EXPECT_EQ(game.TeamName(Side::kLeft), "Squat1");  // the other side is untouched
  EXPECT_EQ(game.PlayerCount(Side::kLeft), 1);
}

}  // namespace
}  // namespace turf::simspark
