// turf-bench-rcssservermj: N scripted RCSSServerMJ agents against turf-sim --rcssservermj (started by bench/run.sh).
// All agents connect at once, init T1 players of two teams, beam, then answer every perception with a PD command
// for all 23 joints: the zero pose with the head and arms swaying (--motion upper: legs held stiff, kp 200) or every
// joint swaying (all). Prints simulated seconds per wall second over the measured stretch (sync mode: as fast as
// the agents answer). The loop is bench/agent_bench.h.
#include <cmath>
#include <cstdio>
#include <string>

#include "bench/agent_bench.h"

namespace {

// The T1's effectors in HJ order (codecs/rcssservermj/robots.cpp); the first 11 are head, arms and waist.
constexpr const char* kEffectors[23] = {"he1",  "he2",  "lae1", "lae2", "lae3", "lae4", "rae1", "rae2",
                                        "rae3", "rae4", "te1",  "lle1", "lle2", "lle3", "lle4", "lle5",
                                        "lle6", "rle1", "rle2", "rle3", "rle4", "rle5", "rle6"};

std::string Motors(double t, bool all) {
  std::string answer;
  for (int j = 0; j < 23; ++j) {
    const bool leg = j >= 11;
    const double amplitude = leg && !all ? 0.0 : 10.0;  // degrees
    char buf[64];
    std::snprintf(buf, sizeof(buf), "(%s %.2f 0 %d 2 0)", kEffectors[j], amplitude * std::sin(t * 2.0 + j),
                  leg ? 200 : 20);
    answer += buf;
  }
  return answer;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"turf-bench-rcssservermj: scripted RCSSServerMJ agents against turf-sim --rcssservermj"};
  turf::bench::AgentBenchOptions o;
  o.port = 60000;
  turf::bench::AddAgentBenchOptions(app, &o, "upper: head and arms sway, legs held; all: every joint sways");
  CLI11_PARSE(app, argc, argv);
  turf::bench::AgentScript script;
  script.hello = [](int i) {
    return "(init T1 " + std::string(i % 2 == 0 ? "BenchA" : "BenchB") + " " + std::to_string(i / 2 + 1) + ")";
  };
  script.answer = [&](int i, uint64_t n, double t) {
    std::string answer = Motors(t, o.motion == "all");
    if (n == 2) answer += "(beam " + std::to_string(2.0 + i / 2) + " " + std::to_string(i % 5 - 2) + " 0)";
    return answer;
  };
  return turf::bench::RunAgentBench(o, script);
}
