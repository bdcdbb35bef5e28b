// turf-bench-rcssservermj: N scripted RCSSServerMJ agents against turf-sim --rcssservermj (started by bench/run.sh).
// All agents connect at once, init T1 players of two teams, beam, then answer every perception with a PD command
// for all 23 joints: the zero pose with the head and arms swaying (--motion upper: legs held stiff, kp 200) or every
// joint swaying (all). Prints simulated seconds per wall second over the measured stretch (sync mode: as fast as
// the agents answer). Each agent acts on its own perceptions, in whatever order they come.
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
// The T1's effectors in HJ order (codecs/rcssservermj/robots.cpp); the first 11 are head, arms and waist.
constexpr const char* kEffectors[23] = {"he1",  "he2",  "lae1", "lae2", "lae3", "lae4", "rae1", "rae2",
                                        "rae3", "rae4", "te1",  "lle1", "lle2", "lle3", "lle4", "lle5",
                                        "lle6", "rle1", "rle2", "rle3", "rle4", "rle5", "rle6"};

double NowIn(const std::string& m) {
  const size_t at = m.find("(now ");
  return at == std::string::npos ? -1.0 : std::stod(m.substr(at + 5));
}

std::string Answer(double t, bool all) {
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
  int port = 60000;
  int agents = 22;
  double seconds = 20.0;
  bool header = false;
  std::string label = "";
  std::string motion = "upper";
  double startup_s = 60.0;
  app.add_option("--port", port, "the front-end's agent port")->capture_default_str();
  app.add_option("--agents", agents, "agents (two teams, up to 22)")->capture_default_str()->check(CLI::Range(1, 22));
  app.add_option("--seconds", seconds, "simulated seconds to measure")->capture_default_str();
  app.add_option("--label", label, "first column of the table row");
  app.add_flag("--header", header, "print the table header");
  app.add_option("--motion", motion, "upper: head and arms sway, legs held; all: every joint sways")
      ->capture_default_str()
      ->check(CLI::IsMember({"all", "upper"}));
  app.add_option("--startup", startup_s, "seconds to wait for the port and every agent's first perception")
      ->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  const auto startup_deadline =
      Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(startup_s));
  std::vector<turf::test::AgentClient> clients(agents);
  while (!clients[0].Connect(static_cast<uint16_t>(port))) {  // turf-sim may not listen yet
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
    clients[i].Send("(init T1 " + std::string(i % 2 == 0 ? "BenchA" : "BenchB") + " " + std::to_string(i / 2 + 1) +
                    ")");
  std::vector<pollfd> fds(agents);
  for (int i = 0; i < agents; ++i) fds[i] = {clients[i].fd(), POLLIN, 0};
  std::vector<uint64_t> perceptions(agents, 0);
  double t_start = -1.0, t_now = 0.0;
  Clock::time_point wall_start;
  uint64_t bytes = 0;
  const auto give_up = Clock::now() + std::chrono::seconds(static_cast<int>(seconds * 20 + 60));
  int started = 0;
  while (Clock::now() < give_up) {
    if (started < agents && Clock::now() >= startup_deadline) {
      std::fprintf(stderr, "%d of %d agents got a perception within %.0f s\n", started, agents, startup_s);
      return 1;
    }
    if (poll(fds.data(), fds.size(), 1000) <= 0) continue;
    for (int i = 0; i < agents; ++i) {
      if (!(fds[i].revents & POLLIN)) continue;
      if (!clients[i].ReadSome()) {
        std::fprintf(stderr, "agent %d: the server closed the connection\n", i);
        return 1;
      }
      while (auto m = clients[i].Next()) {
        bytes += m->size();
        const double t = NowIn(*m);
        if (++perceptions[i] == 1) ++started;
        std::string answer = Answer(t, motion == "all");
        if (perceptions[i] == 2)
          answer += "(beam " + std::to_string(2.0 + i / 2) + " " + std::to_string(i % 5 - 2) + " 0)";
        clients[i].Send(answer);
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
  if (header) std::printf("%-28s %8s %8s %8s %10s %12s\n", "run", "agents", "sim s", "wall s", "RTF", "KB/agent/s");
  std::printf("%-28s %8d %8.2f %8.2f %9.2fx %12.1f\n", label.c_str(), agents, sim, wall, sim / wall,
              bytes / 1024.0 / agents / wall);
  return 0;
}
