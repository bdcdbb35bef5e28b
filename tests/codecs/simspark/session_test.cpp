#include "codecs/simspark/session.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "codecs/simspark/nao_joints.h"
#include "tests/codecs/simspark/golden_perception.h"
#include "tests/support/league_snapshot.h"
#include "tests/support/text.h"

namespace turf::simspark {
namespace {

// A legged world without physics: N Naos (nao_1..nao_N) that stand wherever the
// last requests put them, joints where a test sets them.
class FakeWorld {
 public:
  struct Robot {
    std::string name;
    Eigen::Vector3d position = Eigen::Vector3d::Zero();  // torso centre
    Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
    std::vector<double> joints;  // rad, in NaoJoints(0) order
    std::array<double, 3> gyro{};
    std::array<double, 3> accelerometer{0.0, 0.0, 9.81};
    bool left_contact = true;
    bool right_contact = true;
    std::vector<RobotSnapshot::Link> posed;  // links placed by a test, in the world frame (before the others)
    Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  // the torso's
    double ball_touch_time = -1.0;                       // s, the last step it touched the ball in
  };

  explicit FakeWorld(int n) {
    for (int i = 0; i < n; ++i) {
      Robot r;
      r.name = "nao_" + std::to_string(i + 1);
      // Parked beside the field, one metre apart.
      r.position = Eigen::Vector3d(-10.0 + i, -11.5, 0.4);
      r.joints.assign(NaoJoints(0).size(), 0.0);
      robots_.push_back(r);
    }
  }

  std::vector<std::string> Names() const {
    std::vector<std::string> names;
    for (const Robot& r : robots_) names.push_back(r.name);
    return names;
  }

  std::vector<RobotMove> Parks() const {
    std::vector<RobotMove> parks;
    for (const Robot& r : robots_) parks.push_back({r.name, r.position, r.orientation, false});
    return parks;
  }

  Robot& robot(const std::string& name) {
    for (Robot& r : robots_)
      if (r.name == name) return r;
    ADD_FAILURE() << "no robot " << name;
    return robots_.front();
  }

  // Carries out what the session asked for (moves; joint velocities for one cycle).
  void Apply(const WorldRequests& requests) {
    for (const RobotMove& m : requests.moves) {
      Robot& r = robot(m.robot);
      r.position = m.position;
      r.orientation = m.orientation;
      if (m.reset_joints) std::fill(r.joints.begin(), r.joints.end(), 0.0);
    }
    if (requests.ball) ball_ = requests.ball->position;
    for (const auto& [name, targets] : requests.joints) {
      Robot& r = robot(name);
      for (const JointVelocity& t : targets) {
        const std::vector<NaoJoint>& joints = NaoJoints(0);
        for (size_t i = 0; i < joints.size(); ++i)
          if (t.joint == joints[i].perceptor) r.joints[i] += t.velocity * 0.02;
      }
    }
  }

  // The world after one more cycle. A robot touches the ball (its contact, for the referee) when one of its bodies'
  // centres is within 0.15 m of the ball's centre.
  WorldSnapshot Snapshot() {
    time_ += 0.02;
    WorldSnapshot w;
    w.time = time_;
    w.ball = ball_;
    for (Robot& r : robots_) {
      RobotSnapshot s;
      s.name = r.name;
      for (const NaoJoint& j : NaoJoints(0)) s.joint_names.push_back(j.perceptor);
      s.joint_positions = r.joints;
      s.gyro = r.gyro;
      s.accelerometer = r.accelerometer;
      s.feet.push_back({"lf", r.left_contact, {0.0, 0.0, -0.01}, {0.0, 0.0, 22.5}});
      s.feet.push_back({"rf", r.right_contact, {0.0, 0.0, -0.01}, {0.0, 0.0, 22.5}});
      // Body centres in the torso frame (x right, y forward, z up).
      s.links = r.posed;
      const std::pair<const char*, Eigen::Vector3d> links[] = {
          {"torso", {0.0, 0.0, 0.0}},        {"head", {0.0, 0.0, 0.2}},      {"rlowerarm", {0.1, 0.15, 0.07}},
          {"llowerarm", {-0.1, 0.15, 0.07}}, {"rfoot", {0.055, 0.0, -0.37}}, {"lfoot", {-0.055, 0.0, -0.37}},
      };
      for (const auto& [name, offset] : links)
        s.links.push_back({name, r.position + r.orientation * offset, r.orientation});
      s.velocity = r.velocity;
      for (const RobotSnapshot::Link& l : s.links)
        if ((l.position - ball_).norm() < 0.15) r.ball_touch_time = time_;
      s.ball_touch_time = r.ball_touch_time;
      w.robots.push_back(s);
    }
    w.robot_contacts = contacts;
    return w;
  }

  std::vector<RobotTouch> contacts;  // robots touching, as a test sets them

 private:
  std::vector<Robot> robots_;
  Eigen::Vector3d ball_{0.0, 0.0, 0.042};
  double time_ = 0.0;
};

// A session in front of a fake world: one Cycle() = requests to the world,
// a step, the perceptions back.
struct Harness {
  explicit Harness(int robots, SessionOptions options = {})
      : world(robots), session(options, world.Names(), world.Parks()) {}

  // Requests taken and applied, then one Advance; returns the outputs.
  std::vector<std::pair<int, std::string>> Cycle(WorldRequests* taken = nullptr) {
    WorldRequests requests = session.TakeRequests();
    world.Apply(requests);
    if (taken != nullptr) *taken = requests;
    session.Advance(world.Snapshot());
    return session.TakeOutputs();
  }

  // A new agent with a robot of `type` in team `team` as `unum` (no init when team is empty).
  int Join(const std::string& team, int unum, int type = 0) {
    const int id = session.Connect();
    std::string message = "(scene rsg/agent/nao/nao_hetero.rsg " + std::to_string(type) + ")";
    if (!team.empty()) message += "(init (unum " + std::to_string(unum) + ")(teamname " + team + "))";
    session.Receive(id, message);
    return id;
  }
  // Join(), then one cycle: the agent has its robot.
  int JoinAndCycle(const std::string& team, int unum, int type = 0) {
    const int id = Join(team, unum, type);
    Cycle();
    return id;
  }

  FakeWorld world;
  Session session;

