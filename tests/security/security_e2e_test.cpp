// DDS Security with real turf-sim processes (issue 19): identities from `turf security init` (security_init.h);
// the blue identity moves blue robots, the yellow one cannot publish on blue's command topic, a participant without
// security meets no one, a tampered permissions file or a missing key makes turf-sim refuse to start (exit 2) with
// a clear error, the tournament profile keeps the world state and control from the teams, and a peer that never
// finishes authenticating is named after the timeout (dds/authentication_watch.h), a bridge waiting for it restarting
// itself (participants/common/stalled_authentication.h): an SSL bridge, a 3D-league front-end and turf-render.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <turf/idl/SimControlPubSubTypes.h>
#include <turf/idl/SslRobotPubSubTypes.h>
#include <turf/idl/SslVisionPubSubTypes.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "dds/participant.h"
#include "participants/common/udp.h"
#include "participants/launcher/security_init.h"
#include "tests/support/captured_log.h"
#include "tests/support/process.h"
#include "tests/support/world_observer.h"
#include "tests/test_domain.h"

namespace turf::test {
namespace {

using namespace std::chrono_literals;
namespace fs = std::filesystem;

class StalledSim;
struct WaitingBridge;

class SecurityE2e : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    dir_ = LogDir() + "/security_" + std::to_string(getpid()) + "_" + test;
    fs::remove_all(dir_);
    Init(dds::SecurityProfile::kLab);
  }
  void TearDown() override { fs::remove_all(dir_); }

  void Init(dds::SecurityProfile profile) {
    fs::remove_all(dir_);
    launch::SecurityInitOptions o;
    o.dir = dir_;
    o.prefix = prefix_;
    o.profile = profile;
    const std::vector<std::string> errors = launch::InitSecurity(o);
    ASSERT_TRUE(errors.empty()) << errors.front();
  }
  dds::ParticipantOptions As(const std::string& identity, const std::string& name) const {
    return {domain_, name, prefix_, TURF_SOURCE_DIR "/configs/qos/turf_qos.xml",
            identity.empty() ? "" : dir_ + "/" + identity};
  }
  std::vector<std::string> SimArgs(const std::string& identity_dir) const {
    return {Built("participants/sim/turf-sim"),
            "--realism",
            "ideal",
            "--domain",
            std::to_string(domain_),
            "--prefix",
            prefix_,
            "--security",
            identity_dir};
  }

  // turf-sim with the identity in `identity_dir` (and `env`) exits 2 at start, saying `why`.
  void ExpectSimRefusesToStart(const std::string& name, const std::string& identity_dir, const std::string& why,
                               const Process::Env& env = {}) const {
    Process sim(name, SimArgs(identity_dir), env);
    const std::optional<int> status = sim.Wait(60s);
    ASSERT_TRUE(status.has_value()) << sim.Log();
    ASSERT_TRUE(WIFEXITED(*status)) << sim.Log();
    EXPECT_EQ(WEXITSTATUS(*status), 2) << sim.Log();
    EXPECT_NE(sim.Log().find(why), std::string::npos) << sim.Log();
  }

  // Below, with StalledSim.
  void RestartsAndMeetsTheNextOne(StalledSim& stalled, const WaitingBridge& b, const std::function<void()>& pace);

  const int domain_ = TestDomain(61);
  const std::string prefix_ = "sec" + std::to_string(getpid());
  std::string dir_;
};

const idl::RobotState* Robot(const idl::WorldState& s, idl::Team team, int id) {
  for (const idl::RobotState& r : s.robots())
    if (r.team() == team && r.id() == id) return &r;
  return nullptr;
}

double Distance(const idl::RobotState& a, const idl::RobotState& b) {
  return std::hypot(a.position().x() - b.position().x(), a.position().y() - b.position().y());
}

idl::SslRobotCommand Forward(idl::Team team, int id) {
  idl::SslRobotCommand c;
  c.team(team);
  c.id(static_cast<uint8_t>(id));
  c.move(idl::MOVE_LOCAL_VELOCITY);
  c.velocity().x(1.0);
  return c;
}

