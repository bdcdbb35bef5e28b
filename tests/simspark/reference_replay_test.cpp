// turf's Nao against rcssserver3d's, cycle by cycle (issue 12): a UT Austin Villa agent's recorded messages
// replayed open loop into turf-sim --simspark (sync mode, the match scene), and what turf perceives compared with
// what rcssserver3d perceived for the same messages (tests/data/simspark/*.replay, made with
// bench/ut_agents/replay.py and make_replay.py; the file's header says from which run).
//
// The replay is the same for both servers: the agent's `scene` message, then after each perception k the messages
// of the file's `M k` lines (turf's first grace perceptions read and not answered, see kShift), so that every
// message is taken at the same cycle on both, whatever the machine's speed. An open-loop replay of a walk drifts from
// any closed-loop run, so the checks are over the first seconds of walking, where a faithful Nao follows the
// reference: the leg joints' angles, the gyro, staying upright.
#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <map>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "tests/simspark/front_end_in_sim.h"

namespace turf::test {
namespace {

using namespace std::chrono_literals;

// What one perception says, as far as compared.
struct Perceived {
  double t = NAN;
  std::array<double, 3> gyr{};
  std::array<double, 3> acc{};
  std::map<std::string, double> hj;  // deg
  std::array<double, 2> feet{};      // FRP force z of lf, rf (N; 0: no FRP, the foot touches nothing)
};

struct ReplayFile {
  std::vector<std::string> joints;                   // the R lines' angle order
  std::map<int, std::vector<std::string>> messages;  // by the perception index they answer (-1: before the first)
  std::vector<Perceived> reference;                  // by perception index
  int walk_from = -1;                                // the first cycle of the walk (W line)
};

std::optional<ReplayFile> ReadReplay(const std::string& path) {
  std::ifstream in(path);
  if (!in) return std::nullopt;
  ReplayFile f;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream s(line);
    std::string tag;
    s >> tag;
    if (tag == "J") {
      for (std::string j; s >> j;) f.joints.push_back(j);
    } else if (tag == "W") {
      s >> f.walk_from;
    } else if (tag == "M") {
      int k = 0;
      s >> k;
      std::string message;
      std::getline(s >> std::ws, message);
      f.messages[k].push_back(message);
    } else if (tag == "R") {
      int k = 0;
      std::string pm;
      Perceived p;
      s >> k >> p.t >> pm;
      for (double& g : p.gyr) s >> g;
      for (double& a : p.acc) s >> a;
      for (const std::string& j : f.joints) s >> p.hj[j];
      for (double& fz : p.feet) s >> fz;
      if (!s || k != static_cast<int>(f.reference.size())) return std::nullopt;
      f.reference.push_back(p);
    }
  }
  if (f.joints.empty() || f.reference.empty() || f.walk_from < 0) return std::nullopt;
  return f;
}

std::array<double, 3> Triple(const std::string& text, const std::regex& re) {
  std::smatch m;
  if (!std::regex_search(text, m, re)) return {NAN, NAN, NAN};
  return {std::stod(m[1]), std::stod(m[2]), std::stod(m[3])};
}

Perceived Parse(const std::string& perception) {
  static const std::regex gyr(R"(\(GYR \(n torso\) \(rt ([-0-9.e]+) ([-0-9.e]+) ([-0-9.e]+)\)\))");
  static const std::regex acc(R"(\(ACC \(n torso\) \(a ([-0-9.e]+) ([-0-9.e]+) ([-0-9.e]+)\)\))");
  static const std::regex hj(R"(\(HJ \(n ([a-z0-9]+)\) \(ax ([-0-9.e]+)\)\))");
  static const std::regex frp(R"(\(FRP \(n (lf|rf)\) \(c [-0-9.e ]+\) \(f [-0-9.e]+ [-0-9.e]+ ([-0-9.e]+)\)\))");
  Perceived p;
  p.t = PerceptionTime(perception);
  p.gyr = Triple(perception, gyr);
  p.acc = Triple(perception, acc);
  for (auto it = std::sregex_iterator(perception.begin(), perception.end(), hj); it != std::sregex_iterator(); ++it)
    p.hj[(*it)[1]] = std::stod((*it)[2]);
  for (auto it = std::sregex_iterator(perception.begin(), perception.end(), frp); it != std::sregex_iterator(); ++it)
    p.feet[(*it)[1] == "lf" ? 0 : 1] = std::stod((*it)[2]);
  return p;
}

// What one agent sends: the file's messages, or a rewrite of them.
using Rewrite = std::function<std::string(const std::string&)>;

std::string Unchanged(const std::string& message) { return message; }

// Waits (with a deadline) until turf-sim's front-end serves (its start-up line), as replay.py does: an agent that
// connects while turf-sim still starts is served from a later cycle.
void AwaitFrontEnd(FrontEndInSim& turf) {
  const auto end = std::chrono::steady_clock::now() + 60s;
  while (turf.sim.Log().find("agents: TCP") == std::string::npos && std::chrono::steady_clock::now() < end)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));  // polling the log
}

