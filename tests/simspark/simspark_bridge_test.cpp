// turf-simspark-bridge in process with turf-sim's legged node (the 22-Nao
// match scene) over DDS, and scripted agents over real TCP: the agent
// lifecycle, units (HJ in degrees after a known velocity), vision facing the
// ball and away, sync mode's one cycle per (syn) round, 22 agents at once,
// bad input, and the trainer port.
#include <gtest/gtest.h>
#include <poll.h>
#include <sys/socket.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <future>
#include <memory>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <spdlog/sinks/ostream_sink.h>
#include <spdlog/spdlog.h>

#include "dds/memory_bus.h"
#include "loader/legged_scene_yaml.h"
#include "participants/sim/sim_node.h"
#include "participants/simspark_bridge/simspark_bridge.h"
#include "tests/simspark/agent_client.h"
#include "tests/test_domain.h"

namespace turf {
namespace {

using namespace std::chrono_literals;
using test::AgentClient;

// turf-sim (legged node) and the bridge, each on its own thread.
class Match {
 public:
  // start_sim false: the bridge waits for turf-sim until StartSim().
  explicit Match(bool sync, size_t max_unsent = 1 << 20, bool start_sim = true,
                 std::vector<std::string> operator_allow = kDefaultOperatorAllow)
      : sync_(sync) {
    static int counter = 0;
    const std::string prefix = "simspark" + std::to_string(getpid()) + "_" + std::to_string(++counter);
    const std::string qos = TURF_SOURCE_DIR "/configs/qos/turf_qos.xml";
    sim_options_.domain = test::TestDomain(11);
    sim_options_.prefix = prefix;
    sim_options_.qos_file = qos;
    sim_options_.mode = TimeMode::kLockstep;
    if (start_sim) StartSim();
    SimSparkBridgeOptions o;
    o.domain = sim_options_.domain;
    o.prefix = prefix;
    o.qos_file = qos;
    o.listen = "127.0.0.1";
    o.agent_port = 0;
    o.monitor_port = 0;
    o.sync_mode = sync;
    o.max_unsent = max_unsent;
    o.operator_allow = std::move(operator_allow);
    bridge_ = std::make_unique<SimSparkBridge>(o);
    bridge_thread_ = std::thread([this] {
      bridge_->Run([this] { return stop_.load(); });
      ended_.set_value();
    });
  }
  ~Match() {
    stop_ = true;
    bridge_thread_.join();
    StopSim();
  }
  void StartSim() {
    LeggedSceneLoadResult scene = LoadLeggedSceneFile(TURF_SOURCE_DIR "/configs/scenes/simspark_match.yaml");
    if (!scene.scene) throw std::runtime_error(scene.errors.front());
    stop_sim_ = false;
    sim_ = std::make_unique<SimNode>(std::move(*scene.scene), sim_options_);
    sim_thread_ = std::thread([this] { sim_->Run([this] { return stop_sim_.load() || stop_.load(); }); });
  }
  void StopSim() {
    stop_sim_ = true;
    if (sim_thread_.joinable()) sim_thread_.join();
    sim_.reset();
  }
  SimSparkBridge& bridge() { return *bridge_; }
  // Whether the bridge's Run returned by itself (a trainer's killsim) within `timeout`.
  bool Ended(std::chrono::milliseconds timeout) { return ended_future_.wait_for(timeout) == std::future_status::ready; }

  // A connected agent with a robot (scene sent, first perception read).
  AgentClient Agent(int type = 0) {
    AgentClient a;
    EXPECT_TRUE(a.Connect(bridge_->agent_port()));
    a.Send("(scene rsg/agent/nao/nao_hetero.rsg " + std::to_string(type) + ")");
    EXPECT_TRUE(a.Receive(10s).has_value()) << "no first perception";
    // Sync mode: the 5 grace cycles after scene run without (syn) (SessionOptions).
    for (int i = 1; sync_ && i < 5; ++i) EXPECT_TRUE(a.Receive(10s).has_value()) << "grace cycle " << i;
    return a;
  }

