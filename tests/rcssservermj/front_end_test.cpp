// turf's RCSSServerMJ front-end with turf-sim's legged node (configs/scenes/rcssservermj_fifa.yaml: 22 T1) on an
// in-memory bus (and the 1 v 1 scene with two), and scripted agents over real TCP: init, activation and placement,
// every perceptor's order, units and number format against shared/protocols/rcssservermj.md, a beam, a commanded joint
// moving in HJ, vision every second cycle, sync mode's one cycle per round of actions, 22 agents at once, malformed
// input dropping only its client. No sleeps: every wait is for a message or a condition, with a deadline.
#include <gtest/gtest.h>
#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <regex>
#include <string>
#include <thread>
#include <vector>

#include "codecs/rcssservermj/robots.h"
#include "participants/rcssservermj_bridge/rcssservermj_bridge.h"
#include "participants/rcssservermj_bridge/rcssservermj_flags.h"
#include "tests/simspark/agent_client.h"
#include "tests/support/cli_parse.h"
#include "tests/support/front_end_on_bus.h"
#include "tests/support/legged_scene.h"

namespace turf {
namespace {

using namespace std::chrono_literals;
using test::AgentClient;

// turf-sim's legged node (the FIFA scene) and the front-end on ports the kernel picks, and agents connecting to it.
class Match : public test::FrontEndOnBus<RcssServerMjBridge> {
 public:
  explicit Match(RcssServerMjOptions o, const char* scene = "rcssservermj_fifa.yaml")
      : FrontEndOnBus("mj", test::LoadScene(scene), [&o](dds::Bus& bus) {
          o.listen = "127.0.0.1";
          o.agent_port = 0;
          o.monitor_port = 0;
          return std::make_unique<RcssServerMjBridge>(o, bus);
        }) {}
  AgentClient Connect() {
    AgentClient c;
    EXPECT_TRUE(c.Connect(bridge().agent_port()));
    return c;
  }
};

RcssServerMjOptions Fast(bool sequential = false) {
  RcssServerMjOptions o;
  o.realtime = false;  // implies sync
  o.sequential = sequential;
  return o;
}

// A Python float repr truncated to at most `decimals` decimals.
const std::string kN2 = R"((-?\d+\.\d{1,2}))";
const std::string kN3 = R"((-?\d+\.\d{1,3}))";

struct Perception {
  double now = NAN;
  std::string game;
  std::array<double, 4> quat{};
  std::array<double, 3> pos{}, gyro{}, acc{};
  std::vector<std::pair<std::string, double>> hj;  // name, ax (deg)
  std::optional<std::string> see;
};

// Parses one perception with the facts' grammar and order, whole; nullopt (and a test failure) if it differs.
std::optional<Perception> Parse(const std::string& text) {
  const std::regex head("^\\(time \\(now " + kN2 + "\\)\\)\\(GS \\(t " + kN2 + "\\)\\(pm ([A-Za-z_]+)\\)([^G]*?)\\)" +
                        "\\(quat \\(n torso_quat\\) \\(q " + kN3 + " " + kN3 + " " + kN3 + " " + kN3 + "\\)\\)" +
                        "\\(pos \\(n torso_pos\\) \\(p " + kN3 + " " + kN3 + " " + kN3 + "\\)\\)" +
                        "\\(GYR \\(n torso_gyro\\) \\(rt " + kN2 + " " + kN2 + " " + kN2 + "\\)\\)" +
                        "\\(ACC \\(n torso_acc\\) \\(a " + kN2 + " " + kN2 + " " + kN2 + "\\)\\)");
  std::smatch m;
  if (!std::regex_search(text, m, head)) {
    ADD_FAILURE() << "not the facts' grammar: " << text.substr(0, 400);
    return std::nullopt;
  }
  Perception p;
  p.now = std::stod(m[1]);
  p.game = m[3].str() + m[4].str();
  for (int i = 0; i < 4; ++i) p.quat[i] = std::stod(m[5 + i]);
  for (int i = 0; i < 3; ++i) p.pos[i] = std::stod(m[9 + i]);
  for (int i = 0; i < 3; ++i) p.gyro[i] = std::stod(m[12 + i]);
  for (int i = 0; i < 3; ++i) p.acc[i] = std::stod(m[15 + i]);
  std::string rest = m.suffix();
  const std::regex hj("^\\(HJ \\(n (q_[a-z]+\\d)\\)\\(ax " + kN2 + "\\)\\(vx " + kN2 + "\\)\\)");
  while (std::regex_search(rest, m, hj)) {
    p.hj.emplace_back(m[1], std::stod(m[2]));
    rest = m.suffix();
  }
  if (!rest.empty()) {
    const std::regex see("^\\(See (.*)\\)$");
    if (!std::regex_match(rest, m, see)) {
      ADD_FAILURE() << "after HJ, only See: " << rest.substr(0, 300);
      return std::nullopt;
    }
    p.see = m[1];
  }
  return p;
}

double Joint(const Perception& p, const std::string& name) {
  for (const auto& [n, ax] : p.hj)
    if (n == name) return ax;
  return NAN;
}

// Whether the front-end closes the agent's connection within 20 s (what it sends before is read and dropped).
bool Closed(AgentClient* agent) {
  const auto deadline = std::chrono::steady_clock::now() + 20s;
  while (std::chrono::steady_clock::now() < deadline) {
    agent->Receive(50ms);
    if (!agent->ReadSome()) return true;
  }
  return false;
}

// One round: the agent's message, then its next perception.
std::optional<Perception> Round(AgentClient* agent, const std::string& message) {
  if (!agent->Send(message)) return std::nullopt;
  const std::optional<std::string> text = agent->Receive(20s);
  if (!text) return std::nullopt;
  return Parse(*text);
}

TEST(RcssServerMjFrontEnd, AT1AgentInitsBeamsMovesAJointAndSeesEveryOtherCycle) {
  Match match(Fast(/*sequential=*/true));
  AgentClient agent = match.Connect();
  ASSERT_TRUE(agent.Send("(init T1 teamBlue 2)"));
  const std::optional<std::string> first_text = agent.Receive(60s);  // the scene loads first
  ASSERT_TRUE(first_text.has_value());
  const std::optional<Perception> first = Parse(*first_text);
  ASSERT_TRUE(first);
  EXPECT_EQ(first->game, "BeforeKickOff(tl teamBlue)(sl 0)(sr 0)");
  // Placed at x = -(2n+1), y = half width + border, yaw -90 deg (q = (cos -45, 0, 0, sin -45)).
  EXPECT_NEAR(first->pos[0], -5.0, 0.01);
  EXPECT_NEAR(first->pos[1], 37.0, 0.01);
  EXPECT_NEAR(first->quat[0], 0.707, 0.01);
  EXPECT_NEAR(first->quat[3], -0.707, 0.01);
  // Every joint, in the T1 table's HJ order.
  const rcssservermj::MjRobotModel& t1 = *rcssservermj::FindModel("T1");
  ASSERT_EQ(first->hj.size(), t1.joints.size());
  for (size_t i = 0; i < t1.joints.size(); ++i) EXPECT_EQ(first->hj[i].first, t1.joints[i].perceptor);

  // Beam (left team: x -> -|x|), then sync rounds: exactly 0.02 s per round.
  std::optional<Perception> p = Round(&agent, "(beam 3 1 0)");
  ASSERT_TRUE(p);
  EXPECT_NEAR(p->now - first->now, 0.02, 1e-9);
  EXPECT_NEAR(p->pos[0], -3.0, 0.05);
  EXPECT_NEAR(p->pos[1], 1.0, 0.05);
  EXPECT_NEAR(std::abs(p->quat[0]), 1.0, 0.01);  // facing +x

  // The head's yaw to 30 deg with kp 10 N m/rad: it arrives in HJ (degrees).
  int sees = 0, rounds = 0;
  bool last_saw = p->see.has_value();
  for (int i = 0; i < 50; ++i) {
    const double before = p->now;
    p = Round(&agent, i == 0 ? "(he1 30 0 10 0.2 0)" : "(syn)");
    ASSERT_TRUE(p);
    EXPECT_NEAR(p->now - before, 0.02, 1e-9);
    EXPECT_NE(p->see.has_value(), last_saw) << "See every second cycle";
    last_saw = p->see.has_value();
    sees += p->see.has_value();
    ++rounds;
  }
  EXPECT_EQ(sees, rounds / 2);
  EXPECT_NEAR(Joint(*p, "q_hj1"), 30.0, 3.0);
  // With kp = kd = 1 elsewhere the robot has sunk to the ground within that second: the accelerometer reads about
  // gravity (m/s^2), the gyro deg/s.
  EXPECT_NEAR(std::hypot(p->acc[0], p->acc[1], p->acc[2]), 9.81, 3.0);
  EXPECT_LT(p->pos[2], 0.6);
}

// The Booster SDK example's standing pose and gains (configs/scenes/t1_stand.yaml), sent as motor commands every
// cycle after a beam: the T1 stands on the PD motors for 5 s of simulated time.
TEST(RcssServerMjFrontEnd, AT1HoldingTheStandingPoseStaysUpright) {
  Match match(Fast(/*sequential=*/true));
  AgentClient agent = match.Connect();
  ASSERT_TRUE(agent.Send("(init T1 a 1)"));
  ASSERT_TRUE(agent.Receive(60s));
  const std::string stand =
      "(he1 0 0 5 0.1 0)(he2 0 0 5 0.1 0)(lae1 0 0 40 0.5 0)(lae2 -80.21 0 50 1.5 0)(lae3 0 0 20 0.2 0)"
      "(lae4 -22.92 0 10 0.2 0)(rae1 0 0 40 0.5 0)(rae2 80.21 0 50 1.5 0)(rae3 0 0 20 0.2 0)(rae4 22.92 0 10 0.2 0)"
      "(te1 0 0 100 5 0)(lle1 -11.46 0 350 7.5 0)(lle2 0 0 350 7.5 0)(lle3 0 0 180 3 0)(lle4 22.92 0 350 5.5 0)"
      "(lle5 -11.46 0 550 1.5 0)(lle6 0 0 550 1.5 0)(rle1 -11.46 0 350 7.5 0)(rle2 0 0 350 7.5 0)"
      "(rle3 0 0 180 3 0)(rle4 22.92 0 350 5.5 0)(rle5 -11.46 0 550 1.5 0)(rle6 0 0 550 1.5 0)";
  std::optional<Perception> p = Round(&agent, stand + "(beam 5 0 0)");
  ASSERT_TRUE(p);
  double lowest = 10;
  for (int i = 0; i < 250; ++i) {  // 5 s
    p = Round(&agent, stand);
    ASSERT_TRUE(p);
    lowest = std::min(lowest, p->pos[2]);
  }
  EXPECT_GT(lowest, 0.55) << "the torso sank: it fell";
  EXPECT_NEAR(p->pos[0], -5.0, 0.3);
  EXPECT_NEAR(p->pos[1], 0.0, 0.3);
  EXPECT_GT(p->quat[0] * p->quat[0] + p->quat[3] * p->quat[3], 0.95) << "tilted";  // |tilt| about x, y small
  EXPECT_NEAR(Joint(*p, "q_llj4"), 22.92, 3.0);                                    // the knee at its target (degrees)
}

TEST(RcssServerMjFrontEnd, SeeHasTheFactsGrammar) {
  Match match(Fast(true));
  AgentClient agent = match.Connect();
  ASSERT_TRUE(agent.Send("(init T1 a 1)"));
  ASSERT_TRUE(agent.Receive(60s));
  std::optional<Perception> p = Round(&agent, "(beam 1 0 0)");  // facing the right goal from x = -1 (left: -|x|)
  ASSERT_TRUE(p);
  if (!p->see) p = Round(&agent, "(syn)");
  ASSERT_TRUE(p && p->see);
  // Polar: distance, azimuth, elevation, 2 decimals; the ball and the right goal's posts ahead.
  const std::regex item("^\\(([A-Za-z_]+) \\(pol " + kN2 + " " + kN2 + " " + kN2 + "\\)\\)");
  std::string rest = *p->see;
  std::smatch m;
  std::vector<std::string> names;
  while (std::regex_search(rest, m, item)) {
    names.push_back(m[1]);
    EXPECT_LE(std::abs(std::stod(m[3])), 60.0);
    EXPECT_LE(std::abs(std::stod(m[4])), 60.0);
    // The ball at the centre: 0.9 m ahead of the camera and 1 m below it (camera 1.1 m high).
    if (m[1] == "B") EXPECT_NEAR(std::stod(m[2]), 1.33, 0.15);
    rest = m.suffix();
  }
  EXPECT_NE(std::find(names.begin(), names.end(), "B"), names.end()) << *p->see;
  EXPECT_NE(std::find(names.begin(), names.end(), "g_rup"), names.end()) << *p->see;
  EXPECT_EQ(std::find(names.begin(), names.end(), "g_lup"), names.end()) << *p->see;
}

TEST(RcssServerMjFrontEnd, SyncModeAdvancesOneCyclePerRoundOfActions) {
  const auto started = std::chrono::steady_clock::now();
  Match match(Fast(false));
  AgentClient a = match.Connect(), b = match.Connect();
  ASSERT_TRUE(a.Send("(init T1 blue 1)"));
  std::optional<std::string> first_a = a.Receive(60s);
  ASSERT_TRUE(first_a);
  // b joins; a answers every cycle until b is active (red in a's GS): b's first perception is of that cycle.
  ASSERT_TRUE(b.Send("(init T1 red 1)"));
  for (int i = 0; i < 100 && first_a->find("(tr red)") == std::string::npos; ++i) {
    ASSERT_TRUE(a.Send("(syn)"));
    first_a = a.Receive(20s);
    ASSERT_TRUE(first_a);
  }
  std::optional<std::string> first_b = b.Receive(20s);
  ASSERT_TRUE(first_b);
  const std::optional<Perception> pa = Parse(*first_a), pb = Parse(*first_b);
  ASSERT_TRUE(pa && pb);
  EXPECT_EQ(pa->now, pb->now);
  double now = pa->now;
  for (int round = 1; round <= 5; ++round) {
    ASSERT_TRUE(a.Send("(syn)"));
    // One agent answered: no cycle until the other does.
    EXPECT_FALSE(a.Receive(100ms).has_value());
    ASSERT_TRUE(b.Send("(syn)"));
    const std::optional<std::string> ma = a.Receive(20s), mb = b.Receive(20s);
    ASSERT_TRUE(ma && mb);
    const std::optional<Perception> qa = Parse(*ma), qb = Parse(*mb);
    ASSERT_TRUE(qa && qb);
    EXPECT_NEAR(qa->now - now, 0.02, 1e-9) << "round " << round;  // exactly one cycle
    EXPECT_EQ(qa->now, qb->now);
    now = qa->now;
  }
  // Where the cycles' wall time went (the status line's split), once the cycle after the last round is counted. In
  // each round the server waited at least the 100 ms the second answer was held back, less what was left of the
  // cycle that was stepping meanwhile (the parallel loop sends a perception while the next cycle steps).
  const CycleSplit split =
      match.bridge()
          .WaitForStats([&](const RcssServerMjStats& s) { return s.sim_time >= now + 0.02 - 1e-6; }, 20s)
          .split;
  EXPECT_GE(split.waiting, 5 * 100ms - split.world - split.front_end);
  EXPECT_GT(split.waiting, 0s);
  EXPECT_GT(split.world, 0s);
  EXPECT_GT(split.front_end, 0s);
  EXPECT_LT(split.world + split.front_end + split.waiting, std::chrono::steady_clock::now() - started);
}

// Each agent answers every perception it gets, in whatever order they come (like separate agent processes): an
// init that reaches the server after a cycle has started is activated a cycle later, and a sync-mode cycle waits
// for every active agent's answer.
TEST(RcssServerMjFrontEnd, TwentyTwoAgentsAtOnceAllGetPerceptions) {
  Match match(Fast(false));
  std::vector<AgentClient> agents;
  for (int i = 0; i < 22; ++i) agents.push_back(match.Connect());
  for (int i = 0; i < 22; ++i)
    ASSERT_TRUE(
        agents[i].Send("(init T1 " + std::string(i < 11 ? "left" : "right") + " " + std::to_string(i % 11 + 1) + ")"));
  std::vector<int> perceptions(22, 0);
  std::vector<pollfd> fds(22);
  for (int i = 0; i < 22; ++i) fds[i] = {agents[i].fd(), POLLIN, 0};
  const auto deadline = std::chrono::steady_clock::now() + 120s;
  while (*std::min_element(perceptions.begin(), perceptions.end()) < 3 && std::chrono::steady_clock::now() < deadline) {
    if (poll(fds.data(), fds.size(), 1000) <= 0) continue;
    for (int i = 0; i < 22; ++i) {
      if (!(fds[i].revents & POLLIN)) continue;
      ASSERT_TRUE(agents[i].ReadSome()) << "agent " << i << " closed";
      while (const std::optional<std::string> m = agents[i].Next()) {
        ++perceptions[i];
        if (m->find("(tl left)(tr right)") == std::string::npos && m->find("(tl ") == std::string::npos)
          ADD_FAILURE() << *m;
        ASSERT_TRUE(agents[i].Send("(syn)"));
      }
    }
  }
  for (int i = 0; i < 22; ++i) EXPECT_GE(perceptions[i], 3) << "agent " << i;
  EXPECT_EQ(
      match.bridge().WaitForStats([](const RcssServerMjStats& s) { return s.active_agents == 22; }, 20s).active_agents,
      22);
}

// The monitor port: commands from an allowed address act (kick-off: the agents see the play mode), a client from
// elsewhere is refused and closed.
TEST(RcssServerMjFrontEnd, MonitorCommandsFromAllowedAddressesOnly) {
  RcssServerMjOptions o = Fast(false);
  o.monitor_allow = {"127.0.0.1"};
  Match match(o);
  AgentClient agent = match.Connect();
  ASSERT_TRUE(agent.Send("(init T1 a 1)"));
  ASSERT_TRUE(agent.Receive(60s));
  AgentClient stranger, monitor;
  ASSERT_TRUE(stranger.Connect(match.bridge().monitor_port(), "127.0.0.2"));
  ASSERT_TRUE(monitor.Connect(match.bridge().monitor_port(), "127.0.0.1"));
  ASSERT_TRUE(monitor.Send("(kickOff Right)"));
  const RcssServerMjStats stats = match.bridge().WaitForStats(
      [](const RcssServerMjStats& s) { return s.refused_by_kind.count("monitor_not_allowed") > 0; }, 20s);
  EXPECT_EQ(stats.refused_by_kind.count("monitor_not_allowed"), 1u);
  bool kicked_off = false;
  for (int i = 0; i < 10 && !kicked_off; ++i) {
    const std::optional<Perception> p = Round(&agent, "(syn)");
    ASSERT_TRUE(p);
    kicked_off = p->game.rfind("KickOff_Right", 0) == 0;
  }
  EXPECT_TRUE(kicked_off);
}

TEST(RcssServerMjFrontEnd, MalformedInputDropsOnlyThatClient) {
  Match match(RcssServerMjOptions{});  // real time: cycles run whoever answers
  AgentClient good = match.Connect(), other = match.Connect();
  ASSERT_TRUE(good.Send("(init T1 a 1)"));
  ASSERT_TRUE(other.Send("(init T1 b 1)"));
  ASSERT_TRUE(good.Receive(60s));
  ASSERT_TRUE(other.Receive(20s));
  AgentClient garbage = match.Connect(), oversized = match.Connect(), third = match.Connect();
  ASSERT_TRUE(garbage.Send("((( \x01"));
  ASSERT_TRUE(oversized.SendRaw(std::string("\x7f\xff\xff\xff", 4) + "(syn)"));
  ASSERT_TRUE(third.Send("(init T1 c 1)"));  // a third team: refused at activation
  ASSERT_TRUE(good.Send("(he1 nan 0 1 1 0)(xx9 0 0 1 1 0)"));
  EXPECT_TRUE(Closed(&garbage));
  EXPECT_TRUE(Closed(&oversized));
  EXPECT_TRUE(Closed(&third));
  const RcssServerMjStats stats = match.bridge().WaitForStats(
      [](const RcssServerMjStats& s) {
        // Every refusal is counted, not only seen by its client: a client may read its closed socket before the
        // front-end has counted why it closed it.
        return s.refused_by_kind.count("unknown_effector") > 0 && s.refused_by_kind.count("not_finite") > 0 &&
               s.refused_by_kind.count("frame_too_large") > 0 && s.refused_by_kind.count("init_refused") > 0 &&
               s.dropped_clients >= 3;
      },
      20s);
  EXPECT_EQ(stats.refused_by_kind.count("frame_too_large"), 1u);
  EXPECT_EQ(stats.refused_by_kind.count("init_refused"), 1u);
  EXPECT_EQ(stats.active_agents, 2);
  // The others play on.
  for (int i = 0; i < 3; ++i) {
    ASSERT_TRUE(good.Receive(20s)) << i;
    ASSERT_TRUE(other.Receive(20s)) << i;
  }
}

// The 1 v 1 scene (rcssservermj_fifa_1v1.yaml) parks two T1: one agent a side plays, a third agent is refused
// (no free robot) and the two play on.
TEST(RcssServerMjFrontEnd, TheOneVersusOneSceneTakesAnAgentASideAndRefusesAThird) {
  Match match(RcssServerMjOptions{}, "rcssservermj_fifa_1v1.yaml");  // real time: cycles run whoever answers
  AgentClient left = match.Connect(), right = match.Connect();
  ASSERT_TRUE(left.Send("(init T1 a 1)"));
  ASSERT_TRUE(right.Send("(init T1 b 1)"));
  ASSERT_TRUE(left.Receive(60s));
  ASSERT_TRUE(right.Receive(20s));
  AgentClient third = match.Connect();
  ASSERT_TRUE(third.Send("(init T1 a 2)"));
  EXPECT_TRUE(Closed(&third));
  const RcssServerMjStats stats = match.bridge().WaitForStats(
      [](const RcssServerMjStats& s) { return s.refused_by_kind.count("init_refused") > 0; }, 20s);
  const auto refused = stats.refused_by_kind.find("init_refused");
  EXPECT_EQ(refused == stats.refused_by_kind.end() ? 0u : refused->second, 1u);
  EXPECT_EQ(stats.active_agents, 2);
  for (int i = 0; i < 3; ++i) {
    ASSERT_TRUE(left.Receive(20s)) << i;
    ASSERT_TRUE(right.Receive(20s)) << i;
  }
}

// The K1 1 v 1 scene (rcssservermj_fifa_1v1_k1.yaml) parks two K1: an agent asking for a K1 gets one, with the
// K1's 22 joints in the reference's HJ order (no waist), an agent asking for a T1 is refused.
TEST(RcssServerMjFrontEnd, TheK1SceneServesK1AgentsTheirTwentyTwoJointsAndRefusesAT1) {
  Match match(RcssServerMjOptions{}, "rcssservermj_fifa_1v1_k1.yaml");  // real time: cycles run whoever answers
  AgentClient k1 = match.Connect();
  ASSERT_TRUE(k1.Send("(init K1 a 1)"));
  const std::optional<std::string> first = k1.Receive(60s);
  ASSERT_TRUE(first);
  const std::regex hj(R"(\(HJ \(n (q_[a-z0-9]+)\))");
  std::vector<std::string> joints;
  for (auto it = std::sregex_iterator(first->begin(), first->end(), hj); it != std::sregex_iterator(); ++it)
    joints.push_back((*it)[1]);
  const std::vector<std::string> expected = {
      "q_hj1",  "q_hj2",  "q_laj1", "q_laj2", "q_laj3", "q_laj4", "q_raj1", "q_raj2", "q_raj3", "q_raj4", "q_llj1",
      "q_llj2", "q_llj3", "q_llj4", "q_llj5", "q_llj6", "q_rlj1", "q_rlj2", "q_rlj3", "q_rlj4", "q_rlj5", "q_rlj6"};
  EXPECT_EQ(joints, expected) << *first;
  AgentClient t1 = match.Connect();
  ASSERT_TRUE(t1.Send("(init T1 b 1)"));
  EXPECT_TRUE(Closed(&t1));
  const RcssServerMjStats stats = match.bridge().WaitForStats(
      [](const RcssServerMjStats& s) { return s.refused_by_kind.count("init_refused") > 0; }, 20s);
  EXPECT_EQ(stats.active_agents, 1);
  for (int i = 0; i < 3; ++i) ASSERT_TRUE(k1.Receive(20s)) << i;
}

// The port flags turf-rcssservermj-bridge and turf-sim --rcssservermj share: 0..65535 (0: any free port), refused
// with the range rather than a conversion error.
TEST(RcssServerMjFlags, PortsAreCheckedAgainstTheirRange) {
  RcssServerMjOptions o;
  CLI::App app;
  AddRcssServerMjFlags(app, o, "rcssservermj-");
  ASSERT_TRUE(test::ParseArgs(app, {"--rcssservermj-agent-port", "0", "--rcssservermj-monitor-port", "60101"}));
  EXPECT_EQ(o.agent_port, 0);
  EXPECT_EQ(o.monitor_port, 60101);
  for (const char* bad : {"65536", "-1", "x"}) {
    RcssServerMjOptions unchanged;
    CLI::App strict;
    AddRcssServerMjFlags(strict, unchanged);
    EXPECT_FALSE(test::ParseArgs(strict, {"--agent-port", bad})) << bad;
    EXPECT_EQ(unchanged.agent_port, 60000) << bad;
  }
  CLI::App message;
  AddRcssServerMjFlags(message, o);
  try {
    message.parse(std::vector<std::string>{"70000", "--monitor-port"});
    ADD_FAILURE() << "--monitor-port 70000 was accepted";
  } catch (const CLI::ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("not in range"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace turf