TEST_F(SecurityE2e, TheBlueIdentityMovesBlueRobotsAndTheYellowOneCannotPublishOnBlue) {
  Process sim("security_sim", SimArgs(dir_ + "/sim"));
  WorldObserver world(As("blue", "test-blue-observer"));
  idl::RobotState blue0, blue1;
  ASSERT_TRUE(world.Wait(
      [&](const idl::WorldState& s, const idl::Clock&) {
        const idl::RobotState* a = Robot(s, idl::TEAM_BLUE, 0);
        const idl::RobotState* b = Robot(s, idl::TEAM_BLUE, 1);
        if (a == nullptr || b == nullptr) return false;
        blue0 = *a, blue1 = *b;
        return true;
      },
      30s))
      << sim.Log();

  // Yellow's certificate may not write blue's commands: refused where the writer is made.
  dds::Participant yellow(As("yellow", "test-yellow"));
  try {
    yellow.MakeWriter(dds::Topic::kSslCommandBlue);
    FAIL() << "the yellow identity made a writer of blue's commands";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("ssl/command/blue"), std::string::npos) << e.what();
  }
  auto yellow_own = yellow.MakeWriter(dds::Topic::kSslCommandYellow);  // its own: allowed

  // Blue drives its robot 0 forward: it moves (simulation time, 1 m/s asked, at least 0.3 m).
  dds::Participant blue(As("blue", "test-blue"));
  auto command = blue.MakeWriter(dds::Topic::kSslCommandBlue);
  ASSERT_TRUE(world.Wait(
      [&](const idl::WorldState& s, const idl::Clock&) {
        command->Write(Forward(idl::TEAM_BLUE, 0));
        const idl::RobotState* r = Robot(s, idl::TEAM_BLUE, 0);
        return r != nullptr && Distance(*r, blue0) > 0.3;
      },
      30s))
      << sim.Log();
  // Blue robot 1, which nobody could command, has not moved.
  const idl::RobotState* still = Robot(world.state(), idl::TEAM_BLUE, 1);
  ASSERT_NE(still, nullptr);
  EXPECT_LT(Distance(*still, blue1), 0.01);
}

TEST_F(SecurityE2e, AParticipantWithoutSecurityMeetsNoOne) {
  Process sim("security_sim", SimArgs(dir_ + "/sim"));
  dds::Participant plain(As("", "test-unauthenticated"));
  auto plain_state = plain.MakeReader(dds::Topic::kWorldState);
  auto plain_command = plain.MakeWriter(dds::Topic::kSslCommandBlue);
  // The positive marker: an observer with an identity gets world states, 200 frames' worth after the plain
  // participant is there.
  WorldObserver world(As("observer", "test-observer"));
  uint32_t first = 0;
  ASSERT_TRUE(world.Wait(
      [&](const idl::WorldState& s, const idl::Clock&) {
        if (first == 0) first = s.frame() + 1;
        return s.frame() > first + 200;
      },
      30s))
      << sim.Log();
  std::vector<idl::WorldState> got;
  EXPECT_FALSE(plain_state->Take(&got));
  EXPECT_EQ(plain_state->Matched(), 0);
  EXPECT_EQ(plain_command->Matched(), 0);
  // The observer's authentications: turf-sim's ended (authorized: world states came), none stalled.
  const dds::Authentications observed = world.participant().AuthenticationsNow();
  EXPECT_GE(observed.ended, 1u);
  EXPECT_EQ(observed.stalled, 0u);
}

// The participants' discovery announcements (SPDP) of `domain_`: RTPS's multicast group and port 7400 + 250 * domain.
constexpr const char* kSpdpGroup = "239.255.0.1";
uint16_t SpdpPort(int domain) { return static_cast<uint16_t>(7400 + 250 * domain); }

// The first announcement of the turf participant with process id `pid` that `socket` receives before `deadline`:
// turf announces its pid as the property turf.pid (dds/participant.cpp).
std::optional<std::vector<uint8_t>> AnnouncementOf(UdpSocket& socket, pid_t pid,
                                                   std::chrono::steady_clock::time_point deadline) {
  const std::string key = "turf.pid";
  const std::string value = std::to_string(pid);
  while (std::chrono::steady_clock::now() < deadline) {
    std::optional<Datagram> d = socket.Receive(65536, 200ms);
    if (!d || d->truncated) continue;
    const std::string bytes(d->bytes.begin(), d->bytes.end());
    const size_t at = bytes.find(key);
    if (bytes.compare(0, 4, "RTPS") == 0 && at != std::string::npos &&
        bytes.find(value, at + key.size()) < at + key.size() + 16)
      return d->bytes;
  }
  return std::nullopt;
}

