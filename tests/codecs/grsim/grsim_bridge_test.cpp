// turf-grsim-bridge in-process: turf-sim and the bridge on threads of their
// own, each test on its own DDS domain and prefix. The test speaks real grSim
// UDP on 127.0.0.1 and checks the world over DDS. Waits are bounded.
#include <gtest/gtest.h>
#include <turf/idl/WorldStatePubSubTypes.h>
#include <unistd.h>
#include "tests/test_domain.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>

#include "codecs/proto/grsim.pb.h"
#include "dds/participant.h"
#include "participants/common/udp.h"
#include "participants/grsim_bridge/grsim_bridge.h"
#include "participants/sim/sim_node.h"
#include "tests/codecs/grsim/grsim_messages.h"
#include "tests/core/test_scenes.h"
#include "tests/support/in_process.h"
#include "tests/support/sim_and_bridge.h"

namespace turf {
namespace {

namespace wire = turf::wire::grsim;
using test::GrsimCommands;
using test::GrsimRobot;
using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;
using test::FindRobot;

constexpr double kFace = 0.08;          // robot centre to its flat front
constexpr double kBallRadius = 0.0215;  // m

// turf-sim (scaled x2) and the bridge, each on its thread.
class Stack : public test::SimAndBridge<GrsimBridge> {
 public:
  Stack(Scene scene, const dds::ParticipantOptions& dds, uint16_t blue_status_port, uint16_t yellow_status_port,
        const SourceAllowlists& allow)
      : SimAndBridge(std::move(scene), dds, TimeMode::kScaled, 2.0,
                     MakeBridge(dds, blue_status_port, yellow_status_port, allow)) {}

 private:
  static std::unique_ptr<GrsimBridge> MakeBridge(const dds::ParticipantOptions& dds, uint16_t blue_status_port,
                                                 uint16_t yellow_status_port, const SourceAllowlists& allow) {
    auto b = test::OnDds<GrsimBridgeOptions>(dds);
    b.listen_ip = "127.0.0.1";
    b.port = 0;  // any free port
    b.blue_status_port = blue_status_port;
    b.yellow_status_port = yellow_status_port;
    b.allow = allow;
    return std::make_unique<GrsimBridge>(b);
  }
};

// A grSim client: sends packets to the bridge (from `ip`, a loopback address), receives robot status.
class Team {
 public:
  explicit Team(const std::string& ip = "127.0.0.1")
      : out_(test::BindUdp(ip)), blue_status_(test::BindLoopback()), yellow_status_(test::BindLoopback()) {}
  uint16_t blue_status_port() const { return blue_status_.LocalPort(); }
  uint16_t yellow_status_port() const { return yellow_status_.LocalPort(); }
  void Connect(uint16_t bridge_port) { to_ = *MakeEndpoint("127.0.0.1", bridge_port); }

  void Send(const std::vector<uint8_t>& bytes) {
    std::string error;
    ASSERT_TRUE(out_.SendTo(bytes, to_, &error)) << error;
  }
  void Send(const wire::grSim_Packet& packet) {
    const std::string s = packet.SerializePartialAsString();
    Send(std::vector<uint8_t>(s.begin(), s.end()));
  }
  // Robot status packets that arrived on the blue port, waiting up to `timeout` for one.
  std::optional<wire::Robots_Status> BlueStatus(std::chrono::milliseconds timeout) {
    auto d = blue_status_.Receive(2048, timeout);
    if (!d) return std::nullopt;
    wire::Robots_Status status;
    if (!status.ParseFromArray(d->bytes.data(), static_cast<int>(d->bytes.size()))) return std::nullopt;
    return status;
  }

 private:
  UdpSocket out_, blue_status_, yellow_status_;
  UdpEndpoint to_;
};

// Watches the world over DDS, as a test harness would.
class Observer {
 public:
  explicit Observer(const dds::ParticipantOptions& o)
      : participant_(o), state_(participant_.MakeReader<idl::WorldStatePubSubType>(dds::Topic::kWorldState)) {}

