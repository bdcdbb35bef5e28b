// turf-simproto-bridge in process: turf-sim's node and the bridge on threads,
// a team over real UDP on 127.0.0.1, and a DDS observer of the world. Each test
// has its own DDS domain, topic prefix and free ports. Waits are bounded.
#include <gtest/gtest.h>
#include <turf/idl/ClockPubSubTypes.h>
#include <turf/idl/WorldStatePubSubTypes.h>
#include <unistd.h>
#include "tests/test_domain.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>
#include <thread>

#include "codecs/proto/ssl_simulation.pb.h"
#include "dds/participant.h"
#include "participants/common/udp.h"
#include "participants/sim/sim_node.h"
#include "participants/simproto_bridge/simproto_bridge.h"
#include "tests/core/test_scenes.h"
#include "tests/support/in_process.h"
#include "tests/support/process.h"
#include "tests/support/sim_and_bridge.h"
#include "tests/support/world_observer.h"

namespace turf {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;
namespace ws = wire::simulation;

dds::ParticipantOptions UniqueDds() {
  dds::ParticipantOptions o = test::UniqueDds("observer");
  o.domain = test::TestDomain(37);
  return o;
}

uint16_t FreePort() { return static_cast<uint16_t>(test::FreePort()); }

// turf-sim's node and the bridge, each on a thread of its own.
class Stack {
 public:
  Stack(Scene scene, const dds::ParticipantOptions& dds, TimeMode mode, double speed = 1.0, bool allow_sync = true,
        const SourceAllowlists& allow = {})
      : run_(std::move(scene), dds, mode, speed, MakeBridge(dds, allow_sync, allow)) {}
  SimNode& sim() { return run_.sim(); }
  SimprotoBridge& bridge() { return run_.bridge(); }
  uint16_t control = 0, blue = 0, yellow = 0, sync = 0;  // set before run_ starts

 private:
  std::unique_ptr<SimprotoBridge> MakeBridge(const dds::ParticipantOptions& dds, bool allow_sync,
                                             const SourceAllowlists& allow) {
    auto bo = test::OnDds<SimprotoBridgeOptions>(dds);
    bo.listen = "127.0.0.1";
    bo.control_port = control = FreePort();
    bo.blue_port = blue = FreePort();
    bo.yellow_port = yellow = FreePort();
    bo.sync_port = sync = FreePort();
    bo.sync = allow_sync;  // most tests here drive the match synchronously
    bo.allow = allow;
    return std::make_unique<SimprotoBridge>(bo);
  }
  test::SimAndBridge<SimprotoBridge> run_;
};

// A team (or training loop) on UDP: one socket (on `ip`, a loopback address), request and answer.
class Team {
 public:
  explicit Team(const std::string& ip = "127.0.0.1") : socket_(test::BindUdp(ip)) {}
  // nullopt (and a failure) if there is no answer within `timeout`.
  std::optional<std::vector<uint8_t>> Ask(uint16_t port, const std::vector<uint8_t>& bytes,
                                          std::chrono::milliseconds timeout = 3s) {
    const std::optional<UdpEndpoint> to = MakeEndpoint("127.0.0.1", port);
    if (!socket_.valid() || !to) {
      ADD_FAILURE() << "no socket or no endpoint";
      return std::nullopt;
    }
    while (socket_.Receive(65536, 0ms)) {
    }  // drop late answers
    std::string error;
    EXPECT_TRUE(socket_.SendTo(bytes, *to, &error)) << error;
    std::optional<Datagram> d = socket_.Receive(65536, timeout);
    if (!d) return std::nullopt;
    return d->bytes;
  }
  template <class Request, class Response>
  bool Ask(uint16_t port, const Request& request, Response* response) {
    std::vector<uint8_t> bytes(request.ByteSizeLong());
    request.SerializePartialToArray(bytes.data(), static_cast<int>(bytes.size()));
    const auto answer = Ask(port, bytes);
    return answer && response->ParseFromArray(answer->data(), static_cast<int>(answer->size()));
  }
  // Until the bridge has seen turf-sim (an empty control command answers without errors).
  bool WaitReady(uint16_t control_port) {
    const auto end = Clock::now() + 8s;
    while (Clock::now() < end) {
      ws::SimulatorCommand ping;
      ping.mutable_control();
      ws::SimulatorResponse r;
      if (Ask(control_port, ping, &r) && r.errors_size() == 0) return true;
      std::this_thread::sleep_for(20ms);
    }
    return false;
  }