  // The session raised exactly one issue since the last take: of `kind`, from `agent` (-1: anyone).
  ::testing::AssertionResult OneIssue(const std::string& kind, int agent = -1) {
    const std::vector<SessionIssue> issues = session.TakeIssues();
    if (issues.size() != 1) return ::testing::AssertionFailure() << issues.size() << " issues, not 1";
    if (issues[0].kind != kind) return ::testing::AssertionFailure() << "issue " << issues[0].kind << ", not " << kind;
    if (agent >= 0 && issues[0].agent != agent)
      return ::testing::AssertionFailure() << "issue from agent " << issues[0].agent << ", not " << agent;
    if (issues[0].detail.empty()) return ::testing::AssertionFailure() << "issue " << kind << " without a detail";
    return ::testing::AssertionSuccess();
  }
  // The agents an operator's trainer `command` kicks.
  std::vector<int> KickedBy(const std::string& command) {
    session.Trainer(command, TrainerRole::kOperator);
    return session.TakeKicked();
  }
  // `message` from `agent` raises one issue of `kind` (as OneIssue) and asks the world for no joint or move.
  ::testing::AssertionResult OnlyAnIssue(int agent, const std::string& message, const std::string& kind) {
    session.Receive(agent, message);
    if (::testing::AssertionResult one = OneIssue(kind, agent); !one) return one;
    const WorldRequests requests = session.TakeRequests();
    if (!requests.joints.empty() || !requests.moves.empty())
      return ::testing::AssertionFailure() << "joints or moves requested";
    return ::testing::AssertionSuccess();
  }
};

// The one output for `agent` ("" when none; a failure when more than one).
std::string OutputFor(const std::vector<std::pair<int, std::string>>& outputs, int agent) {
  std::string found;
  int n = 0;
  for (const auto& [id, text] : outputs) {
    if (id != agent) continue;
    found = text;
    ++n;
  }
  EXPECT_LE(n, 1) << "agent " << agent << " got " << n << " perceptions in one cycle";
  return found;
}

bool Contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The number right after `prefix` in `text` (NaN when prefix is absent).
double NumberAfter(const std::string& text, const std::string& prefix) {
  const size_t at = text.find(prefix);
  if (at == std::string::npos) return std::nan("");
  return std::stod(text.substr(at + prefix.size()));
}

// The GS predicate of a perception.
std::string Gs(const std::string& perception) {
  const size_t begin = perception.find("(GS");
  if (begin == std::string::npos) return "";
  return perception.substr(begin, perception.find("))", begin) + 2 - begin);
}

const RobotMove* FindMove(const WorldRequests& requests, const std::string& robot, bool last = true) {
  const RobotMove* found = nullptr;
  for (const RobotMove& m : requests.moves) {
    if (m.robot != robot) continue;
    found = &m;
    if (!last) break;
  }
  return found;
}

std::vector<std::string> IssueKinds(const std::vector<SessionIssue>& issues) {
  std::vector<std::string> kinds;
  for (const SessionIssue& i : issues) kinds.push_back(i.kind);
  return kinds;
}

// The angle in degrees between where the robot's forward (model +y) points and `field_direction`.
double ForwardErrorDeg(const Eigen::Quaterniond& orientation, const Eigen::Vector3d& field_direction) {
  const Eigen::Vector3d forward = orientation * Eigen::Vector3d::UnitY();
  return std::acos(std::clamp(forward.dot(field_direction.normalized()), -1.0, 1.0)) * 180.0 / M_PI;
}

// --- scene, init ---

// The joints an agent's answer asks for, in order, with their velocities (rad/s).
void ExpectJoints(const std::vector<JointVelocity>& v, const std::vector<std::pair<std::string, double>>& expected) {
  ASSERT_EQ(v.size(), expected.size());
  for (size_t i = 0; i < v.size(); ++i) {
    EXPECT_EQ(v[i].joint, expected[i].first) << "joint " << i;
    EXPECT_DOUBLE_EQ(v[i].velocity, expected[i].second) << expected[i].first;
  }
}

TEST(SessionScene, ParksRobotWithResetJointsAndPerceivesAfterNextAdvance) {
  Harness h(2);
  const int a = h.Join("", 0);
  const int idle = h.session.Connect();  // no scene: no robot, no perception
  EXPECT_EQ(h.session.agents(), 2);
  EXPECT_EQ(h.session.agents_with_robot(), 1);
  EXPECT_TRUE(h.session.TakeOutputs().empty());

  WorldRequests requests;
  const auto outputs = h.Cycle(&requests);
  ASSERT_EQ(requests.moves.size(), 1u);
  const RobotMove& fresh = requests.moves[0];
  EXPECT_EQ(fresh.robot, "nao_1");
  EXPECT_TRUE(fresh.reset_joints);
  EXPECT_TRUE(fresh.position.isApprox(h.world.Parks()[0].position));
  EXPECT_TRUE(requests.joints.empty());
  EXPECT_FALSE(requests.ball);

  ASSERT_EQ(outputs.size(), 1u);
  EXPECT_EQ(outputs[0].first, a);
  EXPECT_EQ(OutputFor(outputs, idle), "");
  const std::string& p = outputs[0].second;
  EXPECT_EQ(p.rfind("(time (now 0.02))", 0), 0u) << p;
  EXPECT_EQ(Gs(p), "(GS (sl 0) (sr 0) (t 0.00) (pm BeforeKickOff))");
  EXPECT_TRUE(h.session.TakeIssues().empty());
}

// With the scene's robot types known, `scene` takes a free robot of the asked type; with none free, the last free
// robot of another type serves, with a note (not a refusal).
TEST(SessionScene, TakesARobotOfTheAskedTypeElseTheLastFreeWithANote) {
  Harness h(4);
  h.session.SetRobotTypes({0, 3, 0, 4});
  auto robot_of = [&](int type) {
    h.Join("", 0, type);
    const WorldRequests requests = h.session.TakeRequests();
    h.world.Apply(requests);
    return requests.moves.empty() ? std::string() : requests.moves[0].robot;
  };
  EXPECT_EQ(robot_of(3), "nao_2");
  EXPECT_TRUE(h.session.TakeNotes().empty());
  EXPECT_EQ(robot_of(0), "nao_1");
  EXPECT_EQ(robot_of(3), "nao_4") << "no type 3 left: the last free robot";
  const std::vector<std::string> notes = h.session.TakeNotes();
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("no free robot of type 3"), std::string::npos) << notes[0];
  EXPECT_EQ(robot_of(0), "nao_3");
  EXPECT_TRUE(h.session.TakeIssues().empty());
}

TEST(SessionScene, SecondSceneAndNoFreeRobotAreIssues) {
  Harness h(1);
  const int a = h.Join("", 0);
  h.session.Receive(a, "(scene rsg/agent/nao/nao.rsg)");
  const int b = h.Join("", 0);
  const std::vector<SessionIssue> issues = h.session.TakeIssues();
  ASSERT_EQ(issues.size(), 2u);
  EXPECT_EQ(issues[0].agent, a);
  EXPECT_EQ(issues[0].kind, "scene_twice");
  EXPECT_EQ(issues[1].agent, b);
  EXPECT_EQ(issues[1].kind, "no_robot_free");
  EXPECT_EQ(h.session.agents_with_robot(), 1);
  WorldRequests requests;
  h.Cycle(&requests);
  EXPECT_EQ(requests.moves.size(), 1u);  // only a's robot
}

TEST(SessionInit, MovesToStartPoseFacingPlusXAndAnnouncesOnce) {
  Harness h(2);
  const int a = h.Join("Alpha", 1);
  EXPECT_TRUE(h.session.TakeIssues().empty());
  WorldRequests requests;
  auto outputs = h.Cycle(&requests);
  ASSERT_EQ(requests.moves.size(), 2u);  // fresh robot, then the start pose
  EXPECT_TRUE(requests.moves[0].reset_joints);
  const RobotMove& start = requests.moves[1];
  EXPECT_EQ(start.robot, "nao_1");
  EXPECT_FALSE(start.reset_joints);
  EXPECT_NEAR(start.position.x(), -14.2, 1e-9);
  EXPECT_NEAR(start.position.y(), 9.2, 1e-9);
  EXPECT_NEAR(start.position.z(), 0.4, 1e-9);
  // The Nao's forward is its model +y: it must look along field +x, upright.
  EXPECT_LT(ForwardErrorDeg(start.orientation, Eigen::Vector3d::UnitX()), 1e-6);
  EXPECT_TRUE((start.orientation * Eigen::Vector3d::UnitZ()).isApprox(Eigen::Vector3d::UnitZ(), 1e-9));

  EXPECT_EQ(Gs(OutputFor(outputs, a)), "(GS (unum 1) (team left) (sl 0) (sr 0) (t 0.00) (pm BeforeKickOff))");
  outputs = h.Cycle();
  EXPECT_EQ(Gs(OutputFor(outputs, a)), "(GS (sl 0) (sr 0) (t 0.00) (pm BeforeKickOff))");
  EXPECT_EQ(h.session.game().TeamName(Side::kLeft), "Alpha");
}

TEST(SessionInit, UnumZeroTakesTheLowestFreeNumber) {
  Harness h(2);
  h.Join("Alpha", 1);
  const int b = h.Join("Alpha", 0);
  WorldRequests requests;
  const auto outputs = h.Cycle(&requests);
  EXPECT_TRUE(Contains(Gs(OutputFor(outputs, b)), "(unum 2) (team left)"));
  const RobotMove* start = FindMove(requests, "nao_2");
  ASSERT_NE(start, nullptr);
  EXPECT_NEAR(start->position.y(), 8.0, 1e-9);  // 9.2 - 1.2
}

TEST(SessionInit, SecondTeamIsRightThirdIsRefused) {
  Harness h(3);
  const int a = h.Join("Alpha", 1);
  const int b = h.Join("Beta", 1);
  const int c = h.Join("Gamma", 1);
  EXPECT_TRUE(h.OneIssue("init_refused", c));

  WorldRequests requests;
  const auto outputs = h.Cycle(&requests);
  EXPECT_TRUE(Contains(Gs(OutputFor(outputs, a)), "(unum 1) (team left)"));
  EXPECT_TRUE(Contains(Gs(OutputFor(outputs, b)), "(unum 1) (team right)"));
  // The refused agent keeps its robot (it may init again) but is never announced.
  const std::string gamma = OutputFor(outputs, c);
  ASSERT_FALSE(gamma.empty());
  EXPECT_FALSE(Contains(gamma, "(unum"));

  const RobotMove* right = FindMove(requests, "nao_2");
  ASSERT_NE(right, nullptr);
  EXPECT_NEAR(right->position.x(), 14.2, 1e-9);
  EXPECT_NEAR(right->position.y(), 9.2, 1e-9);
  EXPECT_LT(ForwardErrorDeg(right->orientation, -Eigen::Vector3d::UnitX()), 1e-6);
  // Gamma's robot only got its fresh (parked) pose.
  const RobotMove* third = FindMove(requests, "nao_3");
  ASSERT_NE(third, nullptr);
  EXPECT_TRUE(third->reset_joints);
  EXPECT_EQ(requests.moves.size(), 5u);  // 3 fresh robots, 2 start poses
}

TEST(SessionInit, InitBeforeSceneAndTwiceAreIssues) {
  Harness h(1);
  const int a = h.session.Connect();
  h.session.Receive(a, "(init (unum 1)(teamname Alpha))");
  h.session.Receive(a, "(scene rsg/agent/nao/nao.rsg)(init (unum 1)(teamname Alpha))");
  h.session.Receive(a, "(init (unum 2)(teamname Alpha))");
  EXPECT_EQ(IssueKinds(h.session.TakeIssues()), (std::vector<std::string>{"init_before_scene", "init_twice"}));
  EXPECT_EQ(h.session.game().PlayerCount(Side::kLeft), 1);
}

// --- hinge effectors ---

// Joint velocities asked in a cycle reach the world with the next one (the
// reference's cycle of action latency): the first take has none of them.
WorldRequests TakeAnswered(Session& s) {
  EXPECT_TRUE(s.TakeRequests().joints.empty()) << "joint velocities acted in the cycle they were asked";
  return s.TakeRequests();
}

TEST(SessionEffectors, AnAnswerMovesTheJointsOneCycleLaterAsTheReference) {
  Harness h(1);
  const int a = h.JoinAndCycle("Alpha", 1);
  h.session.Receive(a, "(he1 1)");
  WorldRequests now;
  h.Cycle(&now);
  EXPECT_EQ(now.joints.count("nao_1"), 0u);
  h.session.Receive(a, "(he1 -1)");
  WorldRequests next;
  h.Cycle(&next);
  ASSERT_EQ(next.joints.count("nao_1"), 1u);
  EXPECT_DOUBLE_EQ(next.joints.at("nao_1").at(0).velocity, 1.0);  // the first answer, not the second
  WorldRequests after;
  h.Cycle(&after);
  ASSERT_EQ(after.joints.count("nao_1"), 1u);
  EXPECT_DOUBLE_EQ(after.joints.at("nao_1").at(0).velocity, -1.0);
}

// rcssserver3d's self-collision rule (kernel/simspark/self_collision.h): a type-1 robot's right lower arm deep in its
// right thigh in PlayOn freezes the right arm and leg; a command to them is realized as velocity 0 for 1 s, others
// as sent. Not in BeforeKickOff.
TEST(SessionEffectors, SelfCollisionFreezesTheLimbsCommandsForOneSecond) {
  Harness h(1);
  const int a = h.JoinAndCycle("Alpha", 2, 1);
  const Eigen::Quaterniond thigh(Eigen::AngleAxisd(0.6, Eigen::Vector3d(1, 1, 0).normalized()));
  const Eigen::Quaterniond arm(Eigen::AngleAxisd(1.0, Eigen::Vector3d(0, 1, 1).normalized()));
  h.world.robot("nao_1").posed = {{"rthigh", {-10, -11.5, 0.2}, thigh}, {"rlowerarm", {-10, -11.5, 0.2}, arm}};
  // Commands asked in cycle n reach the world with the requests taken in cycle n + 1.
  const auto sent = [&](const std::string& message) {
    h.session.Receive(a, message);
    h.Cycle();
    WorldRequests taken;
    h.Cycle(&taken);
    std::map<std::string, double> v;
    for (const JointVelocity& t : taken.joints["nao_1"]) v[t.joint] = t.velocity;
    return v;
  };
  EXPECT_DOUBLE_EQ(sent("(rae3 1)(lae3 1)")["raj3"], 1.0) << "BeforeKickOff: no rule";
  h.session.Trainer("(playMode KickOff_Left)", TrainerRole::kOperator);
  const std::map<std::string, double> frozen = sent("(rae3 1)(rle4 1)(lae3 1)");
  EXPECT_DOUBLE_EQ(frozen.at("raj3"), 0.0);
  EXPECT_DOUBLE_EQ(frozen.at("rlj4"), 0.0);
  EXPECT_DOUBLE_EQ(frozen.at("laj3"), 1.0) << "the other arm is free";
  const std::vector<std::string> notes = h.session.TakeNotes();
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_TRUE(Contains(notes[0], "rlowerarm and rthigh")) << notes[0];
  // The arm out of the thigh: still frozen until 1 s of game time has passed, then the command as sent.
  h.world.robot("nao_1").posed.clear();
  int frozen_cycles = 0;
  for (int i = 0; i < 60 && sent("(rae3 1)").at("raj3") == 0.0; ++i) frozen_cycles += 2;
  EXPECT_NEAR(frozen_cycles, 50, 4) << "cycles (of 20 ms) the joint stayed frozen";
}

// The referee's incapable foul (kernel/simspark/incapable.h): a field player lying for more than 15 s of PlayOn is
// held in the air for 0.5 s, then put outside the field as it lies (its torso orientation kept), with a note.
TEST(SessionReferee, APlayerLyingFifteenSecondsIsPutOutsideTheField) {
  Harness h(1);
  h.JoinAndCycle("Alpha", 2);
  h.session.Trainer("(playMode KickOff_Left)", TrainerRole::kOperator);
  h.Cycle();
  FakeWorld::Robot& robot = h.world.robot("nao_1");
  robot.position = Eigen::Vector3d(-1.0, 3.0, 0.1);  // in its own half: the kick-off's clearing leaves it
  robot.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()));
  const Eigen::Quaterniond lying = robot.orientation;
  int cycles = 0;
  int held = 0;
  const RobotMove* out = nullptr;
  WorldRequests taken;
  for (; cycles < 1000 && out == nullptr; ++cycles) {
    h.Cycle(&taken);
    const RobotMove* m = FindMove(taken, "nao_1");
    if (m == nullptr) continue;
    EXPECT_TRUE(m->orientation.isApprox(lying)) << "moved as it lies";
    if (m->position.z() > 0.9) {
      ++held;
      EXPECT_NEAR(m->position.x(), -1.0, 1e-9);
    } else {
      out = m;
    }
  }
  ASSERT_NE(out, nullptr);
  EXPECT_EQ(held, 25);
  EXPECT_NEAR(out->position.x(), -0.6 * (7 - 2), 1e-9);
  EXPECT_NEAR(out->position.y(), -10.5, 1e-9) << "the ball at the centre (y = 0): the right touch line's side";
  EXPECT_NEAR(out->position.z(), 0.4, 1e-9);
  const std::vector<std::string> notes = h.session.TakeNotes();
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_TRUE(Contains(notes[0], "player left 2 could not stand up")) << notes[0];
  EXPECT_NEAR(cycles, 751 + 26 + 1, 2) << "15 s on the ground, 0.5 s held (one cycle of request latency)";
}