  // Polls until `done` holds for a world state, or the timeout; `each`
  // runs on every poll (about every 16 ms, like a team's frame).
  bool Wait(const std::function<bool(const idl::WorldState&)>& done, std::chrono::milliseconds timeout = 5s,
            const std::function<void()>& each = {}) {
    const auto end = Clock::now() + timeout;
    while (Clock::now() < end) {
      if (each) each();
      // Every state counts, not just the newest of a batch (a kick lasts one state).
      state_->Take(&states_);
      for (const idl::WorldState& s : states_) {
        now_ = s;
        has_state_ = true;
        if (done(now_)) return true;
      }
      if (states_.empty() && has_state_ && done(now_)) return true;
      std::this_thread::sleep_for(16ms);
    }
    return false;
  }
  const idl::WorldState& state() const { return now_; }
  bool has_state() const { return has_state_; }

 private:
  dds::Participant participant_;
  std::unique_ptr<dds::Reader<idl::WorldStatePubSubType>> state_;
  std::vector<idl::WorldState> states_;
  idl::WorldState now_;
  bool has_state_ = false;
};

// Everything a test needs, started and matched.
struct Fixture {
  explicit Fixture(Scene scene, const SourceAllowlists& allow = {})
      : dds(test::UniqueDds("observer")),
        stack(std::move(scene), dds, team.blue_status_port(), team.yellow_status_port(), allow),
        observer(dds) {
    team.Connect(stack.bridge().port());
  }
  // turf-sim matched and its field (robots per team) known to the bridge.
  ::testing::AssertionResult Ready() {
    const bool ready = observer.Wait(
        [&](const idl::WorldState&) {
          const GrsimBridgeStats s = stack.bridge().Stats();
          return s.sim_present && s.field_known;
        },
        8s);
    if (ready) return ::testing::AssertionSuccess();
    const GrsimBridgeStats s = stack.bridge().Stats();
    return ::testing::AssertionFailure() << "world state seen: " << observer.has_state()
                                         << ", bridge sees turf-sim: " << s.sim_present
                                         << ", field known: " << s.field_known;
  }
  dds::ParticipantOptions dds;
  Team team;
  Stack stack;
  Observer observer;
};

wire::grSim_RobotReplacement Placed(uint32_t id, bool yellow, double x, double y, double dir_degrees) {
  wire::grSim_RobotReplacement r;
  r.set_id(id);
  r.set_yellowteam(yellow);
  r.set_x(x);
  r.set_y(y);
  r.set_dir(dir_degrees);
  return r;
}

double BallSpeed(const idl::WorldState& s) { return std::hypot(s.ball().velocity().x(), s.ball().velocity().y()); }

TEST(GrsimBridge, EachTeamDrivesAtTheCommandedSpeed) {
  Fixture f(test::Teams(1));  // blue 0 at (-1, -3.5), yellow 0 at (1, -3.5), both facing +x
  ASSERT_TRUE(f.Ready());
  // Blue forward, yellow to its left, 1 m/s each, at a team's 60 Hz; measured after the ramp.
  int64_t t0 = -1, t_start = -1;
  double blue_x = 0, yellow_y = 0;
  const bool done = f.observer.Wait(
      [&](const idl::WorldState& s) {
        if (t0 < 0) t0 = s.sim_time_ns();
        if (t_start < 0 && s.sim_time_ns() - t0 > 700'000'000) {
          t_start = s.sim_time_ns();
          blue_x = FindRobot(s, idl::TEAM_BLUE, 0)->position().x();
          yellow_y = FindRobot(s, idl::TEAM_YELLOW, 0)->position().y();
        }
        return t_start >= 0 && s.sim_time_ns() - t_start >= 600'000'000;
      },
      8s,
      [&] {
        f.team.Send(GrsimCommands(false, {GrsimRobot(0, 1.0f)}));
        f.team.Send(GrsimCommands(true, {GrsimRobot(0, 0.0f, 1.0f)}));
      });
  ASSERT_TRUE(done);
  const idl::WorldState& s = f.observer.state();
  const double dt = (s.sim_time_ns() - t_start) * 1e-9;
  EXPECT_NEAR((FindRobot(s, idl::TEAM_BLUE, 0)->position().x() - blue_x) / dt, 1.0, 0.05);
  EXPECT_NEAR((FindRobot(s, idl::TEAM_YELLOW, 0)->position().y() - yellow_y) / dt, 1.0, 0.05);
  EXPECT_NEAR(FindRobot(s, idl::TEAM_BLUE, 0)->linear_velocity().x(), 1.0, 0.05);
  EXPECT_NEAR(FindRobot(s, idl::TEAM_YELLOW, 0)->linear_velocity().y(), 1.0, 0.05);
  EXPECT_EQ(f.stack.bridge().Stats().refused, 0u);
  EXPECT_EQ(f.stack.sim().Stats().rejected, 0u);
}

TEST(GrsimBridge, ReplacementPlacesBallAndRobots) {
  Fixture f(test::Teams(2));
  ASSERT_TRUE(f.Ready());
  wire::grSim_Packet p;
  *p.mutable_replacement()->add_robots() = Placed(0, false, 2.0, 1.0, 90.0);
  wire::grSim_RobotReplacement off = Placed(1, true, 0, 0, 0);
  off.set_turnon(false);
  *p.mutable_replacement()->add_robots() = off;
  p.mutable_replacement()->mutable_ball()->set_x(-1.0);
  p.mutable_replacement()->mutable_ball()->set_y(0.5);
  p.mutable_replacement()->mutable_ball()->set_vx(0.0);
  p.mutable_replacement()->mutable_ball()->set_vy(0.0);
  f.team.Send(p);
  ASSERT_TRUE(f.observer.Wait([](const idl::WorldState& s) {
    const idl::RobotState* blue = FindRobot(s, idl::TEAM_BLUE, 0);
    const idl::RobotState* yellow = FindRobot(s, idl::TEAM_YELLOW, 1);
    return std::abs(s.ball().position().x() + 1.0) < 1e-3 && std::abs(s.ball().position().y() - 0.5) < 1e-3 &&
           std::abs(blue->position().x() - 2.0) < 1e-3 && std::abs(blue->position().y() - 1.0) < 1e-3 &&
           std::abs(blue->yaw() - M_PI / 2) < 1e-3 && !yellow->on_field();
  })) << "ball ("
      << f.observer.state().ball().position().x() << ", " << f.observer.state().ball().position().y() << ")";
  EXPECT_EQ(f.stack.bridge().Stats().controls, 3u);

  // A ball outside the walls, with a robot: the bridge knows the walls from ssl/field and refuses the packet whole
  // (turf-sim refused the ball after placing the robot).
  wire::grSim_Packet outside;
  *outside.mutable_replacement()->add_robots() = Placed(0, false, -2.0, -1.0, 0.0);
  outside.mutable_replacement()->mutable_ball()->set_x(50.0);
  f.team.Send(outside);
  EXPECT_TRUE(
      f.observer.Wait([&](const idl::WorldState&) { return f.stack.bridge().Rejected("outside_field") == 1; }, 15s));
  EXPECT_EQ(f.stack.bridge().Rejected("control_rejected"), 0u);
  EXPECT_NEAR(f.observer.state().ball().position().x(), -1.0, 1e-3);
  EXPECT_NEAR(FindRobot(f.observer.state(), idl::TEAM_BLUE, 0)->position().x(), 2.0, 1e-3) << "the robot stays";
}

TEST(GrsimBridge, KickAndRobotStatus) {
  Fixture f(test::OneRobot());  // blue 0 at the origin facing +x
  ASSERT_TRUE(f.Ready());
  // A first command tells the bridge where blue's status goes.
  ASSERT_TRUE(f.observer.Wait([&](const idl::WorldState&) { return f.stack.bridge().Stats().commands > 0; }, 15s,
                              [&] { f.team.Send(GrsimCommands(false, {GrsimRobot(0)})); }));
  // The ball at rest against the front face.
  wire::grSim_Packet place;
  *place.mutable_replacement()->add_robots() = Placed(0, false, 0.0, 0.0, 0.0);
  place.mutable_replacement()->mutable_ball()->set_x(kFace + kBallRadius);
  place.mutable_replacement()->mutable_ball()->set_y(0.0);
  f.team.Send(place);

  bool infrared = false;
  for (auto end = Clock::now() + 15s; !infrared && Clock::now() < end;) {
    f.team.Send(GrsimCommands(false, {GrsimRobot(0)}));
    auto status = f.team.BlueStatus(16ms);
    if (!status) continue;
    for (const auto& r : status->robots_status()) infrared |= r.robot_id() == 0 && r.infrared();
  }
  ASSERT_TRUE(infrared) << "no status with infrared on the blue status port";

  wire::grSim_Robot_Command kick = GrsimRobot(0);
  kick.set_kickspeedx(4.0f);
  double fastest = 0;
  const bool kicked = f.observer.Wait(
      [&](const idl::WorldState& s) {
        fastest = std::max(fastest, BallSpeed(s));
        return fastest > 1.0;
      },
      15s, [&] { f.team.Send(GrsimCommands(false, {fastest > 1.0 ? GrsimRobot(0) : kick})); });
  ASSERT_TRUE(kicked);
  // The first world state after the kick (<= 10 ms of sliding later) shows the commanded speed.
  EXPECT_NEAR(fastest, 4.0, 0.1);
  EXPECT_GT(f.observer.state().ball().velocity().x(), 3.8);

  bool flat_kick = false;
  for (auto end = Clock::now() + 15s; !flat_kick && Clock::now() < end;) {
    auto status = f.team.BlueStatus(16ms);
    if (!status) continue;
    for (const auto& r : status->robots_status()) flat_kick |= r.robot_id() == 0 && r.flat_kick();
  }
  EXPECT_TRUE(flat_kick);
}

TEST(GrsimBridge, BadDatagramsChangeNothing) {
  Fixture f(test::OneRobot());
  ASSERT_TRUE(f.Ready());
  wire::grSim_Robot_Command nan = GrsimRobot(0, 1.0f);
  nan.set_velnormal(NAN);
  const std::vector<uint8_t> garbage = {0xFF, 0xFF, 0xFF, 0x0A, 0x99};
  int64_t t0 = -1;
  ASSERT_TRUE(f.observer.Wait(
      [&](const idl::WorldState& s) {
        if (t0 < 0) t0 = s.sim_time_ns();
        return s.sim_time_ns() - t0 > 600'000'000;
      },
      5s,
      [&] {
        f.team.Send(garbage);
        f.team.Send(GrsimCommands(false, {GrsimRobot(0, 1.0f), nan}));  // a good command in a bad datagram
        f.team.Send(GrsimCommands(false, {GrsimRobot(7, 1.0f)}));       // robot 7 of a one-robot team
      }));
  const idl::RobotState* r = FindRobot(f.observer.state(), idl::TEAM_BLUE, 0);
  EXPECT_DOUBLE_EQ(r->position().x(), 0.0);
  EXPECT_DOUBLE_EQ(r->position().y(), 0.0);
  EXPECT_GT(f.stack.bridge().Rejected("malformed"), 0u);
  EXPECT_GT(f.stack.bridge().Rejected("not_finite"), 0u);
  EXPECT_GT(f.stack.bridge().Rejected("unknown_robot"), 0u);  // robots_per_team came from ssl/field
  EXPECT_TRUE(f.stack.bridge().Stats().field_known);
  EXPECT_EQ(f.stack.bridge().Stats().commands, 0u);
  EXPECT_EQ(f.stack.sim().Stats().rejected, 0u);  // nothing bad reached turf-sim

  // The same channel still drives the robot.
  ASSERT_TRUE(
      f.observer.Wait([](const idl::WorldState& s) { return FindRobot(s, idl::TEAM_BLUE, 0)->position().x() > 0.05; },
                      5s, [&] { f.team.Send(GrsimCommands(false, {GrsimRobot(0, 1.0f)})); }));
}

// Source allowlists (--blue-allow, --yellow-allow, --operator-allow): from 127.0.0.2, which none of them holds,
// commands for either team and a replacement move nothing and are counted; the same packets from 127.0.0.1 move.
TEST(GrsimBridge, ASenderNotOnTheAllowlistsMovesNothing) {
  const SourceAllowlists allow{{"127.0.0.1/32"}, {"127.0.0.1/32"}, {"127.0.0.1/32"}};
  Fixture f(test::Teams(1), allow);  // blue 0 at (-1, -3.5), yellow 0 at (1, -3.5)
  ASSERT_TRUE(f.Ready());
  ASSERT_TRUE(f.observer.Wait([](const idl::WorldState&) { return true; }));
  const idl::WorldState before = f.observer.state();
  Team stranger("127.0.0.2");
  stranger.Connect(f.stack.bridge().port());
  wire::grSim_Packet ball;
  ball.mutable_replacement()->mutable_ball()->set_x(1.5);
  ball.mutable_replacement()->mutable_ball()->set_y(1.5);
  constexpr uint64_t kRounds = 5;
  for (uint64_t i = 0; i < kRounds; ++i) {
    stranger.Send(GrsimCommands(false, {GrsimRobot(0, 1.0f)}));
    stranger.Send(GrsimCommands(true, {GrsimRobot(0, 0.0f, 1.0f)}));
    stranger.Send(ball);
  }
  // Positive marker: every stranger's packet refused, then the allowed operator's replacement shows in the world
  // (turf-sim takes requests in order).
  GrsimBridge& bridge = f.stack.bridge();
  ASSERT_TRUE(f.observer.Wait([&](const idl::WorldState&) {
    return bridge.Rejected("blue.not_allowed") == kRounds && bridge.Rejected("yellow.not_allowed") == kRounds &&
           bridge.Rejected("operator.not_allowed") == kRounds;
  })) << "blue "
      << bridge.Rejected("blue.not_allowed") << ", yellow " << bridge.Rejected("yellow.not_allowed") << ", operator "
      << bridge.Rejected("operator.not_allowed");
  wire::grSim_Packet marker;
  marker.mutable_replacement()->mutable_ball()->set_x(-0.5);
  marker.mutable_replacement()->mutable_ball()->set_y(0.25);
  f.team.Send(marker);
  ASSERT_TRUE(f.observer.Wait([](const idl::WorldState& s) {
    return std::abs(s.ball().position().x() + 0.5) < 1e-3 && std::abs(s.ball().position().y() - 0.25) < 1e-3;
  }));
  // Half a simulated second more for any command that got through to show.
  const int64_t t0 = f.observer.state().sim_time_ns();
  ASSERT_TRUE(f.observer.Wait([&](const idl::WorldState& s) { return s.sim_time_ns() - t0 > 500'000'000; }));
  for (const idl::Team team : {idl::TEAM_BLUE, idl::TEAM_YELLOW}) {
    const idl::RobotState* now = FindRobot(f.observer.state(), team, 0);
    const idl::RobotState* then = FindRobot(before, team, 0);
    EXPECT_DOUBLE_EQ(now->position().x(), then->position().x()) << static_cast<int>(team);
    EXPECT_DOUBLE_EQ(now->position().y(), then->position().y()) << static_cast<int>(team);
  }
  const GrsimBridgeStats s = bridge.Stats();
  EXPECT_EQ(s.commands, 0u);
  EXPECT_EQ(s.controls, 1u);  // the marker's
  EXPECT_EQ(s.not_allowed, 3 * kRounds);
  EXPECT_EQ(s.refused, 3 * kRounds);

  // The allowed sender's commands move its robot.
  ASSERT_TRUE(f.observer.Wait(
      [&](const idl::WorldState& w) {
        return FindRobot(w, idl::TEAM_BLUE, 0)->position().x() - FindRobot(before, idl::TEAM_BLUE, 0)->position().x() >
               0.05;
      },
      5s, [&] { f.team.Send(GrsimCommands(false, {GrsimRobot(0, 1.0f)})); }));
  EXPECT_EQ(bridge.Stats().not_allowed, 3 * kRounds);
}

}  // namespace
}  // namespace turf