 private:
  UdpSocket socket_;
};

// turf-sim and the bridge, a team on UDP and a DDS observer of the world, on
// the test's own domain and prefix.
struct Rig {
  Rig(Scene scene, TimeMode mode, double speed = 1.0, const SourceAllowlists& allow = {})
      : stack(std::move(scene), dds, mode, speed, /*allow_sync=*/true, allow), world(dds) {}
  // The bridge answers for turf-sim.
  bool Ready() { return team.WaitReady(stack.control); }

  const dds::ParticipantOptions dds = UniqueDds();
  Stack stack;
  Team team;
  test::WorldObserver world;
};

const idl::RobotState& FindRobot(const idl::WorldState& s, idl::Team team, int id) {
  for (const auto& r : s.robots())
    if (r.team() == team && r.id() == id) return r;
  static const idl::RobotState none;
  ADD_FAILURE() << "no robot " << id;
  return none;
}

ws::RobotCommand* AddLocal(ws::RobotControl* rc, uint32_t id, float forward, float left = 0.0f) {
  ws::RobotCommand* c = rc->add_robot_commands();
  c->set_id(id);
  auto* v = c->mutable_move_command()->mutable_local_velocity();
  v->set_forward(forward);
  v->set_left(left);
  v->set_angular(0.0f);
  return c;
}

bool HasError(const google::protobuf::RepeatedPtrField<ws::SimulatorError>& errors, const std::string& code) {
  for (const auto& e : errors)
    if (e.code() == code) return true;
  return false;
}

// A positive marker for negative checks: teleports the ball to (x, y) through
// the control port and waits for a world state that shows it. turf-sim handles
// requests in order, so that state comes after everything asked before.
bool BallMarker(Team& team, uint16_t control_port, test::WorldObserver& world, float x, float y) {
  ws::SimulatorCommand c;
  c.mutable_control()->mutable_teleport_ball()->set_x(x);
  c.mutable_control()->mutable_teleport_ball()->set_y(y);
  ws::SimulatorResponse r;
  if (!team.Ask(control_port, c, &r) || r.errors_size() != 0) {
    ADD_FAILURE() << "marker teleport refused: " << r.DebugString();
    return false;
  }
  return world.Wait([&](const idl::WorldState& s, const idl::Clock&) {
    return std::abs(s.ball().position().x() - x) < 1e-3 && std::abs(s.ball().position().y() - y) < 1e-3;
  });
}

std::vector<uint8_t> SyncBytes(const ws::SimulationSyncRequest& request) {
  std::vector<uint8_t> bytes(request.ByteSizeLong());
  request.SerializeToArray(bytes.data(), static_cast<int>(bytes.size()));
  return bytes;
}

TEST(SimprotoBridge, LocalVelocityCommandMovesTheRobotAtOneMetrePerSecond) {
  Rig rig(test::OneRobot(), TimeMode::kScaled, 2.0);
  ASSERT_TRUE(rig.Ready());
  ws::RobotControl rc;
  AddLocal(&rc, 0, 1.0f);
  int64_t t_start = -1;
  double x_start = 0.0;
  int answered = 0;
  ASSERT_TRUE(rig.world.Wait(
      [&](const idl::WorldState& s, const idl::Clock&) {
        ws::RobotControlResponse r;
        if (rig.team.Ask(rig.stack.blue, rc, &r)) {
          ++answered;
          EXPECT_EQ(r.errors_size(), 0);
          EXPECT_EQ(r.feedback_size(), 1);
        }
        const idl::RobotState& robot = FindRobot(s, idl::TEAM_BLUE, 0);
        if (t_start < 0 && s.sim_time_ns() > 700'000'000) {
          t_start = s.sim_time_ns();
          x_start = robot.position().x();
        }
        return t_start >= 0 && s.sim_time_ns() - t_start >= 700'000'000;
      },
      10s));
  const idl::WorldState& s = rig.world.state();
  const double speed =
      (FindRobot(s, idl::TEAM_BLUE, 0).position().x() - x_start) / ((s.sim_time_ns() - t_start) * 1e-9);
  EXPECT_NEAR(speed, 1.0, 0.05);
  EXPECT_NEAR(FindRobot(s, idl::TEAM_BLUE, 0).position().y(), 0.0, 0.01);
  EXPECT_GT(answered, 20);
}

TEST(SimprotoBridge, TeleportsBallAndRobotsOnAndOffTheField) {
  Rig rig(test::Teams(2), TimeMode::kScaled, 2.0);
  ASSERT_TRUE(rig.Ready());
  ws::SimulatorCommand c;
  auto* ball = c.mutable_control()->mutable_teleport_ball();
  ball->set_x(1.0f);
  ball->set_y(-2.0f);
  ws::TeleportRobot* on = c.mutable_control()->add_teleport_robot();
  on->mutable_id()->set_id(0);
  on->mutable_id()->set_team(ws::BLUE);
  on->set_x(-3.0f);
  on->set_y(1.5f);
  on->set_orientation(1.0f);
  on->set_present(true);
  ws::TeleportRobot* off = c.mutable_control()->add_teleport_robot();
  off->mutable_id()->set_id(1);
  off->mutable_id()->set_team(ws::YELLOW);
  off->set_present(false);
  ws::SimulatorResponse r;
  ASSERT_TRUE(rig.team.Ask(rig.stack.control, c, &r));
  EXPECT_EQ(r.errors_size(), 0) << r.DebugString();
  ASSERT_TRUE(rig.world.Wait([](const idl::WorldState& s, const idl::Clock&) {
    const idl::RobotState& b0 = FindRobot(s, idl::TEAM_BLUE, 0);
    return std::abs(b0.position().x() + 3.0) < 0.01 && std::abs(b0.position().y() - 1.5) < 0.01 &&
           std::abs(b0.yaw() - 1.0) < 0.01 && !FindRobot(s, idl::TEAM_YELLOW, 1).on_field() &&
           std::abs(s.ball().position().x() - 1.0) < 0.01 && std::abs(s.ball().position().y() + 2.0) < 0.01;
  }));

  // Back on the field where it was asked for; a teleport beyond the walls is refused as a whole.
  ws::SimulatorCommand back;
  ws::TeleportRobot* y1 = back.mutable_control()->add_teleport_robot();
  y1->mutable_id()->set_id(1);
  y1->mutable_id()->set_team(ws::YELLOW);
  y1->set_x(2.0f);
  y1->set_y(2.0f);
  y1->set_present(true);
  ASSERT_TRUE(rig.team.Ask(rig.stack.control, back, &r));
  EXPECT_EQ(r.errors_size(), 0) << r.DebugString();
  ASSERT_TRUE(rig.world.Wait([](const idl::WorldState& s, const idl::Clock&) {
    const idl::RobotState& y = FindRobot(s, idl::TEAM_YELLOW, 1);
    return y.on_field() && std::abs(y.position().x() - 2.0) < 0.01;
  }));
  ws::SimulatorCommand outside;
  outside.mutable_control()->mutable_teleport_ball()->set_x(0.0f);
  outside.mutable_control()->add_teleport_robot()->CopyFrom(*y1);
  outside.mutable_control()->mutable_teleport_robot(0)->set_x(50.0f);
  ASSERT_TRUE(rig.team.Ask(rig.stack.control, outside, &r));
  ASSERT_EQ(r.errors_size(), 1);
  EXPECT_EQ(r.errors(0).code(), "TURF_OUTSIDE_FIELD");
  // Marker: a later teleport of yellow 1; once it shows, the refused one would have too.
  ws::SimulatorCommand marker;
  ws::TeleportRobot* y1_marker = marker.mutable_control()->add_teleport_robot();
  y1_marker->CopyFrom(*y1);
  y1_marker->set_x(2.5f);
  ASSERT_TRUE(rig.team.Ask(rig.stack.control, marker, &r));
  EXPECT_EQ(r.errors_size(), 0) << r.DebugString();
  ASSERT_TRUE(rig.world.Wait([](const idl::WorldState& s, const idl::Clock&) {
    return std::abs(FindRobot(s, idl::TEAM_YELLOW, 1).position().x() - 2.5) < 0.01;
  }));
  EXPECT_NEAR(rig.world.state().ball().position().x(), 1.0, 0.05);  // the ball did not go to x = 0
  EXPECT_NEAR(FindRobot(rig.world.state(), idl::TEAM_YELLOW, 1).position().y(), 2.0, 0.05);
}

TEST(SimprotoBridge, SimulationSpeedReallyChangesTurfSimsClock) {
  Rig rig(test::OneRobot(), TimeMode::kRealtime);
  ASSERT_TRUE(rig.Ready());
  auto speed = [&](float s) {
    ws::SimulatorCommand c;
    c.mutable_control()->set_simulation_speed(s);
    ws::SimulatorResponse r;
    EXPECT_TRUE(rig.team.Ask(rig.stack.control, c, &r));
    EXPECT_EQ(r.errors_size(), 0) << r.DebugString();
  };
  speed(2.0f);
  EXPECT_TRUE(rig.world.Wait([](const idl::WorldState&, const idl::Clock& c) {
    return c.mode() == idl::TIME_SCALED && c.speed() == 2.0 && !c.paused();
  }));
  speed(0.0f);
  EXPECT_TRUE(rig.world.Wait([](const idl::WorldState&, const idl::Clock& c) { return c.paused(); }));
  speed(1.0f);
  EXPECT_TRUE(rig.world.Wait(
      [](const idl::WorldState&, const idl::Clock& c) { return c.mode() == idl::TIME_REALTIME && !c.paused(); }));
}

TEST(SimprotoBridge, TeamPortsCommandOnlyTheirTeamAndAnswerContactForEveryRobot) {
  Scene scene = test::Teams(2);
  scene.ball_start_x = scene.robots[0].pose.x + 0.08 + 0.0215 + 0.001;  // at blue 0's front face
  scene.ball_start_y = scene.robots[0].pose.y;
  Rig rig(scene, TimeMode::kScaled, 2.0);
  ASSERT_TRUE(rig.Ready());
  ws::RobotControl rc;
  AddLocal(&rc, 0, 0.0f)->set_dribbler_speed(1000.0f);
  AddLocal(&rc, 1, 0.0f, 1.0f);  // blue 1 drives left; yellow 1 must not
  ASSERT_TRUE(rig.world.Wait([](auto&, auto&) { return true; }));
  const idl::RobotState yellow_start = FindRobot(rig.world.state(), idl::TEAM_YELLOW, 1);
  bool contact_seen = false;
  const int64_t t0 = rig.world.state().sim_time_ns();
  ASSERT_TRUE(rig.world.Wait(
      [&](const idl::WorldState& s, const idl::Clock&) {
        ws::RobotControlResponse r;
        if (rig.team.Ask(rig.stack.blue, rc, &r)) {
          EXPECT_EQ(r.errors_size(), 0);
          EXPECT_EQ(r.feedback_size(), 2);  // every commanded robot
          for (const auto& f : r.feedback())
            if (f.id() == 0 && f.dribbler_ball_contact()) contact_seen = true;
        }
        return s.sim_time_ns() - t0 > 800'000'000;
      },
      8s));
  EXPECT_TRUE(contact_seen);
  const idl::WorldState& s = rig.world.state();
  EXPECT_GT(FindRobot(s, idl::TEAM_BLUE, 1).position().y() - scene.robots[1].pose.y, 0.3);
  EXPECT_NEAR(FindRobot(s, idl::TEAM_YELLOW, 1).position().y(), yellow_start.position().y(), 1e-6);
  EXPECT_NEAR(FindRobot(s, idl::TEAM_YELLOW, 1).position().x(), yellow_start.position().x(), 1e-6);
}

TEST(SimprotoBridge, BadDatagramsAreAnsweredAndChangeNothing) {
  Rig rig(test::OneRobot(), TimeMode::kScaled, 2.0);
  ASSERT_TRUE(rig.Ready());
  ASSERT_TRUE(rig.world.Wait([](auto&, auto&) { return true; }));
  const idl::WorldState before = rig.world.state();

  ws::RobotControl nan_cmd;
  AddLocal(&nan_cmd, 0, std::nanf(""));
  ws::RobotControl good_and_16;
  AddLocal(&good_and_16, 0, 1.0f);
  AddLocal(&good_and_16, 16, 1.0f);
  ws::SimulatorCommand nan_teleport;
  nan_teleport.mutable_control()->mutable_teleport_ball()->set_x(0.0f);
  nan_teleport.mutable_control()->mutable_teleport_ball()->set_y(std::nanf(""));
  ws::SimulatorCommand geometry;
  geometry.mutable_config()->set_vision_port(10006);
  const std::vector<uint8_t> garbage = {0xFF, 0xFF, 0x01, 0x02};
  for (int round = 0; round < 3; ++round) {
    ws::RobotControlResponse r;
    ASSERT_TRUE(rig.team.Ask(rig.stack.blue, nan_cmd, &r));
    EXPECT_TRUE(HasError(r.errors(), "TURF_NOT_FINITE"));
    EXPECT_EQ(r.feedback_size(), 0);
    ASSERT_TRUE(rig.team.Ask(rig.stack.blue, good_and_16, &r));
    EXPECT_TRUE(HasError(r.errors(), "TURF_UNKNOWN_ROBOT"));
    const auto g = rig.team.Ask(rig.stack.yellow, garbage);
    ASSERT_TRUE(g.has_value());
    ASSERT_TRUE(r.ParseFromArray(g->data(), static_cast<int>(g->size())));
    EXPECT_TRUE(HasError(r.errors(), "TURF_MALFORMED"));
    ws::SimulatorResponse sr;
    ASSERT_TRUE(rig.team.Ask(rig.stack.control, nan_teleport, &sr));
    EXPECT_TRUE(HasError(sr.errors(), "TURF_NOT_FINITE"));
    ASSERT_TRUE(rig.team.Ask(rig.stack.control, geometry, &sr));
    EXPECT_TRUE(HasError(sr.errors(), "TURF_UNSUPPORTED_CONFIG_VISION_PORT"));
    ASSERT_TRUE(rig.team.Ask(rig.stack.control, std::vector<uint8_t>{}).has_value());  // empty: answered too
    ws::SimulationSyncResponse sync;
    const auto sg = rig.team.Ask(rig.stack.sync, garbage);
    ASSERT_TRUE(sg.has_value());
    ASSERT_TRUE(sync.ParseFromArray(sg->data(), static_cast<int>(sg->size())));
    EXPECT_TRUE(HasError(sync.robot_control_response().errors(), "TURF_MALFORMED"));
  }
  const int64_t t0 = rig.world.state().sim_time_ns();
  ASSERT_TRUE(
      rig.world.Wait([&](const idl::WorldState& s, const idl::Clock&) { return s.sim_time_ns() - t0 > 300'000'000; }));
  const idl::RobotState& r = FindRobot(rig.world.state(), idl::TEAM_BLUE, 0);
  EXPECT_DOUBLE_EQ(r.position().x(), FindRobot(before, idl::TEAM_BLUE, 0).position().x());
  EXPECT_DOUBLE_EQ(r.position().y(), FindRobot(before, idl::TEAM_BLUE, 0).position().y());
  EXPECT_DOUBLE_EQ(rig.world.state().ball().position().x(), before.ball().position().x());
  EXPECT_EQ(rig.world.clock().mode(), idl::TIME_SCALED);  // the sync garbage did not switch to lockstep
  EXPECT_EQ(rig.stack.bridge().Rejected("blue.not_finite"), 3u);
  EXPECT_EQ(rig.stack.bridge().Rejected("blue.unknown_robot"), 3u);
  EXPECT_EQ(rig.stack.bridge().Rejected("yellow.malformed"), 3u);
  EXPECT_EQ(rig.stack.bridge().Rejected("control.not_finite"), 3u);
  EXPECT_EQ(rig.stack.bridge().Rejected("control.unsupported"), 3u);
  EXPECT_EQ(rig.stack.bridge().Rejected("control.empty"), 3u);
  EXPECT_EQ(rig.stack.bridge().Rejected("sync.malformed"), 3u);
  EXPECT_EQ(rig.stack.sim().Stats().rejected, 0u);  // nothing bad reached turf-sim
}

// N sync requests of 16 ms: exactly N x 8 physics steps, the frames captured in
// each step in its response, and the same bytes on a second run.
std::vector<std::vector<uint8_t>> SyncRun(TimeMode start_mode, int n, uint64_t* frame_after) {
  Rig rig(test::Teams(2), start_mode, 1.0);
  EXPECT_TRUE(rig.Ready());
  std::vector<std::vector<uint8_t>> responses;
  for (int i = 0; i < n; ++i) {
    ws::SimulationSyncRequest req;
    req.set_sim_step(0.016f);
    if (i == 0) {
      auto* ball = req.mutable_simulator_command()->mutable_control()->mutable_teleport_ball();
      ball->set_x(1.0f);
      ball->set_y(0.5f);
      ball->set_vx(-1.0f);
    }
    AddLocal(req.mutable_robot_control(), 0, static_cast<float>(std::sin(0.3 * i)), 0.5f);
    AddLocal(req.mutable_robot_control(), 17, 0.0f, 1.0f);  // yellow 1
    const auto answer = rig.team.Ask(rig.stack.sync, SyncBytes(req));
    EXPECT_TRUE(answer.has_value());
    if (!answer) break;
    responses.push_back(*answer);
  }
  EXPECT_TRUE(rig.world.Wait([&](const idl::WorldState& s, const idl::Clock& c) {
    return c.mode() == idl::TIME_LOCKSTEP && s.frame() >= 8u * n;
  }));
  // Nothing steps on its own in lockstep: the frame once a later request has taken effect.
  EXPECT_TRUE(BallMarker(rig.team, rig.stack.control, rig.world, -1.0f, -2.0f));
  *frame_after = rig.world.state().frame();
  return responses;
}

TEST(SimprotoBridge, SyncModeStepsExactlyAndIsReproducible) {
  constexpr int kRequests = 12;
  uint64_t frame_a = 0, frame_b = 0;
  const auto a = SyncRun(TimeMode::kLockstep, kRequests, &frame_a);
  const auto b = SyncRun(TimeMode::kLockstep, kRequests, &frame_b);
  EXPECT_EQ(frame_a, 8u * kRequests);
  EXPECT_EQ(frame_b, 8u * kRequests);
  ASSERT_EQ(a.size(), static_cast<size_t>(kRequests));
  ASSERT_EQ(b.size(), a.size());
  int detections = 0;
  for (int i = 0; i < kRequests; ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(a[i], b[i]);  // the same requests give the same bytes
    ws::SimulationSyncResponse r;
    ASSERT_TRUE(r.ParseFromArray(a[i].data(), static_cast<int>(a[i].size())));
    EXPECT_EQ(r.robot_control_response().errors_size(), 0) << r.DebugString();
    ASSERT_EQ(r.robot_control_response().feedback_size(), 2);
    EXPECT_EQ(r.robot_control_response().feedback(1).id(), 17u);
    for (const auto& d : r.detection()) {
      EXPECT_GT(d.t_capture(), 0.016 * i - 1e-9);  // captured during this request's step
      EXPECT_LE(d.t_capture(), 0.016 * (i + 1) + 1e-9);
      ++detections;
    }
  }
  // 60 Hz over 12 x 16 ms: captures at 18, 34, ..., 184 ms (11), four cameras each.
  EXPECT_EQ(detections, 11 * 4);
  ws::SimulationSyncResponse last;
  ASSERT_TRUE(last.ParseFromArray(a.back().data(), static_cast<int>(a.back().size())));
  ASSERT_EQ(last.detection_size(), 4);
  int yellow_seen = 0;
  for (const auto& d : last.detection()) yellow_seen += d.robots_yellow_size();
  EXPECT_EQ(yellow_seen, 2);
}

// Synchronous mode is the choice of whoever starts the match: without it, a sync request from anyone is answered
// TURF_SYNC_DISABLED and the match runs on (one such datagram used to stop vision for every team).
TEST(SimprotoBridge, SyncRequestsAreRefusedUnlessTheMatchAllowsThem) {
  const auto dds = UniqueDds();
  Stack stack(test::Teams(2), dds, TimeMode::kRealtime, 1.0, /*sync=*/false);
  Team team;
  ASSERT_TRUE(team.WaitReady(stack.control));
  ws::SimulationSyncRequest request;
  request.set_sim_step(1.0f / 60);
  ws::SimulationSyncResponse response;
  ASSERT_TRUE(team.Ask(stack.sync, request, &response));
  bool refused = false;
  for (const auto& e : response.robot_control_response().errors())
    refused = refused || e.code() == "TURF_SYNC_DISABLED";
  EXPECT_TRUE(refused) << response.DebugString();
  EXPECT_EQ(stack.bridge().Rejected("sync.disabled"), 1u);
  // The match is still in real time: turf-sim's frame keeps advancing without anyone stepping it.
  const uint64_t frame = stack.sim().Stats().frame;
  const auto deadline = Clock::now() + 10s;
  while (stack.sim().Stats().frame < frame + 50 && Clock::now() < deadline) std::this_thread::sleep_for(5ms);
  EXPECT_GE(stack.sim().Stats().frame, frame + 50) << "turf-sim stopped: it was switched to lockstep";
}

TEST(SimprotoBridge, SyncRequestSwitchesARunningSimToLockstep) {
  uint64_t frame = 0;
  const auto responses = SyncRun(TimeMode::kRealtime, 3, &frame);
  ASSERT_EQ(responses.size(), 3u);
  for (const auto& bytes : responses) {
    ws::SimulationSyncResponse r;
    ASSERT_TRUE(r.ParseFromArray(bytes.data(), static_cast<int>(bytes.size())));
    EXPECT_EQ(r.robot_control_response().errors_size(), 0) << r.DebugString();
  }
}

// What every 60 Hz loop sends: 1/60 s is 8.33 physics steps of 2 ms. 60
// requests reach 1.000 s (within half a step, here exactly 500 steps), every
// response carries the frames of the time actually reached, and a request whose
// share rounds to zero steps runs none but still applies its commands.
TEST(SimprotoBridge, SyncStepsOfASixtiethOfASecondReachOneSecondInSixtyRequests) {
  Rig rig(test::Teams(2), TimeMode::kLockstep, 1.0);
  ASSERT_TRUE(rig.Ready());
  ws::SimulationSyncRequest sixtieth;
  sixtieth.set_sim_step(1.0f / 60.0f);
  AddLocal(sixtieth.mutable_robot_control(), 0, 0.0f);
  double newest_capture = 0.0;
  int detections = 0;
  for (int i = 1; i <= 60; ++i) {
    SCOPED_TRACE(i);
    const auto answer = rig.team.Ask(rig.stack.sync, SyncBytes(sixtieth));
    ASSERT_TRUE(answer.has_value());
    ws::SimulationSyncResponse r;
    ASSERT_TRUE(r.ParseFromArray(answer->data(), static_cast<int>(answer->size())));
    ASSERT_EQ(r.robot_control_response().errors_size(), 0) << r.DebugString();
    for (const auto& d : r.detection()) {
      // Captured during this request's steps: each end is within half a step of the time asked for.
      EXPECT_GT(d.t_capture(), (i - 1) / 60.0 - 0.001 - 1e-9);
      EXPECT_LE(d.t_capture(), i / 60.0 + 0.001 + 1e-9);
      EXPECT_GE(d.t_capture(), newest_capture);
      newest_capture = std::max(newest_capture, d.t_capture());
      ++detections;
    }
  }
  EXPECT_EQ(rig.stack.bridge().Rejected("sync.out_of_range"), 0u);
  // Once a later request shows, the world state is that of the last step.
  ASSERT_TRUE(BallMarker(rig.team, rig.stack.control, rig.world, -1.0f, -2.0f));
  EXPECT_NEAR(rig.world.state().sim_time_ns(), 1'000'000'000, 1'000'000);  // 1.000 s +- half a step
  EXPECT_EQ(rig.world.state().frame(), 500u);
  EXPECT_NEAR(newest_capture, 1.0, 0.001);  // the 60th camera frame, captured at the time reached
  EXPECT_EQ(detections, 60 * 4);            // 60 Hz for 1 s, four cameras

  // 0.1 ms is 0.05 steps: none run, the command waits for the next step.
  const idl::RobotState start = FindRobot(rig.world.state(), idl::TEAM_BLUE, 0);
  ws::SimulationSyncRequest tiny;
  tiny.set_sim_step(0.0001f);
  AddLocal(tiny.mutable_robot_control(), 0, 1.0f);
  const auto tiny_answer = rig.team.Ask(rig.stack.sync, SyncBytes(tiny));
  ASSERT_TRUE(tiny_answer.has_value());
  ws::SimulationSyncResponse tr;
  ASSERT_TRUE(tr.ParseFromArray(tiny_answer->data(), static_cast<int>(tiny_answer->size())));
  EXPECT_EQ(tr.robot_control_response().errors_size(), 0) << tr.DebugString();
  EXPECT_EQ(tr.robot_control_response().feedback_size(), 1);
  EXPECT_EQ(tr.detection_size(), 0);
  ASSERT_TRUE(BallMarker(rig.team, rig.stack.control, rig.world, -1.5f, -2.0f));
  EXPECT_EQ(rig.world.state().frame(), 500u);  // no step

  // A step without commands: the held one drives blue 0 forward.
  ws::SimulationSyncRequest drive;
  drive.set_sim_step(0.3f);
  const auto drive_answer = rig.team.Ask(rig.stack.sync, SyncBytes(drive));
  ASSERT_TRUE(drive_answer.has_value());
  ASSERT_TRUE(BallMarker(rig.team, rig.stack.control, rig.world, -2.0f, -2.0f));
  EXPECT_EQ(rig.world.state().frame(), 650u);  // 1.3001 s: 650.05 steps
  const idl::RobotState& moved = FindRobot(rig.world.state(), idl::TEAM_BLUE, 0);
  const double forward = (moved.position().x() - start.position().x()) * std::cos(start.yaw()) +
                         (moved.position().y() - start.position().y()) * std::sin(start.yaw());
  EXPECT_GT(forward, 0.1);
}

// Source allowlists (--blue-allow, --yellow-allow, --operator-allow): from 127.0.0.2, which none holds, each port
// answers TURF_NOT_ALLOWED and nothing moves, teleports or steps; from 127.0.0.1 the same requests work.
TEST(SimprotoBridge, ASenderNotOnThePortsAllowlistMovesNothing) {
  const SourceAllowlists allow{{"127.0.0.1/32"}, {"127.0.0.1/32"}, {"127.0.0.1/32"}};
  Rig rig(test::Teams(1), TimeMode::kScaled, 2.0, allow);
  ASSERT_TRUE(rig.Ready());  // the allowed operator's control port works
  ASSERT_TRUE(rig.world.Wait([](auto&, auto&) { return true; }));
  const idl::WorldState before = rig.world.state();
  Team stranger("127.0.0.2");

  ws::RobotControl forward;
  AddLocal(&forward, 0, 1.0f);
  ws::SimulatorCommand teleport;
  teleport.mutable_control()->mutable_teleport_ball()->set_x(1.5f);
  teleport.mutable_control()->mutable_teleport_ball()->set_y(1.5f);
  ws::SimulationSyncRequest step;
  step.set_sim_step(0.1f);
  AddLocal(step.mutable_robot_control(), 0, 1.0f);
  // Each answer is the positive marker that the bridge has handled (and refused) that datagram.
  for (const uint16_t port : {rig.stack.blue, rig.stack.yellow}) {
    ws::RobotControlResponse r;
    ASSERT_TRUE(stranger.Ask(port, forward, &r));
    EXPECT_TRUE(HasError(r.errors(), "TURF_NOT_ALLOWED")) << r.DebugString();
    EXPECT_EQ(r.feedback_size(), 0);
  }
  ws::SimulatorResponse sr;
  ASSERT_TRUE(stranger.Ask(rig.stack.control, teleport, &sr));
  EXPECT_TRUE(HasError(sr.errors(), "TURF_NOT_ALLOWED")) << sr.DebugString();
  ws::SimulationSyncResponse sync;
  const auto answer = stranger.Ask(rig.stack.sync, SyncBytes(step));
  ASSERT_TRUE(answer.has_value());
  ASSERT_TRUE(sync.ParseFromArray(answer->data(), static_cast<int>(answer->size())));
  EXPECT_TRUE(HasError(sync.robot_control_response().errors(), "TURF_NOT_ALLOWED")) << sync.DebugString();

  // A later teleport from the allowed operator shows; half a simulated second more for anything else to show.
  ASSERT_TRUE(BallMarker(rig.team, rig.stack.control, rig.world, -0.5f, 0.25f));
  const int64_t t0 = rig.world.state().sim_time_ns();
  ASSERT_TRUE(rig.world.Wait([&](const idl::WorldState& s, const idl::Clock&) {
    return s.sim_time_ns() - t0 > 500'000'000;
  })) << "turf-sim's time stopped; time mode "
      << static_cast<int>(rig.world.clock().mode());
  for (const idl::Team team : {idl::TEAM_BLUE, idl::TEAM_YELLOW}) {
    EXPECT_DOUBLE_EQ(FindRobot(rig.world.state(), team, 0).position().x(), FindRobot(before, team, 0).position().x());
    EXPECT_DOUBLE_EQ(FindRobot(rig.world.state(), team, 0).position().y(), FindRobot(before, team, 0).position().y());
  }
  EXPECT_EQ(rig.world.clock().mode(), idl::TIME_SCALED);  // the stranger's sync request did not switch to lockstep
  SimprotoBridge& bridge = rig.stack.bridge();
  for (const char* kind : {"blue.not_allowed", "yellow.not_allowed", "control.not_allowed", "sync.not_allowed"})
    EXPECT_EQ(bridge.Rejected(kind), 1u) << kind;
  EXPECT_EQ(bridge.Stats().not_allowed, 4u);
  EXPECT_EQ(bridge.Stats().commands, 0u);
  EXPECT_EQ(rig.stack.sim().Stats().rejected, 0u);  // nothing reached turf-sim

  // The allowed team's commands move its robot.
  ASSERT_TRUE(rig.world.Wait(
      [&](const idl::WorldState& s, const idl::Clock&) {
        ws::RobotControlResponse r;
        EXPECT_TRUE(rig.team.Ask(rig.stack.blue, forward, &r));
        EXPECT_EQ(r.errors_size(), 0) << r.DebugString();
        return FindRobot(s, idl::TEAM_BLUE, 0).position().x() - FindRobot(before, idl::TEAM_BLUE, 0).position().x() >
               0.05;
      },
      10s));
  EXPECT_EQ(bridge.Stats().not_allowed, 4u);
}

}  // namespace
}  // namespace turf