// The referee's charging foul (kernel/simspark/fouls.h): left 2 runs at 0.6 m/s into right 3, who stands; away from
// the ball. The charger is held in the air, then put outside the field with a note; the other is not moved, and a
// contact between team mates is no charge.
TEST(SessionReferee, APlayerRunningIntoAnOpponentIsPutOutsideTheField) {
  Harness h(3);
  h.JoinAndCycle("Alpha", 2);
  h.JoinAndCycle("Beta", 3);
  h.JoinAndCycle("Alpha", 4);
  h.session.Trainer("(playMode PlayOn)", TrainerRole::kOperator);
  h.Cycle();
  FakeWorld::Robot& charger = h.world.robot("nao_1");
  FakeWorld::Robot& opponent = h.world.robot("nao_2");
  FakeWorld::Robot& mate = h.world.robot("nao_3");
  charger.position = Eigen::Vector3d(5.0, 3.0, 0.35);
  charger.velocity = Eigen::Vector3d(0.6, 0.0, 0.0);
  opponent.position = Eigen::Vector3d(5.3, 3.0, 0.35);
  mate.position = Eigen::Vector3d(4.7, 3.0, 0.35);
  mate.velocity = Eigen::Vector3d(0.6, 0.0, 0.0);
  h.world.contacts = {{"nao_1", "nao_3", {4.85, 3.0, 0.3}}};  // the mate runs into the charger's back
  WorldRequests taken;
  for (int i = 0; i < 5; ++i) {
    h.Cycle(&taken);
    ASSERT_TRUE(taken.moves.empty()) << "team mates touching: no charge";
  }
  h.world.contacts = {{"nao_2", "nao_1", {5.15, 3.0, 0.3}}};  // either order
  h.Cycle();
  h.world.contacts.clear();
  int held = 0;
  const RobotMove* out = nullptr;
  for (int i = 0; i < 100 && out == nullptr; ++i) {
    h.Cycle(&taken);
    EXPECT_EQ(FindMove(taken, "nao_2"), nullptr) << "the opponent run into stays";
    const RobotMove* m = FindMove(taken, "nao_1");
    ASSERT_NE(m, nullptr) << "cycle " << i;
    if (m->position.z() > 0.9) {
      ++held;
    } else {
      out = m;
    }
  }
  ASSERT_NE(out, nullptr);
  EXPECT_EQ(held, 25);
  EXPECT_NEAR(out->position.x(), -0.6 * (7 - 2), 1e-9);
  const std::vector<std::string> notes = h.session.TakeNotes();
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_TRUE(Contains(notes[0], "player left 2 ran into an opponent (the referee's charging foul)")) << notes[0];
}

// The referee's touching foul (kernel/simspark/touch_groups.h): a third player joining two touching ones is pushed
// 0.4 m out of the group, with a note; the others stay.
TEST(SessionReferee, AThirdPlayerJoiningTwoTouchingIsPushedOut) {
  Harness h(3);
  h.JoinAndCycle("Alpha", 2);
  h.JoinAndCycle("Alpha", 3);
  h.JoinAndCycle("Alpha", 4);
  h.session.Trainer("(playMode PlayOn)", TrainerRole::kOperator);
  h.Cycle();
  h.world.robot("nao_1").position = Eigen::Vector3d(5.0, 3.0, 0.35);
  h.world.robot("nao_2").position = Eigen::Vector3d(5.3, 3.0, 0.35);
  h.world.robot("nao_3").position = Eigen::Vector3d(4.7, 3.0, 0.35);
  h.world.contacts = {{"nao_1", "nao_2", {5.15, 3.0, 0.3}}};
  WorldRequests taken;
  for (int i = 0; i < 3; ++i) {
    h.Cycle(&taken);
    ASSERT_TRUE(taken.moves.empty()) << "two touching";
  }
  h.world.contacts.push_back({"nao_3", "nao_1", {4.85, 3.0, 0.3}});
  h.Cycle();
  h.world.contacts.pop_back();  // pushed away: touching no more
  h.Cycle(&taken);
  ASSERT_EQ(taken.moves.size(), 1u);
  EXPECT_EQ(taken.moves[0].robot, "nao_3");
  EXPECT_NEAR(taken.moves[0].position.x(), 4.7 - 0.4, 1e-9) << "0.4 m from the group's centre (5.0, 3.0)";
  EXPECT_NEAR(taken.moves[0].position.y(), 3.0, 1e-9);
  const std::vector<std::string> notes = h.session.TakeNotes();
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_TRUE(Contains(notes[0], "player left 4 pushed out of a group of 3 players touching")) << notes[0];
}

// The game's kick-in (kernel/simspark/game.h, clearing.h): left 2 touched the ball last before it went over the
// touch line, so right has the kick-in on the line where the ball left. After the 1 s pause the ball is held on the
// spot, left 2 (within 2 m of it) is moved 2.5 m along x towards its goal, and right 3 (within 0.5 m of the spot)
// is pushed to 0.5 m from it; each with a note. Nobody moves again while they keep away.
TEST(SessionGame, AKickInHoldsTheBallAndClearsThePlayersAroundTheSpot) {
  Harness h(2);
  h.JoinAndCycle("Alpha", 2);
  h.JoinAndCycle("Beta", 3);
  h.session.Trainer("(playMode PlayOn)", TrainerRole::kOperator);
  FakeWorld::Robot& left = h.world.robot("nao_1");
  FakeWorld::Robot& right = h.world.robot("nao_2");
  left.position = Eigen::Vector3d(-0.055, 0.0, 0.4);  // its right foot at the ball (0, 0)
  h.Cycle();
  left.position = Eigen::Vector3d(3.5, 9.0, 0.4);
  right.position = Eigen::Vector3d(3.2, 9.8, 0.4);
  h.session.Trainer("(ball (pos 3 9.5 0.042))", TrainerRole::kOperator);
  h.Cycle();
  h.Cycle();
  h.session.Trainer("(ball (pos 3 10.3 0.042))", TrainerRole::kOperator);
  h.Cycle();
  h.Cycle();
  EXPECT_EQ(h.session.game().play_mode(), PlayMode::kKickInRight);
  WorldRequests taken;
  int cycles = 0;
  for (; cycles < 100 && taken.moves.empty(); ++cycles) h.Cycle(&taken);
  EXPECT_NEAR(cycles, 50, 2) << "the kick-in pause";
  ASSERT_TRUE(taken.ball.has_value());
  const Eigen::Vector3d spot(3.0, 10.0 - 0.042, 0.042);
  EXPECT_TRUE(taken.ball->position.isApprox(spot)) << taken.ball->position.transpose();
  const RobotMove* cleared = FindMove(taken, "nao_1");
  ASSERT_NE(cleared, nullptr);
  EXPECT_NEAR(cleared->position.x(), 3.0 - 2.5, 1e-9);
  EXPECT_NEAR(cleared->position.y(), 9.0, 1e-9);
  const RobotMove* pushed = FindMove(taken, "nao_2");
  ASSERT_NE(pushed, nullptr);
  EXPECT_NEAR((pushed->position - spot).head<2>().norm(), 0.5, 1e-9);
  EXPECT_GT(pushed->position.x(), spot.x()) << "pushed the way it stood from the spot";
  const std::vector<std::string> notes = h.session.TakeNotes();
  ASSERT_EQ(notes.size(), 2u);
  for (const std::string& note : notes) EXPECT_TRUE(Contains(note, "the game's clearing in KickIn_Right")) << note;
  for (int i = 0; i < 10; ++i) {
    h.Cycle(&taken);
    EXPECT_TRUE(taken.moves.empty()) << i;
    ASSERT_TRUE(taken.ball.has_value()) << "held until the kick";
  }
}

