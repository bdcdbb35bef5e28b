// DDS Security with real turf-sim processes (issue 19): identities from `turf security init` (security_init.h);
// the blue identity moves blue robots, the yellow one cannot publish on blue's command topic, a participant without
// security meets no one, a tampered permissions file or a missing key makes turf-sim refuse to start (exit 2) with
// a clear error, the tournament profile keeps the world state and control from the teams, and a peer that never
// finishes authenticating is named after the timeout (dds/authentication_watch.h).
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
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
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
// turf-sim's announcement, sent again while turf-sim is stopped. The participant names it after its timeout.
TEST_F(SecurityE2e, APeerThatNeverFinishesAuthenticatingIsNamedAfterTheTimeout) {
  std::string error;
  std::optional<UdpSocket> spdp = UdpSocket::Bind("0.0.0.0", SpdpPort(domain_), /*reuse=*/true, &error);
  ASSERT_TRUE(spdp) << error;
  ASSERT_TRUE(spdp->JoinMulticast(kSpdpGroup, "0.0.0.0", &error)) << error;
  Process sim("security_sim", SimArgs(dir_ + "/sim"));
  const auto announcement = AnnouncementOf(*spdp, sim.pid(), std::chrono::steady_clock::now() + 30s);
  ASSERT_TRUE(announcement) << "no announcement of turf-sim (pid " << sim.pid() << ")\n" << sim.Log();
  sim.Signal(SIGSTOP);

  CapturedLog log(spdlog::level::warn);
  dds::ParticipantOptions options = As("blue", "test-stall-watcher");
  options.authentication_timeout = 2s;
  dds::Participant watcher(options);
  const std::optional<UdpEndpoint> group = MakeEndpoint(kSpdpGroup, SpdpPort(domain_));
  ASSERT_TRUE(group);
  // Sent again every 100 ms (the watcher discovers turf-sim at the first it receives; its lease is 5 s), until the
  // watcher names turf-sim. (Another test's participant on this domain may be refused or named too: the counts
  // are at least, not exactly.)
  const std::string named = "DDS security: turf-sim (pid " + std::to_string(sim.pid()) + " on host";
  const auto deadline = std::chrono::steady_clock::now() + 30s;
  while (log.Text().find(named) == std::string::npos && std::chrono::steady_clock::now() < deadline) {
    ASSERT_TRUE(spdp->SendTo(*announcement, *group, &error)) << error;
    spdp->Receive(65536, 100ms);  // paces the loop; what it receives is not used
  }
  const dds::Authentications now = watcher.AuthenticationsNow();
  sim.Kill();
  const std::string text = log.Text();
  const size_t at = text.find(named);
  ASSERT_NE(at, std::string::npos) << text;
  EXPECT_NE(text.find("has not finished authenticating", at), std::string::npos) << text;
  EXPECT_GE(now.stalled, 1u) << text;
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
  Process sim("security_sim_tampered", SimArgs(tampered));
  const std::optional<int> status = sim.Wait(60s);
  ASSERT_TRUE(status.has_value()) << sim.Log();
  ASSERT_TRUE(WIFEXITED(*status)) << sim.Log();
  EXPECT_EQ(WEXITSTATUS(*status), 2) << sim.Log();
  EXPECT_NE(sim.Log().find("DDS Security refused the identity in " + tampered), std::string::npos) << sim.Log();

  const std::string keyless = dir_ + "/sim-keyless";
  fs::copy(dir_ + "/sim", keyless);
  fs::remove(keyless + "/key.pem");
  Process sim2("security_sim_keyless", SimArgs(keyless));
  const std::optional<int> status2 = sim2.Wait(60s);
  ASSERT_TRUE(status2.has_value()) << sim2.Log();
  ASSERT_TRUE(WIFEXITED(*status2)) << sim2.Log();
  EXPECT_EQ(WEXITSTATUS(*status2), 2) << sim2.Log();
  EXPECT_NE(sim2.Log().find("no readable key.pem"), std::string::npos) << sim2.Log();
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