// A peer that announces itself and never answers its handshake (Fast DDS 2.9.1's stall, as a participant sees it):
// a secured turf-sim stopped (SIGSTOP) after its first announcement, which Announce() sends again on the domain's
// SPDP group (every 100 ms while a participant waits for it: the first one received discovers turf-sim, its lease
// is 5 s).
class StalledSim {
 public:
  StalledSim(int domain, std::vector<std::string> sim_args) : domain_(domain) {
    std::string error;
    spdp_ = UdpSocket::Bind("0.0.0.0", SpdpPort(domain_), /*reuse=*/true, &error);
    if (!spdp_ || !spdp_->JoinMulticast(kSpdpGroup, "0.0.0.0", &error)) {
      error_ = "SPDP socket: " + error;
      return;
    }
    sim_ = std::make_unique<Process>("security_sim_stalled", std::move(sim_args));
    pid_ = sim_->pid();
    announcement_ = AnnouncementOf(*spdp_, pid_, std::chrono::steady_clock::now() + 30s);
    if (!announcement_) {
      error_ = "no announcement of turf-sim (pid " + std::to_string(pid_) + ")\n" + sim_->Log();
      return;
    }
    sim_->Signal(SIGSTOP);
  }
  // "" if turf-sim announced itself and is stopped.
  const std::string& error() const { return error_; }
  pid_t pid() const { return pid_; }
  // The start of the warning that names this turf-sim.
  std::string Named() const { return "DDS security: turf-sim (pid " + std::to_string(pid_) + " on host"; }
  // Sends the announcement every 100 ms until `done()` or `timeout`; false if a send failed.
  bool Announce(const std::function<bool()>& done, std::chrono::milliseconds timeout) {
    const std::optional<UdpEndpoint> group = MakeEndpoint(kSpdpGroup, SpdpPort(domain_));
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    std::string error;
    while (!done() && std::chrono::steady_clock::now() < deadline) {
      if (!group || !spdp_->SendTo(*announcement_, *group, &error)) return false;
      spdp_->Receive(65536, 100ms);  // paces the loop; what it receives is not used
    }
    return true;
  }
  void Kill() { sim_->Kill(); }

 private:
  const int domain_;
  std::optional<UdpSocket> spdp_;
  std::unique_ptr<Process> sim_;
  pid_t pid_ = 0;
  std::optional<std::vector<uint8_t>> announcement_;
  std::string error_;
};

// The participant names the stalled turf-sim after its timeout.
TEST_F(SecurityE2e, APeerThatNeverFinishesAuthenticatingIsNamedAfterTheTimeout) {
  StalledSim sim(domain_, SimArgs(dir_ + "/sim"));
  ASSERT_EQ(sim.error(), "");
  CapturedLog log(spdlog::level::warn);
  dds::ParticipantOptions options = As("blue", "test-stall-watcher");
  options.authentication_timeout = 2s;
  dds::Participant watcher(options);
  // (Another test's participant on this domain may be refused or named too: the counts are at least, not exactly.)
  const std::string named = sim.Named();
  ASSERT_TRUE(sim.Announce([&] { return log.Text().find(named) != std::string::npos; }, 30s));
  const dds::Authentications now = watcher.AuthenticationsNow();
  sim.Kill();
  const std::string text = log.Text();
  const size_t at = text.find(named);
  ASSERT_NE(at, std::string::npos) << text;
  EXPECT_NE(text.find("has not finished authenticating", at), std::string::npos) << text;
  EXPECT_GE(now.stalled, 1u) << text;
}