// The trainer's dropBall acts at once, before the next step (as the reference's monitor commands): the ball placed
// where it is and the players within 2 m of it moved 2.5 m away, in the same requests.
TEST(SessionGame, ADropBallClearsThePlayersAroundTheBallAtOnce) {
  Harness h(2);
  h.JoinAndCycle("Alpha", 2);
  h.JoinAndCycle("Beta", 3);
  h.session.Trainer("(playMode PlayOn)", TrainerRole::kOperator);
  h.world.robot("nao_1").position = Eigen::Vector3d(3.5, 1.3, 0.4);
  h.world.robot("nao_2").position = Eigen::Vector3d(6.5, 1.0, 0.4);  // its box 2.3 m from the ball
  h.session.Trainer("(ball (pos 4 1 0.042))", TrainerRole::kOperator);
  h.Cycle();
  h.session.Trainer("(dropBall)", TrainerRole::kOperator);
  const WorldRequests requests = h.session.TakeRequests();
  ASSERT_TRUE(requests.ball.has_value());
  EXPECT_TRUE(requests.ball->position.isApprox(Eigen::Vector3d(4, 1, 0.042)));
  ASSERT_EQ(requests.moves.size(), 1u) << "only the player within 2 m";
  EXPECT_EQ(requests.moves[0].robot, "nao_1");
  EXPECT_NEAR(requests.moves[0].position.x(), 4.0 - 2.5, 1e-9);
  EXPECT_NEAR(requests.moves[0].position.y(), 1.3, 1e-9);
  EXPECT_EQ(h.session.game().play_mode(), PlayMode::kPlayOn);
  // A trainer's ball move and agent move earlier in the same message count (the reference moves the bodies at once).
  h.Cycle();
  h.session.Trainer("(ball (pos -5 -3 0.042))(agent (unum 3) (team Right) (pos -5.5 -3.2 0.4))(dropBall)",
                    TrainerRole::kOperator);
  const WorldRequests second = h.session.TakeRequests();
  ASSERT_TRUE(second.ball.has_value());
  EXPECT_TRUE(second.ball->position.isApprox(Eigen::Vector3d(-5, -3, 0.042)));
  ASSERT_FALSE(second.moves.empty());
  EXPECT_EQ(second.moves.back().robot, "nao_2");
  EXPECT_NEAR(second.moves.back().position.x(), -5.0 + 2.5, 1e-9) << "the right team away towards its goal";
}

// ClearPlayersBeforeKickOff: at the other team's kick-off, a player in the kick-off team's half goes 2.5 m into its
// own; a kick-off team's player wholly in the centre circle stays, one beyond it in the other half is moved back.
TEST(SessionGame, AKickOffClearsThePlayersFromTheOtherHalf) {
  Harness h(3);
  h.JoinAndCycle("Alpha", 2);
  h.JoinAndCycle("Alpha", 3);
  h.JoinAndCycle("Beta", 4);
  h.world.robot("nao_1").position = Eigen::Vector3d(0.8, 0.3, 0.4);   // left: in the circle
  h.world.robot("nao_2").position = Eigen::Vector3d(5.0, -4.0, 0.4);  // left: in the right half
  h.world.robot("nao_3").position = Eigen::Vector3d(-6.0, 3.0, 0.4);  // right: in the left half
  h.session.Trainer("(playMode KickOff_Left)", TrainerRole::kOperator);
  h.Cycle();
  WorldRequests taken;
  h.Cycle(&taken);
  EXPECT_EQ(FindMove(taken, "nao_1"), nullptr) << "wholly in the centre circle";
  const RobotMove* back = FindMove(taken, "nao_2");
  ASSERT_NE(back, nullptr);
  EXPECT_NEAR(back->position.x(), -2.5, 1e-9);
  EXPECT_NEAR(back->position.y(), -4.0, 1e-9);
  const RobotMove* home = FindMove(taken, "nao_3");
  ASSERT_NE(home, nullptr);
  EXPECT_NEAR(home->position.x(), 2.5, 1e-9);
  EXPECT_NEAR(home->position.y(), 3.0, 1e-9);
}

// The referee's illegal defence (kernel/simspark/fouls.h): a fourth Alpha player walking into its own penalty area
// is moved out over the nearer edge, with a note.
TEST(SessionReferee, AFourthDefenderInThePenaltyAreaIsMovedOut) {
  Harness h(4);
  for (int unum : {2, 3, 4, 5}) h.JoinAndCycle("Alpha", unum);
  h.session.Trainer("(playMode PlayOn)", TrainerRole::kOperator);
  h.world.robot("nao_1").position = Eigen::Vector3d(-14.5, -1.0, 0.35);
  h.world.robot("nao_2").position = Eigen::Vector3d(-14.5, 0.0, 0.35);
  h.world.robot("nao_3").position = Eigen::Vector3d(-14.5, 1.0, 0.35);
  h.world.robot("nao_4").position = Eigen::Vector3d(-12.9, 0.5, 0.35);
  WorldRequests taken;
  for (int i = 0; i < 3; ++i) {
    h.Cycle(&taken);
    ASSERT_TRUE(taken.moves.empty()) << "three in the area";
  }
  h.world.robot("nao_4").position = Eigen::Vector3d(-13.4, 0.5, 0.35);
  h.Cycle();
  h.Cycle(&taken);
  ASSERT_EQ(taken.moves.size(), 1u);
  EXPECT_EQ(taken.moves[0].robot, "nao_4");
  EXPECT_NEAR(taken.moves[0].position.x(), -13.2 + 0.4, 1e-9);
  const std::vector<std::string> notes = h.session.TakeNotes();
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_TRUE(Contains(notes[0], "player left 5 moved out of its penalty area")) << notes[0];
}

TEST(SessionEffectors, HingeVelocitiesByModelJointNameClampedForType0) {
  Harness h(1);
  const int a = h.Join("Alpha", 1);
  h.Cycle();  // as agents do: effectors after the first perception
  h.session.Receive(a, "(he1 1.5)(rle4 -20)(lae3 20)(lle5 7)");
  h.session.Receive(a, "(he1 0.25)");  // the last for a joint wins
  const WorldRequests requests = TakeAnswered(h.session);
  ASSERT_EQ(requests.joints.size(), 1u);
  ExpectJoints(requests.joints.at("nao_1"), {{"hj1", 0.25}, {"rlj4", -6.1395}, {"laj3", 6.1395}, {"llj5", 6.1395}});
  EXPECT_TRUE(h.session.TakeIssues().empty());
  // Taken: the next cycle asks nothing new.
  EXPECT_TRUE(h.session.TakeRequests().joints.empty());
}

TEST(SessionEffectors, Type2AnklesHaveTheirOwnLimits) {
  Harness h(1);
  const int a = h.JoinAndCycle("Alpha", 1, 2);
  h.session.Receive(a, "(rle5 20)(lle5 -20)(rle6 20)(lle6 -1)(rle4 20)");
  const WorldRequests requests = TakeAnswered(h.session);
  ExpectJoints(requests.joints.at("nao_1"),
               {{"rlj5", 8.80667}, {"llj5", -8.80667}, {"rlj6", 3.47234}, {"llj6", -1.0}, {"rlj4", 6.1395}});
}

TEST(SessionEffectors, UnknownEffectorIsAnIssueAndRequestsNothing) {
  Harness h(1);
  const int a = h.JoinAndCycle("Alpha", 1);
  h.session.Receive(a, "(lle7 1)");  // toes: type 4 only
  h.session.Receive(a, "(xyz 1)");   // no robot type has it
  const std::vector<SessionIssue> issues = h.session.TakeIssues();
  ASSERT_EQ(issues.size(), 2u);
  for (const SessionIssue& i : issues) {
    EXPECT_EQ(i.agent, a);
    EXPECT_EQ(i.kind, "unknown_effector");
  }
  EXPECT_TRUE(Contains(issues[0].detail, "lle7"));
  const WorldRequests requests = h.session.TakeRequests();
  EXPECT_TRUE(requests.joints.empty());
  EXPECT_TRUE(requests.moves.empty());
}

TEST(SessionEffectors, Type4ToesAreNotAnIssue) {
  Harness h(1);
  const int a = h.JoinAndCycle("Alpha", 1, 4);
  h.session.Receive(a, "(lle7 1)(he1 1)");
  EXPECT_TRUE(h.session.TakeIssues().empty());
  const WorldRequests requests = TakeAnswered(h.session);
  ASSERT_EQ(requests.joints.count("nao_1"), 1u);
  EXPECT_EQ(requests.joints.at("nao_1").back().joint, "hj1");
}

TEST(SessionEffectors, HingesWithoutRobotAreDropped) {
  Harness h(1);
  const int a = h.session.Connect();
  h.session.Receive(a, "(he1 1)");
  EXPECT_TRUE(h.session.TakeRequests().joints.empty());
}

