// `turf launch simspark` with real processes: turf-sim with the 22-Nao scene
// and turf-simspark-bridge on ports of the test's own. An agent connects to
// the agent port, takes a robot and gets perceptions; Ctrl-C stops both
// cleanly.
#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <optional>
#include <regex>
#include <string>
#include <thread>

#include "tests/simspark/agent_client.h"
#include "tests/support/process.h"
#include "tests/test_domain.h"

namespace turf::test {
namespace {

using namespace std::chrono_literals;

// The pid `turf` logged for a process's start.
pid_t ChildPid(const Process& turf, const std::string& process) {
  const std::string log = turf.Log();
  std::smatch m;
  if (!std::regex_search(log, m, std::regex("started " + process + " \\(pid ([0-9]+)\\)"))) return -1;
  return std::stoi(m[1]);
}

bool Alive(pid_t pid) { return pid > 0 && kill(pid, 0) == 0; }

TEST(LaunchSimSpark, AnAgentGetsPerceptionsAndCtrlCStopsBoth) {
  const uint16_t agent_port = FreePort(SOCK_STREAM), monitor_port = FreePort(SOCK_STREAM);
  const std::string prefix = "ls" + std::to_string(getpid());
  Process turf(
      "launch_simspark",
      {Built("participants/launcher/turf"), "launch", "simspark", "--domain", std::to_string(TestDomain()), "--prefix",
       prefix, "--set", "simspark.listen=127.0.0.1", "--set", "simspark.agent-port=" + std::to_string(agent_port),
       "--set", "simspark.monitor-port=" + std::to_string(monitor_port), "--set",
       "viewer.port=" + std::to_string(FreePort(SOCK_STREAM))});
  const auto start = std::chrono::steady_clock::now();

  // The bridge opens its ports once turf-sim has loaded the scene (about 2 s;
  // much longer on a busy machine).
  AgentClient agent;
  bool connected = false;
  while (!connected && std::chrono::steady_clock::now() - start < 20s) {
    connected = agent.Connect(agent_port);
    if (!connected) {
      agent.Close();
      std::this_thread::sleep_for(50ms);
    }
  }
  ASSERT_TRUE(connected) << turf.Log();
  ASSERT_TRUE(agent.Send("(scene rsg/agent/nao/nao_hetero.rsg 0)"));
  std::optional<std::string> perception;
  const auto connected_at = std::chrono::steady_clock::now();
  while (std::chrono::steady_clock::now() - connected_at < 15s) {
    perception = agent.Receive(1000ms);
    if (perception && perception->find("(time (now") != std::string::npos) break;
  }
  ASSERT_TRUE(perception.has_value()) << turf.Log();
  EXPECT_NE(perception->find("(time (now"), std::string::npos) << *perception;
  std::printf(
      "first perception %lld ms after `turf launch simspark`\n",
      static_cast<long long>(
          std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now() - start).count()));

  const pid_t sim = ChildPid(turf, "sim"), bridge = ChildPid(turf, "simspark");
  ASSERT_TRUE(Alive(sim) && Alive(bridge)) << turf.Log();
  turf.Signal(SIGINT);
  const auto status = turf.Wait(8s);
  ASSERT_TRUE(status.has_value()) << turf.Log();
  EXPECT_TRUE(WIFEXITED(*status) && WEXITSTATUS(*status) == 0) << turf.Log();
  for (pid_t pid : {sim, bridge}) EXPECT_FALSE(Alive(pid)) << pid;
  const std::string log = turf.Log();
  EXPECT_NE(log.find("sim stopped (exit status 0)"), std::string::npos) << log;
  EXPECT_NE(log.find("simspark stopped (exit status 0)"), std::string::npos) << log;
  EXPECT_EQ(log.find("crashed"), std::string::npos) << log;
}

}  // namespace
}  // namespace turf::test
