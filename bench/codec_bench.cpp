// What the agent protocols' text costs the front-ends (codecs/): parsing an agent's message and formatting a
// perception, per message, for the messages the agent benches send and receive (bench/rcssservermj_agents.cpp: a PD
// command for each of the T1's 23 joints; a T1's perception with the ball, 8 markers and 21 players seen). At 5x real
// time a 22-agent match parses and formats 22 of each every 4 ms. Prints a table; run on demand
// (bench/run.sh codecs).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <stdexcept>
#include <string>

#include "codecs/rcssservermj/actions.h"
#include "codecs/rcssservermj/perception.h"
#include "codecs/rcssservermj/robots.h"
#include "codecs/simspark/sexpr.h"

namespace {

using Clock = std::chrono::steady_clock;

// Wall time of one call of `f` in microseconds: the best mean of 5 rounds of `n` calls (a busy machine only ever
// slows a round down).
double MeanUs(int n, const std::function<void()>& f) {
  double best = INFINITY;
  for (int round = 0; round < 5; ++round) {
    const auto start = Clock::now();
    for (int i = 0; i < n; ++i) f();
    best = std::min(best, std::chrono::duration<double, std::micro>(Clock::now() - start).count() / n);
  }
  return best;
}

// The 22-agent bench's answer: head and arms swaying, legs held.
std::string AgentMessage(const turf::rcssservermj::MjRobotModel& t1) {
  std::string message;
  for (size_t j = 0; j < t1.joints.size(); ++j) {
    char buf[64];
    std::snprintf(buf, sizeof(buf), "(%s %.2f 0 %d 2 0)", t1.joints[j].effector, 10.0 * std::sin(0.3 + j),
                  j >= 11 ? 200 : 20);
    message += buf;
  }
  return message;
}

turf::rcssservermj::MjPerception Perception(const turf::rcssservermj::MjRobotModel& t1) {
  using turf::rcssservermj::SeenMarker;
  turf::rcssservermj::MjPerception p;
  p.time = 123.456;
  p.game = {61.2, "PlayOn", "BenchA", "BenchB", 1, 0};
  p.has_robot = true;
  p.quat = {0.98, 0.01, -0.02, 0.19};
  p.pos = {-3.25, 1.5, 0.68};
  p.gyro = {0.12, -0.4, 0.03};
  p.acc = {0.2, -0.1, 9.79};
  for (size_t j = 0; j < t1.joints.size(); ++j)
    p.joints.push_back({t1.joints[j].perceptor, 0.1 * static_cast<double>(j) - 1.0, 0.37 * std::cos(j)});
  turf::rcssservermj::SeeItems see;
  const char* markers[] = {"B", "F1L", "F2L", "F1R", "F2R", "G1L", "G2L", "G1R", "G2R"};
  double k = 0;
  for (const char* m : markers) see.markers.push_back({m, {12.34 + k, -41.7 + 9 * k, -3.21 + k}}), k += 1;
  for (int n = 1; n <= 21; ++n) {
    turf::rcssservermj::SeenPlayer player{n % 2 ? "BenchA" : "BenchB", n / 2 + 1, {}};
    for (const char* part : {"head", "lfoot", "rfoot"}) player.parts.push_back({part, {7.5 + n, 20.0 - n, -2.5}});
    see.players.push_back(player);
  }
  p.see = see;
  return p;
}

void Row(const char* what, size_t bytes, double us) { std::printf("| %-44s | %6zu | %8.2f |\n", what, bytes, us); }

}  // namespace

int main() {
  const turf::rcssservermj::MjRobotModel* t1 = turf::rcssservermj::FindModel("T1");
  if (t1 == nullptr) throw std::runtime_error("no T1 model");
  const std::string message = AgentMessage(*t1);
  const turf::rcssservermj::MjPerception perception = Perception(*t1);
  const std::string formatted = turf::rcssservermj::FormatPerception(perception);
  if (turf::rcssservermj::ParseActions(message, *t1).motors.size() != t1->joints.size())
    throw std::runtime_error("the agent message does not parse");

  size_t sink = 0;
  std::printf("| message | bytes | us each |\n| --- | --- | --- |\n");
  Row("RCSSServerMJ actions: S-expressions only", message.size(),
      MeanUs(4000, [&] { sink += turf::simspark::ParseSExprs(message).exprs.size(); }));
  Row("RCSSServerMJ actions: ParseActions (23 motors)", message.size(),
      MeanUs(4000, [&] { sink += turf::rcssservermj::ParseActions(message, *t1).motors.size(); }));
  Row("RCSSServerMJ perception: FormatPerception", formatted.size(),
      MeanUs(4000, [&] { sink += turf::rcssservermj::FormatPerception(perception).size(); }));
  Row("RCSSServerMJ perception: S-expressions only", formatted.size(),
      MeanUs(4000, [&] { sink += turf::simspark::ParseSExprs(formatted).exprs.size(); }));
  return sink == 0 ? 1 : 0;
}