 private:
  bool sync_;
  SimNodeOptions sim_options_;
  std::atomic<bool> stop_{false};
  std::atomic<bool> stop_sim_{false};
  std::unique_ptr<SimNode> sim_;
  std::unique_ptr<SimSparkBridge> bridge_;
  std::thread sim_thread_;
  std::thread bridge_thread_;
  std::promise<void> ended_;
  std::future<void> ended_future_ = ended_.get_future();
};

double Number(const std::string& message, const std::string& pattern) {
  std::smatch m;
  if (!std::regex_search(message, m, std::regex(pattern))) return NAN;
  return std::stod(m[1]);
}
double Time(const std::string& m) { return Number(m, R"(\(time \(now ([-0-9.]+)\)\))"); }
double Joint(const std::string& m, const std::string& j) {
  return Number(m, R"(\(HJ \(n )" + j + R"(\) \(ax ([-0-9.]+)\)\))");
}

// Sync mode: answers with `effectors` and (syn), returns the next perception.
std::string Cycle(AgentClient& a, const std::string& effectors = "") {
  a.Send(effectors + "(syn)");
  auto m = a.Receive(10s);
  EXPECT_TRUE(m.has_value());
  return m.value_or("");
}

// The next perception that has a See.
std::string NextSee(AgentClient& a) {
  for (int i = 0; i < 3; ++i) {
    const std::string m = Cycle(a);
    if (m.find("(See") != std::string::npos) return m;
  }
  ADD_FAILURE() << "no See in 3 cycles";
  return "";
}

TEST(SimSparkBridgeTest, AgentInitsBeamsAndReadsJointAnglesInDegrees) {
  Match match(/*sync=*/true);
  AgentClient a = match.Agent();
  std::string m = Cycle(a, "(init (unum 0)(teamname Alpha))");
  EXPECT_NE(m.find("(GS (unum 1) (team left)"), std::string::npos) << m;
  m = Cycle(a);
  EXPECT_EQ(m.find("(unum"), std::string::npos);  // only in the first GS after init
  EXPECT_NE(m.find("(pm BeforeKickOff)"), std::string::npos);
  for (int i = 0; i < 50; ++i) m = Cycle(a);  // 1 s: settle at the start spot
  // Standing: proper acceleration about +g up, both feet on the ground.
  EXPECT_NEAR(Number(m, R"(\(ACC \(n torso\) \(a [-0-9.]+ [-0-9.]+ ([-0-9.]+)\)\))"), 9.81, 1.0) << m;
  EXPECT_NE(m.find("(FRP (n lf)"), std::string::npos);
  EXPECT_NE(m.find("(FRP (n rf)"), std::string::npos);
  EXPECT_EQ(std::count(m.begin(), m.end(), 'H') >= 22, true);
  const double hj1_start = Joint(m, "hj1");
  const double t0 = Time(m);
  // (he1 1.0) for 25 cycles turns hj1 by 0.5 rad = 28.65 deg (the reference, verified).
  m = Cycle(a, "(he1 1.0)");
  for (int i = 1; i < 25; ++i) {
    const double t = Time(m);
    m = Cycle(a);
    EXPECT_NEAR(Time(m) - t, 0.02, 1e-6);  // one cycle per (syn) round
  }
  for (int i = 0; i < 10; ++i) m = Cycle(a, "(he1 0.0)");
  EXPECT_NEAR(Time(m) - t0, 0.02 * 35, 1e-6);
  const double turned = Joint(m, "hj1") - hj1_start;
  std::printf("hj1 after (he1 1.0) for 25 cycles: %.2f deg\n", turned);
  EXPECT_NEAR(turned, 28.65, 1.0);
}

// Determinism: the same scene, seed and agent stream in sync mode give the
// same perceptions, byte for byte (physics, beam noise and vision noise).
std::vector<std::string> ScriptedRun() {
  Match match(/*sync=*/true);
  AgentClient a = match.Agent(4);  // type 4: a robot with toes (the match scene parks two)
  std::vector<std::string> seen;
  seen.push_back(Cycle(a, "(init (unum 2)(teamname Alpha))"));
  seen.push_back(Cycle(a, "(beam -4.0 1.0 30.0)"));
  for (int i = 0; i < 60; ++i) {
    const double v = std::sin(i * 0.3);
    char effectors[160];
    std::snprintf(effectors, sizeof(effectors), "(he1 %.3f)(rle4 %.3f)(lae1 %.3f)(lle7 1.0)(say hi%d)", v, -v, 2 * v,
                  i % 10);
    seen.push_back(Cycle(a, effectors));
  }
  return seen;
}

TEST(SimSparkBridgeTest, SameAgentStreamGivesTheSamePerceptions) {
  const std::vector<std::string> first = ScriptedRun();
  const std::vector<std::string> second = ScriptedRun();
  ASSERT_EQ(first.size(), second.size());
  for (size_t i = 0; i < first.size(); ++i) ASSERT_EQ(first[i], second[i]) << "perception " << i;
  EXPECT_NE(first.back().find("(hear Alpha"), std::string::npos);
  EXPECT_NE(first.back().find("(HJ (n rlj4)"), std::string::npos);
  EXPECT_NE(Joint(first.back(), "hj1"), Joint(first[1], "hj1"));  // the commands did move joints
  // The toe: (lle7 1.0) for 1.2 s turns it up to near its 70 degree stop; the right one, uncommanded, stays within
  // a few degrees (its motor holds it at 10 N m while the foot rocks on the reference's soft contact: 3.2 deg).
  EXPECT_GT(Joint(first.back(), "llj7"), 60.0) << first.back();
  EXPECT_NEAR(Joint(first.back(), "rlj7"), 0.0, 5.0) << first.back();
}

TEST(SimSparkBridgeTest, SeesTheBallWhenFacingItAndNotWhenFacingAway) {
  Match match(/*sync=*/true);
  AgentClient a = match.Agent();
  Cycle(a, "(init (unum 3)(teamname Alpha))");
  // Beam in the team's frame: 2 m behind the ball on the centre, facing it (+x).
  Cycle(a, "(beam -2.0 0.0 0.0)");
  for (int i = 0; i < 10; ++i) Cycle(a);
  std::string see = NextSee(a);
  const double d = Number(see, R"(\(B \(pol ([-0-9.]+) )");
  const double h = Number(see, R"(\(B \(pol [-0-9.]+ ([-0-9.]+) )");
  std::printf("ball facing it: d %.2f m, h %.2f deg\n", d, h);
  EXPECT_NEAR(d, 2.05, 0.15) << see;  // head 0.6 m up, beam noise +-0.05 m
  EXPECT_LT(std::abs(h), 12.0);       // beam noise +-10 deg
  // The flags and goal posts of the right side are ahead too; the left ones are behind.
  EXPECT_NE(see.find("(G1R (pol"), std::string::npos);
  EXPECT_EQ(see.find("(G1L (pol"), std::string::npos);

  Cycle(a, "(beam -2.0 0.0 180.0)");
  for (int i = 0; i < 10; ++i) Cycle(a);
  see = NextSee(a);
  EXPECT_EQ(see.find("(B (pol"), std::string::npos) << see;
  EXPECT_NE(see.find("(G1L (pol"), std::string::npos);
}

TEST(SimSparkBridgeTest, SyncModeWaitsForEveryAgentsSyn) {
  Match match(/*sync=*/true);
  AgentClient a = match.Agent();
  AgentClient b;
  ASSERT_TRUE(b.Connect(match.bridge().agent_port()));
  b.Send("(scene rsg/agent/nao/nao_hetero.rsg 0)");
  // a's grace cycles may be over: the world waits for a's (syn) until b has a robot.
  bool b_has_robot = false;
  for (int i = 0; i < 50 && !b_has_robot; ++i) {
    a.Send("(syn)");
    ASSERT_TRUE(a.Receive(10s).has_value());
    b_has_robot = b.Receive(50ms).has_value();
  }
  ASSERT_TRUE(b_has_robot);
  // Past the grace cycles after scene, both answering: b first, so that a's
  // (syn) is the one that completes each cycle. The other way round, b's
  // (syn) could reach the bridge after a's had started a grace cycle, count
  // for the next cycle, and keep b one (syn) ahead for good (a soak run on a
  // loaded machine: a's lone (syn) below then stepped).
  std::string ma;
  for (int i = 0; i < 8; ++i) {
    b.Send("(syn)");
    a.Send("(syn)");
    ma = a.Receive(10s).value_or("");
    ASSERT_TRUE(b.Receive(10s).has_value());
  }
  // A (syn) sent during b's grace cycles may already count for the next
  // cycle: drain until both have read everything. Quiet for 2 s: on a loaded
  // machine a cycle's perception came more than 300 ms late (a soak run).
  for (auto m = a.Receive(2s); m; m = a.Receive(2s)) ma = *m;
  while (b.Receive(2s)) {
  }
  b.Send("(syn)");
  a.Send("(syn)");
  ma = a.Receive(10s).value_or("");
  ASSERT_TRUE(b.Receive(10s).has_value());
  const double t = Time(ma);
  a.Send("(syn)");
  EXPECT_FALSE(a.Receive(400ms).has_value()) << "stepped without b's (syn)";
  b.Send("(syn)");
  auto next_a = a.Receive(10s);
  auto next_b = b.Receive(10s);
  ASSERT_TRUE(next_a && next_b);
  EXPECT_NEAR(Time(*next_a) - t, 0.02, 1e-6);
  EXPECT_NEAR(Time(*next_b) - t, 0.02, 1e-6);
  EXPECT_FALSE(a.Receive(200ms).has_value());  // exactly one cycle
}

TEST(SimSparkBridgeTest, TwentyTwoAgentsConnectAtOnceAndAllPlay) {
  Match match(/*sync=*/false);  // real time
  constexpr int kTypes[11] = {0, 0, 0, 0, 0, 0, 0, 1, 1, 2, 3};
  std::vector<AgentClient> agents(22);
  for (AgentClient& a : agents) ASSERT_TRUE(a.Connect(match.bridge().agent_port()));
  for (int i = 0; i < 22; ++i)
    agents[i].Send("(scene rsg/agent/nao/nao_hetero.rsg " + std::to_string(kTypes[i / 2]) + ")");
  for (int i = 0; i < 22; ++i) {
    ASSERT_TRUE(agents[i].Receive(10s).has_value()) << "agent " << i;
    agents[i].Send(std::string("(init (unum ") + std::to_string(i / 2 + 1) + ")(teamname " +
                   (i % 2 ? "Beta" : "Alpha") + "))");
  }
  int inited = 0;
  for (int i = 0; i < 22; ++i) {
    const std::string side = i % 2 ? "right" : "left";
    const std::string want = "(GS (unum " + std::to_string(i / 2 + 1) + ") (team " + side + ")";
    for (int k = 0; k < 20; ++k) {
      auto m = agents[i].Receive(10s);
      ASSERT_TRUE(m.has_value()) << "agent " << i;
      if (m->find(want) != std::string::npos) {
        ++inited;
        break;
      }
    }
  }
  EXPECT_EQ(inited, 22);
  // Everyone sees teammates and opponents on vision cycles.
  bool saw_other_team = false;
  for (int k = 0; k < 6 && !saw_other_team; ++k) {
    auto m = agents[0].Receive(10s);
    ASSERT_TRUE(m.has_value());
    saw_other_team = m->find("(P (team Beta)") != std::string::npos;
  }
  EXPECT_TRUE(saw_other_team);
  EXPECT_EQ(match.bridge().Stats().agents, 22);
}

// Sync mode with a team's worth of agents at once, each acting on its own
// perceptions as separate processes would: (init) and (syn) after the first
// perception, (syn) after every other one.
class Teams {
 public:
  static constexpr int kAgents = 22;