TEST(SessionEffectors, ParseErrorIsAnIssue) {
  Harness h(1);
  EXPECT_TRUE(h.OnlyAnIssue(h.JoinAndCycle("Alpha", 1), "(he1 1", "parse"));
}

// --- perception ---

TEST(SessionPerception, JointsInDegreesGyroInDegPerSecondForcesOnlyInContact) {
  Harness h(1);
  const int a = h.JoinAndCycle("Alpha", 1);
  FakeWorld::Robot& robot = h.world.robot("nao_1");
  robot.joints[0] = 0.5;    // hj1
  robot.joints[13] = -1.0;  // rlj4
  robot.gyro = {1.0, 0.0, -0.5};
  robot.accelerometer = {0.1, -0.2, 9.81};
  robot.left_contact = true;
  robot.right_contact = false;
  const std::string p = OutputFor(h.Cycle(), a);
  EXPECT_TRUE(Contains(p, "(HJ (n hj1) (ax 28.65))")) << p;
  EXPECT_TRUE(Contains(p, "(HJ (n rlj4) (ax -57.30))")) << p;
  EXPECT_TRUE(Contains(p, "(HJ (n hj2) (ax 0.00))")) << p;
  EXPECT_EQ(turf::test::Occurrences(p, "(HJ "), 22u);
  EXPECT_TRUE(Contains(p, "(GYR (n torso) (rt 57.30 0.00 -28.65))")) << p;
  EXPECT_TRUE(Contains(p, "(ACC (n torso) (a 0.10 -0.20 9.81))")) << p;
  EXPECT_TRUE(Contains(p, "(FRP (n lf) (c 0.00 0.00 -0.01) (f 0.00 0.00 22.50))")) << p;
  EXPECT_FALSE(Contains(p, "(FRP (n rf)")) << p;
  EXPECT_FALSE(Contains(p, "(HJ (n llj7)"));

  robot.left_contact = false;
  const std::string airborne = OutputFor(h.Cycle(), a);
  EXPECT_FALSE(Contains(airborne, "(FRP")) << airborne;
}

TEST(SessionPerception, SeeEveryThirdPerceptionPerAgent) {
  Harness h(2);
  const int a = h.Join("Alpha", 1);
  std::vector<bool> a_sees, b_sees;
  int b = -1;
  for (int cycle = 1; cycle <= 8; ++cycle) {
    const auto outputs = h.Cycle();
    a_sees.push_back(Contains(OutputFor(outputs, a), "(See"));
    if (b >= 0) b_sees.push_back(Contains(OutputFor(outputs, b), "(See"));
    if (cycle == 1) b = h.Join("Alpha", 2);  // one cycle later: another phase
  }
  EXPECT_EQ(a_sees, (std::vector<bool>{true, false, false, true, false, false, true, false}));
  EXPECT_EQ(b_sees, (std::vector<bool>{true, false, false, true, false, false, true}));
}

// The accelerometer as rcssserver3d's: the torso's velocity change over the cycle before the last (its poses of the
// last four cycles), gravity added, in that cycle's torso frame; the world's own accelerometer until there are four
// poses of the robot. A move keeps the velocities of the cycles before it.
TEST(SessionPerception, AccelerometerIsTheTorsosVelocityChangeOverTheCycleBeforeAsTheReferences) {
  Harness h(1);
  const int a = h.JoinAndCycle("Alpha", 1);
  FakeWorld::Robot& robot = h.world.robot("nao_1");
  robot.accelerometer = {1.0, 2.0, 3.0};  // the world's own, seen until the session has four poses
  robot.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));  // facing -x
  const Eigen::Vector3d start = robot.position;
  std::vector<std::string> acc;
  for (int k = 1; k <= 6; ++k) {
    robot.position = start + Eigen::Vector3d(0.5 * 2.0 * std::pow(0.02 * k, 2), 0.0, 0.0);  // 2 m/s^2 along +x
    const std::string p = OutputFor(h.Cycle(), a);
    const size_t at = p.find("(ACC (n torso) (a ");
    acc.push_back(at == std::string::npos ? "" : p.substr(at + 18, p.find(')', at + 18) - at - 18));
  }
  // The poses before this test's first move count as well: the session's own first move (at init) restarts them.
  EXPECT_EQ(acc[0], "1.00 2.00 3.00");
  EXPECT_EQ(acc[1], "1.00 2.00 3.00");
  // From four poses on: 2 m/s^2 along world +x is the torso's -y (it faces -x), gravity up.
  EXPECT_EQ(acc[3], "0.00 -2.00 9.81");
  EXPECT_EQ(acc[5], "0.00 -2.00 9.81");
  // A beam puts the robot at rest elsewhere (here it stays there): the first ACC after it is still the change
  // before it, in the frame before it; the next one is the change to rest from the last cycle's 0.22 m/s along
  // +x, -11 m/s^2, in the beamed torso's frame (facing +x, give or take the beam's noise).
  h.session.Receive(a, "(beam -3 0 0)");
  EXPECT_TRUE(Contains(OutputFor(h.Cycle(), a), "(ACC (n torso) (a 0.00 -2.00 9.81))"));
  const std::string after = OutputFor(h.Cycle(), a);
  const size_t at = after.find("(ACC (n torso) (a ");
  ASSERT_NE(at, std::string::npos) << after;
  std::istringstream values(after.substr(at + 18));
  double x = NAN, y = NAN, z = NAN;
  values >> x >> y >> z;
  EXPECT_NEAR(std::hypot(x, y), 11.0, 0.01) << after;
  EXPECT_LT(y, -10.0) << after;
  EXPECT_NEAR(z, 9.81, 0.005) << after;
}

// UT Austin Villa's agents beam every cycle for their first 2.25 s ("hovering"): each step starts from rest where
// the beam put the robot, which then falls for 20 ms. rcssserver3d's accelerometer reads the velocity each step
// leaves, the same every cycle, so ACC reads gravity, up (traced: 9.6-9.8 m/s^2), where the falling robot's own
// accelerometer reads 0. UT's inertial filter starts from the ACC of those cycles: read as 0, its tilt starts
// 90 degrees off.
TEST(SessionPerception, AnAgentBeamingEveryCycleReadsGravity) {
  Harness h(1);
  const int a = h.JoinAndCycle("Alpha", 1);
  FakeWorld::Robot& robot = h.world.robot("nao_1");
  robot.accelerometer = {0.0, 0.0, 0.0};  // in free fall
  std::string p;
  for (int k = 0; k < 8; ++k) {
    h.session.Receive(a, "(beam -3 0 0)");
    h.world.Apply(h.session.TakeRequests());
    robot.position.z() -= 9.81 * 0.02 * 0.02;  // one 20 ms step's fall from rest (ODE's semi-implicit Euler)
    h.session.Advance(h.world.Snapshot());
    p = OutputFor(h.session.TakeOutputs(), a);
  }
  EXPECT_TRUE(Contains(p, "(ACC (n torso) (a 0.00 0.00 9.81))")) << p;
}

// A robot lying face down beside the field, feet in the air, on a vision
// cycle: it sees nothing and hears nothing. The whole message is what the
// reference sends: no hear, no FRP, and "(See )" right after hj2.
TEST(SessionPerception, FallenRobotThatSeesNothingGetsTheReferencesMessage) {
  Harness h(1);
  const int a = h.Join("", 0);
  h.Cycle();  // parked
  FakeWorld::Robot& robot = h.world.robot("nao_1");
  robot.position.z() = 0.1;
  robot.orientation = Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitX());  // forward (+y) points down
  robot.left_contact = false;
  robot.right_contact = false;
  for (int i = 0; i < 5; ++i) h.Cycle();
  // The 7th perception: a vision cycle, and the torso has lain still for the three cycles the accelerometer looks
  // back (the reference's: gravity in the torso's frame, forward pointing down).
  const std::string p = OutputFor(h.Cycle(), a);
  EXPECT_EQ(p, std::string("(time (now 0.14))(GS (sl 0) (sr 0) (t 0.00) (pm BeforeKickOff))"
                           "(GYR (n torso) (rt 0.00 0.00 0.00))(ACC (n torso) (a 0.00 -9.81 0.00))"
                           "(HJ (n hj1) (ax 0.00))(HJ (n hj2) (ax 0.00))(See )") +
                   test::kLimbJointsAtZero);
}

TEST(SessionPerception, SeeListsBallAndOtherPlayers) {
  SessionOptions options;
  options.vision.noise = false;
  Harness h(2, options);
  const int a = h.Join("Alpha", 1);
  h.Join("Beta", 1);
  h.Cycle();  // both at their start poses now
  // In PlayOn (BeforeKickOff holds the ball at the centre), the ball 2 m in
  // front of a (facing +x, head 0.6 m high) and b 3 m in front of it.
  h.session.Trainer("(playMode PlayOn)(ball (pos -12.2 9.2 0.042))(agent (unum 1) (team Right) (pos -11.2 9.2 0.4))",
                    TrainerRole::kOperator);
  h.Cycle();
  h.Cycle();
  const std::string p = OutputFor(h.Cycle(), a);  // a's 4th perception
  ASSERT_TRUE(Contains(p, "(See")) << p;
  // Distances within the calibration offset (each axis +-0.005 m).
  EXPECT_NEAR(NumberAfter(p, "(B (pol "), std::hypot(2.0, 0.6 - 0.042), 0.01) << p;
  EXPECT_NEAR(NumberAfter(p, "(P (team Beta) (id 1) (head (pol "), 3.0, 0.01) << p;
  EXPECT_TRUE(Contains(p, "(P (team Alpha) (id 1) (rlowerarm (pol ")) << p;  // its own arms
  EXPECT_FALSE(Contains(p, "(P (team Alpha) (id 1) (head")) << p;            // never its own head
}

// --- beam ---

