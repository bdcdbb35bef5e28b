// turf-bench-simspark: N scripted SimSpark agents against turf-simspark-bridge
// (started by bench/run.sh with turf-sim). All agents connect at once, build
// mixed robot types (the team composition rules), join two teams, beam, then
// answer every perception with all 22 hinge velocities (a slow sway) and
// (syn) (--motion upper: legs hold, the robots stand). Prints simulated
// seconds per wall second over the measured stretch.
//
// Started together with the bridge and turf-sim: the agents connect as soon
// as the bridge listens and wait for their first perception until turf-sim
// has loaded its scene and the bridge has attached to it (seconds on a busy
// machine; --startup bounds it). The loop is bench/agent_bench.h.
#include <cmath>
#include <cstdio>
#include <string>

#include "bench/agent_bench.h"

namespace {

constexpr int kTypes[11] = {0, 0, 0, 0, 0, 0, 0, 1, 1, 2, 3};  // <= 7 of a type, <= 9 of two, >= 3 types
constexpr const char* kEffectors[22] = {"he1",  "he2",  "rae1", "rae2", "rae3", "rae4", "lae1", "lae2",
                                        "lae3", "lae4", "rle1", "rle2", "rle3", "rle4", "rle5", "rle6",
                                        "lle1", "lle2", "lle3", "lle4", "lle5", "lle6"};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"turf-bench-simspark: scripted agents against turf-simspark-bridge"};
  turf::bench::AgentBenchOptions o;
  o.port = 3100;
  o.motion = "all";
  turf::bench::AddAgentBenchOptions(
      app, &o, "all: every joint sways (the robots fall and lie); upper: head and arms sway, legs hold (they stand)");
  CLI11_PARSE(app, argc, argv);
  turf::bench::AgentScript script;
  script.hello = [](int i) { return "(scene rsg/agent/nao/nao_hetero.rsg " + std::to_string(kTypes[i % 11]) + ")"; };
  script.answer = [&](int i, uint64_t n, double t) {
    std::string answer;
    if (n == 1)
      answer = "(init (unum " + std::to_string(i / 2 + 1) + ")(teamname " + (i % 2 == 0 ? "BenchA" : "BenchB") + "))";
    if (n == 3) answer = "(beam " + std::to_string(-2.0 - i / 2) + " " + std::to_string(i % 5 - 2) + " 0)";
    for (int j = 0; j < 22; ++j) {
      char buf[32];
      const double amplitude = o.motion == "all" || j < 10 ? 0.3 : 0.0;  // joints 10..21 are the legs
      std::snprintf(buf, sizeof(buf), "(%s %.2f)", kEffectors[j], amplitude * std::sin(t * 2.0 + j));
      answer += buf;
    }
    return answer + "(syn)";
  };
  return turf::bench::RunAgentBench(o, script);
}
