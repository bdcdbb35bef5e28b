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
// machine; --startup bounds it). Each agent acts on its own perceptions, in
// whatever order they come, like separate agent processes.
#include <poll.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include "tests/simspark/agent_client.h"

namespace {

using Clock = std::chrono::steady_clock;
constexpr int kTypes[11] = {0, 0, 0, 0, 0, 0, 0, 1, 1, 2, 3};  // <= 7 of a type, <= 9 of two, >= 3 types
constexpr const char* kEffectors[22] = {"he1",  "he2",  "rae1", "rae2", "rae3", "rae4", "lae1", "lae2",
                                        "lae3", "lae4", "rle1", "rle2", "rle3", "rle4", "rle5", "rle6",
                                        "lle1", "lle2", "lle3", "lle4", "lle5", "lle6"};

double NowIn(const std::string& m) {
  const size_t at = m.find("(now ");
  return at == std::string::npos ? -1.0 : std::stod(m.substr(at + 5));
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"turf-bench-simspark: scripted agents against turf-simspark-bridge"};
  int port = 3100;
  int agents = 22;
  double seconds = 20.0;
  bool header = false;
  std::string label = "";
  std::string motion = "all";
  double startup_s = 60.0;
  app.add_option("--port", port, "the bridge's agent port")->capture_default_str();
  app.add_option("--agents", agents, "agents (two teams, up to 22)")->capture_default_str()->check(CLI::Range(1, 22));
  app.add_option("--seconds", seconds, "simulated seconds to measure")->capture_default_str();
  app.add_option("--label", label, "first column of the table row");
  app.add_flag("--header", header, "print the table header");
  app.add_option("--motion", motion,
                 "all: every joint sways (the robots fall and lie); upper: head and arms sway, legs hold (they stand)")
      ->capture_default_str()
      ->check(CLI::IsMember({"all", "upper"}));
  app.add_option("--startup", startup_s,
                 "seconds to wait for the bridge's port and every agent's first perception (turf-sim loading its "
                 "scene, the bridge attaching: up to its 30 s attach timeout)")
      ->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  const auto startup_deadline =
      Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(startup_s));
  std::vector<turf::test::AgentClient> clients(agents);
  // The bridge process may not listen yet: try again until it does.
  while (!clients[0].Connect(static_cast<uint16_t>(port))) {
    if (Clock::now() >= startup_deadline) {
      std::fprintf(stderr, "agent 0 cannot connect to port %d within %.0f s\n", port, startup_s);
      return 1;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  for (int i = 1; i < agents; ++i) {
    if (!clients[i].Connect(static_cast<uint16_t>(port))) {
      std::fprintf(stderr, "agent %d cannot connect to port %d\n", i, port);
      return 1;
    }
  }
  for (int i = 0; i < agents; ++i)
    clients[i].Send("(scene rsg/agent/nao/nao_hetero.rsg " + std::to_string(kTypes[i % 11]) + ")");
  std::vector<pollfd> fds(agents);
  for (int i = 0; i < agents; ++i) fds[i] = {clients[i].fd(), POLLIN, 0};
  std::vector<uint64_t> perceptions(agents, 0);
  double t_start = -1.0;
  double t_now = 0.0;
  Clock::time_point wall_start;
  uint64_t bytes = 0;
  const auto give_up = Clock::now() + std::chrono::seconds(static_cast<int>(seconds * 20 + 60));
  int started = 0;  // agents with a first perception
  while (Clock::now() < give_up) {
    if (started < agents && Clock::now() >= startup_deadline) {
      for (int i = 0; i < agents; ++i)
        if (perceptions[i] == 0) std::fprintf(stderr, "agent %d got no perception within %.0f s\n", i, startup_s);
      return 1;
    }
    if (poll(fds.data(), fds.size(), 1000) <= 0) continue;
    for (int i = 0; i < agents; ++i) {
      if (!(fds[i].revents & POLLIN)) continue;
      if (!clients[i].ReadSome()) {
        std::fprintf(stderr, "agent %d: the bridge closed the connection\n", i);
        return 1;
      }
      while (auto m = clients[i].Next()) {
        bytes += m->size();
        const double t = NowIn(*m);
        ++perceptions[i];
        std::string answer;
        if (perceptions[i] == 1) {
          ++started;
          const std::string team = i % 2 == 0 ? "BenchA" : "BenchB";
          answer = "(init (unum " + std::to_string(i / 2 + 1) + ")(teamname " + team + "))";
        }
        if (perceptions[i] == 3)
          answer = "(beam " + std::to_string(-2.0 - i / 2) + " " + std::to_string(i % 5 - 2) + " 0)";
        for (int j = 0; j < 22; ++j) {
          char buf[32];
          const double amplitude = motion == "all" || j < 10 ? 0.3 : 0.0;  // joints 10..21 are the legs
          std::snprintf(buf, sizeof(buf), "(%s %.2f)", kEffectors[j], amplitude * std::sin(t * 2.0 + j));
          answer += buf;
        }
        clients[i].Send(answer + "(syn)");
        if (i == 0 && t >= 0) {
          t_now = t;
          if (t_start < 0 && perceptions[0] >= 10) {
            t_start = t;
            wall_start = Clock::now();
          }
        }
      }
    }
    if (t_start >= 0 && t_now - t_start >= seconds) break;
  }
  const double wall = std::chrono::duration<double>(Clock::now() - wall_start).count();
  const double sim = t_now - t_start;
  if (sim < seconds) {
    std::fprintf(stderr, "measured only %.2f s of simulation\n", sim);
    return 1;
  }
  uint64_t total = 0;
  for (uint64_t p : perceptions) total += p;
  if (header) std::printf("%-28s %8s %8s %8s %10s %12s\n", "run", "agents", "sim s", "wall s", "RTF", "KB/agent/s");
  std::printf("%-28s %8d %8.2f %8.2f %9.2fx %12.1f\n", label.c_str(), agents, sim, wall, sim / wall,
              bytes / 1024.0 / agents / wall);
  return total > 0 ? 0 : 1;
}