TEST(SessionBeam, AllowedBeforeKickOffMovesTheRobot) {
  Harness h(1);
  const int a = h.JoinAndCycle("Alpha", 1);
  h.session.Receive(a, "(beam -2 1 90)");
  const WorldRequests requests = h.session.TakeRequests();
  ASSERT_EQ(requests.moves.size(), 1u);
  const RobotMove& m = requests.moves[0];
  EXPECT_EQ(m.robot, "nao_1");
  EXPECT_FALSE(m.reset_joints);
  EXPECT_NEAR(m.position.x(), -2.0, 0.05 + 1e-9);
  EXPECT_NEAR(m.position.y(), 1.0, 0.05 + 1e-9);
  EXPECT_NEAR(m.position.z(), 0.4, 1e-9);
  EXPECT_LE(ForwardErrorDeg(m.orientation, Eigen::Vector3d::UnitY()), 10.0 + 1e-6);  // rot 90 = facing +y
  EXPECT_TRUE(h.session.TakeIssues().empty());
}

TEST(SessionBeam, RightTeamIsMirrored) {
  Harness h(2);
  h.Join("Alpha", 1);
  const int b = h.JoinAndCycle("Beta", 1);
  h.session.Receive(b, "(beam -2 1 0)");
  const RobotMove* m = FindMove(h.session.TakeRequests(), "nao_2");
  ASSERT_NE(m, nullptr);
  EXPECT_NEAR(m->position.x(), 2.0, 0.05 + 1e-9);
  EXPECT_NEAR(m->position.y(), -1.0, 0.05 + 1e-9);
  EXPECT_LE(ForwardErrorDeg(m->orientation, -Eigen::Vector3d::UnitX()), 10.0 + 1e-6);
}

TEST(SessionBeam, IgnoredInPlayOn) {
  Harness h(1);
  const int a = h.JoinAndCycle("Alpha", 1);
  h.session.Trainer("(playMode PlayOn)", TrainerRole::kOperator);
  h.session.Receive(a, "(beam -2 1 90)");
  EXPECT_TRUE(h.session.TakeRequests().moves.empty());
  EXPECT_TRUE(h.session.TakeIssues().empty());
  EXPECT_EQ(Gs(OutputFor(h.Cycle(), a)), "(GS (sl 0) (sr 0) (t 0.02) (pm PlayOn))");
}

TEST(SessionBeam, BeforeInitIsAnIssue) {
  Harness h(1);
  EXPECT_TRUE(h.OnlyAnIssue(h.JoinAndCycle("", 0), "(beam -2 1 90)", "beam_before_init"));
}

// --- sync mode ---

TEST(SessionSync, WaitsForSynAfterTheGraceCycles) {
  SessionOptions options;
  options.sync_mode = true;
  options.sync_grace_cycles = 3;
  Harness h(2, options);
  const int idle = h.session.Connect();  // no robot: never awaited
  const int a = h.Join("Alpha", 1);
  for (int i = 0; i < 3; ++i) {
    EXPECT_TRUE(h.session.ReadyToStep()) << "grace cycle " << i;
    h.Cycle();
  }
  EXPECT_FALSE(h.session.ReadyToStep());
  EXPECT_EQ(h.session.Waiting(), std::vector<int>{a});  // not idle
  h.session.Receive(a, "(syn)");
  EXPECT_TRUE(h.session.ReadyToStep());
  EXPECT_TRUE(h.session.Waiting().empty());
  EXPECT_EQ(h.session.agents(), 2);
  h.session.Receive(idle, "(syn)");  // a robotless agent's syn changes nothing
  h.session.TakeRequests();
  EXPECT_FALSE(h.session.ReadyToStep());  // a new cycle needs a new (syn)
  h.session.Receive(a, "(he1 1)");
  EXPECT_FALSE(h.session.ReadyToStep());
  h.session.Receive(a, "(he1 1)(syn)");
  EXPECT_TRUE(h.session.ReadyToStep());
}

TEST(SessionSync, EveryAgentWithARobotIsAwaited) {
  SessionOptions options;
  options.sync_mode = true;
  options.sync_grace_cycles = 0;
  Harness h(2, options);
  const int a = h.Join("Alpha", 1);
  const int b = h.Join("Alpha", 2);
  EXPECT_FALSE(h.session.ReadyToStep());
  EXPECT_EQ(h.session.Waiting(), (std::vector<int>{a, b}));
  h.session.Receive(b, "(syn)");
  EXPECT_FALSE(h.session.ReadyToStep());
  EXPECT_EQ(h.session.Waiting(), std::vector<int>{a});
  h.session.Receive(a, "(syn)");
  EXPECT_TRUE(h.session.ReadyToStep());
  // A leaving agent is no longer awaited.
  h.session.TakeRequests();
  h.session.Receive(a, "(syn)");
  h.session.Disconnect(b);
  EXPECT_TRUE(h.session.ReadyToStep());
}

TEST(SessionSync, OffMeansAlwaysReady) {
  SessionOptions options;
  options.sync_grace_cycles = 0;
  Harness h(1, options);
  h.Join("Alpha", 1);
  h.Cycle();
  EXPECT_TRUE(h.session.ReadyToStep());
}

// --- trainer ---

TEST(SessionTrainer, BallPositionAndVelocity) {
  Harness h(1);
  h.session.Trainer("(ball (pos 1 2 0.042) (vel 0 0 0))", TrainerRole::kOperator);
  WorldRequests requests = h.session.TakeRequests();
  ASSERT_TRUE(requests.ball);
  EXPECT_TRUE(requests.ball->position.isApprox(Eigen::Vector3d(1, 2, 0.042)));
  EXPECT_TRUE(requests.ball->velocity.isZero());
  EXPECT_TRUE(h.session.TakeIssues().empty());

  // Velocity only: the ball stays where the world last had it.
  h.world.Apply(requests);
  h.session.Advance(h.world.Snapshot());  // no player registered: the ball is not held at the centre
  h.session.Trainer("(ball (vel 1 0 0))", TrainerRole::kOperator);
  requests = h.session.TakeRequests();
  ASSERT_TRUE(requests.ball);
  EXPECT_TRUE(requests.ball->position.isApprox(Eigen::Vector3d(1, 2, 0.042)));
  EXPECT_TRUE(requests.ball->velocity.isApprox(Eigen::Vector3d(1, 0, 0)));
}

TEST(SessionTrainer, MoveAgentKeepsItsOrientation) {
  Harness h(2);
  h.Join("Alpha", 1);
  h.Cycle();
  h.session.Trainer("(agent (unum 1) (team Left) (pos -3 0 0.4))", TrainerRole::kOperator);
  const WorldRequests requests = h.session.TakeRequests();
  ASSERT_EQ(requests.moves.size(), 1u);
  const RobotMove& m = requests.moves[0];
  EXPECT_EQ(m.robot, "nao_1");
  EXPECT_TRUE(m.position.isApprox(Eigen::Vector3d(-3, 0, 0.4)));
  EXPECT_FALSE(m.reset_joints);
  EXPECT_LT(ForwardErrorDeg(m.orientation, Eigen::Vector3d::UnitX()), 1e-6);  // as init left it
  EXPECT_TRUE(h.session.TakeIssues().empty());
}

TEST(SessionTrainer, MoveAgentWithYaw) {
  Harness h(1);
  h.Join("Alpha", 1);
  h.Cycle();
  h.session.Trainer("(agent (unum 1) (team Left) (move -3 0 0.4 0))", TrainerRole::kOperator);
  const RobotMove* m = FindMove(h.session.TakeRequests(), "nao_1");
  ASSERT_NE(m, nullptr);
  EXPECT_LT(ForwardErrorDeg(m->orientation, Eigen::Vector3d::UnitY()), 1e-6);  // raw yaw 0: model axes
}

TEST(SessionTrainer, MoveUnknownAgentIsAnIssue) {
  Harness h(1);
  h.Join("Alpha", 1);
  h.Cycle();
  h.session.Trainer("(agent (unum 2) (team Left) (pos -3 0 0.4))(agent (unum 1) (team Right) (pos -3 0 0.4))",
                    TrainerRole::kOperator);
  EXPECT_EQ(IssueKinds(h.session.TakeIssues()), (std::vector<std::string>{"unknown_agent", "unknown_agent"}));
  EXPECT_TRUE(h.session.TakeRequests().moves.empty());
}

TEST(SessionTrainer, KickOffLeftShowsInTheNextGs) {
  Harness h(1);
  const int a = h.JoinAndCycle("Alpha", 1);
  h.session.Trainer("(kickOff Left)", TrainerRole::kOperator);
  EXPECT_EQ(h.session.game().play_mode(), PlayMode::kKickOffLeft);
  const std::string gs = Gs(OutputFor(h.Cycle(), a));
  EXPECT_TRUE(Contains(gs, "(pm KickOff_Left)")) << gs;
  EXPECT_TRUE(Contains(gs, "(t 0.02)")) << gs;  // the clock runs outside BeforeKickOff
}

TEST(SessionTrainer, KillKicksTheAgentAndKillsimQuits) {
  Harness h(2);
  h.Join("Alpha", 1);
  const int b = h.Join("Alpha", 2);
  EXPECT_EQ(h.KickedBy("(kill (unum 2) (team Left))"), std::vector<int>{b});
  EXPECT_TRUE(h.session.TakeKicked().empty());
  EXPECT_TRUE(h.KickedBy("(kill (unum 3) (team Left))").empty());
  EXPECT_FALSE(h.session.quit_requested());
  h.session.Trainer("(killsim)", TrainerRole::kOperator);
  EXPECT_TRUE(h.session.quit_requested());
}

TEST(SessionTrainer, ScoreAndTime) {
  Harness h(1);
  const int a = h.Join("Alpha", 1);
  h.session.Trainer("(score (left 2) (right 1))(time 12.5)", TrainerRole::kOperator);
  const std::string gs = Gs(OutputFor(h.Cycle(), a));
  EXPECT_TRUE(Contains(gs, "(sl 2) (sr 1) (t 12.50)")) << gs;
}

