// The kicker as team software uses it: ONE kick command, then plain commands
// every frame. A kick arms the kicker; it fires at the first step the ball is
// within reach, or expires after the scene's arm time. Measured on the World.
#include <gtest/gtest.h>

#include <cmath>

#include "core/link_model.h"
#include "core/world.h"
#include "tests/core/test_scenes.h"

namespace turf {
namespace {

int Steps(const World& w, double seconds) { return static_cast<int>(std::lround(seconds / w.scene().physics.step)); }

RobotCommand Kick(double speed) {
  RobotCommand c;
  c.kick = KickKind::kFlat;
  c.kick_speed = speed;
  return c;
}

RobotCommand Plain() { return RobotCommand{}; }  // stand still, no kick

uint32_t Kicks(const World& w) { return w.Snapshot().robots[0].kick_count; }

double BallSpeed(const World& w) {
  const Vec3 v = w.Snapshot().ball.velocity;
  return std::hypot(v.x, v.y);
}

// The ball at rest with its surface `gap` in front of the face of robot 0
// (at the origin, facing +x), `lateral` to its left.
void PlaceBall(World& w, double gap, double lateral = 0.0) {
  const double x = w.scene().robot.center_to_dribbler + w.scene().ball.radius + gap;
  ASSERT_EQ(w.TeleportBall({{x, lateral, 0.0}, {0, 0, 0}, false}), InputError::kOk);
}

// Steps `seconds`, sending a plain command every 8 steps (a team's frame).
void PlainCommandsFor(World& w, double seconds) {
  for (int i = 0; i < Steps(w, seconds); ++i) {
    if (i % 8 == 0) {
      ASSERT_EQ(w.SetCommand(Plain()), InputError::kOk);
    }
    w.Step();
  }
}

TEST(Kicker, OneKickThenAPlainCommandBeforeTheNextStepStillKicks) {
  // A loaded simulator takes a frame's kick and the next plain command
  // together; the plain one must not cancel the kick.
  World w(test::OneRobot());
  PlaceBall(w, 0.002);
  ASSERT_EQ(w.SetCommand(Kick(4.0)), InputError::kOk);
  ASSERT_EQ(w.SetCommand(Plain()), InputError::kOk);
  w.Step();
  EXPECT_EQ(Kicks(w), 1u);
  EXPECT_NEAR(BallSpeed(w), 4.0, 0.1);
}

// A pass redirected by a kick keeps what it brought across the kick's direction (the plate pushes along the
// heading only; grSim's kick and ER-Force's impulse keep it too): crossing the face at 2 and 3 m/s, a 5 m/s kick
// leaves at (5, 2) and (5, 3), -22 and -31 degrees off the heading of a team that aims as on those simulators.
TEST(Kicker, ARedirectKeepsTheBallsSidewaysVelocity) {
  for (const double side : {-3.0, 2.0}) {
    World w(test::OneRobot());
    const double x = w.scene().robot.center_to_dribbler + w.scene().ball.radius + 0.002;
    ASSERT_EQ(w.TeleportBall({{x, 0.0, 0.0}, {0.0, side, 0.0}, false}), InputError::kOk);
    ASSERT_EQ(w.SetCommand(Kick(5.0)), InputError::kOk);
    w.Step();
    ASSERT_EQ(Kicks(w), 1u) << side;
    const Vec3 v = w.Snapshot().ball.velocity;
    EXPECT_NEAR(v.x, 5.0, 0.05) << side;
    EXPECT_NEAR(v.y, side, 0.05) << side;
  }
}

TEST(Kicker, KickArmedBeforeTheBallArrivesFiresWhenItIsWithinReach) {
  // The kick reaches the robot before the ball's placement does.
  World w(test::OneRobot());
  ASSERT_EQ(w.SetCommand(Kick(4.0)), InputError::kOk);
  PlainCommandsFor(w, 0.5 * w.scene().robot.kicker.arm_time);
  ASSERT_EQ(Kicks(w), 0u);
  PlaceBall(w, 0.005);
  PlainCommandsFor(w, 0.01);
  EXPECT_EQ(Kicks(w), 1u);
  EXPECT_GT(BallSpeed(w), 3.5);
}

TEST(Kicker, ArmedKickExpiresAfterTheArmTime) {
  World w(test::OneRobot());
  ASSERT_EQ(w.SetCommand(Kick(4.0)), InputError::kOk);
  PlainCommandsFor(w, w.scene().robot.kicker.arm_time + 0.02);
  PlaceBall(w, 0.002);
  PlainCommandsFor(w, 0.2);
  // The positive marker: the ball lay within reach for 0.2 s of simulation.
  EXPECT_GE(w.time_ns(), std::llround((w.scene().robot.kicker.arm_time + 0.22) * 1e9) - w.step_ns());
  EXPECT_EQ(Kicks(w), 0u);
  EXPECT_LT(BallSpeed(w), 0.01);
}

TEST(Kicker, AKickFiresOnceThenNeedsANewCommand) {
  World w(test::OneRobot());
  PlaceBall(w, 0.002);
  ASSERT_EQ(w.SetCommand(Kick(2.0)), InputError::kOk);
  PlainCommandsFor(w, 0.01);
  ASSERT_EQ(Kicks(w), 1u);
  PlaceBall(w, 0.002);  // back at the face within the arm time
  PlainCommandsFor(w, 0.05);
  EXPECT_EQ(Kicks(w), 1u);
  EXPECT_LT(BallSpeed(w), 0.01);
  ASSERT_EQ(w.SetCommand(Kick(2.0)), InputError::kOk);
  PlainCommandsFor(w, 0.01);
  EXPECT_EQ(Kicks(w), 2u);
}

TEST(Kicker, OneKickFiresAnywhereWithinTheReachAndNotBeyond) {
  const double reach = World(test::OneRobot()).scene().robot.kicker.reach;
  int fired = 0, tried = 0;
  for (int i = 0; i <= 20; ++i) {
    for (double lateral : {-0.03, -0.015, 0.0, 0.015, 0.03}) {
      World w(test::OneRobot());
      PlaceBall(w, reach * i / 20.0, lateral);
      ASSERT_EQ(w.SetCommand(Kick(4.0)), InputError::kOk);
      PlainCommandsFor(w, 0.05);
      ++tried;
      if (Kicks(w) == 1) ++fired;
      EXPECT_EQ(Kicks(w), 1u) << "gap " << reach * i / 20.0 << " m, lateral " << lateral << " m";
    }
  }
  EXPECT_EQ(fired, tried);
  World w(test::OneRobot());
  PlaceBall(w, reach + 0.002);
  ASSERT_EQ(w.SetCommand(Kick(4.0)), InputError::kOk);
  PlainCommandsFor(w, 0.05);
  EXPECT_EQ(Kicks(w), 0u);
}

TEST(Kicker, TakingTheRobotOffTheFieldDisarms) {
  World w(test::OneRobot());
  ASSERT_EQ(w.SetCommand(Kick(4.0)), InputError::kOk);
  RobotTeleport off;
  off.team = Team::kBlue;
  off.id = 0;
  off.on_field = false;
  ASSERT_EQ(w.TeleportRobot(off), InputError::kOk);
  RobotTeleport back = off;
  back.on_field = true;
  ASSERT_EQ(w.TeleportRobot(back), InputError::kOk);
  PlaceBall(w, 0.002);
  PlainCommandsFor(w, 0.05);
  EXPECT_EQ(Kicks(w), 0u);
}

TEST(Kicker, ArmTimeComesFromTheScene) {
  Scene s = test::OneRobot();
  s.robot.kicker.arm_time = 0.0;  // grSim's behaviour: fire now or never
  World w(s);
  ASSERT_EQ(w.SetCommand(Kick(4.0)), InputError::kOk);
  PlainCommandsFor(w, 0.01);
  PlaceBall(w, 0.002);
  PlainCommandsFor(w, 0.05);
  EXPECT_EQ(Kicks(w), 0u);
  PlaceBall(w, 0.002);
  ASSERT_EQ(w.SetCommand(Kick(4.0)), InputError::kOk);
  w.Step();
  EXPECT_EQ(Kicks(w), 1u);
}

}  // namespace
}  // namespace turf

