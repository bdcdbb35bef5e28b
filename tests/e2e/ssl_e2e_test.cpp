// End to end with real processes on loopback: turf-sim, turf-grsim-bridge,
// turf-vision-bridge and turf-simproto-bridge, driven by a test client that
// speaks the legacy protocols, as an SSL team's software would (ssl_match.h).
#include "tests/e2e/ssl_match.h"

namespace turf::test {
namespace {

// Every test: turf-sim and the SSL bridges running, the vision stream seen,
// and the team's socket.
class SslEndToEnd : public ::testing::Test {
 protected:
  void SetUp() override { WaitForVision(m, v); }

  Match m;
  VisionClient v{m.vision_port};
  Udp team;
};

// The ball's x (m) when it rests against the front face of a robot at `robot_x` facing +x.
double BallAtFaceX(double robot_x) { return robot_x + 0.08 + 0.0215 + 0.002; }

// Places blue robot `id` at (x, y) facing +x with the ball resting against its
// front face; true once vision shows both there.
bool PlaceBlueWithBall(Udp& team, Match& m, VisionClient& v, int id, double x, double y) {
  const double ball_x = BallAtFaceX(x);
  return PlaceAndWait(team, GrsimPlace(false, id, x, y, 0.0, ball_x, y), m.grsim_port, v,
                      [&](const VisionClient& c) { return RobotSeenAt(c, 0, id, x, y) && BallSeenAt(c, ball_x, y); });
}

TEST_F(SslEndToEnd, GrsimCommandMovesRobotAtCommandedSpeedInVision) {
  // A free lane of the kick-off formation: y = 2 m, from x = -3 m towards the halfway line.
  ASSERT_TRUE(PlaceAndWait(team, GrsimPlace(false, 3, -3.0, 2.0, 0.0), m.grsim_port, v,
                           [](const VisionClient& c) { return RobotSeenAt(c, 0, 3, -3.0, 2.0); }));
  // Through the 1/3 s ramp, then measure over 0.8 s, all in simulation time.
  const auto a = KeepFor(team, GrsimMove(false, 3, 1.0, 0.0, 0.0), m.grsim_port, v, 0, 3, 0.6);
  const auto b = KeepFor(team, GrsimMove(false, 3, 1.0, 0.0, 0.0), m.grsim_port, v, 0, 3, 0.8);
  ASSERT_TRUE(a && b);
  const double speed = (b->x - a->x) / 1000.0 / (b->t - a->t);
  EXPECT_NEAR(speed, 1.0, 0.05);
  EXPECT_NEAR(b->y, 2000.0, 10.0);
  EXPECT_EQ(v.bad_times, 0);
  EXPECT_EQ(v.unparseable, 0);
  EXPECT_EQ(v.geometry->field().field_length(), 12000);
}

TEST_F(SslEndToEnd, ReplacementPlacesBallAndRobots) {
  ASSERT_TRUE(
      PlaceAndWait(team, GrsimPlace(true, 4, 2.0, -1.5, 90.0, 1.0, 2.0), m.grsim_port, v,
                   [](const VisionClient& c) { return RobotSeenAt(c, 1, 4, 2.0, -1.5) && BallSeenAt(c, 1.0, 2.0); }));
  const auto r = v.Robot(1, 4);
  ASSERT_TRUE(r);
  EXPECT_NEAR(r->x, 2000.0, 5.0);
  EXPECT_NEAR(r->y, -1500.0, 5.0);
  EXPECT_NEAR(r->orientation, M_PI / 2, 0.01);
  EXPECT_NEAR(v.ball.x, 1000.0, 5.0);
  EXPECT_NEAR(v.ball.y, 2000.0, 5.0);
}

TEST_F(SslEndToEnd, KickGivesTheBallTheCommandedSpeed) {
  // Robot at (1, 0) facing +x, ball resting against its front face.
  const double ball_x = BallAtFaceX(1.0);
  ASSERT_TRUE(PlaceBlueWithBall(team, m, v, 5, 1.0, 0.0));
  // One kick command, then plain commands as team software sends them, until
  // the ball has flown 0.6 m.
  v.ball_track.clear();
  team.Send(GrsimMove(false, 5, 0.0, 0.0, 0.0, 4.0), m.grsim_port);
  ASSERT_TRUE(KeepUntil(team, GrsimMove(false, 5, 0.0, 0.0, 0.0), m.grsim_port, v, [&](const VisionClient& c) {
    return c.ball.x > ball_x * 1000.0 + 600.0;
  })) << "the ball never flew 0.6 m";
  // The speed over the flight from 0.1 m to 0.5 m past the face, from vision's
  // simulation-time stamps: the mean speed over [t_i, t_j] plus the sliding
  // deceleration (the scene's 3 m/s^2) over half the window is the speed at
  // t_i, however many frames a loaded machine dropped in between.
  size_t i = 0;
  while (i < v.ball_track.size() && v.ball_track[i].x < ball_x * 1000.0 + 100.0) ++i;
  size_t j = i;
  while (j < v.ball_track.size() && v.ball_track[j].x < ball_x * 1000.0 + 500.0) ++j;
  ASSERT_LT(j, v.ball_track.size());
  ASSERT_GT(v.ball_track[j].t, v.ball_track[i].t);
  const double dt = v.ball_track[j].t - v.ball_track[i].t;
  const double speed = (v.ball_track[j].x - v.ball_track[i].x) / 1000.0 / dt + 3.0 * dt / 2;
  EXPECT_NEAR(speed, 4.0 - 3.0 * 0.1 / 4.0, 0.2);  // at 0.1 m it has slid 25 ms at 3 m/s^2
  EXPECT_NEAR(v.ball.y, 0.0, 20.0);
}

TEST_F(SslEndToEnd, StatusPacketsArriveOnTheTeamsPort) {
  Udp blue_status(m.blue_status_port);
  Udp yellow_status(m.yellow_status_port);
  // The status goes to the address that sent the team's commands: send some first.
  ASSERT_TRUE(KeepForSim(team, GrsimMove(false, 6, 0.0, 0.0, 0.0), m.grsim_port, v, 0.2));
  ASSERT_TRUE(PlaceBlueWithBall(team, m, v, 6, -1.0, -1.0));
  bool infrared = false;
  const auto end = Clock::now() + 15s;
  while (Clock::now() < end && !infrared) {
    team.Send(GrsimMove(false, 6, 0.0, 0.0, 0.0), m.grsim_port);
    if (auto bytes = blue_status.Receive()) {
      wire::grsim::Robots_Status status;
      ASSERT_TRUE(status.ParseFromString(*bytes));
      for (const auto& s : status.robots_status()) infrared = infrared || (s.robot_id() == 6 && s.infrared());
    }
  }
  ASSERT_TRUE(infrared);
  // Blue's status arrived (the positive marker): yellow, which sent nothing, got none.
  EXPECT_FALSE(yellow_status.Receive().has_value());
}

TEST_F(SslEndToEnd, SimulationProtocolMovesOnlyItsOwnTeam) {
  // Teleport blue 2 and yellow 2 through the control port.
  wire::simulation::SimulatorCommand cmd;
  for (auto [team_id, y] : {std::pair{wire::simulation::BLUE, 2.0f}, std::pair{wire::simulation::YELLOW, -2.0f}}) {
    auto* t = cmd.mutable_control()->add_teleport_robot();
    t->mutable_id()->set_id(2);
    t->mutable_id()->set_team(team_id);
    t->set_x(-3.0f);
    t->set_y(y);
    t->set_orientation(0.0f);
    t->set_present(true);
  }
  const auto placed = Command(team, cmd, m.control_port);
  ASSERT_TRUE(placed);
  ASSERT_EQ(placed->errors_size(), 0) << placed->errors(0).message();
  const auto placed_by = Clock::now() + 5s;
  do {
    v.Drain(50ms);
  } while (Clock::now() < placed_by && !(v.Robot(1, 2) && std::abs(v.Robot(1, 2)->x + 3000.0) < 5.0));
  const auto yellow_before = v.Robot(1, 2);
  ASSERT_TRUE(yellow_before);
  EXPECT_NEAR(yellow_before->x, -3000.0, 5.0);
  // The blue port commands blue 2 only.
  const auto a = KeepFor(team, SimprotoMove(2, 1.0), m.blue_port, v, 0, 2, 0.6);
  const auto b = KeepFor(team, SimprotoMove(2, 1.0), m.blue_port, v, 0, 2, 0.8);
  ASSERT_TRUE(a && b);
  EXPECT_NEAR((b->x - a->x) / 1000.0 / (b->t - a->t), 1.0, 0.05);
  const auto yellow_after = v.Robot(1, 2);
  ASSERT_TRUE(yellow_after);
  EXPECT_NEAR(yellow_after->x, yellow_before->x, 1.0);
  EXPECT_NEAR(yellow_after->y, yellow_before->y, 1.0);
  // Every commanded robot gets feedback.
  bool feedback = false;
  const auto feedback_by = Clock::now() + 15s;
  while (Clock::now() < feedback_by && !feedback) {
    team.Send(SimprotoMove(2, 0.0), m.blue_port);
    if (auto bytes = team.Receive()) {
      wire::simulation::RobotControlResponse r;
      if (r.ParseFromString(*bytes))
        for (const auto& f : r.feedback()) feedback = feedback || (f.id() == 2 && f.has_dribbler_ball_contact());
    }
  }
  EXPECT_TRUE(feedback);
}

TEST_F(SslEndToEnd, ErForceRealismKnobsChangeTheVisionStream) {
  wire::simulation::RealismConfigErForce knobs;
  knobs.set_vision_processing_time(20'000'000);  // ns
  knobs.set_stddev_robot_p(0.01f);               // m
  wire::simulation::SimulatorCommand cmd;
  auto* any = cmd.mutable_config()->mutable_realism_config()->add_custom();
  any->set_type_url("type.googleapis.com/sslsim.RealismConfigErForce");
  any->set_value(knobs.SerializeAsString());
  const auto answer = Command(team, cmd, m.control_port);
  ASSERT_TRUE(answer);
  const wire::simulation::SimulatorResponse& response = *answer;
  EXPECT_EQ(response.errors_size(), 0) << response.errors(0).code() << ": " << response.errors(0).message();
  // Now every detection left the vision system 20 ms after its capture, and
  // standing robots jitter by about a centimetre. Frames captured before the
  // change may still be on their way: count from the first delayed one on.
  auto delayed = [](double dt) { return std::abs(dt - 0.020) < 0.0005; };
  std::optional<double> changed_at;
  size_t first = 0;
  const auto end = Clock::now() + 20s;
  while (Clock::now() < end && !changed_at) {
    v.Drain(50ms);
    for (; first < v.send_delays.size() && !changed_at; ++first)
      if (delayed(v.send_delays[first])) changed_at = v.capture_times[first];
  }
  ASSERT_TRUE(changed_at) << "no detection was ever delayed by 20 ms";
  // 400 detections captured a frame or more later (about 0.4 s of simulation time).
  const double from = *changed_at + 0.02;
  auto after = [&] {
    return std::count_if(v.capture_times.begin(), v.capture_times.end(), [&](double t) { return t >= from; });
  };
  while (Clock::now() < end && after() < 400) v.Drain(50ms);
  ASSERT_GE(after(), 400);
  int frames = 0, late = 0;
  for (size_t i = 0; i < v.send_delays.size(); ++i) {
    if (v.capture_times[i] < from) continue;
    ++frames;
    late += delayed(v.send_delays[i]);
  }
  EXPECT_EQ(late, frames);
  std::vector<double> xs;
  for (const Seen& r : v.blue_tracks[10])
    if (r.t >= from) xs.push_back(r.x);
  ASSERT_GT(xs.size(), 50u);
  double mean = 0, ss = 0;
  for (double x : xs) mean += x / xs.size();
  for (double x : xs) ss += (x - mean) * (x - mean);
  EXPECT_GT(std::sqrt(ss / xs.size()), 3.0);  // mm
}

TEST_F(SslEndToEnd, BadDatagramsChangeNothing) {
  ASSERT_TRUE(PlaceAndWait(team, GrsimPlace(false, 7, 0.5, 4.0, 0.0), m.grsim_port, v,  // a free lane
                           [](const VisionClient& c) { return RobotSeenAt(c, 0, 7, 0.5, 4.0); }));
  const auto before = v.Robot(0, 7);
  ASSERT_TRUE(before);
  const std::string valid = GrsimMove(false, 7, 1.0, 0.0, 0.0);
  const std::string nan = GrsimMove(false, 7, NAN, 0.0, 0.0);
  const std::string huge_id = GrsimMove(false, 99, 1.0, 0.0, 0.0);
  const std::string garbage = "\xff\xfe\x01\x02 not a protobuf at all \x80\x80\x80";
  const std::string oversized(70000, 'x');
  // Bad input for 1 s of simulation time (the positive marker that it had
  // every chance to move the robot).
  const double until = v.latest_t + 1.0;
  const auto end = Clock::now() + 20s;
  while (Clock::now() < end && v.latest_t < until) {
    team.Send(nan, m.grsim_port);
    team.Send(huge_id, m.grsim_port);
    team.Send(garbage, m.grsim_port);
    team.Send(valid.substr(0, valid.size() / 2), m.grsim_port);  // truncated
    team.Send(oversized.substr(0, 60000), m.grsim_port);
    team.Send(garbage, m.blue_port);
    team.Send(SimprotoMove(7, NAN), m.blue_port);
    team.Send(garbage, m.control_port);
    v.Drain(16ms);
  }
  ASSERT_GE(v.latest_t, until);
  const auto after = v.Robot(0, 7);
  ASSERT_TRUE(after);
  EXPECT_NEAR(after->x, before->x, 1.0);
  EXPECT_NEAR(after->y, before->y, 1.0);
  EXPECT_TRUE(m.AllRunning());
  // And the bridges still work afterwards.
  ASSERT_TRUE(KeepForSim(team, valid, m.grsim_port, v, 1.0));
  ASSERT_TRUE(v.Robot(0, 7));
  EXPECT_GT(v.Robot(0, 7)->x - after->x, 200.0);
}

}  // namespace
}  // namespace turf::test
