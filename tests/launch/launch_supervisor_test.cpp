// `turf launch` supervising real processes: a crashed bridge is restarted and
// the match resumes; Ctrl-C stops everything cleanly; a process that keeps
// crashing is given up alone; a configuration error ends the launch at once; a clean exit ends the launch; and two
// launches on other domains or prefixes do not see each other.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <regex>
#include <string>
#include <thread>
#include <vector>

#include "tests/multihost/support/ssl_client.h"
#include "tests/support/process.h"
#include "tests/support/world_observer.h"
#include "tests/test_domain.h"

namespace turf::test {
namespace {

using namespace std::chrono_literals;

// A division B match on loopback: turf-sim, grSim and vision bridges on ports
// of its own; `extra` is appended to the profile.
struct Launch {
  Launch(const std::string& name, int domain, const std::string& prefix, const std::string& extra = "",
         std::vector<std::string> args = {}) {
    grsim_port = FreePort();
    vision_port = FreePort();
    path = LogDir() + "/" + name + "_" + std::to_string(getpid()) + ".yaml";
    std::ofstream(path) << "scene: " << TURF_SOURCE_DIR << "/configs/scenes/ssl_div_b.yaml\n"
                        << "realism: ideal\ndomain: " << domain << "\nprefix: " << prefix << "\n"
                        << "bridges:\n"
                        << "  grsim: {listen: 127.0.0.1, port: " << grsim_port << ", blue-status-port: " << FreePort()
                        << ", yellow-status-port: " << FreePort() << "}\n"
                        << "  vision: {address: 127.0.0.1, port: " << vision_port << ", geometry-every: 30}\n"
                        << extra;
    args.insert(args.begin(), {Built("participants/launcher/turf"), "launch", path});
    turf = std::make_unique<Process>(name, args);
  }
  // The pid `turf` logged for a process's latest start.
  pid_t ChildPid(const std::string& process) const {
    const std::string log = turf->Log();
    const std::regex started("started " + process + " \\(pid ([0-9]+)\\)");
    pid_t pid = -1;
    for (std::sregex_iterator it(log.begin(), log.end(), started), end; it != end; ++it) pid = std::stoi((*it)[1]);
    return pid;
  }
  int grsim_port, vision_port;
  std::string path;
  std::unique_ptr<Process> turf;
};

// The process exits within `timeout` with exit status `code`.
::testing::AssertionResult ExitsWithin(Process& p, std::chrono::milliseconds timeout, int code) {
  const auto status = p.Wait(timeout);
  if (!status) return ::testing::AssertionFailure() << "still running\n" << p.Log();
  if (!WIFEXITED(*status) || WEXITSTATUS(*status) != code)
    return ::testing::AssertionFailure() << "wait status " << *status << ", expected exit " << code << "\n" << p.Log();
  return ::testing::AssertionSuccess();
}

bool Alive(pid_t pid) { return pid > 0 && kill(pid, 0) == 0; }

template <class F>
bool WaitFor(F done, std::chrono::milliseconds timeout) {
  const auto end = SteadyClock::now() + timeout;
  while (!done()) {
    if (SteadyClock::now() > end) return false;
    std::this_thread::sleep_for(20ms);
  }
  return true;
}

TEST(LaunchSupervisor, RestartsACrashedBridgeAndStopsCleanlyOnCtrlC) {
  Launch launch("launch_restart", TestDomain(), "lr" + std::to_string(getpid()), "restart: {backoff_initial: 0.2}\n");
  VisionClient client("127.0.0.1", launch.vision_port);
  UdpSocket team;
  ASSERT_TRUE(client.WaitForStream(2, 15s)) << launch.turf->Log();
  const pid_t sim = launch.ChildPid("sim"), grsim = launch.ChildPid("grsim"), vision = launch.ChildPid("vision");
  ASSERT_TRUE(Alive(sim) && Alive(grsim) && Alive(vision));

  kill(vision, SIGKILL);
  const auto killed = SteadyClock::now();
  ASSERT_TRUE(WaitFor([&] { return launch.ChildPid("vision") != vision; }, 5s)) << launch.turf->Log();
  client.Drain(100ms);
  const auto resumed = client.UntilDetection(15s);
  ASSERT_TRUE(resumed.has_value()) << launch.turf->Log();
  const auto since_kill = std::chrono::duration_cast<std::chrono::milliseconds>(SteadyClock::now() - killed);
  RecordProperty("vision_after_kill_ms", static_cast<int>(since_kill.count()));
  std::printf("vision resumed %lld ms after the kill (0.2 s backoff included)\n",
              static_cast<long long>(since_kill.count()));
  EXPECT_NE(launch.turf->Log().find("vision crashed (killed by signal 9"), std::string::npos);
  EXPECT_EQ(launch.ChildPid("sim"), sim) << "only the crashed process restarts";
  EXPECT_GT(DriveBlueRobot(team, "127.0.0.1", launch.grsim_port, client, 1, -3.0, 2.0, 600ms).value_or(0), 0.2);

  // Output lines carry the process name.
  const std::string log = launch.turf->Log();
  EXPECT_NE(log.find("\nsim    | "), std::string::npos);
  EXPECT_NE(log.find("\nvision | "), std::string::npos);

  const pid_t new_vision = launch.ChildPid("vision");
  launch.turf->Signal(SIGINT);
  ASSERT_TRUE(ExitsWithin(*launch.turf, 10s, 0));
  for (pid_t pid : {sim, grsim, new_vision}) EXPECT_FALSE(Alive(pid)) << pid;
  EXPECT_NE(launch.turf->Log().find("sim stopped (exit status 0)"), std::string::npos);
}

// A process that refuses its configuration (exit status 2) would refuse it again: no retries, exit 2 at once.
TEST(LaunchSupervisor, AConfigurationErrorEndsTheLaunchAtOnce) {
  Launch launch("launch_badconfig", TestDomain(), "lb" + std::to_string(getpid()),
                "restart: {max_restarts: 5, backoff_initial: 2, backoff_max: 8}\n",
                {"--set", "vision.address=not-an-address"});
  ASSERT_TRUE(ExitsWithin(*launch.turf, 20s, 2));
  const std::string log = launch.turf->Log();
  EXPECT_NE(log.find("vision refused its configuration (exit status 2"), std::string::npos) << log;
  EXPECT_EQ(log.find("restart 1 of"), std::string::npos) << "not retried: " << log;
  // Stopped, whether it had installed its SIGTERM handler yet (exit status 0) or not (killed by signal 15).
  EXPECT_NE(log.find("sim stopped ("), std::string::npos) << log;
}

// A bridge that keeps crashing is given up alone: turf-sim and the other bridge go on, and SIGUSR1 tries again.
TEST(LaunchSupervisor, GivesUpOnACrashLoopingBridgeAndTheMatchGoesOn) {
  const int busy_port = FreePort();
  auto squatter = std::make_unique<UdpSocket>("127.0.0.1", busy_port);  // the grSim bridge cannot bind it: exit 1
  ASSERT_TRUE(squatter->ok());
  Launch launch("launch_crashloop", TestDomain(), "lc" + std::to_string(getpid()),
                "restart: {max_restarts: 2, backoff_initial: 0.1, backoff_max: 0.2}\n",
                {"--set", "grsim.port=" + std::to_string(busy_port)});
  ASSERT_TRUE(WaitFor([&] { return launch.turf->Log().find("giving up on it") != std::string::npos; }, 30s))
      << launch.turf->Log();
  std::string log = launch.turf->Log();
  EXPECT_NE(log.find("grsim crashed (exit status 1"), std::string::npos) << log;
  EXPECT_NE(log.find("restart 2 of 2 in 0.20 s"), std::string::npos) << log;
  EXPECT_NE(log.find("the match goes on without it"), std::string::npos) << log;
  // The match goes on: vision still streams what turf-sim simulates, and turf keeps running.
  VisionClient client("127.0.0.1", launch.vision_port);
  EXPECT_TRUE(client.WaitForStream(2, 15s)) << launch.turf->Log();
  EXPECT_FALSE(launch.turf->Wait(0ms).has_value()) << launch.turf->Log();
  EXPECT_TRUE(Alive(launch.ChildPid("sim")));

  // The port is free again; SIGUSR1 brings the bridge back.
  squatter.reset();
  const pid_t gave_up = launch.ChildPid("grsim");
  launch.turf->Signal(SIGUSR1);
  ASSERT_TRUE(WaitFor([&] { return launch.ChildPid("grsim") != gave_up; }, 10s)) << launch.turf->Log();
  EXPECT_NE(launch.turf->Log().find("SIGUSR1: trying grsim again"), std::string::npos);
  UdpSocket team;
  EXPECT_GT(DriveBlueRobot(team, "127.0.0.1", busy_port, client, 1, -3.0, 2.0, 600ms).value_or(0), 0.2)
      << launch.turf->Log();
  launch.turf->Signal(SIGINT);
  ASSERT_TRUE(ExitsWithin(*launch.turf, 10s, 0));
}

// kill -9 of turf-sim: the supervisor restarts it, and it continues from its newest snapshot (every 0.5 s of sim
// time here) instead of from kick-off; the bridges go on without a restart.
TEST(LaunchSupervisor, ACrashedTurfSimResumesWhereItWasAndTheBridgesGoOn) {
  const int domain = TestDomain();
  const std::string prefix = "lk" + std::to_string(getpid());
  Launch launch("launch_resume", domain, prefix,
                "sim: {speed: 2, snapshot-every: 0.5}\nrestart: {backoff_initial: 0.2}\n");
  VisionClient client("127.0.0.1", launch.vision_port);
  ASSERT_TRUE(client.WaitForStream(2, 15s)) << launch.turf->Log();
  const dds::ParticipantOptions observer{domain, "test-observer", prefix, dds::DefaultQosFile()};
  int64_t before_ns = 0;
  {
    WorldObserver world(observer);
    ASSERT_TRUE(
        world.Wait([](const idl::WorldState& s, const idl::Clock&) { return s.sim_time_ns() >= 8'000'000'000; }, 30s))
        << launch.turf->Log();
    before_ns = world.state().sim_time_ns();
  }
  const pid_t sim = launch.ChildPid("sim"), vision = launch.ChildPid("vision");
  kill(sim, SIGKILL);
  ASSERT_TRUE(WaitFor([&] { return launch.ChildPid("sim") != sim; }, 10s)) << launch.turf->Log();

  // The restarted turf-sim says where it resumed, and what it publishes starts there.
  std::smatch resumed;
  ASSERT_TRUE(WaitFor(
      [&] {
        const std::string log = launch.turf->Log();
        return std::regex_search(log, resumed, std::regex("resumed from \\S+ at t=([0-9.]+)s"));
      },
      15s))
      << launch.turf->Log();
  const double resumed_s = std::stod(resumed[1]);
  EXPECT_GE(resumed_s, before_ns * 1e-9 - 1.0) << "lost more than 1 s of the match";
  WorldObserver world(observer);  // a new participant: it hears only the restarted turf-sim
  ASSERT_TRUE(world.Wait([](const idl::WorldState&, const idl::Clock&) { return true; }, 15s)) << launch.turf->Log();
  EXPECT_GE(world.state().sim_time_ns() * 1e-9, resumed_s - 1e-9);

  EXPECT_EQ(launch.ChildPid("vision"), vision) << "the bridges are not restarted";
  client.Drain(100ms);
  ASSERT_TRUE(client.UntilDetection(15s).has_value()) << launch.turf->Log();
  launch.turf->Signal(SIGINT);
  ASSERT_TRUE(ExitsWithin(*launch.turf, 10s, 0));
  // The launch's snapshot directory goes with it: a new launch is a new match.
  const std::string log = launch.turf->Log();
  std::smatch file;
  ASSERT_TRUE(std::regex_search(log, file, std::regex("of sim time to (\\S+)/[^/\\s]+\\.resume"))) << log;
  EXPECT_FALSE(std::filesystem::exists(file[1].str())) << file[1];
}

TEST(LaunchSupervisor, ACleanExitEndsTheLaunch) {
  Launch launch("launch_duration", TestDomain(), "ld" + std::to_string(getpid()), "sim: {speed: 4, duration: 2}\n");
  ASSERT_TRUE(ExitsWithin(*launch.turf, 20s, 0));
  const std::string log = launch.turf->Log();
  EXPECT_NE(log.find("sim exited cleanly"), std::string::npos) << log;
  EXPECT_NE(log.find("vision stopped (exit status 0)"), std::string::npos) << log;
}

// Three matches at once: two on the same prefix in other domains, two in the
// same domain with other prefixes. A robot driven in one moves in no other.
TEST(LaunchSupervisor, MatchesOnOtherDomainsOrPrefixesDoNotSeeEachOther) {
  const int domain = TestDomain(), other_domain = TestDomain(50);
  const std::string prefix = "lm" + std::to_string(getpid());
  Launch a("launch_match_a", domain, prefix);
  Launch b("launch_match_b", other_domain, prefix);
  Launch c("launch_match_c", domain, prefix + "_c");
  VisionClient va("127.0.0.1", a.vision_port), vb("127.0.0.1", b.vision_port), vc("127.0.0.1", c.vision_port);
  for (VisionClient* v : {&va, &vb, &vc}) ASSERT_TRUE(v->WaitForStream(2, 20s)) << a.turf->Log();
  vb.Drain(100ms);
  vc.Drain(100ms);
  const auto b_before = vb.Robot(false, 3), c_before = vc.Robot(false, 3);
  ASSERT_TRUE(b_before && c_before);
  UdpSocket team;
  EXPECT_GT(DriveBlueRobot(team, "127.0.0.1", a.grsim_port, va, 3, -3.0, 2.0, 800ms).value_or(0), 0.3);
  vb.Drain(200ms);
  vc.Drain(200ms);
  for (const auto& [v, before] : {std::pair{&vb, b_before}, std::pair{&vc, c_before}}) {
    const auto after = v->Robot(false, 3);
    ASSERT_TRUE(after.has_value());
    EXPECT_NEAR(after->x, before->x, 2.0);
    EXPECT_NEAR(after->y, before->y, 2.0);
    EXPECT_GT(after->t, before->t) << "that match kept running";
  }
}

}  // namespace
}  // namespace turf::test