  // Connects every agent and sends every (scene), before anyone reads.
  explicit Teams(uint16_t port) : agents_(kAgents), state_(kAgents) {
    constexpr int kTypes[11] = {0, 0, 0, 0, 0, 0, 0, 1, 1, 2, 3};  // the team composition rules
    for (AgentClient& a : agents_) EXPECT_TRUE(a.Connect(port));
    for (int i = 0; i < kAgents; ++i)
      agents_[i].Send("(scene rsg/agent/nao/nao_hetero.rsg " + std::to_string(kTypes[i / 2]) + ")");
  }

  // As the benchmark's agent did: reads each agent's first perception in
  // turn, before that agent has sent anything but (scene). false: agent
  // `*failed` got none by the deadline.
  bool FirstPerceptionsInTurn(std::chrono::steady_clock::time_point deadline, int* failed) {
    for (int i = 0; i < kAgents; ++i) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Now());
      auto m = agents_[i].Receive(std::max(left, 0ms));
      if (!m) {
        *failed = i;
        return false;
      }
      Answer(i, *m);
    }
    return true;
  }

  // Answers every agent's perceptions as they come until each has been told
  // its unum (init was applied) and had one more perception after it.
  // Returns the agents that did not get there by the deadline.
  std::vector<int> PlayUntilAllJoined(std::chrono::steady_clock::time_point deadline) {
    std::vector<pollfd> fds;
    for (const AgentClient& a : agents_) fds.push_back({a.fd(), POLLIN, 0});
    while (Now() < deadline && !Missing().empty()) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Now());
      if (poll(fds.data(), fds.size(), static_cast<int>(std::clamp<int64_t>(left.count(), 0, 1000))) <= 0) continue;
      for (int i = 0; i < kAgents; ++i) {
        if (fds[i].revents == 0) continue;
        if (!agents_[i].ReadSome()) fds[i].fd = -1;  // closed by the bridge: it stays missing
        while (auto m = agents_[i].Next()) Answer(i, *m);
      }
    }
    return Missing();
  }

  int perceptions(int agent) const { return state_[agent].perceptions; }

 private:
  struct State {
    int perceptions = 0;
    bool told_unum = false;
    int after_unum = 0;
  };
  static std::chrono::steady_clock::time_point Now() { return std::chrono::steady_clock::now(); }

  void Answer(int i, const std::string& perception) {
    State& s = state_[i];
    ++s.perceptions;
    if (s.told_unum) ++s.after_unum;
    const std::string unum = std::to_string(i / 2 + 1);
    if (perception.find("(GS (unum " + unum + ")") != std::string::npos) s.told_unum = true;
    if (s.perceptions == 1) {
      agents_[i].Send("(init (unum " + unum + ")(teamname " + (i % 2 ? "Beta" : "Alpha") + "))(syn)");
    } else {
      agents_[i].Send("(syn)");
    }
  }

  std::vector<int> Missing() const {
    std::vector<int> out;
    for (int i = 0; i < kAgents; ++i)
      if (state_[i].after_unum < 1) out.push_back(i);
    return out;
  }

  std::vector<AgentClient> agents_;
  std::vector<State> state_;
};