// Plays the file's messages into turf as replay.py --grace 1 does, from `agent` (connected): the file's answer to
// perception k after perception k (turf-sim started with --simspark-sync-grace-cycles 0: it waits for the agent from
// its first perception, as rcssserver3d). turf's perceptions by index (fewer on a failure).
std::vector<Perceived> Replay(const ReplayFile& f, AgentClient& agent, const Rewrite& rewrite = Unchanged) {
  std::vector<Perceived> got;
  const auto scene = f.messages.find(-1);
  if (scene == f.messages.end() || scene->second.empty()) {
    ADD_FAILURE() << "the replay file has no message before the first perception";
    return got;
  }
  EXPECT_TRUE(agent.Send(rewrite(scene->second.front())));
  std::optional<std::string> m = agent.Receive(60s);
  for (int k = 0; m; ++k) {
    got.push_back(Parse(*m));
    if (got.size() == f.reference.size()) break;
    const auto answer = f.messages.find(k);
    if (answer != f.messages.end()) {
      for (const std::string& message : answer->second) EXPECT_TRUE(agent.Send(rewrite(message))) << "cycle " << k;
    }
    m = agent.Receive(60s);
    if (!m) ADD_FAILURE() << "no perception " << k + 1;
  }
  return got;
}

// Connects `agent` to turf's agent port once it listens (polling, with a deadline).
bool Connect(FrontEndInSim& turf, AgentClient& agent) {
  const auto end = std::chrono::steady_clock::now() + 60s;
  while (!agent.Connect(static_cast<uint16_t>(turf.agent_port))) {
    if (std::chrono::steady_clock::now() > end) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));  // polling until it listens
  }
  return true;
}

// One agent replaying the file into turf (the test's own connection).
std::vector<Perceived> Replay(const ReplayFile& f, FrontEndInSim& turf, const Rewrite& rewrite = Unchanged) {
  AwaitFrontEnd(turf);
  EXPECT_TRUE(Connect(turf, turf.agent)) << turf.sim.Log();
  std::vector<Perceived> got = Replay(f, turf.agent, rewrite);
  if (got.size() != f.reference.size()) ADD_FAILURE() << turf.sim.Log();
  return got;
}

// Leg joints' RMS difference (deg), gyro's (deg/s), accelerometer's (m/s^2, vectors) and the feet's forces (N, each
// foot's FRP z) over cycles [from, to).
struct Difference {
  double legs = 0.0;
  double gyro = 0.0;
  double acc = 0.0;
  double feet = 0.0;
};

Difference Compare(const std::vector<std::string>& joints_in, const std::vector<Perceived>& turf,
                   const std::vector<Perceived>& reference, size_t from, size_t to) {
  double legs = 0.0, gyro = 0.0, acc = 0.0, feet = 0.0;
  int joints = 0;
  for (size_t k = from; k < to; ++k) {
    for (const std::string& j : joints_in) {
      if (j.find("lj") == std::string::npos) continue;
      const double d = turf[k].hj.at(j) - reference[k].hj.at(j);
      legs += d * d;
      ++joints;
    }
    for (int i = 0; i < 3; ++i) {
      gyro += std::pow(turf[k].gyr[i] - reference[k].gyr[i], 2);
      acc += std::pow(turf[k].acc[i] - reference[k].acc[i], 2);
    }
    for (int i = 0; i < 2; ++i) feet += std::pow(turf[k].feet[i] - reference[k].feet[i], 2);
  }
  const double cycles = std::max<double>(1, to - from);
  return {std::sqrt(legs / std::max(joints, 1)), std::sqrt(gyro / cycles), std::sqrt(acc / cycles),
          std::sqrt(feet / (2 * cycles))};
}

