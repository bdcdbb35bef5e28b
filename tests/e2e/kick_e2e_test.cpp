// A single kick command kicks, every time: the ball rests anywhere within the
// kicker's reach in front of a standing robot, the team sends ONE command with
// a kick over its port and then plain commands at 60 Hz (as team software
// does), and vision must show the ball flying. 100 placements per port and
// realism preset, through real processes (ssl_match.h).
#include "tests/e2e/ssl_match.h"

namespace turf::test {
namespace {

constexpr int kTrials = 100;
constexpr int kRobot = 5;                                            // blue
constexpr double kRobotX = 1.0, kRobotY = 0.0;                       // m, facing +x
constexpr double kFace = 0.08, kBallRadius = 0.0215, kReach = 0.01;  // configs/scenes/ssl_div_a.yaml
constexpr double kKickSpeed = 4.0;                                   // m/s

enum class Port { kGrsim, kSimulation };

struct Placement {
  double x, y;  // ball centre, m
};

// Trial k's ball: its surface 0 to kReach (both ends included) off the face,
// up to 24 mm left or right of the kicker's centre.
Placement BallFor(int k) {
  const double gap = kReach * (k % 11) / 10.0;
  const double lateral = 0.012 * ((k / 11) % 5 - 2);
  return {kRobotX + kFace + kBallRadius + gap, kRobotY + lateral};
}

std::string SimprotoCommand(double kick_speed) {
  wire::simulation::RobotControl rc;
  auto* c = rc.add_robot_commands();
  c->set_id(kRobot);
  auto* v = c->mutable_move_command()->mutable_local_velocity();
  v->set_forward(0);
  v->set_left(0);
  v->set_angular(0);
  if (kick_speed > 0) c->set_kick_speed(static_cast<float>(kick_speed));
  return rc.SerializeAsString();
}

wire::simulation::SimulatorCommand SimprotoPlace(const Placement& ball) {
  wire::simulation::SimulatorCommand cmd;
  auto* b = cmd.mutable_control()->mutable_teleport_ball();
  b->set_x(static_cast<float>(ball.x));
  b->set_y(static_cast<float>(ball.y));
  b->set_z(0);
  b->set_vx(0);
  b->set_vy(0);
  b->set_vz(0);
  auto* r = cmd.mutable_control()->add_teleport_robot();
  r->mutable_id()->set_id(kRobot);
  r->mutable_id()->set_team(wire::simulation::BLUE);
  r->set_x(static_cast<float>(kRobotX));
  r->set_y(static_cast<float>(kRobotY));
  r->set_orientation(0);
  r->set_present(true);
  return cmd;
}

class SingleKick {
 public:
  SingleKick(Port port, const std::string& realism)
      : port_(port), m_(MatchOptions{realism, 2.0}), v_(m_.vision_port), noise_mm_(realism == "ideal" ? 2.0 : 10.0) {}

  // Places robot and ball, waits until vision shows both there, sends one
  // kick and then plain commands. "" if the ball flew, else what happened.
  std::string Trial(int k) {
    const Placement ball = BallFor(k);
    if (!Place(ball)) return "the placement never showed in vision";
    const double t0 = v_.latest_t;
    Send(kKickSpeed);
    const double kicked_x = ball.x * 1000.0 + 100.0;  // mm: flown 0.1 m
    bool flew = false;
    const bool decided = KeepUntil(team_, PlainPacket(), CommandPort(), v_, [&](const VisionClient& c) {
      flew = flew || c.ball.x > kicked_x;
      return flew || c.latest_t > t0 + 1.0;
    });
    if (flew) return "";
    return decided ? "the ball did not move within 1 s of simulation time" : "vision stopped";
  }

  void Start() {
    WaitForVision(m_, v_);
    if (port_ == Port::kSimulation) {
      // The simulation bridge answers once it has seen turf-sim.
      const auto answer = Command(team_, SimprotoPlace(BallFor(0)), m_.control_port);
      ASSERT_TRUE(answer);
      ASSERT_EQ(answer->errors_size(), 0) << answer->errors(0).message();
    }
  }

 private:
  bool Place(const Placement& ball) {
    auto placed = [&](const VisionClient& c) {
      return RobotSeenAt(c, 0, kRobot, kRobotX, kRobotY, noise_mm_) && BallSeenAt(c, ball.x, ball.y, noise_mm_);
    };
    if (port_ == Port::kGrsim)
      return PlaceAndWait(team_, GrsimPlace(false, kRobot, kRobotX, kRobotY, 0.0, ball.x, ball.y), m_.grsim_port, v_,
                          placed);
    const auto answer = Command(team_, SimprotoPlace(ball), m_.control_port);
    if (!answer || answer->errors_size() > 0) return false;
    return KeepUntil(team_, PlainPacket(), CommandPort(), v_, placed);
  }

  void Send(double kick_speed) {
    team_.Send(port_ == Port::kGrsim ? GrsimMove(false, kRobot, 0, 0, 0, kick_speed) : SimprotoCommand(kick_speed),
               CommandPort());
  }
  std::string PlainPacket() const {
    return port_ == Port::kGrsim ? GrsimMove(false, kRobot, 0, 0, 0) : SimprotoCommand(0);
  }
  int CommandPort() const { return port_ == Port::kGrsim ? m_.grsim_port : m_.blue_port; }

  Port port_;
  Match m_;
  VisionClient v_;
  Udp team_;
  double noise_mm_;
};

void KicksEveryTime(Port port, const std::string& realism) {
  SingleKick s(port, realism);
  ASSERT_NO_FATAL_FAILURE(s.Start());
  int kicked = 0;
  for (int k = 0; k < kTrials; ++k) {
    const std::string failure = s.Trial(k);
    if (failure.empty()) {
      ++kicked;
    } else {
      const Placement b = BallFor(k);
      ADD_FAILURE() << "trial " << k << " (ball " << (b.x - kRobotX - kFace - kBallRadius) * 1000.0
                    << " mm off the face, " << (b.y - kRobotY) * 1000.0 << " mm lateral): " << failure;
    }
  }
  EXPECT_EQ(kicked, kTrials);
}

TEST(SingleKickCommand, KicksEveryTimeOverTheGrsimPortIdeal) { KicksEveryTime(Port::kGrsim, "ideal"); }
TEST(SingleKickCommand, KicksEveryTimeOverTheGrsimPortRealistic) { KicksEveryTime(Port::kGrsim, "realistic"); }
TEST(SingleKickCommand, KicksEveryTimeOverTheSimulationPortIdeal) { KicksEveryTime(Port::kSimulation, "ideal"); }
TEST(SingleKickCommand, KicksEveryTimeOverTheSimulationPortRealistic) {
  KicksEveryTime(Port::kSimulation, "realistic");
}

}  // namespace
}  // namespace turf::test
