// turf-sim with a 3D-league front-end (SimSpark's or RCSSServerMJ's ports) in its own process, as a real process on
// free ports and a private domain, and an agent connecting to it: the set-up of the in-process tests.
#pragma once

#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
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
  // flag that makes it step as fast as the agents answer.
  FrontEndInSim(const std::string& front_end, const std::string& scene, const std::string& mode, int domain_offset)
      : agent_port(FreePort(SOCK_STREAM)),
        monitor_port(FreePort(SOCK_STREAM)),
        sim(front_end + "_in_sim",
            {Built("participants/sim/turf-sim"), "--scene", std::string(TURF_SOURCE_DIR) + "/configs/scenes/" + scene,
             "--lockstep", "--" + front_end, "--" + front_end + "-agent-port", std::to_string(agent_port),
             "--" + front_end + "-monitor-port", std::to_string(monitor_port), "--" + front_end + "-" + mode,
             "--domain", std::to_string(TestDomain(domain_offset)), "--prefix",
             front_end + "insim" + std::to_string(getpid())}) {}

  // Connects `agent` once turf-sim listens: loading 22 robots takes seconds on a loaded machine.
  bool Connect(AgentClient& agent) const {
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (!agent.Connect(static_cast<uint16_t>(agent_port)) && std::chrono::steady_clock::now() < end)
      std::this_thread::sleep_for(std::chrono::milliseconds(50));  // polling until it listens
    return agent.fd() >= 0;
  }

  int agent_port;
  int monitor_port;
  Process sim;
};

}  // namespace turf::test
