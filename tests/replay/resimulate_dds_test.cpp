// turf replay --resimulate with real processes on a private domain: turf-sim in real time with realistic sensors,
// turf-record, and this test commanding every blue robot over DDS at each world state it receives (as a team
// would, so where each command lands depends on the network and the scheduler). turf-replay --resimulate re-runs
// the file and finds every recorded output again (exit 0).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <turf/idl/SslRobotPubSubTypes.h>
#include <turf/idl/WorldStatePubSubTypes.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <string>
#include <thread>
#include <vector>

#include "dds/participant.h"
#include "tests/support/process.h"
#include "tests/support/wake_wait.h"
#include "tests/test_domain.h"

namespace turf::test {
namespace {

using namespace std::chrono_literals;

TEST(ResimulateDds, ARealTimeMatchCommandedOverDdsIsReproduced) {
  const int domain = TestDomain(46);
  const std::string prefix = "resimdds" + std::to_string(getpid());
  const std::string file = LogDir() + "/" + prefix + ".mcap";
  const std::vector<std::string> where = {"--domain", std::to_string(domain), "--prefix", prefix};
  auto with = [&](std::vector<std::string> args) {
    args.insert(args.end(), where.begin(), where.end());
    return args;
  };
  Process recorder(prefix + "_record", with({Built("participants/recorder/turf-record"), file}));
  // The recorder's readers exist before turf-sim starts, so the file holds the run from step 0 (polling the child's
  // log: no notification exists for it).
  const auto ready_by = std::chrono::steady_clock::now() + 30s;
  while (recorder.Log().find("reads " + prefix + "/robots/state") == std::string::npos &&
         std::chrono::steady_clock::now() < ready_by)
    std::this_thread::sleep_for(100ms);
  ASSERT_NE(recorder.Log().find("reads " + prefix + "/robots/state"), std::string::npos) << recorder.Log();
  dds::Participant team({domain, "resimulate-test", prefix, TURF_SOURCE_DIR "/configs/qos/turf_qos.xml"});
  WakeWait wake;
  auto world = team.MakeReader(dds::Topic::kWorldState, [&wake] { wake.Wake(); });
  auto blue = team.MakeWriter(dds::Topic::kSslCommandBlue);
  Process sim(prefix + "_sim", with({Built("participants/sim/turf-sim"), "--realism", "realistic", "--duration", "3"}));

  // Commands at every world state until turf-sim's 3 s are over.
  std::vector<idl::WorldState> states;
  int64_t last_ns = 0;
  int rounds = 0;
  const auto deadline = std::chrono::steady_clock::now() + 60s;
  while (last_ns < 2'990'000'000 && wake.Until(deadline, [&] { return world->Take(&states); })) {
    last_ns = states.back().sim_time_ns();
    for (int id = 0; id < 6; ++id) {
      idl::SslRobotCommand c;
      c.team(idl::TEAM_BLUE);
      c.id(static_cast<uint8_t>(id));
      c.move(idl::MOVE_LOCAL_VELOCITY);
      c.velocity().x(std::sin(1e-9 * static_cast<double>(last_ns) + id));
      c.velocity().z(0.8);
      blue->Write(c);
    }
    ++rounds;
  }
  EXPECT_GE(last_ns, 2'990'000'000) << sim.Log();
  EXPECT_GT(rounds, 20);
  const std::optional<int> sim_status = sim.Wait(30s);
  EXPECT_TRUE(sim_status && WIFEXITED(*sim_status) && WEXITSTATUS(*sim_status) == 0) << sim.Log();
  recorder.Signal(SIGINT);
  const std::optional<int> rec_status = recorder.Wait(20s);
  ASSERT_TRUE(rec_status && WIFEXITED(*rec_status) && WEXITSTATUS(*rec_status) == 0) << recorder.Log();

  Process resim(prefix + "_resim", {Built("participants/replay/turf-replay"), "--resimulate", file});
  const std::optional<int> status = resim.Wait(120s);
  ASSERT_TRUE(status && WIFEXITED(*status)) << resim.Log();
  EXPECT_EQ(WEXITSTATUS(*status), 0) << resim.Log();
  EXPECT_NE(resim.Log().find("] identical: "), std::string::npos) << resim.Log();
  EXPECT_EQ(resim.Log().find(" from 0 applied-inputs records"), std::string::npos) << resim.Log();
}

}  // namespace
}  // namespace turf::test