TEST(SessionTrainer, MalformedInputIsAnIssue) {
  Harness h(1);
  for (const char* bad : {"(ball (pos 1 2))", "(frobnicate 1)", "((", "(playMode NoSuchMode)"}) {
    h.session.Trainer(bad, TrainerRole::kOperator);
    const std::vector<SessionIssue> issues = h.session.TakeIssues();
    ASSERT_EQ(issues.size(), 1u) << bad;
    EXPECT_EQ(issues[0].agent, -1);
    EXPECT_EQ(issues[0].kind.rfind("trainer.", 0), 0u) << issues[0].kind;
  }
  const WorldRequests requests = h.session.TakeRequests();
  EXPECT_FALSE(requests.ball);
  EXPECT_EQ(h.session.game().play_mode(), PlayMode::kBeforeKickOff);
}

// --- disconnect ---

TEST(SessionDisconnect, ParksTheRobotDropsItsJointsAndFreesTheSlot) {
  Harness h(2);
  const int a = h.Join("Alpha", 1);
  const int b = h.JoinAndCycle("Alpha", 2);
  h.session.Receive(a, "(he1 1)");
  h.session.Receive(b, "(he1 1)");
  h.session.Disconnect(a);
  EXPECT_EQ(h.session.agents(), 1);
  EXPECT_EQ(h.session.game().PlayerCount(Side::kLeft), 1);

  WorldRequests requests;
  auto outputs = h.Cycle(&requests);
  ASSERT_EQ(requests.moves.size(), 1u);
  EXPECT_EQ(requests.moves[0].robot, "nao_1");
  EXPECT_TRUE(requests.moves[0].reset_joints);
  EXPECT_TRUE(requests.moves[0].position.isApprox(h.world.Parks()[0].position));
  EXPECT_TRUE(requests.joints.empty());  // answers act one cycle later
  EXPECT_EQ(OutputFor(outputs, a), "");
  WorldRequests next;
  h.Cycle(&next);
  EXPECT_EQ(next.joints.count("nao_1"), 0u);
  EXPECT_EQ(next.joints.count("nao_2"), 1u);

  // A newcomer gets the free robot and the free number.
  const int c = h.Join("Alpha", 1);
  EXPECT_TRUE(h.session.TakeIssues().empty());
  outputs = h.Cycle(&requests);
  EXPECT_TRUE(Contains(Gs(OutputFor(outputs, c)), "(unum 1) (team left)"));
  const RobotMove* start = FindMove(requests, "nao_1");
  ASSERT_NE(start, nullptr);
  EXPECT_NEAR(start->position.x(), -14.2, 1e-9);
  // Disconnecting twice or an unknown agent does nothing.
  h.session.Disconnect(a);
  h.session.Disconnect(99);
  EXPECT_EQ(h.session.agents(), 2);
}

TEST(SessionDisconnect, LastTeamMemberLeavingKeepsOtherAgentsRunning) {
  Harness h(2);
  const int a = h.Join("Alpha", 1);
  const int b = h.JoinAndCycle("Beta", 1);
  h.session.Disconnect(b);
  const auto outputs = h.Cycle();
  ASSERT_EQ(outputs.size(), 1u);
  EXPECT_EQ(outputs[0].first, a);
}

// --- say / hear ---

TEST(SessionRadio, SayIsHeardBySelfTeammateAndOpponent) {
  Harness h(3);
  const int a = h.Join("Alpha", 1);  // (-14.2, 9.2)
  const int b = h.Join("Alpha", 2);  // (-14.2, 8.0)
  const int c = h.Join("Beta", 2);   // (14.2, 8.0)
  h.Cycle();
  h.session.Receive(a, "(say hello)");
  const auto outputs = h.Cycle();
  const std::string pa = OutputFor(outputs, a);
  const std::string pb = OutputFor(outputs, b);
  const std::string pc = OutputFor(outputs, c);
  EXPECT_TRUE(Contains(pa, "(hear Alpha 0.00 self hello)")) << pa;
  EXPECT_EQ(turf::test::Occurrences(pa, "(hear"), 1u);
  // Direction: speaker - listener in the listener team's frame, degrees.
  EXPECT_TRUE(Contains(pb, "(hear Alpha 0.00 90.00 hello)")) << pb;
  // Right team: x, y negated, so (28.4, -1.2): atan2 = -2.42 deg.
  EXPECT_TRUE(Contains(pc, "(hear Alpha 0.00 -2.42 hello)")) << pc;
  // Heard once.
  for (const auto& [id, text] : h.Cycle()) EXPECT_FALSE(Contains(text, "(hear")) << id;
}

TEST(SessionRadio, SayBeforeInitIsNotHeard) {
  Harness h(2);
  const int a = h.Join("", 0);
  const int b = h.JoinAndCycle("Alpha", 1);
  h.session.Receive(a, "(say hello)");
  const auto outputs = h.Cycle();
  EXPECT_FALSE(Contains(OutputFor(outputs, a), "(hear"));
  EXPECT_FALSE(Contains(OutputFor(outputs, b), "(hear"));
}

// --- determinism ---

std::string RunScript(uint64_t seed) {
  SessionOptions options;
  options.seed = seed;
  Harness h(3, options);
  const int a = h.Join("Alpha", 1);
  const int b = h.Join("Alpha", 2);
  const int c = h.Join("Beta", 1);
  std::string log;
  for (int cycle = 0; cycle < 12; ++cycle) {
    if (cycle == 1) {
      h.session.Receive(a, "(beam -1 0.5 0)");
      h.session.Receive(c, "(beam -3 2 45)");
    }
    if (cycle == 3) h.session.Trainer("(kickOff None)", TrainerRole::kOperator);
    h.session.Receive(b, "(he1 " + std::to_string(0.1 * cycle) + ")(say b" + std::to_string(cycle) + ")");
    for (const auto& [id, text] : h.Cycle()) log += std::to_string(id) + ":" + text + "\n";
    log += h.session.TakeMonitorOutput() + "\n";
  }
  return log;
}

TEST(SessionDeterminism, SameSeedSameBytes) {
  const std::string first = RunScript(7);
  EXPECT_TRUE(Contains(first, "(See")) << "the script must exercise the noisy vision";
  EXPECT_TRUE(Contains(first, "(pol "));
  EXPECT_EQ(first, RunScript(7));
  EXPECT_NE(first, RunScript(8));  // the noise (and beam) do depend on the seed
}

// --- monitor ---

TEST(SessionMonitor, GameStateEverySecondCycle) {
  Harness h(1);
  h.Join("Alpha", 1);
  std::vector<bool> written;
  for (int i = 0; i < 4; ++i) {
    h.Cycle();
    const std::string frame = h.session.TakeMonitorOutput();
    written.push_back(!frame.empty());
    if (i == 1) {
      EXPECT_TRUE(Contains(frame, "(play_mode 0)")) << frame;
      EXPECT_TRUE(Contains(frame, "(team_left Alpha)")) << frame;
    }
  }
  EXPECT_EQ(written, (std::vector<bool>{false, true, false, true}));
  h.session.Trainer("(kickOff Left)", TrainerRole::kOperator);
  h.Cycle();
  h.Cycle();
  EXPECT_TRUE(Contains(h.session.TakeMonitorOutput(), "(play_mode 1)"));
}

TEST(SessionMonitor, GreetingHasTheEnvironmentAndGame) {
  Harness h(1);
  const std::string greeting = h.session.MonitorGreeting();
  EXPECT_TRUE(Contains(greeting, "(FieldLength 30)")) << greeting;
  EXPECT_TRUE(Contains(greeting, "(play_mode 0)")) << greeting;
}

}  // namespace
}  // namespace turf::simspark

namespace turf::simspark {
namespace {

// --- league snapshots ---

// A scripted match of four players: beams, a coin-toss kick-off, joints, say,
// a trainer move onto the ball (a touch: PlayOn), back to BeforeKickOff with
// beams and another coin toss. Inputs(i) gives cycle i's inputs, the same on
// every run; Step(i) also runs the cycle and returns every byte the session
// sent, by player (agent ids change when a player reconnects).
struct LeagueMatch : turf::test::LeagueScript<LeagueMatch> {
  LeagueMatch() : h(5, Options()) {
    a = h.Join("Alpha", 1);
    b = h.Join("Alpha", 2);
    c = h.Join("Beta", 1);
    d = h.Join("Beta", 2);
  }
  static SessionOptions Options() {
    SessionOptions options;
    options.seed = 11;
    return options;
  }

  void Inputs(int i) {
    if (i == 1 || i == 22) {
      h.session.Receive(a, "(beam -1 0.5 0)");
      h.session.Receive(c, "(beam -3 2 45)");
    }
    if (i == 3 || i == 24) h.session.Trainer("(kickOff None)", TrainerRole::kOperator);
    if (i == 14) h.session.Receive(d, "(beam -2 -2 90)");  // ignored once in play
    if (i == 16) h.session.Trainer("(agent (team Left)(unum 1)(pos 0.05 0 0.4))", TrainerRole::kOperator);
    if (i == 21) h.session.Trainer("(playMode BeforeKickOff)", TrainerRole::kOperator);
    h.session.Receive(b, "(he1 " + std::to_string(0.1 * i) + ")(say b" + std::to_string(i) + ")");
    if (i % 2 == 1) h.session.Receive(d, "(lae1 -0.5)(say d" + std::to_string(i) + ")");
    if (i % 5 == 0) h.session.Receive(a, "(say a" + std::to_string(i) + ")");
  }
  std::string Cycle() {
    std::string log;
    for (const auto& [id, text] : h.Cycle()) log += Name(id) + ":" + text + "\n";
    return log + "monitor:" + h.session.TakeMonitorOutput() + "\n";
  }
  Session& session() { return h.session; }
  FakeWorld& world() { return h.world; }
  std::string Name(int id) const { return turf::test::NameOf(id, {{a, "a"}, {b, "b"}, {c, "c"}, {d, "d"}}); }