std::string Join(const std::vector<int>& v) {
  std::string out;
  for (int i : v) out += (out.empty() ? "" : " ") + std::to_string(i);
  return out;
}

// Issue 11: 22 agents connecting in the same instant in sync mode, again and
// again on one bridge; every one gets perceptions and plays, every round.
// Even rounds read each first perception in turn (the benchmark's agent);
// odd rounds answer whichever agent's perception comes first.
TEST(SimSparkBridgeTest, TwentyTwoAgentsConnectingAtOnceInSyncModeAllGetPerceptions) {
  Match match(/*sync=*/true);
  constexpr int kRounds = 50;
  int good_rounds = 0;
  for (int round = 0; round < kRounds; ++round) {
    {
      Teams teams(match.bridge().agent_port());
      const auto deadline = std::chrono::steady_clock::now() + 20s;
      int failed = -1;
      if (round % 2 == 0 && !teams.FirstPerceptionsInTurn(deadline, &failed)) {
        ADD_FAILURE() << "round " << round << ": agent " << failed << " got no perception";
        break;
      }
      const std::vector<int> missing = teams.PlayUntilAllJoined(deadline);
      if (!missing.empty()) {
        ADD_FAILURE() << "round " << round << ": agents " << Join(missing) << " did not join and play (agent "
                      << missing.front() << " had " << teams.perceptions(missing.front()) << " perceptions)";
        break;
      }
      ++good_rounds;
    }  // every agent disconnects
    // The bridge has let them all go (their robots are free for the next round).
    const uint64_t gone = static_cast<uint64_t>(Teams::kAgents) * (round + 1);
    const SimSparkBridgeStats stats =
        match.bridge().WaitForStats([&](const SimSparkBridgeStats& s) { return s.dropped_clients >= gone; }, 20s);
    ASSERT_GE(stats.dropped_clients, gone) << "round " << round;
    ASSERT_EQ(stats.agents, 0) << "round " << round;
  }
  EXPECT_EQ(good_rounds, kRounds);
  EXPECT_EQ(match.bridge().Stats().refused, 0u) << "no init refused, nothing malformed";
}

