// Physics measured from the simulated state, against stated tolerances.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/ball_handling.h"
#include "core/ball_model.h"
#include "core/world.h"
#include "tests/core/test_scenes.h"

namespace turf {
namespace {

constexpr double kG = 9.81;

int Steps(const World& w, double seconds) { return static_cast<int>(std::lround(seconds / w.scene().physics.step)); }

void Advance(World& w, double seconds) {
  for (int i = Steps(w, seconds); i > 0; --i) w.Step();
}

// A kick command for robot 0 (the chip at `chip_angle`, radians).
RobotCommand Kick(KickKind kind, double speed, double chip_angle = 0.0) {
  RobotCommand c;
  c.kick = kind;
  c.kick_speed = speed;
  c.chip_angle = chip_angle;
  return c;
}

RobotCommand Move(MoveKind kind, double x, double y, double omega) {
  RobotCommand c;
  c.move = kind;
  c.velocity = {x, y, omega};
  return c;
}

// Keeps re-sending a command, as a team does every frame, while stepping.
void Drive(World& w, const RobotCommand& c, double seconds) {
  const int steps = Steps(w, seconds);
  for (int i = 0; i < steps; ++i) {
    if (i % 8 == 0) {
      ASSERT_EQ(w.SetCommand(c), InputError::kOk);
    }
    w.Step();
  }
}

const RobotSnapshot& Robot0(const WorldSnapshot& s) { return s.robots[0]; }

double Speed(const Vec3& v) { return std::hypot(v.x, v.y); }

// Distance covered from rest at constant acceleration a up to top speed v.
double RampDistance(double v, double a, double t) {
  const double t_ramp = v / a;
  return t <= t_ramp ? 0.5 * a * t * t : 0.5 * v * t_ramp + v * (t - t_ramp);
}

TEST(Physics, ForwardReachesCommandedSpeedWithinAccelerationLimit) {
  World w(test::OneRobot());
  const double a = w.scene().robot.drive.acc_speedup;
  const RobotCommand c = Move(MoveKind::kLocalVelocity, 1.0, 0.0, 0.0);
  // Halfway through the ramp the robot must not be faster than the limit allows.
  Drive(w, c, 0.5 / a);
  EXPECT_LT(Robot0(w.Snapshot()).vx, 0.5 * 1.05);
  Drive(w, c, 0.5 / a + 0.05);
  const RobotSnapshot r = Robot0(w.Snapshot());
  EXPECT_NEAR(r.vx, 1.0, 0.05);
  EXPECT_NEAR(r.vy, 0.0, 0.01);
  Drive(w, c, 2.0 - (1.0 / a + 0.05));
  const RobotSnapshot end = Robot0(w.Snapshot());
  EXPECT_NEAR(end.x, RampDistance(1.0, a, 2.0), 0.05 * RampDistance(1.0, a, 2.0));
  EXPECT_NEAR(end.y, 0.0, 0.01);
  EXPECT_NEAR(end.yaw, 0.0, 0.01);
}

TEST(Physics, SidewaysReachesCommandedSpeed) {
  World w(test::OneRobot(0, 0, M_PI / 2));  // facing +y, so "left" is -x
  const double a = w.scene().robot.drive.acc_speedup;
  Drive(w, Move(MoveKind::kLocalVelocity, 0.0, 1.0, 0.0), 2.0);
  const RobotSnapshot r = Robot0(w.Snapshot());
  EXPECT_NEAR(r.vx, -1.0, 0.05);
  EXPECT_NEAR(r.vy, 0.0, 0.01);
  EXPECT_NEAR(r.x, -RampDistance(1.0, a, 2.0), 0.05 * RampDistance(1.0, a, 2.0));
}

TEST(Physics, RotationReachesCommandedRate) {
  World w(test::OneRobot());
  const double alpha = w.scene().robot.drive.acc_angular;
  Drive(w, Move(MoveKind::kLocalVelocity, 0.0, 0.0, 3.0), 1.0);
  const RobotSnapshot r = Robot0(w.Snapshot());
  EXPECT_NEAR(r.omega, 3.0, 0.15);
  const double expected = RampDistance(3.0, alpha, 1.0);
  EXPECT_NEAR(std::remainder(r.yaw - expected, 2 * M_PI), 0.0, 0.05 * expected);
  EXPECT_NEAR(std::hypot(r.x, r.y), 0.0, 0.005);
}

TEST(Physics, BrakesAtTheBrakeLimit) {
  World w(test::OneRobot());
  const double a_brake = w.scene().robot.drive.acc_brake;
  Drive(w, Move(MoveKind::kLocalVelocity, 2.0, 0.0, 0.0), 2.0);
  const double x0 = Robot0(w.Snapshot()).x;
  Drive(w, Move(MoveKind::kLocalVelocity, 0.0, 0.0, 0.0), 1.5);
  const RobotSnapshot r = Robot0(w.Snapshot());
  EXPECT_NEAR(r.vx, 0.0, 0.01);
  const double stop = 2.0 * 2.0 / (2 * a_brake);
  EXPECT_NEAR(r.x - x0, stop, 0.05 * stop);
}

TEST(Physics, GlobalVelocityMovesInFieldFrameWhileTurning) {
  World w(test::OneRobot());
  Drive(w, Move(MoveKind::kGlobalVelocity, 0.0, 1.0, 2.0), 2.0);
  const RobotSnapshot r = Robot0(w.Snapshot());
  EXPECT_NEAR(r.vx, 0.0, 0.05);
  EXPECT_NEAR(r.vy, 1.0, 0.05);
  EXPECT_NEAR(r.omega, 2.0, 0.1);
}

TEST(Physics, WheelSpeedsGiveTheKinematicBodyVelocity) {
  World w(test::OneRobot());
  const DriveParams& d = w.scene().robot.drive;
  const double vx = 0.8, vy = -0.5, wz = 1.5;
  RobotCommand c;
  c.move = MoveKind::kWheelVelocity;
  // Rim speed of wheel i: tangent (-sin phi, cos phi) . v + distance * omega.
  for (int i = 0; i < 4; ++i) {
    const double phi = d.wheel_angles[i];
    c.wheel_velocity[i] = -std::sin(phi) * vx + std::cos(phi) * vy + d.wheel_distance * wz;
  }
  Drive(w, c, 2.0);
  const RobotSnapshot r = Robot0(w.Snapshot());
  // Back into the robot frame.
  const double lx = std::cos(r.yaw) * r.vx + std::sin(r.yaw) * r.vy;
  const double ly = -std::sin(r.yaw) * r.vx + std::cos(r.yaw) * r.vy;
  EXPECT_NEAR(lx, vx, 0.05 * vx);
  EXPECT_NEAR(ly, vy, 0.05 * std::abs(vy));
  EXPECT_NEAR(r.omega, wz, 0.05 * wz);
}

// Steps until robot 0 has kicked (at most `seconds`); true if it did.
bool StepUntilKick(World& w, double seconds) {
  for (int i = Steps(w, seconds); i > 0; --i) {
    w.Step();
    if (w.Snapshot().robots[0].kick_count > 0) return true;
  }
  return false;
}

// The ball resting against the robot's face (robot at origin facing +x).
void BallAtFace(World& w, double vx = 0.0) {
  const double x = w.scene().robot.center_to_dribbler + w.scene().ball.radius + 0.002;
  ASSERT_EQ(w.TeleportBall({{x, 0.0, 0.0}, {vx, 0.0, 0.0}, false}), InputError::kOk);
}

TEST(Physics, FlatKickLaunchesBallAtCommandedSpeed) {
  World w(test::OneRobot());
  BallAtFace(w);
  ASSERT_EQ(w.SetCommand(Kick(KickKind::kFlat, 5.0)), InputError::kOk);
  ASSERT_TRUE(StepUntilKick(w, 0.05));
  Advance(w, 0.01);  // off the face, sliding
  const WorldSnapshot s = w.Snapshot();
  EXPECT_NEAR(Speed(s.ball.velocity), 5.0, 0.3);
  EXPECT_NEAR(s.ball.velocity.y, 0.0, 0.05);
  EXPECT_EQ(Robot0(s).kick_count, 1u);
  EXPECT_EQ(Robot0(s).last_kick, KickKind::kFlat);
}

TEST(Physics, KickIsClampedToTheConfiguredLimit) {
  World w(test::OneRobot());
  BallAtFace(w);
  ASSERT_EQ(w.SetCommand(Kick(KickKind::kFlat, 12.0)), InputError::kOk);
  ASSERT_TRUE(StepUntilKick(w, 0.05));
  EXPECT_NEAR(Speed(w.Snapshot().ball.velocity), w.scene().robot.kicker.max_flat_speed, 0.05);
}

TEST(Physics, NoKickWithoutBallAtTheKicker) {
  World w(test::OneRobot());
  ASSERT_EQ(w.TeleportBall({{0.0, 0.3, 0.0}, {0, 0, 0}, false}), InputError::kOk);  // beside, not in front
  ASSERT_EQ(w.SetCommand(Kick(KickKind::kFlat, 5.0)), InputError::kOk);
  Advance(w, 0.2);
  EXPECT_LT(Speed(w.Snapshot().ball.velocity), 0.01);
  EXPECT_EQ(Robot0(w.Snapshot()).kick_count, 0u);
}

TEST(Physics, ChipLandsWhereAngleAndSpeedPredict) {
  World w(test::OneRobot());
  BallAtFace(w);
  const double speed = 4.0, angle = 50.0 * M_PI / 180.0;
  ASSERT_EQ(w.SetCommand(Kick(KickKind::kChip, speed, angle)), InputError::kOk);
  const double x0 = w.Snapshot().ball.position.x;
  const double r = w.scene().ball.radius;
  double apex = 0.0, land_x = NAN;
  bool flew = false;
  for (int i = 0; i < Steps(w, 2.0) && std::isnan(land_x); ++i) {
    w.Step();
    const Vec3 p = w.Snapshot().ball.position;
    apex = std::max(apex, p.z);
    if (p.z > r + 0.05) flew = true;
    if (flew && p.z <= r + 0.002) land_x = p.x;
  }
  ASSERT_TRUE(flew);
  const double range = speed * speed * std::sin(2 * angle) / kG;
  const double height = std::pow(speed * std::sin(angle), 2) / (2 * kG);
  EXPECT_NEAR(land_x - x0, range, 0.05 * range);
  EXPECT_NEAR(apex - r, height, 0.05 * height);
}

TEST(Physics, ChipBouncesAndLosesVerticalSpeed) {
  World w(test::EmptyDivA());
  const double r = w.scene().ball.radius;
  ASSERT_EQ(w.TeleportBall({{0, 0, r}, {0.5, 0, 3.0}, false}), InputError::kOk);
  // Vertical speed when the ball last was airborne before its first landing,
  // and when it first is airborne again after it.
  const double airborne = r + 0.005;
  double before = 0.0, after = 0.0;
  bool was_up = false, landed = false;
  for (int i = 0; i < Steps(w, 2.0) && after == 0.0; ++i) {
    w.Step();
    const BallSnapshot& ball = w.Snapshot().ball;
    const bool up = ball.position.z > airborne;
    if (up && !landed) before = ball.velocity.z;
    if (!up && was_up) landed = true;
    if (up && landed) after = ball.velocity.z;
    was_up = was_up || up;
  }
  ASSERT_LT(before, -2.0);
  EXPECT_NEAR(after / -before, w.scene().ball.floor_restitution, 0.05);
}

// The chip model turf publishes in its geometry (SSL_BallModelChipFixedLoss) is what its ball does: a chipped ball
// (sliding, no spin) keeps damping_xy_first_hop of its horizontal speed across its first bounce (the carpet's
// friction during the bounce spins it up towards rolling), damping_xy_other_hops across the next, and
// floor_restitution of its vertical speed. Team software predicts where a chip stops from these numbers.
TEST(Physics, ThePublishedChipModelIsWhatTheBallDoes) {
  for (const double v : {2.5, 3.0, 3.5}) {
    World w(test::EmptyDivA());
    const BallParams& b = w.scene().ball;
    ASSERT_EQ(w.TeleportBall({{-4.0, 0, b.radius}, {v, 0, v}, false}), InputError::kOk);
    // Horizontal speed when the ball last was airborne before each landing, and when first airborne after it.
    const double airborne = b.radius + 0.005;
    std::vector<double> before, after;
    bool up_before = false;
    double last_up = 0.0;
    for (int i = 0; i < Steps(w, 3.0) && after.size() < 2; ++i) {
      w.Step();
      const BallSnapshot& ball = w.Snapshot().ball;
      const bool up = ball.position.z > airborne;
      if (up && !up_before && !before.empty()) after.push_back(std::hypot(ball.velocity.x, ball.velocity.y));
      if (!up && up_before) before.push_back(last_up);
      if (up) last_up = std::hypot(ball.velocity.x, ball.velocity.y);
      up_before = up;
    }
    ASSERT_EQ(after.size(), 2u) << v;
    EXPECT_NEAR(after[0] / before[0], b.chip_damping_xy_first_hop, 0.02) << "first hop, " << v << " m/s";
    EXPECT_NEAR(after[1] / before[1], b.chip_damping_xy_other_hops, 0.02) << "second hop, " << v << " m/s";
  }
}

// Straight ball: slides at acc_slide, switches to rolling at k_switch of its
// start speed, then rolls at acc_roll until it stops.
TEST(Physics, BallSlidesThenRollsWithConfiguredDecelerations) {
  World w(test::EmptyDivA());
  const BallParams& b = w.scene().ball;
  const double v0 = 3.0;  // slides ~0.8 m and rolls ~5.5 m: stays clear of the walls
  ASSERT_EQ(w.TeleportBall({{-5.9, 0, b.radius}, {v0, 0, 0}, false}), InputError::kOk);
  std::vector<double> t, v, slip;
  for (int i = 0; i < Steps(w, 8.0); ++i) {
    w.Step();
    const WorldSnapshot s = w.Snapshot();
    t.push_back(s.time_ns * 1e-9);
    v.push_back(Speed(s.ball.velocity));
    slip.push_back(BallSlipSpeed({s.ball.position, s.ball.velocity, s.ball.angular_velocity}, b.radius));
  }
  // Mean deceleration between two speeds, from the recorded curve.
  auto decel = [&](double v_hi, double v_lo) {
    size_t i = 0;
    while (i < v.size() && v[i] > v_hi) ++i;
    size_t j = i;
    while (j < v.size() && v[j] > v_lo) ++j;
    EXPECT_LT(j, v.size());
    return -(v[j] - v[i]) / (t[j] - t[i]);
  };
  const double v_switch = b.k_switch * v0;
  EXPECT_NEAR(decel(0.95 * v0, 1.05 * v_switch), -b.acc_slide, 0.05 * -b.acc_slide);
  EXPECT_NEAR(decel(0.9 * v_switch, 0.2 * v_switch), -b.acc_roll, 0.05 * -b.acc_roll);
  // The switch: the first moment the contact point stops slipping.
  size_t k = 0;
  while (k < slip.size() && slip[k] > 0.01) ++k;
  ASSERT_LT(k, slip.size());
  EXPECT_NEAR(v[k] / v0, b.k_switch, 0.02);
  EXPECT_LT(v.back(), 1e-3);  // it stops
}

TEST(Physics, RollingTeleportRollsFromTheStart) {
  World w(test::EmptyDivA());
  const BallParams& b = w.scene().ball;
  ASSERT_EQ(w.TeleportBall({{-5.0, 0, b.radius}, {2.0, 0, 0}, true}), InputError::kOk);
  Advance(w, 1.0);
  EXPECT_NEAR(Speed(w.Snapshot().ball.velocity), 2.0 + b.acc_roll * 1.0, 0.05);
}

TEST(Physics, DribblerHoldsBallWhileTurning) {
  World w(test::OneRobot());
  BallAtFace(w);
  RobotCommand c = Move(MoveKind::kLocalVelocity, 0.0, 0.0, 1.0);
  c.dribbler_speed = 10000;
  const RobotParams& rp = w.scene().robot;
  const int steps = Steps(w, 4.0);  // more than half a turn
  for (int i = 0; i < steps; ++i) {
    if (i % 8 == 0) {
      ASSERT_EQ(w.SetCommand(c), InputError::kOk);
    }
    w.Step();
    const WorldSnapshot s = w.Snapshot();
    const RobotSnapshot& r = Robot0(s);
    const RobotKinematics k{r.x, r.y, r.yaw, r.vx, r.vy, r.omega};
    ASSERT_TRUE(BallAtFront(k, s.ball.position, rp, w.scene().ball.radius, rp.dribbler.capture_distance))
        << "ball lost after " << i << " steps";
  }
  EXPECT_GT(std::abs(Robot0(w.Snapshot()).yaw), 1.0);
}

// A pass rolled straight at a standing robot's front: the dribbler bar bounces it back with its own restitution
// (ER-Force's 0.2, not the body's 0.6), and a spinning dribbler then keeps it: caught at 1 and 2 m/s, as teams tuned
// on grSim (which fixes the ball to the robot) and ER-Force expect; at 3 and 4 m/s the rolling ball's spin makes the
// bounce 0.2-0.35 of its speed and it may get away (before the bar: 0.39 at 2 m/s, never caught from 2 m/s up).
// Against the round side the body's bounce stays.
TEST(Physics, APassIntoTheDribblerIsCaught) {
  for (const double v : {1.0, 2.0, 3.0, 4.0}) {
    World w(test::OneRobot());
    const double r = w.scene().ball.radius;
    const RobotParams& rp = w.scene().robot;
    ASSERT_EQ(w.TeleportBall({{0.6, 0.0, r}, {-v, 0.0, 0.0}, true}), InputError::kOk);
    RobotCommand spin;
    spin.dribbler_speed = 10000;
    double back = 0.0;  // fastest speed away from the robot after the bounce
    for (int i = 0; i < Steps(w, 1.5); ++i) {
      if (i % 8 == 0) {
        ASSERT_EQ(w.SetCommand(spin), InputError::kOk);
      }
      w.Step();
      back = std::max(back, w.Snapshot().ball.velocity.x);
    }
    EXPECT_LT(back, (v <= 2.0 ? 0.3 : 0.4) * v) << v << " m/s: bounced off the bar too hard";
    if (v > 2.0) continue;
    const WorldSnapshot s = w.Snapshot();
    const RobotSnapshot& robot = Robot0(s);
    EXPECT_TRUE(BallAtFront({robot.x, robot.y, robot.yaw, robot.vx, robot.vy, robot.omega}, s.ball.position, rp, r,
                            rp.dribbler.capture_distance))
        << v << " m/s: not caught; the ball is at x " << s.ball.position.x;
  }
  // The round side: the body's restitution (about 0.6 of a 2 m/s ball's speed comes back).
  World side(test::OneRobot());
  const double r = side.scene().ball.radius;
  ASSERT_EQ(side.TeleportBall({{0.0, 0.6, r}, {0.0, -2.0, 0.0}, true}), InputError::kOk);
  double back = 0.0;
  for (int i = 0; i < Steps(side, 0.3); ++i) {
    side.Step();
    back = std::max(back, side.Snapshot().ball.velocity.y);
  }
  EXPECT_GT(back, 0.8) << "the side bounced like the bar";
}

TEST(Physics, BallWithoutDribblerIsNotHeldWhileTurning) {
  World w(test::OneRobot());
  BallAtFace(w);
  Drive(w, Move(MoveKind::kLocalVelocity, 0.0, 0.0, 3.0), 2.0);
  const WorldSnapshot s = w.Snapshot();
  const RobotSnapshot& r = Robot0(s);
  EXPECT_FALSE(BallAtFront({r.x, r.y, r.yaw, r.vx, r.vy, r.omega}, s.ball.position, w.scene().robot,
                           w.scene().ball.radius, 0.01));
}

bool InsideWalls(const World& w, const WorldSnapshot& s) {
  const FieldParams& f = w.scene().field;
  const double x_in = f.length / 2 + f.boundary_width_goal_line, y_in = f.width / 2 + f.boundary_width;
  auto ok = [](double v) { return std::isfinite(v); };
  if (!(ok(s.ball.position.x) && ok(s.ball.position.y) && ok(s.ball.position.z))) return false;
  if (std::abs(s.ball.position.x) > x_in || std::abs(s.ball.position.y) > y_in) return false;
  for (const RobotSnapshot& r : s.robots) {
    if (!r.on_field) continue;
    if (!(ok(r.x) && ok(r.y) && ok(r.yaw) && ok(r.vx) && ok(r.vy) && ok(r.omega))) return false;
    if (std::abs(r.x) > x_in || std::abs(r.y) > y_in) return false;
  }
  return true;
}

TEST(Physics, WallsKeepTheBallIn) {
  World w(test::EmptyDivA());
  for (double angle = 0.1; angle < 2 * M_PI; angle += 0.7) {
    ASSERT_EQ(w.TeleportBall({{0, 0, 0.0215}, {6.5 * std::cos(angle), 6.5 * std::sin(angle), 0}, false}),
              InputError::kOk);
    for (int i = 0; i < Steps(w, 3.0); ++i) {
      w.Step();
      ASSERT_TRUE(InsideWalls(w, w.Snapshot())) << "angle " << angle << " step " << i;
    }
  }
  // A chip over the wall stays in too.
  ASSERT_EQ(w.TeleportBall({{5.5, 0, 0.0215}, {3.0, 0, 3.0}, false}), InputError::kOk);
  for (int i = 0; i < Steps(w, 3.0); ++i) {
    w.Step();
    ASSERT_TRUE(InsideWalls(w, w.Snapshot()));
  }
}

// The boundary walls as the learning configuration may build them (core/mjcf.cpp: several boxes, each a static
// body of its own; or none, the containment stage alone keeping the ball in) give the ball the path the scenes'
// one-box walls of the world body give it, to the bit: the containment stage puts it back at a wall's inner face
// after every step, so no wall box is ever inside it at a collision test.
TEST(Physics, WallBoxesInBodiesBounceTheBallAsOneBoxWallsDo) {
  Scene one_box = test::EmptyDivA();
  one_box.physics.wall_segments = 1;
  Scene boxes = one_box, none = one_box;
  boxes.physics.wall_segments = 2;
  none.physics.wall_segments = 0;
  World a(one_box), b(boxes), c(none);
  for (double angle = 0.1; angle < 2 * M_PI; angle += 0.7) {
    const BallTeleport t{{0, 0, 0.0215}, {6.5 * std::cos(angle), 6.5 * std::sin(angle), 0}, false};
    for (World* w : {&a, &b, &c}) ASSERT_EQ(w->TeleportBall(t), InputError::kOk);
    for (int i = 0; i < Steps(a, 2.0); ++i) {
      for (World* w : {&a, &b, &c}) w->Step();
      const Vec3 pa = a.Snapshot().ball.position;
      for (const World* w : {&b, &c}) {
        ASSERT_EQ(pa.x, w->Snapshot().ball.position.x) << "angle " << angle << " step " << i;
        ASSERT_EQ(pa.y, w->Snapshot().ball.position.y) << "angle " << angle << " step " << i;
      }
    }
  }
  EXPECT_GT(a.health().containment_corrections, 0u);  // the walls were reached
}

TEST(Physics, GoalStopsTheBall) {
  World w(test::EmptyDivA());
  const FieldParams& f = w.scene().field;
  ASSERT_EQ(w.TeleportBall({{4.0, 0, 0.0215}, {6.0, 0, 0}, true}), InputError::kOk);
  double max_x = 0.0;
  for (int i = 0; i < Steps(w, 2.0); ++i) {
    w.Step();
    max_x = std::max(max_x, w.Snapshot().ball.position.x);
  }
  // Into the goal, but not through its back wall.
  EXPECT_GT(max_x, f.length / 2 + w.scene().ball.radius);
  EXPECT_LT(max_x, f.length / 2 + f.goal_depth);
}

TEST(Physics, RobotsDrivenIntoWallsStayFiniteAndInside) {
  World w(test::Teams(11));
  for (int i = 0; i < Steps(w, 6.0); ++i) {
    if (i % 8 == 0) {
      for (int team = 0; team < 2; ++team) {
        for (int id = 0; id < 11; ++id) {
          RobotCommand c = Move(MoveKind::kGlobalVelocity, (team ? 1 : -1) * 10.0, (id % 2 ? 1 : -1) * 10.0, 5);
          c.team = static_cast<Team>(team);
          c.id = id;
          ASSERT_EQ(w.SetCommand(c), InputError::kOk);
        }
      }
    }
    w.Step();
    ASSERT_TRUE(InsideWalls(w, w.Snapshot())) << "step " << i;
  }
}

TEST(Physics, ThirtyTwoRobotsStackedOnOneSpotStayFiniteAndInside) {
  World w(test::Teams(16));
  for (int team = 0; team < 2; ++team)
    for (int id = 0; id < 16; ++id)
      ASSERT_EQ(w.TeleportRobot({static_cast<Team>(team), id, true, 0.0, 0.0, 0.1 * id, {0, 0, 0}}), InputError::kOk);
  ASSERT_EQ(w.TeleportBall({{0, 0, 0.0215}, {0, 0, 0}, false}), InputError::kOk);
  for (int i = 0; i < Steps(w, 3.0); ++i) {
    w.Step();
    ASSERT_TRUE(InsideWalls(w, w.Snapshot())) << "step " << i;
  }
  // They pushed each other apart.
  const WorldSnapshot s = w.Snapshot();
  int near_origin = 0;
  for (const RobotSnapshot& r : s.robots) near_origin += std::hypot(r.x, r.y) < 0.05;
  EXPECT_LE(near_origin, 1);
}

TEST(Physics, WatchdogStopsARobotWithoutFreshCommands) {
  World w(test::OneRobot());
  ASSERT_EQ(w.SetCommand(Move(MoveKind::kLocalVelocity, 1.0, 0, 0)), InputError::kOk);
  const double timeout = w.scene().rates.command_timeout;
  Advance(w, timeout - 0.05);
  EXPECT_NEAR(Robot0(w.Snapshot()).vx, 1.0, 0.05);  // still driving just before the timeout
  Advance(w, 0.05 + 1.0 / w.scene().robot.drive.acc_brake + 0.1);
  EXPECT_NEAR(Robot0(w.Snapshot()).vx, 0.0, 0.01);
}

TEST(Physics, BadCommandsAreRefusedAndMoveNothing) {
  World w(test::OneRobot());
  RobotCommand nan = Move(MoveKind::kLocalVelocity, NAN, 0, 0);
  EXPECT_EQ(w.SetCommand(nan), InputError::kNotFinite);
  RobotCommand inf = Move(MoveKind::kLocalVelocity, 0, 0, INFINITY);
  EXPECT_EQ(w.SetCommand(inf), InputError::kNotFinite);
  EXPECT_EQ(w.SetCommand(Move(MoveKind::kLocalVelocity, 500, 0, 0)), InputError::kOutOfRange);
  RobotCommand unknown = Move(MoveKind::kLocalVelocity, 1, 0, 0);
  unknown.id = 7;  // the scene has one robot a team
  EXPECT_EQ(w.SetCommand(unknown), InputError::kUnknownRobot);
  RobotCommand kick;
  kick.kick = KickKind::kFlat;
  kick.kick_speed = -1;
  EXPECT_EQ(w.SetCommand(kick), InputError::kOutOfRange);
  EXPECT_EQ(w.TeleportBall({{100, 0, 0}, {0, 0, 0}, false}), InputError::kOutsideField);
  EXPECT_EQ(w.TeleportBall({{0, NAN, 0}, {0, 0, 0}, false}), InputError::kNotFinite);
  EXPECT_EQ(w.TeleportRobot({Team::kBlue, 0, true, 0, 20, 0, {0, 0, 0}}), InputError::kOutsideField);
  EXPECT_EQ(w.TeleportRobot({Team::kYellow, 3, true, 0, 0, 0, {0, 0, 0}}), InputError::kUnknownRobot);
  // Taking a robot off the field with nonsense in its pose is refused too (it stays on).
  EXPECT_EQ(w.TeleportRobot({Team::kBlue, 0, false, 1e308, 0, 0, {0, 0, 0}}), InputError::kOutOfRange);
  EXPECT_EQ(w.TeleportRobot({Team::kBlue, 0, false, 0, 0, 1e300, {0, 0, 0}}), InputError::kOutOfRange);
  EXPECT_EQ(w.TeleportRobot({Team::kBlue, 0, false, 0, NAN, 0, {0, 0, 0}}), InputError::kNotFinite);
  const WorldSnapshot before = w.Snapshot();
  Advance(w, 1.0);
  const WorldSnapshot after = w.Snapshot();
  EXPECT_DOUBLE_EQ(Robot0(after).x, Robot0(before).x);
  EXPECT_DOUBLE_EQ(Robot0(after).y, Robot0(before).y);
  EXPECT_DOUBLE_EQ(after.ball.position.x, before.ball.position.x);
  EXPECT_TRUE(Robot0(after).on_field);
}

TEST(Physics, RobotsTakenOffTheFieldAreParkedAndBackOnAgain) {
  World w(test::OneRobot());
  ASSERT_EQ(w.TeleportRobot({Team::kBlue, 0, false, 0, 0, 0, {0, 0, 0}}), InputError::kOk);
  ASSERT_EQ(w.SetCommand(Move(MoveKind::kLocalVelocity, 1.0, 0, 0)), InputError::kOk);
  Advance(w, 0.5);
  EXPECT_FALSE(Robot0(w.Snapshot()).on_field);
  EXPECT_DOUBLE_EQ(Robot0(w.Snapshot()).vx, 0.0);
  ASSERT_EQ(w.TeleportRobot({Team::kBlue, 0, true, 1.0, 2.0, 0.5, {0, 0, 0}}), InputError::kOk);
  Advance(w, 0.01);
  EXPECT_TRUE(Robot0(w.Snapshot()).on_field);
  EXPECT_NEAR(Robot0(w.Snapshot()).x, 1.0, 0.01);
  EXPECT_NEAR(Robot0(w.Snapshot()).y, 2.0, 0.01);
}

// The constraint solver's cap is counted (WorldHealth): 22 robots driving and turning at once, at one iteration a
// step, hit it; at the scenes' cap (20) the solver converges, so no robot's motion depends on the others'.
TEST(Physics, StepsWhereTheSolverStoppedAtItsCapAreCounted) {
  for (const int iterations : {1, 20}) {
    Scene scene = test::Teams(11);
    scene.physics.solver_iterations = iterations;
    World w(scene);
    const int steps = Steps(w, 2.0);
    for (int i = 0; i < steps; ++i) {
      if (i % 8 == 0) {
        for (const RobotSetup& r : scene.robots) {
          RobotCommand c = Move(MoveKind::kLocalVelocity, 1.5, 0.5, 3.0);
          c.team = r.team;
          c.id = r.id;
          ASSERT_EQ(w.SetCommand(c), InputError::kOk);
        }
      }
      w.Step();
    }
    std::printf("%d iterations: %llu of %d steps capped\n", iterations,
                static_cast<unsigned long long>(w.health().solver_capped_steps), steps);
    if (iterations == 1)
      EXPECT_GT(w.health().solver_capped_steps, 0u);
    else
      EXPECT_EQ(w.health().solver_capped_steps, 0u);
  }
}

TEST(Physics, ResetRestoresTheStart) {
  World w(test::OneRobot(1.0, -1.0, 0.3));
  const WorldSnapshot start = w.Snapshot();
  Drive(w, Move(MoveKind::kLocalVelocity, 1.0, 0.5, 1.0), 1.0);
  w.Reset();
  const WorldSnapshot again = w.Snapshot();
  EXPECT_EQ(again.frame, 0u);
  EXPECT_DOUBLE_EQ(Robot0(again).x, Robot0(start).x);
  EXPECT_DOUBLE_EQ(Robot0(again).yaw, Robot0(start).yaw);
  EXPECT_DOUBLE_EQ(Robot0(again).vx, 0.0);
}

}  // namespace
}  // namespace turf
