// turf-sim with a 3D-league front-end (SimSpark's or RCSSServerMJ's ports) in its own process, as a real process on
// free ports and a private domain, and an agent connecting to it: the set-up and checks of the in-process tests.
#pragma once

#include <gtest/gtest.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <optional>
#include <regex>
#include <string>
#include <thread>
#include <vector>

#include "tests/simspark/agent_client.h"
#include "tests/support/process.h"
#include "tests/test_domain.h"

namespace turf::test {

// The simulation time in a perception's `(time (now T))`; NaN if it has none.
inline double PerceptionTime(const std::string& perception) {
  static const std::regex now(R"(\(time \(now ([-0-9.]+)\)\))");
  std::smatch m;
  return std::regex_search(perception, m, now) ? std::stod(m[1]) : NAN;
}

struct FrontEndInSim {
  // `front_end`: the flags' prefix (simspark, rcssservermj); `scene`: a file in configs/scenes; `mode`: the front-end
  // flag that makes it step as fast as the agents answer; `extra`: more of turf-sim's flags.
  FrontEndInSim(const std::string& front_end, const std::string& scene, const std::string& mode, int domain_offset,
                const std::vector<std::string>& extra = {})
      : agent_port(FreePort(SOCK_STREAM)),
        monitor_port(FreePort(SOCK_STREAM)),
        sim(front_end + "_in_sim", Args(front_end, scene, mode, domain_offset, extra)) {}

  std::vector<std::string> Args(const std::string& front_end, const std::string& scene, const std::string& mode,
                                int domain_offset, const std::vector<std::string>& extra) const {
    std::vector<std::string> a = {Built("participants/sim/turf-sim"),
                                  "--scene",
                                  std::string(TURF_SOURCE_DIR) + "/configs/scenes/" + scene,
                                  "--" + front_end,
                                  "--" + front_end + "-agent-port",
                                  std::to_string(agent_port),
                                  "--" + front_end + "-monitor-port",
                                  std::to_string(monitor_port),
                                  "--" + front_end + "-" + mode,
                                  "--domain",
                                  std::to_string(TestDomain(domain_offset)),
                                  "--prefix",
                                  front_end + "insim" + std::to_string(getpid())};
    a.insert(a.end(), extra.begin(), extra.end());
    return a;
  }

  // Connects the agent once turf-sim listens (loading 22 robots takes seconds on a loaded machine) and sends
  // `hello`; the first answer within `timeout`, or nullopt (a failure, with turf-sim's log).
  std::optional<std::string> Hello(const std::string& hello, std::chrono::milliseconds timeout) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (!agent.Connect(static_cast<uint16_t>(agent_port)) && std::chrono::steady_clock::now() < end)
      std::this_thread::sleep_for(std::chrono::milliseconds(50));  // polling until it listens
    EXPECT_TRUE(agent.Send(hello)) << "not connected\n" << sim.Log();
    std::optional<std::string> m = agent.Receive(timeout);
    if (!m) ADD_FAILURE() << "no answer to " << hello << "\n" << sim.Log();
    return m;
  }

  // Sends (syn) `rounds` times; the times of the perceptions that answered, each within `timeout` (a failure for
  // each that did not).
  std::vector<double> SynRounds(int rounds, std::chrono::milliseconds timeout) {
    std::vector<double> times;
    for (int i = 0; i < rounds; ++i) {
      EXPECT_TRUE(agent.Send("(syn)"));
      const std::optional<std::string> m = agent.Receive(timeout);
      if (!m) {
        ADD_FAILURE() << "no perception after (syn) " << i << "\n" << sim.Log();
        break;
      }
      times.push_back(PerceptionTime(*m));
    }
    return times;
  }

  // turf-sim's log announces `what` on the agent port ("agents: TCP 127.0.0.1:<port>"); the agent leaves and turf-sim,
  // sent SIGTERM, exits 0.
  void ExpectAnnouncedAndCleanStop(const std::string& what) {
    EXPECT_NE(sim.Log().find(what + ": TCP 127.0.0.1:" + std::to_string(agent_port)), std::string::npos) << sim.Log();
    agent.Close();
    const int status = sim.Stop();
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << sim.Log();
  }

  int agent_port;
  int monitor_port;
  Process sim;
  AgentClient agent;
};

// Each time 20 ms of simulation after the one before (one cycle per round).
inline void ExpectCyclesOf20ms(const std::vector<double>& times) {
  for (size_t i = 1; i < times.size(); ++i) EXPECT_NEAR(times[i] - times[i - 1], 0.02, 1e-6) << "round " << i;
}

}  // namespace turf::test