// The benchmark's agents connected while turf-sim was still loading its scene
// (seconds on a busy machine): the bridge holds them and serves them once
// turf-sim is there.
TEST(SimSparkBridgeTest, AgentsConnectingBeforeTurfSimIsThereAreServedOnceItIs) {
  Match match(/*sync=*/true, 1 << 20, /*start_sim=*/false);
  Teams teams(match.bridge().agent_port());
  match.StartSim();
  const std::vector<int> missing = teams.PlayUntilAllJoined(std::chrono::steady_clock::now() + 20s);
  EXPECT_TRUE(missing.empty()) << "agents " << Join(missing) << " did not join and play";
}

// Refusals of one kind so far.
uint64_t Refused(const SimSparkBridgeStats& stats, const std::string& kind) {
  auto it = stats.refused_by_kind.find(kind);
  return it == stats.refused_by_kind.end() ? 0 : it->second;
}

// The agent's next perception, within `timeout`, reads its joints (hj1's angle): it is served.
void ExpectServed(AgentClient& a, std::chrono::milliseconds timeout) {
  const std::optional<std::string> m = a.Receive(timeout);
  ASSERT_TRUE(m.has_value());
  EXPECT_NE(m->find("(HJ (n hj1)"), std::string::npos);
}

TEST(SimSparkBridgeTest, BadInputIsRefusedAndOthersCarryOn) {
  Match match(/*sync=*/false, /*max_unsent=*/16 * 1024);
  AgentClient good = match.Agent();
  AgentClient noisy = match.Agent();
  noisy.Send("(he1 nan)");
  noisy.Send("((((");
  noisy.Send("(fly 1.0)");
  noisy.Send("(he1 1.0");
  noisy.Send(std::string("(say \0x)", 8));
  AgentClient huge;
  ASSERT_TRUE(huge.Connect(match.bridge().agent_port()));
  huge.SendRaw(std::string("\xff\xff\xff\xff", 4) + "(scene rsg/agent/nao/nao.rsg)");
  AgentClient half;
  ASSERT_TRUE(half.Connect(match.bridge().agent_port()));
  half.SendRaw(std::string("\x00\x00\x00\x40(scene rsg/ag", 17));
  half.Close();  // disconnects mid-message
  // A client that stops reading: a small receive buffer, never read.
  AgentClient stalled;
  const int small = 4096;
  ASSERT_TRUE(stalled.Connect(match.bridge().agent_port()));
  setsockopt(stalled.fd(), SOL_SOCKET, SO_RCVBUF, &small, sizeof(small));
  stalled.Send("(scene rsg/agent/nao/nao_hetero.rsg 1)");

  // The huge prefix closes that connection.
  auto closed = huge.Receive(5s);
  EXPECT_FALSE(closed.has_value());
  EXPECT_FALSE(huge.ReadSome());
  // The others get perceptions all along, until the stalled client is dropped.
  const auto deadline = std::chrono::steady_clock::now() + 30s;
  while (match.bridge().Stats().dropped_clients < 3 && std::chrono::steady_clock::now() < deadline) {
    ASSERT_TRUE(good.Receive(5s).has_value());
    ASSERT_TRUE(noisy.Receive(5s).has_value());
  }
  const SimSparkBridgeStats stats = match.bridge().Stats();
  EXPECT_GE(stats.dropped_clients, 3u);  // huge prefix, mid-message disconnect, stopped reading
  EXPECT_GE(Refused(stats, "not_finite"), 1u);
  EXPECT_GE(Refused(stats, "parse"), 2u);  // "((((" and "(he1 1.0"
  EXPECT_GE(Refused(stats, "unknown_effector"), 1u);
  EXPECT_GE(Refused(stats, "frame_too_large"), 1u);
  ExpectServed(good, 5s);
}