  Harness h;
  int a = 0, b = 0, c = 0, d = 0;
};

TEST(SessionLeagueSnapshot, RestoredMatchSendsTheSameBytes) {
  LeagueMatch m;
  EXPECT_EQ(
      m.RestoredMatchSendsTheSameBytes(
          10, 30, {"(See", "(pol ", "(hear Alpha", "(hear Beta", "(pm PlayOn)", "(pm KickOff_", "(pm BeforeKickOff)"}),
      "");
}

// Saved between a cycle's inputs and its step: said messages, beams and joint
// velocities not yet taken are in the snapshot.
TEST(SessionLeagueSnapshot, SavedWithInputsPendingGoesOnTheSame) {
  LeagueMatch m;
  EXPECT_EQ(m.SavedWithInputsPendingGoesOnTheSame(22, 30, [] {}), "");
}

// A player that left and came back (another connection, another noise
// generator) takes the snapshot's player state: the league state is the
// snapshot's again. (Its perceptions are not byte for byte the saved run's:
// vision lists the other players in connection order.)
TEST(SessionLeagueSnapshot, ReconnectedPlayerTakesTheSavedState) {
  LeagueMatch m;
  const std::string snapshot = m.SaveAfter(10);
  m.Run(10, 20);
  m.h.session.Disconnect(m.d);
  m.h.session.Disconnect(m.a);
  m.a = m.h.Join("Alpha", 1);
  m.d = m.h.Join("Beta", 2);
  m.h.Cycle();
  ASSERT_EQ(m.h.session.RestoreLeague(snapshot), "");
  EXPECT_EQ(m.h.session.SaveLeague(), snapshot);
}

TEST(SessionLeagueSnapshot, SnapshotOfTheSameStateIsTheSameBytes) {
  LeagueMatch m;
  EXPECT_EQ(m.SnapshotOfTheSameStateIsTheSameBytes(12), "");
}

TEST(SessionLeagueSnapshot, TruncatedOrCorruptedIsRefusedAndChangesNothing) {
  LeagueMatch m;
  const std::string snapshot = m.SaveAfter(8);
  m.Run(8, 12);
  const std::string now = m.h.session.SaveLeague();
  EXPECT_EQ(turf::test::DamagedSnapshotsChangeNothing(
                snapshot, now, [&] { return m.h.session.SaveLeague(); },
                [&](const std::string& bytes) { return m.h.session.RestoreLeague(bytes); }),
            "");
  EXPECT_EQ(m.h.session.RestoreLeague(""), "not a SimSpark league snapshot");
  EXPECT_EQ(m.h.session.RestoreLeague(snapshot.substr(0, 10)), "invalid league snapshot: truncated");
  EXPECT_EQ(m.h.session.RestoreLeague(snapshot + "x"), "invalid league snapshot: trailing bytes");
  std::string version = snapshot;
  version[4] ^= 1;
  EXPECT_EQ(m.h.session.RestoreLeague(version), "league snapshot format version differs");
  EXPECT_EQ(m.h.session.SaveLeague(), now);
}

// A generator state of all zeros (found by fuzz_league) would make the vision
// noise wait forever for a non-zero draw.
TEST(SessionLeagueSnapshot, AllZeroNoiseGeneratorIsRefused) {
  LeagueMatch m;
  std::string snapshot = m.SaveAfter(4);
  const std::string now = snapshot;
  // The last player's generator ends the snapshot: four state words, has_spare, spare.
  const size_t state_at = snapshot.size() - (4 * 8 + 1 + 8);
  std::fill(snapshot.begin() + state_at, snapshot.begin() + state_at + 4 * 8, '\0');
  EXPECT_EQ(m.h.session.RestoreLeague(snapshot), "invalid league snapshot: random generator state all zero");
  EXPECT_EQ(m.h.session.SaveLeague(), now);
}

TEST(SessionLeagueSnapshot, PlayerNotConnectedIsRefused) {
  LeagueMatch m;
  const std::string snapshot = m.SaveAfter(6);
  m.h.session.Disconnect(m.d);
  m.Step(6);
  const std::string now = m.h.session.SaveLeague();
  EXPECT_EQ(m.h.session.RestoreLeague(snapshot), "the snapshot's player right 2 is not connected (or has no team)");
  EXPECT_EQ(m.h.session.SaveLeague(), now);
  // Back in the same robot (the lowest free one): the snapshot fits again.
  m.d = m.h.Join("Beta", 2);
  EXPECT_EQ(m.h.session.RestoreLeague(snapshot), "");
  EXPECT_EQ(m.h.session.cycle(), 6u);
  EXPECT_EQ(m.h.session.game().PlayerCount(Side::kRight), 2);
}

TEST(SessionLeagueSnapshot, PlayerNotInTheSnapshotIsRefused) {
  LeagueMatch m;
  const std::string snapshot = m.SaveAfter(4);
  const int e = m.h.Join("Beta", 5);
  m.h.Cycle();
  const std::string now = m.h.session.SaveLeague();
  EXPECT_EQ(m.h.session.RestoreLeague(snapshot), "player right 5 is connected but not in the snapshot");
  EXPECT_EQ(m.h.session.SaveLeague(), now);
  // Leaving makes it fit; an agent without a team is not the league's.
  m.h.session.Disconnect(e);
  m.h.Join("", 0);
  EXPECT_EQ(m.h.session.RestoreLeague(snapshot), "");
}

TEST(SessionLeagueSnapshot, PlayerInAnotherRobotIsRefused) {
  LeagueMatch m;
  const std::string snapshot = m.SaveAfter(4);
  m.h.session.Disconnect(m.a);
  m.h.Join("", 0);  // takes nao_1
  m.a = m.h.Join("Alpha", 1);
  EXPECT_EQ(m.h.session.RestoreLeague(snapshot), "the snapshot's player left 1 drove nao_1, now nao_5");
}

// Issue 20: an unauthenticated (killsim) ended the match. A trainer that is
// not an operator may move things but not end, restart or rewrite the match.
TEST(SessionTrainer, MatchControlNeedsAnOperator) {
  Harness h(2);
  const int a = h.Join("Alpha", 1);
  h.Join("Beta", 1);
  h.Cycle();
  for (const char* text : {"(killsim)", "(kill (unum 1) (team Left))", "(kickOff Left)", "(time 250)",
                           "(score (left 5))", "(playMode GameOver)", "(turfResetTeam Right)"}) {
    h.session.Trainer(text, TrainerRole::kTrainer);
    EXPECT_TRUE(h.OneIssue("trainer.not_operator")) << text;
  }
  EXPECT_FALSE(h.session.quit_requested());
  EXPECT_TRUE(h.session.TakeKicked().empty());
  EXPECT_EQ(h.session.game().play_mode(), PlayMode::kBeforeKickOff);
  EXPECT_EQ(h.session.game().game_time(), 0.0);
  EXPECT_EQ(h.session.game().score(Side::kLeft), 0);
  EXPECT_EQ(h.session.game().TeamName(Side::kRight), "Beta");
  // In one message, the allowed commands still apply.
  h.session.Trainer("(playMode GameOver)(ball (pos 1 2 0.042))", TrainerRole::kTrainer);
  EXPECT_TRUE(h.OneIssue("trainer.not_operator"));
  ASSERT_TRUE(h.session.TakeRequests().ball.has_value());
  // An operator's are carried out.
  h.session.Trainer("(kickOff Left)", TrainerRole::kOperator);
  EXPECT_EQ(h.session.game().play_mode(), PlayMode::kKickOffLeft);
  h.session.Trainer("(killsim)", TrainerRole::kOperator);
  EXPECT_TRUE(h.session.quit_requested());
  EXPECT_TRUE(h.session.TakeIssues().empty());
  EXPECT_FALSE(OutputFor(h.Cycle(), a).empty());
}

TEST(SessionTrainer, OutOfRangeValuesChangeNothing) {
  Harness h(1);
  h.Join("Alpha", 1);
  h.session.Trainer("(time 12)", TrainerRole::kOperator);
  h.session.Trainer("(time 1e308)", TrainerRole::kOperator);
  EXPECT_TRUE(h.OneIssue("trainer.out_of_range"));
  EXPECT_EQ(h.session.game().game_time(), 12.0);
  h.session.Trainer("(ball (pos 0 0 0.042) (vel 1e300 0 0))", TrainerRole::kOperator);
  EXPECT_TRUE(h.OneIssue("trainer.out_of_range"));
  EXPECT_FALSE(h.session.TakeRequests().ball.has_value());
}

// Issue 20: two throwaway agents claimed both team names and the real team was
// refused until a restart.
TEST(SessionTeams, ATeamNameIsFreedWhenItsLastAgentDisconnects) {
  Harness h(3);
  const int squat1 = h.Join("Squat1", 1);
  const int squat2 = h.JoinAndCycle("Squat2", 1);
  h.session.Disconnect(squat1);
  h.session.Disconnect(squat2);
  const int real = h.Join("Real", 0);
  EXPECT_TRUE(h.session.TakeIssues().empty());
  const std::string gs = Gs(OutputFor(h.Cycle(), real));
  EXPECT_TRUE(Contains(gs, "(unum 1) (team left)")) << gs;
  EXPECT_EQ(h.session.game().TeamName(Side::kLeft), "Real");
  EXPECT_FALSE(h.session.game().TeamName(Side::kRight).has_value());
}

TEST(SessionTeams, AnOperatorResetsASideWhoseSquattersStayConnected) {
  Harness h(3);
  h.Join("Squat1", 1);
  const int squat2 = h.JoinAndCycle("Squat2", 1);
  EXPECT_EQ(h.KickedBy("(turfResetTeam Right)"), std::vector<int>{squat2});
  // The side is free at once, before the participant has dropped the squatter...
  const int real = h.Join("Real", 1);
  EXPECT_TRUE(h.session.TakeIssues().empty());
  EXPECT_EQ(h.session.game().TeamName(Side::kRight), "Real");
  // ...whose input is ignored meanwhile, and whose leaving takes nothing from the new team.
  h.session.Receive(squat2, "(init (unum 1)(teamname Squat2))");
  h.session.Disconnect(squat2);
  EXPECT_EQ(h.session.game().PlayerCount(Side::kRight), 1);
  EXPECT_EQ(h.session.game().TeamName(Side::kRight), "Real");
  const std::string gs = Gs(OutputFor(h.Cycle(), real));
  EXPECT_TRUE(Contains(gs, "(unum 1) (team right)")) << gs;
}

}  // namespace
}  // namespace turf::simspark
