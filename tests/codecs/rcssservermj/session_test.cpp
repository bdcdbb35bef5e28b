// The session (shared/protocols/rcssservermj.md): activation at the next cycle and its refusals, placement, beams
// per side and play mode, motor defaults and persistence, one cycle of latency in the parallel loop and none in
// the sequential one, sync mode's one message per cycle, vision every second cycle, monitor commands.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <utility>

#include "codecs/rcssservermj/session.h"
#include "tests/codecs/rcssservermj/session_fixture.h"

namespace turf::rcssservermj {
namespace {

const PdCommand* Command(const WorldRequests& r, const std::string& robot, const std::string& joint) {
  auto it = r.joints.find(robot);
  if (it == r.joints.end()) return nullptr;
  for (const PdCommand& c : it->second)
    if (c.joint == joint) return &c;
  return nullptr;
}

double Yaw(const Eigen::Quaterniond& q) {
  return std::atan2(2 * (q.w() * q.z() + q.x() * q.y()), 1 - 2 * (q.y() * q.y() + q.z() * q.z())) * 180 / M_PI;
}

TEST(MjSession, ActivatesAtTheNextCycleAndPlacesBySide) {
  Fixture f;
  const int a = f.Join("(init T1 teamBlue 2)");
  const int b = f.Join("(init T1 teamRed 3)");
  EXPECT_TRUE(f.session.TakeOutputs().empty());
  EXPECT_EQ(f.session.active_agents(), 0);
  const WorldRequests r = f.world.Cycle(&f.session);
  EXPECT_EQ(f.session.active_agents(), 2);
  ASSERT_EQ(r.moves.size(), 2u);
  EXPECT_EQ(r.moves[0].position, Eigen::Vector3d(-5, 37, 0.6735));  // -(2n+1), half width + border
  EXPECT_EQ(r.moves[1].position, Eigen::Vector3d(7, 37, 0.6735));
  EXPECT_NEAR(Yaw(r.moves[0].orientation), -90, 1e-9);
  EXPECT_TRUE(r.moves[0].reset_joints);
  // Perceptions start in the activation cycle; the parallel loop sends them at the next cycle's start, after
  // collecting actions (-0.0: the sign of an exact zero).
  EXPECT_TRUE(f.session.TakeOutputs().empty());
  f.world.Cycle(&f.session);
  const auto out = f.Outputs();
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out.at(a).rfind("(time (now 0.02))(GS (t 0.0)(pm BeforeKickOff)(tl teamBlue)(tr teamRed)(sl 0)(sr 0))"
                            "(quat (n torso_quat) (q 0.707 -0.0 -0.0 -0.707))(pos (n torso_pos) (p -5.0 37.0 0.673))",
                            0),
            0u)
      << out.at(a);
  EXPECT_NE(out.at(b).find("(pos (n torso_pos) (p 7.0 37.0 0.673))"), std::string::npos);
}

TEST(MjSession, RefusalsCloseTheConnection) {
  Fixture f({}, 14, 0);
  const int not_init = f.Join("(syn)");
  const int model = f.Join("(init Nao teamBlue 1)");
  const int ok1 = f.Join("(init T1 teamBlue 1)");
  const int twice = f.Join("(init T1 teamBlue 101)");  // |101| mod 100 = 1: taken
  const int right = f.Join("(init T1 teamRed 1)");
  const int third = f.Join("(init T1 teamGreen 1)");
  std::vector<int> kicked = f.session.TakeKicked();
  EXPECT_EQ(kicked, std::vector<int>{not_init});  // at once: the first message is not an init
  f.world.Cycle(&f.session);
  kicked = f.session.TakeKicked();
  std::sort(kicked.begin(), kicked.end());
  EXPECT_EQ(kicked, (std::vector<int>{model, twice, third}));
  EXPECT_EQ(f.session.active_agents(), 2);
  for (int id : kicked) f.session.Disconnect(id);
  f.session.Disconnect(not_init);
  (void)ok1;
  (void)right;
  // At most 11 a team; the 12th is refused (the scene has robots to spare).
  for (int n = 2; n <= 12; ++n) f.Join("(init T1 teamBlue " + std::to_string(n) + ")");
  f.world.Cycle(&f.session);
  EXPECT_EQ(f.session.TakeKicked().size(), 1u);
  EXPECT_EQ(f.session.active_agents(), 12);  // 11 blue and 1 red
}

TEST(MjSession, NoFreeRobotOfTheModelIsARefusal) {
  Fixture f({}, 1, 0);
  f.Join("(init T1 a 1)");
  const int k1 = f.JoinAndCycle("(init K1 a 2)");
  EXPECT_EQ(f.session.TakeKicked(), std::vector<int>{k1});
}

TEST(MjSession, BeamPerSideOnlyBeforeKickOff) {
  Fixture f(Sequential());  // the beam acts in the next cycle
  const auto [l, r] = f.JoinTwo("(init T1 L 1)", "(init T1 R 1)");
  f.session.Receive(l, "(beam 3 1 30)");
  f.session.Receive(r, "(beam -3 1 30)");
  WorldRequests req = f.world.Cycle(&f.session);
  ASSERT_EQ(req.moves.size(), 2u);
  EXPECT_EQ(req.moves[0].position, Eigen::Vector3d(-3, 1, 0.6745));
  EXPECT_NEAR(Yaw(req.moves[0].orientation), 30, 1e-9);
  EXPECT_EQ(req.moves[1].position, Eigen::Vector3d(3, 1, 0.6745));
  EXPECT_NEAR(Yaw(req.moves[1].orientation), -150, 1e-9);  // 30 + 180
  EXPECT_TRUE(req.moves[1].reset_joints);
  f.session.Monitor("(kickOff Left)");
  f.session.Receive(l, "(syn)");
  f.session.Receive(r, "(syn)");
  f.world.Cycle(&f.session);
  EXPECT_EQ(f.session.referee().play_mode(), PlayMode::kKickOffLeft);
  f.session.Receive(l, "(beam 3 1 30)");
  f.session.Receive(r, "(syn)");
  EXPECT_TRUE(f.world.Cycle(&f.session).moves.empty());
}

TEST(MjSession, MotorDefaultsPersistenceAndTargetsAsSent) {
  Fixture f(Sequential());
  const int a = f.Join("(init T1 a 1)");
  WorldRequests r = f.world.Cycle(&f.session);
  ASSERT_EQ(r.joints.at("t1_1").size(), 23u);
  const PdCommand* knee = Command(r, "t1_1", "Left_Knee_Pitch");
  ASSERT_NE(knee, nullptr);
  EXPECT_EQ(knee->q, 0);
  EXPECT_EQ(knee->kp, 1);
  EXPECT_EQ(knee->kd, 1);
  f.session.Receive(a, "(lle4 30 10 50 2 100)(lle4 45 0 60 3 1)(he1 200 0 5 0 0)");
  r = f.world.Cycle(&f.session);
  knee = Command(r, "t1_1", "Left_Knee_Pitch");
  EXPECT_NEAR(knee->q, M_PI / 4, 1e-12);  // the last one wins
  EXPECT_EQ(knee->kp, 60);
  EXPECT_EQ(knee->tau, 1);
  // 200 deg, past the joint's 90: as sent (RCSSServerMJ's position actuators have no control range).
  EXPECT_NEAR(Command(r, "t1_1", "AAHead_yaw")->q, 200 * M_PI / 180, 1e-12);
  f.session.Receive(a, "(syn)");
  r = f.world.Cycle(&f.session);
  EXPECT_NEAR(Command(r, "t1_1", "Left_Knee_Pitch")->q, M_PI / 4, 1e-12);  // persists
  f.session.Receive(a, "(lle4 0 0 1 1 500)");
  r = f.world.Cycle(&f.session);
  EXPECT_EQ(Command(r, "t1_1", "Left_Knee_Pitch")->tau, 500);  // the world clamps the law's sum, not tau alone
}

// The agent answers its first perception as soon as it has it; the result is the number of steps after the one
// whose state that perception shows until the step that applies the answer.
int Latency(bool sequential, bool sync_mode = false) {
  SessionOptions o;
  o.sequential = sequential;
  o.sync_mode = sync_mode;
  Fixture f(o);
  const int a = f.Join("(init T1 a 1)");
  std::optional<int> shown;  // the cycle whose state the answered perception shows
  for (int cycle = 1; cycle <= 6; ++cycle) {
    const WorldRequests r = f.world.Cycle(&f.session);
    if (shown && Command(r, "t1_1", "Left_Knee_Pitch")->kp == 50) return cycle - *shown;
    for (const auto& [agent, text] : f.Outputs()) {
      if (agent != a) continue;
      if (shown) {
        f.session.Receive(a, "(syn)");
        continue;
      }
      double now = 0;
      EXPECT_EQ(std::sscanf(text.c_str(), "(time (now %lf", &now), 1) << text;
      shown = static_cast<int>(std::lround(now / kCycleSeconds));
      f.session.Receive(a, "(lle4 30 0 50 1 0)");
    }
  }
  return -1;
}

TEST(MjSession, ParallelLoopHasOneCycleOfLatencySequentialNone) {
  EXPECT_EQ(Latency(false), 2);        // the answer to step k acts in step k+2
  EXPECT_EQ(Latency(false, true), 2);  // also in sync mode
  EXPECT_EQ(Latency(true), 1);         // in step k+1
}

TEST(MjSession, SyncModeTakesExactlyOneMessagePerAgentPerCycle) {
  SessionOptions o;
  o.sync_mode = true;
  Fixture f(o);
  const int a = f.Join("(init T1 a 1)");
  const int b = f.Join("(init T1 b 1)");
  EXPECT_TRUE(f.session.ReadyToStep());  // nobody active yet
  f.world.Cycle(&f.session);             // activation, first perceptions
  // Parallel loop: the perceptions go out at the next cycle's start, while the world steps (the agents think
  // meanwhile); the cycle after waits for their answers.
  EXPECT_TRUE(f.session.ReadyToStep());
  f.world.Cycle(&f.session);
  EXPECT_FALSE(f.session.ReadyToStep());
  f.session.Receive(a, "(syn)");
  EXPECT_FALSE(f.session.ReadyToStep());
  EXPECT_EQ(f.session.Waiting(), std::vector<int>{b});
  f.session.Receive(b, "(lle4 30 0 50 1 0)");
  f.session.Receive(b, "(lle4 60 0 70 1 0)");  // two: the second is next cycle's message
  EXPECT_TRUE(f.session.ReadyToStep());
  WorldRequests r = f.world.Cycle(&f.session);
  EXPECT_EQ(Command(r, "t1_2", "Left_Knee_Pitch")->kp, 50);  // the answer to the first perception
  EXPECT_FALSE(f.session.ReadyToStep());                     // a has nothing queued
  EXPECT_EQ(f.session.Waiting(), std::vector<int>{a});
  f.session.Receive(a, "(syn)");
  EXPECT_TRUE(f.session.ReadyToStep());
  r = f.world.Cycle(&f.session);
  EXPECT_EQ(Command(r, "t1_2", "Left_Knee_Pitch")->kp, 70);
}

TEST(MjSession, SequentialSyncWaitsForTheAnswerToTheLatestPerception) {
  Fixture f(Sequential());
  const int a = f.JoinAndCycle("(init T1 a 1)");
  EXPECT_FALSE(f.session.ReadyToStep());
  f.session.Receive(a, "(lle4 30 0 50 1 0)");
  EXPECT_TRUE(f.session.ReadyToStep());
  const WorldRequests r = f.world.Cycle(&f.session);
  EXPECT_EQ(Command(r, "t1_1", "Left_Knee_Pitch")->kp, 50);
  EXPECT_FALSE(f.session.ReadyToStep());
}

TEST(MjSession, VisionEverySecondCycle) {
  Fixture f;
  const int a = f.Join("(init T1 a 1)");
  int seen = 0, perceptions = 0;
  for (uint64_t i = 1; i <= 7; ++i) {
    f.world.Cycle(&f.session);
    for (const auto& [agent, text] : f.Outputs()) {
      ASSERT_EQ(agent, a);
      double now = 0;
      ASSERT_EQ(std::sscanf(text.c_str(), "(time (now %lf", &now), 1) << text;
      const long cycle = std::lround(now / kCycleSeconds);  // the cycle whose state it shows
      const bool see = text.find("(See ") != std::string::npos;
      EXPECT_EQ(see, cycle % 2 == 0) << cycle;
      seen += see;
      ++perceptions;
    }
  }
  EXPECT_EQ(perceptions, 6);  // the last cycle's goes out at the next cycle's start
  EXPECT_EQ(seen, 3);
}

TEST(MjSession, SeesItselfAndTheOthersParts) {
  Fixture f(Sequential());
  const auto [a, b] = f.JoinTwo("(init T1 blue 1)", "(init T1 red 1)");
  // Face to face on the x axis, 4 m apart, heads 0.9 m high.
  f.session.Receive(a, "(beam 2 0 0)");
  f.session.Receive(b, "(beam 2 0 0)");
  f.world.Cycle(&f.session);
  std::string text = f.Outputs().at(a);
  if (text.find("(See ") == std::string::npos) {
    f.session.Receive(a, "(syn)");
    f.session.Receive(b, "(syn)");
    f.world.Cycle(&f.session);
    text = f.Outputs().at(a);
  }
  EXPECT_NE(text.find("(P (team red)(id 1)(head (pol "), std::string::npos) << text;
  EXPECT_NE(text.find(")(lfoot (pol "), std::string::npos) << text;
  EXPECT_EQ(text.find("(P (team blue)"), std::string::npos) << text;  // its own parts are behind its camera
  EXPECT_NE(text.find("(B (pol "), std::string::npos) << text;
  EXPECT_NE(text.find("(g_rup (pol "), std::string::npos) << text;
}

TEST(MjSession, MonitorKickOffAndAgentMove) {
  Fixture f;
  f.Join("(init T1 blue 4)");
  f.world.Cycle(&f.session);
  f.session.Monitor("(kickOff Right)(agent (unum 4) (team blue) (move -3 1 0.7 90))(bogus)");
  f.world.Cycle(&f.session);
  EXPECT_EQ(f.session.referee().play_mode(), PlayMode::kKickOffRight);
  const WorldRequests r = f.world.Cycle(&f.session);
  ASSERT_EQ(r.moves.size(), 1u);
  EXPECT_EQ(r.moves[0].position, Eigen::Vector3d(-3, 1, 0.7));
  EXPECT_NEAR(Yaw(r.moves[0].orientation), 90, 1e-9);
  ASSERT_TRUE(r.ball);
  EXPECT_EQ(*r.ball, Eigen::Vector3d(0, 0, 0.11));
  bool unknown = false;
  for (const SessionIssue& i : f.session.TakeIssues()) unknown = unknown || i.kind == "unknown_op";
  EXPECT_TRUE(unknown);
  f.session.Monitor("(killsim)");
  f.world.Cycle(&f.session);
  EXPECT_TRUE(f.session.quit_requested());
}

TEST(MjSession, UnknownEffectorIsCountedNotApplied) {
  Fixture f(Sequential());
  const int a = f.JoinAndCycle("(init K1 a 1)");
  f.session.TakeIssues();
  f.session.Receive(a, "(te1 30 0 50 1 0)(lle4 nan 0 1 1 0)");
  const WorldRequests r = f.world.Cycle(&f.session);
  EXPECT_EQ(r.joints.at("k1_25").size(), 22u);
  EXPECT_EQ(Command(r, "k1_25", "Left_Knee_Pitch")->kp, 1);
  std::vector<std::string> kinds;
  for (const SessionIssue& i : f.session.TakeIssues()) kinds.push_back(i.kind);
  EXPECT_EQ(kinds, (std::vector<std::string>{"unknown_effector", "not_finite"}));
}

// Sync mode with no agent: no cycle runs, so monitor messages wait; past kMaxQueuedMonitor they are dropped and
// counted, and those kept still act at the next cycle.
TEST(MjSession, AMonitorFloodWhileNoCycleRunsIsCappedAndCounted) {
  SessionOptions o;
  o.sync_mode = true;
  Fixture f(o);
  for (size_t i = 0; i < kMaxQueuedMonitor; ++i) f.session.Monitor("(kickOff Left)");
  f.session.TakeIssues();
  for (int i = 0; i < 1000; ++i) f.session.Monitor("(kickOff Right)");
  size_t full = 0;
  for (const SessionIssue& i : f.session.TakeIssues()) full += i.kind == "monitor_queue_full" ? 1 : 0;
  EXPECT_EQ(full, 1000u);
  f.world.Cycle(&f.session);
  EXPECT_EQ(f.session.referee().play_mode(), PlayMode::kKickOffLeft);  // the kept ones, none of the dropped
  f.session.Monitor("(killsim)");                                      // room again after the cycle
  f.world.Cycle(&f.session);
  EXPECT_TRUE(f.session.quit_requested());
}

TEST(MjSession, FloodingDropsTheAgent) {
  SessionOptions o;
  o.sync_mode = true;
  Fixture f(o);
  const int a = f.JoinAndCycle("(init T1 a 1)");
  for (int i = 0; i < 17; ++i) f.session.Receive(a, "(syn)");
  EXPECT_EQ(f.session.TakeKicked(), std::vector<int>{a});
}

}  // namespace
}  // namespace turf::rcssservermj