// turf-sim stops and comes back: the bridge drops its agents (their world is
// gone, as with a restarted rcssserver3d) and serves new ones.
TEST(SimSparkBridgeTest, AgentsReconnectAfterTurfSimRestarts) {
  Match match(/*sync=*/false);
  AgentClient a = match.Agent();
  match.StopSim();
  const auto deadline = std::chrono::steady_clock::now() + 20s;
  bool closed = false;
  while (!closed && std::chrono::steady_clock::now() < deadline) {
    a.Receive(200ms);
    closed = !a.ReadSome();
  }
  EXPECT_TRUE(closed) << "the bridge kept an agent whose world is gone";
  match.StartSim();
  AgentClient b = match.Agent();
  ExpectServed(b, 10s);
}

TEST(SimSparkBridgeTest, TrainerSetsPlayModesAndMovesTheBall) {
  Match match(/*sync=*/true);
  AgentClient a = match.Agent();
  Cycle(a, "(init (unum 1)(teamname Alpha))");
  Cycle(a, "(beam -1.0 0.0 0.0)");
  AgentClient monitor;
  ASSERT_TRUE(monitor.Connect(match.bridge().monitor_port()));
  auto greeting = monitor.Receive(5s);
  ASSERT_TRUE(greeting.has_value());
  EXPECT_NE(greeting->find("(FieldLength 30)"), std::string::npos);
  monitor.Send("(kickOff Left)");
  std::string m = Cycle(a);
  for (int i = 0; i < 3 && m.find("(pm KickOff_Left)") == std::string::npos; ++i) m = Cycle(a);
  EXPECT_NE(m.find("(pm KickOff_Left)"), std::string::npos) << m;
  monitor.Send("(playMode PlayOn)");
  for (int i = 0; i < 3 && m.find("(pm PlayOn)") == std::string::npos; ++i) m = Cycle(a);
  EXPECT_NE(m.find("(pm PlayOn)"), std::string::npos);
  // The ball 5 m ahead of the agent, then seen there.
  monitor.Send("(ball (pos 4.0 0.0 0.042) (vel 0 0 0))");
  for (int i = 0; i < 5; ++i) Cycle(a);
  const std::string see = NextSee(a);
  EXPECT_NEAR(Number(see, R"(\(B \(pol ([-0-9.]+) )"), 5.03, 0.2) << see;
  // A monitor frame reports the play mode by index (PlayOn = 3).
  bool saw = false;
  for (int i = 0; i < 10 && !saw; ++i) {
    auto frame = monitor.Receive(2s);
    saw = frame && frame->find("(play_mode 3)") != std::string::npos;
    Cycle(a);
  }
  EXPECT_TRUE(saw);
}

// Real time: init, then the first GS that announces the agent's team within
// 25 perceptions ("" when none came: the init was refused).
std::string JoinTeam(AgentClient& a, const std::string& team) {
  a.Send("(init (unum 0)(teamname " + team + "))");
  for (int i = 0; i < 25; ++i) {
    const std::optional<std::string> m = a.Receive(5s);
    if (!m) break;
    if (m->find("(GS (unum") != std::string::npos) return *m;
  }
  return "";
}

