// Two simulators on one DDS domain and prefix (issue 20), with real processes: a second turf-sim refuses to start
// (exit 2, naming the first one's pid), and another writer of world_state that appears while turf-sim runs is
// reported by turf-sim and by a bridge, each line naming the writers, while turf-sim keeps running.
#include <gtest/gtest.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <turf/idl/ClockPubSubTypes.h>
#include <turf/idl/WorldStatePubSubTypes.h>
#include <unistd.h>

#include <chrono>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include "dds/participant.h"
#include "tests/support/bridge_args.h"
#include "tests/support/process.h"
#include "tests/test_domain.h"

namespace turf::test {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

constexpr auto kDeadline = 30s;

struct Domain {
  int domain;
  std::string prefix;
  std::vector<std::string> Args() const { return {"--domain", std::to_string(domain), "--prefix", prefix}; }
  dds::ParticipantOptions Participant(const std::string& name) const {
    return {domain, name, prefix, TURF_SOURCE_DIR "/configs/qos/turf_qos.xml"};
  }
};

std::vector<std::string> SimArgs(const Domain& d) {
  std::vector<std::string> args = {Built("participants/sim/turf-sim"), "--realism", "ideal"};
  for (const std::string& a : d.Args()) args.push_back(a);
  return args;
}

// Waits, through discovery from this test's own participant, until process `pid` writes world_state.
bool WaitForWorldStateOf(const dds::Participant& watcher, pid_t pid) {
  auto has = [pid](const std::vector<dds::RemoteWriter>& writers) {
    for (const dds::RemoteWriter& w : writers)
      if (w.participant.pid == pid) return true;
    return false;
  };
  return has(watcher.WaitForOtherWriters(dds::Topic::kWorldState, has, Clock::now() + kDeadline));
}

// A child's log has no notification: read it until it has `text` or the deadline passes.
bool WaitForLog(const Process& p, const std::string& text) {
  const auto end = Clock::now() + kDeadline;
  while (p.Log().find(text) == std::string::npos) {
    if (Clock::now() > end) return false;
    std::this_thread::sleep_for(50ms);  // polling a file, not waiting for an event
  }
  return true;
}

// The line of `log` that holds `text` ("" if none).
std::string LineWith(const std::string& log, const std::string& text) {
  const auto at = log.find(text);
  if (at == std::string::npos) return "";
  const auto begin = log.rfind('\n', at);
  const auto end = log.find('\n', at);
  return log.substr(begin == std::string::npos ? 0 : begin + 1, end - (begin == std::string::npos ? 0 : begin + 1));
}

TEST(TwoSims, TheSecondOnTheSameDomainAndPrefixExitsTwoNamingTheFirst) {
  const Domain d{TestDomain(83), "twosims" + std::to_string(getpid())};
  Process first(d.prefix + "_first", SimArgs(d));
  dds::Participant watcher(d.Participant("test-watcher"));
  ASSERT_TRUE(WaitForWorldStateOf(watcher, first.pid())) << first.Log();
  // Its start-up report names every topic it publishes, the run's own ones too.
  EXPECT_TRUE(WaitForLog(first, "publishing " + d.prefix + "/sim/run (latched") &&
              WaitForLog(first, d.prefix + "/sim/applied_inputs (every input applied"))
      << first.Log();

  Process second(d.prefix + "_second", SimArgs(d));
  const auto status = second.Wait(kDeadline);
  ASSERT_TRUE(status.has_value()) << "the second turf-sim kept running:\n" << second.Log();
  ASSERT_TRUE(WIFEXITED(*status)) << second.Log();
  EXPECT_EQ(WEXITSTATUS(*status), 2) << second.Log();
  const std::string line = LineWith(second.Log(), "refusing to start");
  EXPECT_NE(line.find("turf-sim (pid " + std::to_string(first.pid()) + " on host "), std::string::npos) << second.Log();
  EXPECT_NE(line.find(d.prefix + "/world_state"), std::string::npos) << line;
  EXPECT_EQ(second.Log().find("publishing"), std::string::npos) << "it started anyway:\n" << second.Log();

  EXPECT_TRUE(first.Running()) << first.Log();
  const int stopped = first.Stop();
  EXPECT_TRUE(WIFEXITED(stopped) && WEXITSTATUS(stopped) == 0) << first.Log();
}

TEST(TwoSims, AnotherWriterWhileRunningIsReportedByTurfSimAndABridge) {
  const Domain d{TestDomain(89), "twosimsrun" + std::to_string(getpid())};
  Process sim(d.prefix + "_sim", SimArgs(d));
  Process bridge(d.prefix + "_bridge", SimprotoControlOnly(FreePort(), d.Args()));
  {
    // Made after turf-sim's participant (seen through discovery first), so turf-sim does not give way to it.
    dds::Participant watcher(d.Participant("test-watcher"));
    ASSERT_TRUE(WaitForWorldStateOf(watcher, sim.pid())) << sim.Log();
  }
  dds::Participant intruder(d.Participant("intruder"));
  auto writer = intruder.MakeWriter(dds::Topic::kWorldState);

  const std::string test_pid = "(pid " + std::to_string(getpid()) + " on host ";
  ASSERT_TRUE(WaitForLog(sim, "another writer of " + d.prefix + "/world_state")) << sim.Log();
  EXPECT_NE(LineWith(sim.Log(), "another writer of").find("'intruder' " + test_pid), std::string::npos) << sim.Log();
  ASSERT_TRUE(WaitForLog(bridge, "2 writers of " + d.prefix + "/world_state")) << bridge.Log();
  const std::string line = LineWith(bridge.Log(), "2 writers of");
  EXPECT_NE(line.find("turf-sim (pid " + std::to_string(sim.pid()) + " on host "), std::string::npos) << line;
  EXPECT_NE(line.find("'intruder' " + test_pid), std::string::npos) << line;

  EXPECT_TRUE(sim.Running()) << sim.Log();
  EXPECT_TRUE(bridge.Running()) << bridge.Log();
  const int bridge_stopped = bridge.Stop();
  const int sim_stopped = sim.Stop();
  EXPECT_TRUE(WIFEXITED(sim_stopped) && WEXITSTATUS(sim_stopped) == 0) << sim.Log();
  EXPECT_TRUE(WIFEXITED(bridge_stopped) && WEXITSTATUS(bridge_stopped) == 0) << bridge.Log();
}

}  // namespace
}  // namespace turf::test