size_t Occurrences(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

// A bridge: its arguments after --security and --authentication-timeout, the turf-sim arguments it meets after the
// restart (beyond SimArgs), and the line it logs once it has that turf-sim.
struct WaitingBridge {
  std::string name;
  std::vector<std::string> args;  // program, --domain, --prefix, --security DIR: added
  std::vector<std::string> sim_args;
  std::string connected;
};

// A bridge still waiting for turf-sim whose authentication with it stalls restarts itself
// (participants/common/stalled_authentication.h): the stalled turf-sim is a stopped one's announcement sent again,
// as above. The restarted bridge (the same process, its program run again) then meets the next turf-sim.
void SecurityE2e::RestartsAndMeetsTheNextOne(StalledSim& stalled, const WaitingBridge& b,
                                             const std::function<void()>& pace) {
  ASSERT_EQ(stalled.error(), "");
  std::vector<std::string> args = {b.args.front(), "--domain", std::to_string(domain_), "--prefix", prefix_,
                                   // 10 s: long enough for a handshake on a loaded machine, so that the bridge meets
                                   // the next turf-sim at its first try (a slower one would restart it again, which
                                   // the test would survive but not need).
                                   "--authentication-timeout", "10"};
  args.insert(args.end(), b.args.begin() + 1, b.args.end());
  Process bridge("security_" + b.name, std::move(args));
  const std::string restarting = "starting again with the same arguments";
  ASSERT_TRUE(stalled.Announce([&] { return bridge.Log().find(restarting) != std::string::npos; }, 60s));
  const std::string named = stalled.Named();
  stalled.Kill();
  ASSERT_NE(bridge.Log().find(restarting), std::string::npos) << bridge.Log();
  EXPECT_NE(bridge.Log().find(named), std::string::npos) << bridge.Log();
  EXPECT_NE(bridge.Log().find("still waiting for turf-sim, and 1 DDS authentication(s) of this participant stalled"),
            std::string::npos)
      << bridge.Log();

  // The same process started again: it says so a second time, and it meets the next turf-sim.
  std::vector<std::string> sim_args = SimArgs(dir_ + "/sim");
  sim_args.insert(sim_args.end(), b.sim_args.begin(), b.sim_args.end());
  Process sim("security_sim", std::move(sim_args));
  const auto until = std::chrono::steady_clock::now() + 90s;
  while (bridge.Log().find(b.connected, bridge.Log().find(restarting)) == std::string::npos &&
         std::chrono::steady_clock::now() < until)
    pace();
  const std::string log = bridge.Log();
  EXPECT_TRUE(bridge.Running()) << log;
  EXPECT_GE(Occurrences(log, "waiting for turf-sim"), 2u) << log;
  EXPECT_NE(log.find(b.connected, log.find(restarting)), std::string::npos) << log << sim.Log();
  bridge.Signal(SIGINT);
  const std::optional<int> status = bridge.Wait(30s);
  ASSERT_TRUE(status.has_value()) << bridge.Log();
  EXPECT_TRUE(WIFEXITED(*status) && WEXITSTATUS(*status) == 0) << bridge.Log();
}

// An SSL bridge, which waits in its own loop (vision_bridge.cpp).
TEST_F(SecurityE2e, ABridgeWaitingForAStalledTurfSimRestartsItselfAndMeetsTheNextOne) {
  StalledSim stalled(domain_, SimArgs(dir_ + "/sim"));
  std::string error;
  std::optional<UdpSocket> vision = UdpSocket::Bind("127.0.0.1", 0, /*reuse=*/false, &error);
  ASSERT_TRUE(vision) << error;
  const std::string port = std::to_string(vision->LocalPort());
  RestartsAndMeetsTheNextOne(
      stalled,
      {"vision_bridge",
       {Built("participants/vision_bridge/turf-vision-bridge"), "--security", dir_ + "/vision-bridge", "--address",
        "127.0.0.1", "--port", port, "--tracked-port", port},
       {},
       "receiving camera frames"},
      // Paces the loop; the frames' datagrams are not checked here.
      [&] { vision->Receive(65536, 100ms); });
}

// A 3D-league front-end, which waits in LeggedLockstep::Attach (the SimSpark one; RCSSServerMJ's and HLVS's share it).
TEST_F(SecurityE2e, ALockstepFrontEndWaitingForAStalledTurfSimRestartsItselfAndMeetsTheNextOne) {
  StalledSim stalled(domain_, SimArgs(dir_ + "/sim"));
  RestartsAndMeetsTheNextOne(
      stalled,
      {"simspark_bridge",
       {Built("participants/simspark_bridge/turf-simspark-bridge"), "--security", dir_ + "/simspark-bridge", "--listen",
        "127.0.0.1", "--agent-port", "0", "--monitor-port", "0"},
       {"--scene", TURF_SOURCE_DIR "/configs/scenes/legged_example.yaml"},
       "robots for agents"},
      [] { std::this_thread::sleep_for(100ms); });  // polling the log
}

// turf-render, which waits for turf-sim's robot states in its render loop.
TEST_F(SecurityE2e, TurfRenderWaitingForAStalledTurfSimRestartsItselfAndMeetsTheNextOne) {
  const std::string scene = dir_ + "/render_scene.yaml";
  std::ofstream(scene) << "kind: legged\nname: security-render-restart\nphysics: {step: 0.005}\n"
                          "rates: {joint_state_hz: 200}\nrobots:\n  - name: t1\n    model: " TURF_SOURCE_DIR
                          "/configs/robots/t1.xml\n    z: 0.665\n    cameras:\n"
                          "      - {name: camera, width: 64, height: 48, rate_hz: 20}\n";
  StalledSim stalled(domain_, SimArgs(dir_ + "/sim"));
  RestartsAndMeetsTheNextOne(
      stalled,
      {"render",
       {Built("participants/render/turf-render"), "--security", dir_ + "/render", "--scene", scene},
       {"--scene", scene},
       "receiving turf-sim's robot states"},
      [] { std::this_thread::sleep_for(100ms); });  // polling the log
}

TEST_F(SecurityE2e, ATamperedPermissionsFileOrAMissingKeyMakesTurfSimRefuseToStart) {
  const std::string tampered = dir_ + "/sim-tampered";
  fs::copy(dir_ + "/sim", tampered);
  {
    std::ifstream in(tampered + "/permissions.p7s");
    std::stringstream text;
    text << in.rdbuf();
    std::string p7s = text.str();
    const std::string from = prefix_ + "/ssl/camera";
    const auto at = p7s.find(from);
    ASSERT_NE(at, std::string::npos);
    p7s.replace(at, from.size(), prefix_ + "/ssl/cameRa");  // one letter of the signed text
    std::ofstream(tampered + "/permissions.p7s", std::ios::trunc) << p7s;
  }
  ExpectSimRefusesToStart("security_sim_tampered", tampered, "DDS Security refused the identity in " + tampered);

  const std::string keyless = dir_ + "/sim-keyless";
  fs::copy(dir_ + "/sim", keyless);
  fs::remove(keyless + "/key.pem");
  ExpectSimRefusesToStart("security_sim_keyless", keyless, "no readable key.pem");
}

// A discovery server would be an unauthenticated participant: `turf launch` refuses its --discovery-server with
// --security, and a participant started by hand with ROS_DISCOVERY_SERVER set refuses too (it ran, then aborted).
TEST_F(SecurityE2e, SecurityWithADiscoveryServerInTheEnvironmentIsRefused) {
  ExpectSimRefusesToStart("security_sim_discovery_server", dir_ + "/sim",
                          "--security with ROS_DISCOVERY_SERVER=127.0.0.1:47999",
                          {{"ROS_DISCOVERY_SERVER", "127.0.0.1:47999"}});
}

TEST_F(SecurityE2e, InTheTournamentProfileATeamCanNeitherReadTheWorldStateNorControl) {
  Init(dds::SecurityProfile::kTournament);
  dds::Participant blue(As("blue", "test-blue"));
  EXPECT_THROW(blue.MakeReader(dds::Topic::kWorldState), std::runtime_error);
  EXPECT_THROW(blue.MakeWriter(dds::Topic::kControl), std::runtime_error);
  EXPECT_NO_THROW(blue.MakeWriter(dds::Topic::kSslCommandBlue));
  EXPECT_NO_THROW(blue.MakeReader(dds::Topic::kSslCamera));
  dds::Participant op(As("operator", "test-operator"));
  EXPECT_NO_THROW(op.MakeWriter(dds::Topic::kControl));
}

TEST_F(SecurityE2e, InitRefusesADirectoryThatHasACa) {
  Process again("security_init_again", {Built("participants/launcher/turf"), "security", "init", dir_});
  const std::optional<int> status = again.Wait(30s);
  ASSERT_TRUE(status.has_value()) << again.Log();
  ASSERT_TRUE(WIFEXITED(*status));
  EXPECT_EQ(WEXITSTATUS(*status), 2) << again.Log();
  EXPECT_NE(again.Log().find("already has a ca.pem"), std::string::npos) << again.Log();
}

}  // namespace
}  // namespace turf::test
