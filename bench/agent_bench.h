// The 3D-league agent benchmarks' common part (turf-bench-simspark, turf-bench-rcssservermj): N scripted agents
// connect at once (trying again until the front-end listens), say hello, then answer every perception; each agent
// acts on its own perceptions, in whatever order they come, like separate agent processes. Prints simulated seconds
// per wall second over the measured stretch (from agent 0's 10th perception on) as one table row, with the CPU time
// per 20 ms cycle of the server (--server-pid: user + system of that process, from /proc) and of the agents (this
// process) over the same stretch: less sensitive to other load on the machine than the wall-clock rate.
#pragma once

#include <poll.h>
#include <sys/resource.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "tests/simspark/agent_client.h"

namespace turf::bench {

struct AgentBenchOptions {
  int port = 0;
  int agents = 22;
  double seconds = 20.0;
  bool header = false;
  std::string label;
  std::string motion = "upper";
  double startup_s = 60.0;
  int server_pid = 0;  // 0: the server's CPU time is not reported
};

inline void AddAgentBenchOptions(CLI::App& app, AgentBenchOptions* o, const std::string& motion_help) {
  app.add_option("--port", o->port, "the front-end's agent port")->capture_default_str();
  app.add_option("--agents", o->agents, "agents (two teams, up to 22)")
      ->capture_default_str()
      ->check(CLI::Range(1, 22));
  app.add_option("--seconds", o->seconds, "simulated seconds to measure")->capture_default_str();
  app.add_option("--label", o->label, "first column of the table row");
  app.add_flag("--header", o->header, "print the table header");
  app.add_option("--motion", o->motion, motion_help)->capture_default_str()->check(CLI::IsMember({"all", "upper"}));
  app.add_option("--startup", o->startup_s,
                 "seconds to wait for the port and every agent's first perception (turf-sim loading its scene, a "
                 "bridge attaching: up to its 30 s attach timeout)")
      ->capture_default_str();
  app.add_option("--server-pid", o->server_pid, "report this process's CPU time per cycle (the server's)");
}

// The simulation time of a perception ("(time (now 1.22))"), -1 without one.
inline double PerceptionTime(const std::string& m) {
  const size_t at = m.find("(now ");
  return at == std::string::npos ? -1.0 : std::stod(m.substr(at + 5));
}

struct AgentScript {
  std::function<std::string(int agent)> hello;                                  // sent on connecting ("" none)
  std::function<std::string(int agent, uint64_t perception, double t)> answer;  // to its n-th perception (1-based)
};

namespace detail {

using Clock = std::chrono::steady_clock;

// User + system CPU seconds of process `pid` (/proc/<pid>/stat), of this process for 0; -1 if unreadable.
inline double CpuSeconds(int pid) {
  if (pid == 0) {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return u.ru_utime.tv_sec + u.ru_stime.tv_sec + (u.ru_utime.tv_usec + u.ru_stime.tv_usec) * 1e-6;
  }
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string stat((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const size_t comm_end = stat.rfind(')');
  if (comm_end == std::string::npos) return -1.0;
  std::istringstream fields(stat.substr(comm_end + 2));  // from field 3 (state) on
  std::string field;
  double ticks = 0;
  for (int i = 3; i <= 15 && fields >> field; ++i)
    if (i >= 14) ticks += std::stod(field);  // utime, stime
  return ticks / static_cast<double>(sysconf(_SC_CLK_TCK));
}

inline bool ConnectAll(const AgentBenchOptions& o, Clock::time_point deadline,
                       std::vector<turf::test::AgentClient>* clients) {
  while (!(*clients)[0].Connect(static_cast<uint16_t>(o.port))) {  // the front-end may not listen yet
    if (Clock::now() >= deadline) {
      std::fprintf(stderr, "agent 0 cannot connect to port %d within %.0f s\n", o.port, o.startup_s);
      return false;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  for (int i = 1; i < o.agents; ++i) {
    if (!(*clients)[i].Connect(static_cast<uint16_t>(o.port))) {
      std::fprintf(stderr, "agent %d cannot connect to port %d\n", i, o.port);
      return false;
    }
  }
  return true;
}

}  // namespace detail

inline int RunAgentBench(const AgentBenchOptions& o, const AgentScript& script) {
  using detail::Clock;
  const auto startup_deadline =
      Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(o.startup_s));
  std::vector<turf::test::AgentClient> clients(o.agents);
  if (!detail::ConnectAll(o, startup_deadline, &clients)) return 1;
  for (int i = 0; i < o.agents; ++i) {
    const std::string hello = script.hello(i);
    if (!hello.empty()) clients[i].Send(hello);
  }
  std::vector<pollfd> fds(o.agents);
  for (int i = 0; i < o.agents; ++i) fds[i] = {clients[i].fd(), POLLIN, 0};
  std::vector<uint64_t> perceptions(o.agents, 0);
  double t_start = -1.0, t_now = 0.0;
  Clock::time_point wall_start;
  double server_cpu_start = 0, agents_cpu_start = 0;
  uint64_t bytes = 0;
  const auto give_up = Clock::now() + std::chrono::seconds(static_cast<int>(o.seconds * 20 + 60));
  int started = 0;  // agents with a first perception
  while (Clock::now() < give_up) {
    if (started < o.agents && Clock::now() >= startup_deadline) {
      for (int i = 0; i < o.agents; ++i)
        if (perceptions[i] == 0) std::fprintf(stderr, "agent %d got no perception within %.0f s\n", i, o.startup_s);
      return 1;
    }
    if (poll(fds.data(), fds.size(), 1000) <= 0) continue;
    for (int i = 0; i < o.agents; ++i) {
      if (!(fds[i].revents & POLLIN)) continue;
      if (!clients[i].ReadSome()) {
        std::fprintf(stderr, "agent %d: the front-end closed the connection\n", i);
        return 1;
      }
      while (auto m = clients[i].Next()) {
        bytes += m->size();
        const double t = PerceptionTime(*m);
        if (++perceptions[i] == 1) ++started;
        clients[i].Send(script.answer(i, perceptions[i], t));
        if (i != 0 || t < 0) continue;
        t_now = t;
        if (t_start < 0 && perceptions[0] >= 10) {
          t_start = t;
          wall_start = Clock::now();
          server_cpu_start = o.server_pid > 0 ? detail::CpuSeconds(o.server_pid) : -1.0;
          agents_cpu_start = detail::CpuSeconds(0);
        }
      }
    }
    if (t_start >= 0 && t_now - t_start >= o.seconds) break;
  }
  const double wall = std::chrono::duration<double>(Clock::now() - wall_start).count();
  const double server_cpu = o.server_pid > 0 ? detail::CpuSeconds(o.server_pid) - server_cpu_start : -1.0;
  const double agents_cpu = detail::CpuSeconds(0) - agents_cpu_start;
  const double sim = t_now - t_start;
  if (sim < o.seconds) {
    std::fprintf(stderr, "measured only %.2f s of simulation\n", sim);
    return 1;
  }
  const double cycles = sim / 0.02;  // both leagues' cycle
  char server_column[32] = "-";
  if (server_cpu >= 0) std::snprintf(server_column, sizeof(server_column), "%.2f", server_cpu * 1e3 / cycles);
  if (o.header)
    std::printf("%-28s %8s %8s %8s %10s %12s %14s %14s\n", "run", "agents", "sim s", "wall s", "RTF", "KB/agent/s",
                "server ms/cyc", "agents ms/cyc");
  std::printf("%-28s %8d %8.2f %8.2f %9.2fx %12.1f %14s %14.2f\n", o.label.c_str(), o.agents, sim, wall, sim / wall,
              bytes / 1024.0 / o.agents / wall, server_column, agents_cpu * 1e3 / cycles);
  return 0;
}

}  // namespace turf::bench
