#include "codecs/simspark/trainer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace turf::simspark {
namespace {

std::vector<std::string> Errors(const TrainerMessage& m) {
  std::vector<std::string> errors;
  for (const TrainerIssue& issue : m.issues) errors.push_back(issue.error);
  return errors;
}

// By value: callers pass temporaries.
template <class T>
T Only(const TrainerMessage& m) {
  EXPECT_TRUE(m.issues.empty()) << (m.issues.empty() ? "" : m.issues[0].error + ": " + m.issues[0].detail);
  EXPECT_EQ(m.commands.size(), 1u);
  if (m.commands.size() != 1 || !std::holds_alternative<T>(m.commands[0])) {
    ADD_FAILURE() << "not the expected command";
    return T{};
  }
  return std::get<T>(m.commands[0]);
}

TEST(Trainer, MoveAgent) {
  const TrainerMessage m = ParseTrainerMessage("(agent (unum 2) (team Left) (pos -3 0 0.4))");
  const MoveAgent a = Only<MoveAgent>(m);
  EXPECT_EQ(a.unum, 2);
  EXPECT_EQ(a.team, TrainerTeam::kLeft);
  EXPECT_DOUBLE_EQ(a.pos[0], -3.0);
  EXPECT_DOUBLE_EQ(a.pos[1], 0.0);
  EXPECT_DOUBLE_EQ(a.pos[2], 0.4);
  EXPECT_FALSE(a.yaw_deg);
}

TEST(Trainer, MoveAndTurnAgent) {
  const MoveAgent a = Only<MoveAgent>(ParseTrainerMessage("(agent (team Right) (unum 10) (move 1 2 0.4 -90))"));
  EXPECT_EQ(a.unum, 10);
  EXPECT_EQ(a.team, TrainerTeam::kRight);
  EXPECT_DOUBLE_EQ(a.pos[1], 2.0);
  ASSERT_TRUE(a.yaw_deg);
  EXPECT_DOUBLE_EQ(*a.yaw_deg, -90.0);
}

TEST(Trainer, AgentStateIsAcceptedWithoutEffect) {
  Only<AgentStateCmd>(ParseTrainerMessage("(agent (unum 2) (team Left) (battery 80))"));
  Only<AgentStateCmd>(ParseTrainerMessage("(agent (unum 2) (team Left) (temperature 30))"));
  const TrainerMessage both = ParseTrainerMessage("(agent (unum 2) (team Left) (pos 0 0 0.4) (battery 80))");
  EXPECT_TRUE(both.issues.empty());
  ASSERT_EQ(both.commands.size(), 2u);
  EXPECT_TRUE(std::holds_alternative<MoveAgent>(both.commands[0]));
  EXPECT_TRUE(std::holds_alternative<AgentStateCmd>(both.commands[1]));
}

TEST(Trainer, AgentErrorsDropTheWholeCommand) {
  struct Case {
    const char* text;
    const char* error;
  };
  for (const Case& c :
       {Case{"(agent (unum 2) (pos 0 0 0))", "bad_arguments"}, Case{"(agent (team Left) (pos 0 0 0))", "bad_arguments"},
        Case{"(agent (unum 2) (team Blue) (pos 0 0 0))", "bad_arguments"},
        Case{"(agent (unum 2) (team left) (pos 0 0 0))", "bad_arguments"},  // case-sensitive
        Case{"(agent (unum 2) (team Left))", "bad_arguments"},
        Case{"(agent (unum 2) (team Left) (pos 0 0))", "bad_arguments"},
        Case{"(agent (unum 2) (team Left) (move 0 0 0))", "bad_arguments"},
        Case{"(agent (unum 2) (team Left) (pos 0 0 0) (fly 1))", "bad_arguments"},
        Case{"(agent (unum 2) (team Left) (pos 0 0 0) junk)", "bad_arguments"},
        Case{"(agent (unum 2.5) (team Left) (pos 0 0 0))", "bad_arguments"},
        Case{"(agent (unum 100) (team Left) (pos 0 0 0))", "out_of_range"},
        Case{"(agent (unum 2) (team Left) (pos nan 0 0))", "not_finite"},
        Case{"(agent (unum 2) (team Left) (pos 0 0 0) (battery inf))", "not_finite"},
        Case{"(agent (unum 2) (team Left) (move 0 0 0 1.0abc))", "bad_arguments"}}) {
    const TrainerMessage m = ParseTrainerMessage(c.text);
    EXPECT_TRUE(m.commands.empty()) << c.text;
    EXPECT_EQ(Errors(m), std::vector<std::string>{c.error}) << c.text;
  }
}

TEST(Trainer, Ball) {
  SetBall b = Only<SetBall>(ParseTrainerMessage("(ball (pos 1 0 0.042) (vel 0 0 0))"));
  ASSERT_TRUE(b.pos && b.vel);
  EXPECT_DOUBLE_EQ((*b.pos)[0], 1.0);
  EXPECT_DOUBLE_EQ((*b.pos)[2], 0.042);
  b = Only<SetBall>(ParseTrainerMessage("(ball (vel 2 -1 0.5))"));
  EXPECT_FALSE(b.pos);
  ASSERT_TRUE(b.vel);
  EXPECT_DOUBLE_EQ((*b.vel)[1], -1.0);
  for (const char* text : {"(ball)", "(ball (pos 1 2))", "(ball (spin 1 2 3))", "(ball (pos 1 2 3) x)"}) {
    const TrainerMessage m = ParseTrainerMessage(text);
    EXPECT_TRUE(m.commands.empty()) << text;
    EXPECT_EQ(Errors(m), std::vector<std::string>{"bad_arguments"}) << text;
  }
  const TrainerMessage nan = ParseTrainerMessage("(ball (pos 1 2 3) (vel 0 NaN 0))");
  EXPECT_TRUE(nan.commands.empty());
  EXPECT_EQ(Errors(nan), std::vector<std::string>{"not_finite"});
}

TEST(Trainer, PlayModeAndKickOff) {
  EXPECT_EQ(Only<SetPlayModeCmd>(ParseTrainerMessage("(playMode PlayOn)")).mode, PlayMode::kPlayOn);
  EXPECT_EQ(Only<SetPlayModeCmd>(ParseTrainerMessage("(playMode direct_free_kick_right)")).mode,
            PlayMode::kDirectFreeKickRight);
  EXPECT_EQ(Only<KickOffCmd>(ParseTrainerMessage("(kickOff Left)")).team, TrainerTeam::kLeft);
  EXPECT_EQ(Only<KickOffCmd>(ParseTrainerMessage("(kickOff Right)")).team, TrainerTeam::kRight);
  EXPECT_EQ(Only<KickOffCmd>(ParseTrainerMessage("(kickOff None)")).team, TrainerTeam::kNone);
  for (const char* text : {"(playMode PLAY_ON)", "(playMode 3)", "(playMode)", "(playMode PlayOn KickOff_Left)",
                           "(kickOff)", "(kickOff left)", "(kickOff (Left))"}) {
    const TrainerMessage m = ParseTrainerMessage(text);
    EXPECT_TRUE(m.commands.empty()) << text;
    EXPECT_EQ(Errors(m), std::vector<std::string>{"bad_arguments"}) << text;
  }
}

TEST(Trainer, ArgumentlessCommands) {
  Only<DropBallCmd>(ParseTrainerMessage("(dropBall)"));
  Only<RequestFullState>(ParseTrainerMessage("(reqfullstate)"));
  Only<KillSim>(ParseTrainerMessage("(killsim)"));
  const TrainerMessage ack = ParseTrainerMessage("(getAck)");
  EXPECT_TRUE(ack.commands.empty());
  EXPECT_TRUE(ack.issues.empty());
  for (const char* text : {"(dropBall now)", "(reqfullstate 1)", "(killsim (x))", "(getAck 1)"}) {
    const TrainerMessage m = ParseTrainerMessage(text);
    EXPECT_TRUE(m.commands.empty()) << text;
    EXPECT_EQ(Errors(m), std::vector<std::string>{"bad_arguments"}) << text;
  }
}

TEST(Trainer, GameTime) {
  EXPECT_DOUBLE_EQ(Only<SetGameTime>(ParseTrainerMessage("(time 120)")).time, 120.0);
  EXPECT_DOUBLE_EQ(Only<SetGameTime>(ParseTrainerMessage("(time 0)")).time, 0.0);
  EXPECT_EQ(Errors(ParseTrainerMessage("(time -0.5)")), std::vector<std::string>{"out_of_range"});
  EXPECT_EQ(Errors(ParseTrainerMessage("(time inf)")), std::vector<std::string>{"not_finite"});
  EXPECT_EQ(Errors(ParseTrainerMessage("(time)")), std::vector<std::string>{"bad_arguments"});
  EXPECT_EQ(Errors(ParseTrainerMessage("(time 12s)")), std::vector<std::string>{"bad_arguments"});
}

TEST(Trainer, Score) {
  SetScoreCmd s = Only<SetScoreCmd>(ParseTrainerMessage("(score (left 1) (right 0))"));
  EXPECT_EQ(s.left, 1);
  EXPECT_EQ(s.right, 0);
  s = Only<SetScoreCmd>(ParseTrainerMessage("(score (right 999))"));
  EXPECT_FALSE(s.left);
  EXPECT_EQ(s.right, 999);
  EXPECT_EQ(Errors(ParseTrainerMessage("(score (left 1000))")), std::vector<std::string>{"out_of_range"});
  EXPECT_EQ(Errors(ParseTrainerMessage("(score (left -1))")), std::vector<std::string>{"out_of_range"});
  for (const char* text : {"(score)", "(score (left 1.5))", "(score (middle 1))", "(score (left x) (right 0))"})
    EXPECT_EQ(Errors(ParseTrainerMessage(text)), std::vector<std::string>{"bad_arguments"}) << text;
  EXPECT_TRUE(ParseTrainerMessage("(score (left 1000) (right 1))").commands.empty());
}

TEST(Trainer, SelectKillRepos) {
  const KillAgent k = Only<KillAgent>(ParseTrainerMessage("(kill (unum 2) (team Left))"));
  EXPECT_EQ(k.unum, 2);
  EXPECT_EQ(k.team, TrainerTeam::kLeft);
  const SelectAgent s = Only<SelectAgent>(ParseTrainerMessage("(select (team Right) (unum 5))"));
  EXPECT_EQ(s.unum, 5);
  EXPECT_EQ(s.team, TrainerTeam::kRight);
  const ReposAgent r = Only<ReposAgent>(ParseTrainerMessage("(repos (unum 9) (team None))"));
  EXPECT_EQ(r.unum, 9);
  EXPECT_EQ(r.team, TrainerTeam::kNone);
  for (const char* text : {"(kill (unum 2))", "(select (team Left))", "(repos (unum 2) (team Left) (pos 0 0 0))"})
    EXPECT_EQ(Errors(ParseTrainerMessage(text)), std::vector<std::string>{"bad_arguments"}) << text;
}

TEST(Trainer, UnknownCommandsAndOrder) {
  const TrainerMessage m = ParseTrainerMessage("(dropBall)(teleport 1)(playMode PlayOn)(time nan)()(kickOff Left)");
  ASSERT_EQ(m.commands.size(), 3u);
  EXPECT_TRUE(std::holds_alternative<DropBallCmd>(m.commands[0]));
  EXPECT_TRUE(std::holds_alternative<SetPlayModeCmd>(m.commands[1]));
  EXPECT_TRUE(std::holds_alternative<KickOffCmd>(m.commands[2]));
  EXPECT_EQ(Errors(m), (std::vector<std::string>{"unknown_command", "not_finite", "unknown_command"}));
  EXPECT_EQ(m.issues[0].detail, "teleport");
}

TEST(Trainer, UnparsableMessageAppliesNothing) {
  for (const std::string& text : {std::string("(dropBall)(killsim"), std::string("(killsim))"),
                                  std::string("(killsim)x"), std::string("(killsim)\0", 10)}) {
    const TrainerMessage m = ParseTrainerMessage(text);
    EXPECT_TRUE(m.commands.empty()) << text;
    EXPECT_EQ(Errors(m), std::vector<std::string>{"parse"}) << text;
  }
}

TEST(Monitor, NumbersAsAStreamWritesThem) {
  EXPECT_EQ(FormatMonitorNumber(30), "30");
  EXPECT_EQ(FormatMonitorNumber(0.042), "0.042");
  EXPECT_EQ(FormatMonitorNumber(12.34), "12.34");
  EXPECT_EQ(FormatMonitorNumber(1234.5678), "1234.57");
  EXPECT_EQ(FormatMonitorNumber(0), "0");
  EXPECT_EQ(FormatMonitorNumber(std::nan("")), "0");
}

TEST(Monitor, Environment) {
  EXPECT_EQ(FormatMonitorEnvironment(),
            "(FieldLength 30)(FieldWidth 20)(FieldHeight 40)(GoalWidth 2.1)(GoalDepth 0.6)(GoalHeight 0.8)"
            "(BorderSize 0)(FreeKickDistance 2)(WaitBeforeKickOff 30)(AgentRadius 0.4)(BallRadius 0.042)"
            "(BallMass 0.026)(RuleGoalPauseTime 3)(RuleKickInPauseTime 1)(RuleHalfTime 300)"
            "(PassModeMinOppBallDist 1)(PassModeDuration 4)"
            "(play_modes BeforeKickOff KickOff_Left KickOff_Right PlayOn KickIn_Left KickIn_Right corner_kick_left "
            "corner_kick_right goal_kick_left goal_kick_right offside_left offside_right GameOver Goal_Left "
            "Goal_Right free_kick_left free_kick_right direct_free_kick_left direct_free_kick_right pass_left "
            "pass_right)");
}

TEST(Monitor, GameStateFullThenChangesOnly) {
  MonitorGameState s;
  EXPECT_EQ(FormatMonitorGame(s, nullptr), "(time 0)(half 1)(score_left 0)(score_right 0)(play_mode 0)");
  MonitorGameState next = s;
  next.time = 0.04;
  EXPECT_EQ(FormatMonitorGame(next, &s), "(time 0.04)");
  MonitorGameState later = next;
  later.time = 12.5;
  later.team_left = "FHO";
  later.play_mode = PlayMode::kGoalRight;
  later.score_right = 1;
  EXPECT_EQ(FormatMonitorGame(later, &next), "(time 12.5)(team_left FHO)(score_right 1)(play_mode 14)");
  MonitorGameState after = later;
  after.team_right = "Probe";
  after.half = 2;
  EXPECT_EQ(FormatMonitorGame(after, &later), "(time 12.5)(team_right Probe)(half 2)");
  EXPECT_EQ(FormatMonitorGame(after, nullptr),
            "(time 12.5)(team_left FHO)(team_right Probe)(half 2)(score_left 0)(score_right 1)(play_mode 14)");
}

// Every number is range-checked; one value out of range drops its command whole (issue 20: (time 1e308) was
// accepted). The limits: trainer.h.
TEST(Trainer, ValuesOutOfRangeAreRefusedWhole) {
  for (const char* text : {"(time 1e308)",
                           "(time 86400.5)",  // game time
                           "(ball (pos 1e308 0 0.042))",
                           "(ball (pos 0 -1001 0.042))",
                           "(ball (pos 0 0 -0.1))",  // ball position
                           "(ball (pos 0 0 10.5))",
                           "(ball (pos 0 0 0.042) (vel 31 0 0))",
                           "(ball (vel 0 0 -30.5))",
                           "(ball (vel 20 20 11))",                           // past 30 m/s in x, y and z together
                           "(agent (unum 2) (team Left) (pos 1e300 0 0.4))",  // agent position
                           "(agent (unum 2) (team Left) (pos 0 100.5 0.4))",  // past turf-sim's legged limit
                           "(ball (pos -100.5 0 0))",
                           "(agent (unum 2) (team Left) (pos 0 0 -1))",
                           "(agent (unum 2) (team Left) (pos 0 0 11))",
                           "(agent (unum 2) (team Left) (move 0 0 0.4 1e308))",         // yaw
                           "(agent (unum 2) (team Left) (pos 0 0 0.4) (battery 101))",  // agent state
                           "(agent (unum 2) (team Left) (battery -1))",
                           "(agent (unum 2) (team Left) (temperature -300))",
                           "(agent (unum 2) (team Left) (temperature 1e9))",
                           "(kill (unum 100) (team Left))",
                           "(select (unum -1) (team Left))",
                           "(score (left 1000))"}) {
    const TrainerMessage m = ParseTrainerMessage(text);
    EXPECT_TRUE(m.commands.empty()) << text;
    EXPECT_EQ(Errors(m), std::vector<std::string>{"out_of_range"}) << text;
    EXPECT_FALSE(m.issues.empty() || m.issues[0].detail.empty()) << text;
  }
  // The limits themselves are in range.
  EXPECT_DOUBLE_EQ(Only<SetGameTime>(ParseTrainerMessage("(time 86400)")).time, kMaxTrainerTime);
  Only<SetBall>(ParseTrainerMessage("(ball (pos -100 100 10) (vel 0 0 -30))"));
  Only<SetBall>(ParseTrainerMessage("(ball (pos 0 0 0))"));
  Only<MoveAgent>(ParseTrainerMessage("(agent (unum 99) (team Right) (move 100 -100 0 -90))"));
  Only<AgentStateCmd>(ParseTrainerMessage("(agent (unum 2) (team Left) (battery 0) (temperature -273.15))"));
}

TEST(Trainer, ResetTeamIsTurfsOwnCommand) {
  EXPECT_EQ(Only<ResetTeamCmd>(ParseTrainerMessage("(turfResetTeam Left)")).team, TrainerTeam::kLeft);
  EXPECT_EQ(Only<ResetTeamCmd>(ParseTrainerMessage("(turfResetTeam Right)")).team, TrainerTeam::kRight);
  for (const char* text : {"(turfResetTeam None)", "(turfResetTeam)", "(turfResetTeam Blue)",
                           "(turfResetTeam Left Right)", "(turfResetTeam (team Left))"})
    EXPECT_EQ(Errors(ParseTrainerMessage(text)), std::vector<std::string>{"bad_arguments"}) << text;
}

TEST(Trainer, MatchControlCommandsAreTheOnesThatEndRestartOrRewriteTheMatch) {
  const auto control = [](const char* text) {
    const TrainerMessage m = ParseTrainerMessage(text);
    EXPECT_EQ(m.commands.size(), 1u) << text;
    return !m.commands.empty() && IsMatchControl(m.commands[0]);
  };
  for (const char* text : {"(killsim)", "(kill (unum 1) (team Left))", "(kickOff None)", "(time 10)",
                           "(score (left 1))", "(turfResetTeam Right)", "(playMode BeforeKickOff)",
                           "(playMode KickOff_Left)", "(playMode KickOff_Right)", "(playMode GameOver)"})
    EXPECT_TRUE(control(text)) << text;
  for (const char* text : {"(ball (pos 0 0 0.042))", "(agent (unum 1) (team Left) (pos 0 0 0.4))",
                           "(agent (unum 1) (team Left) "
                           "(battery 50))",
                           "(dropBall)", "(playMode PlayOn)", "(playMode free_kick_left)", "(playMode Goal_Left)",
                           "(select (unum 1) (team Left))", "(repos (unum 1) (team Left))", "(reqfullstate)"})
    EXPECT_FALSE(control(text)) << text;
  EXPECT_STREQ(TrainerCommandName(ParseTrainerMessage("(turfResetTeam Left)").commands.at(0)), "turfResetTeam");
  EXPECT_STREQ(TrainerCommandName(ParseTrainerMessage("(killsim)").commands.at(0)), "killsim");
  EXPECT_STREQ(TrainerCommandName(ParseTrainerMessage("(playMode PlayOn)").commands.at(0)), "playMode");
}

}  // namespace
}  // namespace turf::simspark
