// turf-sim's SSL node and a client in one process (tests/sim/sim_harness.h), on a MemoryBus; one test also over
// a private DDS domain. Waits are bounded; assertions are on the simulated state.
#include "tests/sim/sim_harness.h"

namespace turf::test {
namespace {

// One blue robot at twice real time, and a client that turf-sim has matched.
class SslNode : public ::testing::TestWithParam<Transport> {
 protected:
  void SetUp() override { ASSERT_TRUE(client.WaitMatched()); }

  const TestTransport net{GetParam()};
  SimUnderTest sim{test::OneRobot(), net, TimeMode::kScaled, 2.0};
  Client client{net};
};
INSTANTIATE_TEST_SUITE_P(On, SslNode, ::testing::Values(Transport::kMemory), TransportName);

// The same, also over DDS (the node's DDS adapter and a team stack's path).
class SslNodeAnyTransport : public SslNode {};
INSTANTIATE_TEST_SUITE_P(On, SslNodeAnyTransport, ::testing::Values(Transport::kMemory, Transport::kDds),
                         TransportName);

// Scenes of their own, on a MemoryBus.
class SslNodeScenes : public ::testing::TestWithParam<Transport> {};
INSTANTIATE_TEST_SUITE_P(On, SslNodeScenes, ::testing::Values(Transport::kMemory), TransportName);

TEST_P(SslNodeAnyTransport, CommandMovesRobotAsSeenInWorldState) {
  // Drive forward at 1 m/s, re-sending at ~60 Hz like a team, for 1.5 s of sim time.
  const auto cmd = LocalVelocity(idl::TEAM_BLUE, 0, 1.0, 0.0, 0.0);
  int64_t t_start = -1;
  double x_start = 0.0;
  const bool reached = client.WaitState(
      [&](const idl::WorldState& s) {
        client.Command(cmd);
        const idl::RobotState* r = FindRobot(s, idl::TEAM_BLUE, 0);
        if (r == nullptr) return false;
        // Measure over the second half, after the 1/3 s ramp.
        if (t_start < 0 && s.sim_time_ns() > 700'000'000) {
          t_start = s.sim_time_ns();
          x_start = r->position().x();
        }
        return t_start >= 0 && s.sim_time_ns() - t_start >= 700'000'000;
      },
      10s);
  ASSERT_TRUE(reached);
  const idl::RobotState* r = FindRobot(client.state(), idl::TEAM_BLUE, 0);
  ASSERT_NE(r, nullptr);
  const double speed = (r->position().x() - x_start) / ((client.state().sim_time_ns() - t_start) * 1e-9);
  EXPECT_NEAR(speed, 1.0, 0.05);
  EXPECT_NEAR(r->linear_velocity().x(), 1.0, 0.05);
  EXPECT_NEAR(r->position().y(), 0.0, 0.01);
}

TEST_P(SslNode, WatchdogStopsARobotWhoseCommandsStop) {
  const auto cmd = LocalVelocity(idl::TEAM_BLUE, 0, 1.0, 0.0, 0.0);
  ASSERT_TRUE(client.WaitState([&](const idl::WorldState& s) {
    client.Command(cmd);
    const idl::RobotState* r = FindRobot(s, idl::TEAM_BLUE, 0);
    return r != nullptr && r->linear_velocity().x() > 0.9;
  }));
  // Silence: the robot must stop by itself within timeout + braking time.
  const int64_t silent_from = client.state().sim_time_ns();
  ASSERT_TRUE(
      client.WaitState([&](const idl::WorldState& s) { return s.sim_time_ns() - silent_from > 1'200'000'000; }));
  const idl::RobotState* r = FindRobot(client.state(), idl::TEAM_BLUE, 0);
  ASSERT_NE(r, nullptr);
  EXPECT_NEAR(r->linear_velocity().x(), 0.0, 0.01);
}

TEST_P(SslNode, ControlTeleportsPausesStepsAndResets) {
  auto pause = client.Control(Op(idl::OP_PAUSE));
  ASSERT_TRUE(pause.has_value());
  EXPECT_EQ(pause->result(), idl::RESULT_OK);
  const uint64_t paused_frame = pause->frame();
  // Time stands still: later requests, each handled in a turn of turf-sim's
  // loop that would have stepped if it could, are answered at the same frame.
  for (int i = 0; i < 5; ++i) {
    const auto probe = client.Control(Op(idl::OP_PAUSE));
    ASSERT_TRUE(Ok(probe));
    EXPECT_EQ(probe->frame(), paused_frame);
  }
  ASSERT_TRUE(client.WaitClock([](const idl::Clock& c) { return c.paused(); }));
  EXPECT_EQ(client.clock().frame(), paused_frame);

  idl::SimControl tb = Op(idl::OP_TELEPORT_BALL);
  tb.ball().position().x(1.0);
  tb.ball().position().y(-2.0);
  auto teleported = client.Control(tb);
  ASSERT_TRUE(teleported.has_value());
  EXPECT_EQ(teleported->result(), idl::RESULT_OK);
  ASSERT_TRUE(client.WaitState([](const idl::WorldState& s) {
    return std::abs(s.ball().position().x() - 1.0) < 1e-6 && std::abs(s.ball().position().y() + 2.0) < 1e-6;
  }));

  idl::SimControl tr = Op(idl::OP_TELEPORT_ROBOT);
  tr.robot().team(idl::TEAM_BLUE);
  tr.robot().id(0);
  tr.robot().on_field(true);
  tr.robot().position().x(-3.0);
  tr.robot().position().y(1.5);
  tr.robot().orientation(1.0);
  ASSERT_TRUE(Ok(client.Control(tr)));
  ASSERT_TRUE(client.WaitState([](const idl::WorldState& s) {
    const auto* r = FindRobot(s, idl::TEAM_BLUE, 0);
    return r != nullptr && std::abs(r->position().x() + 3.0) < 1e-6 && std::abs(r->yaw() - 1.0) < 1e-6;
  }));

  idl::SimControl outside = tb;
  outside.ball().position().x(50.0);
  auto refused = client.Control(outside);
  ASSERT_TRUE(refused.has_value());
  EXPECT_EQ(refused->result(), idl::RESULT_REJECTED);
  EXPECT_NE(refused->reason().find("outside_field"), std::string::npos) << refused->reason();

  idl::SimControl step = Op(idl::OP_STEP);
  step.step_count(25);
  auto stepped = client.Control(step);
  ASSERT_TRUE(stepped.has_value());
  EXPECT_EQ(stepped->result(), idl::RESULT_OK);
  EXPECT_EQ(stepped->frame(), paused_frame + 25);

  ASSERT_TRUE(Ok(client.Control(Op(idl::OP_RESUME))));
  ASSERT_TRUE(client.WaitState([&](const idl::WorldState& s) { return s.frame() > paused_frame + 100; }));

  auto reset = client.Control(Op(idl::OP_RESET));
  ASSERT_TRUE(reset.has_value());
  EXPECT_EQ(reset->result(), idl::RESULT_OK);
  EXPECT_EQ(reset->frame(), 0u);
  ASSERT_TRUE(client.WaitState([](const idl::WorldState& s) {
    const auto* r = FindRobot(s, idl::TEAM_BLUE, 0);
    return r != nullptr && s.frame() < 200 && std::abs(r->position().x()) < 1e-3;  // back at the scene's start
  }));
}

TEST_P(SslNode, BadSamplesAreCountedAndMoveNothing) {
  auto nan = LocalVelocity(idl::TEAM_BLUE, 0, NAN, 0.0, 0.0);
  auto huge = LocalVelocity(idl::TEAM_BLUE, 0, 1e9, 0.0, 0.0);
  auto unknown = LocalVelocity(idl::TEAM_BLUE, 9, 1.0, 0.0, 0.0);
  auto wrong_team = LocalVelocity(idl::TEAM_BLUE, 0, 1.0, 0.0, 0.0);  // sent on the yellow topic
  auto bad_enum = LocalVelocity(idl::TEAM_BLUE, 0, 1.0, 0.0, 0.0);
  bad_enum.move(static_cast<idl::MoveKind>(77));
  const int64_t t0 = client.state().sim_time_ns();
  ASSERT_TRUE(client.WaitState([&](const idl::WorldState& s) {
    client.Command(nan);
    client.Command(huge);
    client.Command(unknown);
    client.CommandOnTopic(Team::kYellow, wrong_team);
    client.Command(bad_enum);
    return s.sim_time_ns() - t0 > 500'000'000;
  }));
  const idl::RobotState* r = FindRobot(client.state(), idl::TEAM_BLUE, 0);
  ASSERT_NE(r, nullptr);
  EXPECT_DOUBLE_EQ(r->position().x(), 0.0);
  EXPECT_DOUBLE_EQ(r->position().y(), 0.0);
  for (const char* kind :
       {"command.not_finite", "command.out_of_range", "command.unknown_robot", "command.team_mismatch"})
    EXPECT_GT(sim.node().Rejected(kind), 0u) << kind;
}

TEST_P(SslNodeScenes, CamerasReportWhatEachCameraSees) {
  const TestTransport net(GetParam());
  Scene scene = test::Teams(2);  // blue 0, 1 and yellow 0, 1
  SimUnderTest sim(scene, net, TimeMode::kScaled, 2.0);
  Client client(net);
  ASSERT_TRUE(client.WaitMatched());
  const auto pause = client.Control(Op(idl::OP_PAUSE));
  ASSERT_TRUE(Ok(pause));
  const int64_t paused_at = pause->sim_time_ns();
  auto place = [&](idl::Team team, int id, double x, double y) {
    idl::SimControl tr = Op(idl::OP_TELEPORT_ROBOT);
    tr.robot().team(team);
    tr.robot().id(static_cast<uint8_t>(id));
    tr.robot().on_field(true);
    tr.robot().position().x(x);
    tr.robot().position().y(y);
    ASSERT_TRUE(Ok(client.Control(tr)));
  };
  place(idl::TEAM_BLUE, 0, 3.0, 2.0);     // camera 0 only
  place(idl::TEAM_BLUE, 1, -3.0, -2.0);   // camera 2 only
  place(idl::TEAM_YELLOW, 0, 0.05, 3.0);  // in the overlap of cameras 0 and 1
  if (HasFatalFailure()) return;
  idl::SimControl off = Op(idl::OP_TELEPORT_ROBOT);
  off.robot().team(idl::TEAM_YELLOW);
  off.robot().id(1);
  off.robot().on_field(false);  // off the field: no camera sees it
  ASSERT_TRUE(Ok(client.Control(off)));
  idl::SimControl tb = Op(idl::OP_TELEPORT_BALL);
  tb.ball().position().x(-2.0);
  tb.ball().position().y(1.0);  // camera 1
  ASSERT_TRUE(Ok(client.Control(tb)));
  idl::SimControl step = Op(idl::OP_STEP);
  step.step_count(20);  // 40 ms: at least two camera frames
  ASSERT_TRUE(Ok(client.Control(step)));
  // Every camera's newest frame is of one capture after the teleports (made
  // while paused at `paused_at`), and the latched field arrived.
  auto& cams = client.cameras();
  ASSERT_TRUE(client.WaitFor([&] {
    if (cams.size() != 4 || !client.field()) return false;
    for (const auto& [id, frame] : cams)
      if (frame.capture_time_ns() <= paused_at || frame.capture_time_ns() != cams.begin()->second.capture_time_ns())
        return false;
    return true;
  })) << cams.size()
      << " cameras";
  auto sees = [&](uint32_t cam, idl::Team team, int id) {
    for (const auto& r : cams[cam].robots())
      if (r.team() == team && r.id() == id) return true;
    return false;
  };
  EXPECT_TRUE(sees(0, idl::TEAM_BLUE, 0));
  EXPECT_FALSE(sees(1, idl::TEAM_BLUE, 0));
  EXPECT_TRUE(sees(2, idl::TEAM_BLUE, 1));
  EXPECT_TRUE(sees(0, idl::TEAM_YELLOW, 0));
  EXPECT_TRUE(sees(1, idl::TEAM_YELLOW, 0));
  EXPECT_FALSE(sees(2, idl::TEAM_YELLOW, 0));
  for (uint32_t c = 0; c < 4; ++c) EXPECT_FALSE(sees(c, idl::TEAM_YELLOW, 1));
  EXPECT_EQ(cams[1].balls().size(), 1u);
  EXPECT_EQ(cams[0].balls().size(), 0u);
  EXPECT_NEAR(cams[1].balls()[0].position().x(), -2.0, 1e-3);
  EXPECT_EQ(cams[1].capture_time_ns(), cams[0].capture_time_ns());
  // The latched field arrived too.
  ASSERT_TRUE(client.field().has_value());
  EXPECT_EQ(client.field()->cameras().size(), 4u);
  EXPECT_DOUBLE_EQ(client.field()->field_length(), 12.0);
  EXPECT_EQ(client.field()->robots_per_team(), 2);
  EXPECT_DOUBLE_EQ(client.field()->max_flat_kick_speed(), 6.5);
}

// A STEP's commands are applied all or none: one refused command (NaN, an unknown robot, an unknown team) refuses the
// STEP whole, naming it, and the good command before it moves nothing.
TEST_P(SslNodeScenes, AStepWithOneBadCommandIsRefusedWholeAndMovesNothing) {
  const TestTransport net(GetParam(), "atomic");
  SimUnderTest sim(test::OneRobot(), net, TimeMode::kLockstep);
  Client client(net);
  ASSERT_TRUE(client.WaitMatched(Client::kNoState));
  auto bad_team = LocalVelocity(idl::TEAM_BLUE, 0, 1.0, 0.0, 0.0);
  bad_team.team(static_cast<idl::Team>(7));
  const struct {
    idl::SslRobotCommand bad;
    idl::ControlError error;
  } cases[] = {{LocalVelocity(idl::TEAM_BLUE, 0, NAN, 0.0, 0.0), idl::CONTROL_NOT_FINITE},
               {LocalVelocity(idl::TEAM_BLUE, 9, 1.0, 0.0, 0.0), idl::CONTROL_UNKNOWN_ROBOT},
               {bad_team, idl::CONTROL_UNKNOWN_ENUM}};
  for (const auto& c : cases) {
    idl::SimControl step = StepRequest(10);
    step.commands().push_back(LocalVelocity(idl::TEAM_BLUE, 0, 1.5, 0.0, 0.0));
    step.commands().push_back(c.bad);
    const std::optional<idl::SimControlReply> reply = client.Control(step);
    ASSERT_TRUE(reply);
    EXPECT_EQ(reply->result(), idl::RESULT_REJECTED);
    EXPECT_EQ(reply->error(), c.error) << reply->reason();
    EXPECT_NE(reply->reason().find("command 1 of the STEP"), std::string::npos) << reply->reason();
  }
  ASSERT_TRUE(Ok(client.Control(StepRequest(200))));
  ASSERT_TRUE(client.WaitState([](const idl::WorldState& s) { return s.frame() == 200; }));
  const idl::RobotState* r = FindRobot(client.state(), idl::TEAM_BLUE, 0);
  ASSERT_NE(r, nullptr);
  EXPECT_DOUBLE_EQ(r->position().x(), 0.0) << "a refused STEP's command moved it";
  EXPECT_DOUBLE_EQ(r->position().y(), 0.0);
}

// The same scene and the same lockstep command stream, run twice, give identical worlds.
TEST_P(SslNodeScenes, LockstepRunsAreIdentical) {
  auto run = [&](const char* name) {
    const TestTransport net(GetParam(), name);
    SimUnderTest sim(test::Teams(3), net, TimeMode::kLockstep);
    Client client(net);
    EXPECT_TRUE(client.WaitMatched(Client::kNoState));  // lockstep: no state before the first step
    for (int i = 0; i < 40; ++i) {
      idl::SimControl step = Op(idl::OP_STEP);
      step.step_count(8);
      for (int id = 0; id < 3; ++id)
        step.commands().push_back(LocalVelocity(idl::TEAM_YELLOW, id, std::sin(i * 0.3 + id), 0.5, 2.0));
      EXPECT_TRUE(Ok(client.Control(step)));
    }
    EXPECT_TRUE(client.WaitState([](const idl::WorldState& s) { return s.frame() == 320; }));
    return client.state();
  };
  const idl::WorldState a = run("a");
  const idl::WorldState b = run("b");
  ASSERT_EQ(a.frame(), 320u);
  ASSERT_EQ(a.robots().size(), b.robots().size());
  for (size_t i = 0; i < a.robots().size(); ++i) {
    EXPECT_EQ(a.robots()[i].position().x(), b.robots()[i].position().x());
    EXPECT_EQ(a.robots()[i].position().y(), b.robots()[i].position().y());
    EXPECT_EQ(a.robots()[i].yaw(), b.robots()[i].yaw());
  }
  const idl::RobotState* moved = FindRobot(a, idl::TEAM_YELLOW, 1);
  ASSERT_NE(moved, nullptr);
  EXPECT_GT(std::abs(moved->position().y() - test::Teams(3).robots[4].pose.y), 0.1);
}

}  // namespace
}  // namespace turf::test