// Two agents take both team names: `left` as Squat1 on the left, `right` as Squat2 on the right; whether both got
// their side.
bool SquatBothSides(AgentClient& left, AgentClient& right) {
  const std::string l = JoinTeam(left, "Squat1");
  const std::string r = JoinTeam(right, "Squat2");
  EXPECT_NE(l.find("(team left)"), std::string::npos) << l;
  EXPECT_NE(r.find("(team right)"), std::string::npos) << r;
  return l.find("(team left)") != std::string::npos && r.find("(team right)") != std::string::npos;
}

// Issue 20: a (killsim) from anyone who could reach the monitor port ended the
// match. Here the operators are 127.0.0.1 alone; a trainer from 127.0.0.2 (this
// machine too, but not in the list) stands for any other host.
TEST(SimSparkBridgeTest, OnlyAnOperatorsTrainerCanEndTheMatch) {
  Match match(/*sync=*/false, 1 << 20, true, {"127.0.0.1/32"});
  AgentClient a = match.Agent();
  AgentClient outsider;
  ASSERT_TRUE(outsider.Connect(match.bridge().monitor_port(), "127.0.0.2"));
  ASSERT_TRUE(outsider.Receive(5s).has_value());  // the greeting: monitors are served to anyone
  outsider.Send("(killsim)(kickOff Left)(time 250)");
  const SimSparkBridgeStats refused = match.bridge().WaitForStats(
      [](const SimSparkBridgeStats& s) { return Refused(s, "trainer.not_operator") >= 3; }, 10s);
  EXPECT_EQ(Refused(refused, "trainer.not_operator"), 3u);
  // The match goes on.
  const uint64_t cycles = refused.cycles;
  EXPECT_GT(
      match.bridge().WaitForStats([&](const SimSparkBridgeStats& s) { return s.cycles > cycles + 5; }, 10s).cycles,
      cycles + 5);
  EXPECT_FALSE(match.Ended(0ms));
  std::optional<std::string> m = a.Receive(5s);
  ASSERT_TRUE(m.has_value());
  EXPECT_NE(m->find("(pm BeforeKickOff)"), std::string::npos) << *m;
  // The operator's killsim ends it.
  AgentClient operator_;
  ASSERT_TRUE(operator_.Connect(match.bridge().monitor_port(), "127.0.0.1"));
  ASSERT_TRUE(operator_.Receive(5s).has_value());
  operator_.Send("(killsim)");
  EXPECT_TRUE(match.Ended(10s));
}

// Issue 20: two throwaway agents claimed both team names, and the real team was
// refused until the bridge restarted.
TEST(SimSparkBridgeTest, ATeamNameIsFreedWhenItsLastAgentLeaves) {
  Match match(/*sync=*/false);
  {
    AgentClient squat1 = match.Agent();
    AgentClient squat2 = match.Agent();
    EXPECT_TRUE(SquatBothSides(squat1, squat2));
  }  // both leave
  EXPECT_EQ(match.bridge().WaitForStats([](const SimSparkBridgeStats& s) { return s.agents == 0; }, 10s).agents, 0);
  AgentClient real = match.Agent();
  const std::string gs = JoinTeam(real, "Real");
  EXPECT_NE(gs.find("(GS (unum 1) (team left)"), std::string::npos) << gs;
}

// Squatters that stay connected: an operator frees their side with turf's
// (turfResetTeam Right); their connections are dropped and the real team takes the side.
TEST(SimSparkBridgeTest, AnOperatorFreesASideWhoseSquattersStayConnected) {
  Match match(/*sync=*/false);
  AgentClient squat1 = match.Agent();
  AgentClient squat2 = match.Agent();
  ASSERT_TRUE(SquatBothSides(squat1, squat2));
  AgentClient op;
  ASSERT_TRUE(op.Connect(match.bridge().monitor_port()));
  ASSERT_TRUE(op.Receive(5s).has_value());
  op.Send("(turfResetTeam Right)");
  // The squatter's connection ends (its perceptions stop, then the close).
  bool closed = false;
  const auto deadline = std::chrono::steady_clock::now() + 10s;
  while (!closed && std::chrono::steady_clock::now() < deadline) closed = !squat2.Receive(1s).has_value();
  EXPECT_TRUE(closed) << "the reset side's agent is still connected";
  AgentClient real = match.Agent();
  const std::string gs = JoinTeam(real, "Real");
  EXPECT_NE(gs.find("(GS (unum 1) (team right)"), std::string::npos) << gs;
  EXPECT_TRUE(squat1.Receive(5s).has_value());  // the other side plays on
}