namespace turf {
namespace {

TEST(KickRadio, AnAcknowledgedSampleIsSentAgainUntilItGetsThrough) {
  LinkParams p;
  p.latency = 0.008;
  p.burst = {true, 0.005, 0.3, 0.005, 0.7};  // the realistic preset's radio
  p.burst.p_good_to_bad = 1.0;               // always in a burst: the worst case
  p.burst.p_bad_to_good = 0.3;
  Link link(p, 42);
  int delivered = 0, delayed = 0;
  for (int i = 0; i < 10000; ++i) {
    const int64_t sent = i * 16'666'667LL;
    const std::optional<int64_t> due = link.TransmitAcknowledged(sent, 1'000'000, 50);
    if (!due) continue;
    ++delivered;
    if (*due > sent + 8'000'000) ++delayed;
    EXPECT_LE(*due, sent + 8'000'000 + 49 * 1'000'000);
  }
  EXPECT_EQ(delivered, 10000);
  EXPECT_GT(delayed, 1000);  // retries really happened: many first tries were lost
}

TEST(KickRadio, ATotallyDeadLinkStillLosesIt) {
  LinkParams p;
  p.loss = 1.0;
  Link link(p, 1);
  EXPECT_FALSE(link.TransmitAcknowledged(0, 1'000'000, 50).has_value());
  EXPECT_EQ(link.counters().sent, 50u);
  EXPECT_EQ(link.counters().lost, 50u);
}

}  // namespace
}  // namespace turf