Difference Compare(const ReplayFile& f, const std::vector<Perceived>& turf, size_t from, size_t to) {
  return Compare(f.joints, turf, f.reference, from, to);
}

// The first cycle from `from` in which the agent would think itself fallen (its low-pass of ACC z, 0.9 old +
// 0.1 new as UT's parser keeps it, under 5 m/s^2), or -1.
int FirstFallen(const std::vector<Perceived>& p, size_t from) {
  double low = 9.81;
  for (size_t k = 0; k < p.size(); ++k) {
    low = 0.9 * low + 0.1 * p[k].acc[2];
    if (k >= from && low < 5.0) return static_cast<int>(k);
  }
  return -1;
}

struct Case {
  const char* file;
  int walk_cycles;               // compared from the walk's first cycle on
  double standing_legs_rms_deg;  // tolerances: the second before the walk
  double legs_rms_deg;           // the walk
  double gyro_rms_dps;
  double acc_rms;   // m/s^2
  double feet_rms;  // N
};

class ReferenceReplay : public ::testing::TestWithParam<Case> {};

TEST_P(ReferenceReplay, TurfsNaoFollowsRcssserver3dsForTheSameCommands) {
  const Case c = GetParam();
  const std::optional<ReplayFile> f = ReadReplay(std::string(TURF_SOURCE_DIR) + "/tests/data/simspark/" + c.file);
  ASSERT_TRUE(f) << "cannot read " << c.file;
  const size_t from = static_cast<size_t>(f->walk_from);
  const size_t to = std::min(f->reference.size(), from + c.walk_cycles);
  ASSERT_LT(from, to);
  ASSERT_EQ(FirstFallen(f->reference, from), -1) << "the reference itself falls";

  FrontEndInSim turf("simspark", "simspark_match.yaml", "sync", 19, {"--simspark-sync-grace-cycles", "0"});
  const std::vector<Perceived> got = Replay(*f, turf);
  ASSERT_EQ(got.size(), f->reference.size());

  std::printf(
      "| cycles | t | legs RMS deg | gyro RMS deg/s | ACC RMS m/s^2 | feet RMS N |\n| --- | --- | --- | --- | --- | "
      "--- |\n");
  for (size_t w = from; w < to; w += 25) {
    const Difference d = Compare(*f, got, w, std::min(to, w + 25));
    std::printf("| %zu-%zu | %.2f | %.2f | %.1f | %.1f | %.1f |\n", w, std::min(to, w + 25) - 1, f->reference[w].t,
                d.legs, d.gyro, d.acc, d.feet);
  }
  const Difference standing = Compare(*f, got, from > 50 ? from - 50 : 0, from);
  const Difference walk = Compare(*f, got, from, to);
  std::printf(
      "standing: legs %.3f deg, gyro %.2f deg/s; walk: legs %.2f deg, gyro %.1f deg/s, ACC %.1f m/s^2, feet %.1f N\n",
      standing.legs, standing.gyro, walk.legs, walk.gyro, walk.acc, walk.feet);
  EXPECT_LE(standing.legs, c.standing_legs_rms_deg);
  EXPECT_EQ(FirstFallen(got, from), -1) << "turf's Nao falls where the reference's does not";
  EXPECT_LE(walk.legs, c.legs_rms_deg);
  EXPECT_LE(walk.gyro, c.gyro_rms_dps);
  EXPECT_LE(walk.acc, c.acc_rms);
  EXPECT_LE(walk.feet, c.feet_rms);
  turf.ExpectAnnouncedAndCleanStop("agents");
}

// The file's messages as agent `unum` (of the file's team) sends them, its beam `dy` m to the side of the file's.
std::string AsAgent(const std::string& message, int unum, double dy) {
  static const std::regex init(R"(\(init \(unum [0-9]+\))");
  static const std::regex beam(R"(\(beam ([-0-9.e]+) ([-0-9.e]+) )");
  std::string out = std::regex_replace(message, init, "(init (unum " + std::to_string(unum) + ")");
  std::smatch m;
  if (!std::regex_search(out, m, beam)) return out;
  std::ostringstream b;
  b << m.prefix() << "(beam " << m[1] << " " << std::stod(m[2]) + dy << " " << m.suffix();
  return b.str();
}