// Logs of the default logger while it lives (info and above), for reading once the bridge has stopped.
class CapturedLog {
 public:
  CapturedLog() : previous_(spdlog::default_logger()) {
    auto sink = std::make_shared<spdlog::sinks::ostream_sink_mt>(text_);
    sink->set_pattern("%v");
    spdlog::set_default_logger(std::make_shared<spdlog::logger>("captured", sink));
    spdlog::set_level(spdlog::level::info);
  }
  ~CapturedLog() { spdlog::set_default_logger(previous_); }
  CapturedLog(const CapturedLog&) = delete;
  CapturedLog& operator=(const CapturedLog&) = delete;
  std::string Text() const { return text_.str(); }

 private:
  std::shared_ptr<spdlog::logger> previous_;
  std::ostringstream text_;
};

int CountLines(const std::string& text, const std::regex& pattern) {
  std::istringstream lines(text);
  int n = 0;
  for (std::string line; std::getline(lines, line);) n += std::regex_search(line, pattern);
  return n;
}

// Issue 20: every connect and disconnect was a log line, so a client looping
// connect/close filled the log. Now: at most one line a second per kind.
TEST(SimSparkBridgeTest, AConnectionFloodLogsAtMostALineASecondPerKind) {
  CapturedLog log;
  constexpr int kFlood = 50;  // below max_clients: none is refused
  double seconds = 0;
  {
    Match match(/*sync=*/false);
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < kFlood; ++i) {
      AgentClient c;
      ASSERT_TRUE(c.Connect(match.bridge().agent_port()));
    }
    const SimSparkBridgeStats stats = match.bridge().WaitForStats(
        [](const SimSparkBridgeStats& s) { return s.dropped_clients >= static_cast<uint64_t>(kFlood); }, 20s);
    ASSERT_EQ(stats.dropped_clients, static_cast<uint64_t>(kFlood));
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  const std::string text = log.Text();
  // Main's lines ("agent 3 connected from ...", "agent 3 (...) left: ...") and the rate-limited ones
  // ("SimSpark client (agent_connected): agent 3 from ...", "... (agent_left): agent 3 (...): ...").
  const int connected = CountLines(text, std::regex(R"(agent \d+ (connected )?from)"));
  const int left = CountLines(text, std::regex(R"(agent \d+ \([^)]*\):? (left: )?)"));
  const int allowed = 1 + static_cast<int>(std::ceil(seconds));
  EXPECT_GE(connected, 1) << text;
  EXPECT_LE(connected, allowed) << text;
  EXPECT_GE(left, 1) << text;
  EXPECT_LE(left, allowed) << text;
}

}  // namespace
}  // namespace turf

namespace turf {
namespace {

// The bridge on a dds::MemoryBus shared with the legged node, as a front-end in turf-sim's process would run: no
// DDS domain. Sync mode: each (syn) round is one 20 ms cycle.
TEST(SimSparkBridgeOnMemoryBus, SyncCyclesAdvanceTheSharedNode) {
  dds::MemoryBus bus("simspark_memory");
  LeggedSceneLoadResult scene = LoadLeggedSceneFile(TURF_SOURCE_DIR "/configs/scenes/simspark_match.yaml");
  ASSERT_TRUE(scene.scene.has_value());
  SimNodeOptions sim_options;
  sim_options.mode = TimeMode::kLockstep;
  SimNode sim(std::move(*scene.scene), sim_options, bus);
  SimSparkBridgeOptions o;
  o.listen = "127.0.0.1";
  o.agent_port = 0;
  o.monitor_port = 0;
  o.sync_mode = true;
  SimSparkBridge bridge(o, bus);
  std::atomic<bool> stop{false};
  std::thread sim_thread([&] { sim.Run([&] { return stop.load(); }); });
  std::thread bridge_thread([&] { bridge.Run([&] { return stop.load(); }); });
  {
    AgentClient a;
    ASSERT_TRUE(a.Connect(bridge.agent_port()));
    a.Send("(scene rsg/agent/nao/nao_hetero.rsg 0)");
    std::optional<std::string> first = a.Receive(10s);
    ASSERT_TRUE(first.has_value());
    for (int i = 1; i < 5; ++i) ASSERT_TRUE(a.Receive(10s).has_value()) << "grace cycle " << i;
    const double t0 = Time(Cycle(a));
    const double t1 = Time(Cycle(a));
    const double t2 = Time(Cycle(a));
    EXPECT_NEAR(t1 - t0, 0.02, 1e-6);
    EXPECT_NEAR(t2 - t1, 0.02, 1e-6);
  }
  stop = true;
  bridge_thread.join();
  sim_thread.join();
}

}  // namespace
}  // namespace turf