// rcssserver3d steps each robot as an island of its own (ODE): what one robot does cannot change how another moves.
// turf solves every robot's contacts and motors as one MuJoCo problem, so the solver has to converge however many
// robots move: with 20 iterations it stopped short in 37-48 % of a 4-agent match's steps, and UT Austin Villa's
// walking robots no longer turned where one alone did (issue 12). Here the same walk, replayed by four agents at
// once, has to move each robot as it moves alone.
TEST(ReferenceReplay, AWalkingRobotMovesAsItDoesAloneWhileThreeOthersWalk) {
  const std::optional<ReplayFile> f =
      ReadReplay(std::string(TURF_SOURCE_DIR) + "/tests/data/simspark/ut_walk_type0.replay");
  ASSERT_TRUE(f);
  const std::vector<std::string> grace = {"--simspark-sync-grace-cycles", "0"};
  constexpr std::array<double, 4> kSide = {0.0, -3.0, 3.0, -6.0};  // m: the beams' offsets
  std::vector<Perceived> alone;
  {
    FrontEndInSim turf("simspark", "simspark_match.yaml", "sync", 29, grace);
    alone = Replay(*f, turf, [&](const std::string& m) { return AsAgent(m, 1, kSide[0]); });
    turf.ExpectAnnouncedAndCleanStop("agents");
  }
  ASSERT_EQ(alone.size(), f->reference.size());

  FrontEndInSim turf("simspark", "simspark_match.yaml", "sync", 31, grace);
  AwaitFrontEnd(turf);
  std::array<AgentClient, 4> agents;
  for (AgentClient& a : agents) ASSERT_TRUE(Connect(turf, a)) << turf.sim.Log();
  std::array<std::vector<Perceived>, 4> together;
  std::vector<std::thread> threads;
  for (size_t i = 0; i < agents.size(); ++i)
    threads.emplace_back([&, i] {
      together[i] = Replay(*f, agents[i], [&](const std::string& m) { return AsAgent(m, i + 1, kSide[i]); });
    });
  for (std::thread& t : threads) t.join();

  const size_t from = static_cast<size_t>(f->walk_from);
  const size_t to = f->reference.size();
  for (size_t i = 0; i < agents.size(); ++i) {
    ASSERT_EQ(together[i].size(), alone.size()) << "agent " << i + 1 << "\n" << turf.sim.Log();
    const Difference d = Compare(f->joints, together[i], alone, from, to);
    std::printf("agent %zu against alone, the walk: legs %.3f deg, gyro %.2f deg/s, ACC %.2f m/s^2 RMS\n", i + 1,
                d.legs, d.gyro, d.acc);
    EXPECT_LE(d.legs, 0.1) << "agent " << i + 1;
    EXPECT_LE(d.gyro, 1.0) << "agent " << i + 1;
  }
}

// ut_walk: a field player's walk from its kick-off (no beams after cycle 4); its feet land as the reference's, a
// short hard contact each step (feet 33 N RMS from the reference's forces cycle by cycle at one 20 ms step with the
// whole ODE law; 47 N at three 6.67 ms steps with its friction alone, the scene before 2026-11-27, session 14).
// ut_hover: an agent's first 60 cycles, beaming every cycle with its stance commands (UT's 2.25 s "hover"), closed loop
// on the reference: its ACC reads gravity there (a free-fall 0 fails both the ACC bound and the fall check); the legs
// drift by the one frozen cycle in ten turf does not model.
INSTANTIATE_TEST_SUITE_P(UtAgents, ReferenceReplay,
                         ::testing::Values(Case{"ut_walk_type0.replay", 100, 0.05, 1.0, 45.0, 12.0, 40.0},
                                           Case{"ut_hover_type0.replay", 52, 0.05, 2.5, 3.0, 6.0, 5.0}),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           std::string name = info.param.file;
                           name = name.substr(0, name.find('.'));
                           std::string out;
                           for (char ch : name)
                             if (std::isalnum(static_cast<unsigned char>(ch))) out += ch;
                           return out;
                         });

}  // namespace
}  // namespace turf::test
