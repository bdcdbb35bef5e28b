// The ball of each league's shipped scenes, as its reference simulator has it: measured rolling, in simulation time.
//
// rcssserver3d (configs/scenes/simspark_match.yaml): a DragController on the ball, a force -c_l v and a torque
// -c_a w (c_l = 0.01 N s/m, c_a = 0.00005 N m s/rad; shared/protocols/simspark.md). A ball rolling without slip
// (w = v / r, inertia 0.4 m r^2) obeys 1.4 m dv/dt = -(c_l + c_a / r^2) v: its speed decays as exp(-k t) with
// k = (0.01 + 0.00005 / 0.042^2) / (1.4 x 0.026) = 1.053 /s, so a ball kicked to 2 m/s rolls about 1.4 m.
//
// RCSSServerMJ (configs/scenes/rcssservermj_fifa_1v1.yaml): friction 0.4 / 0.01 / 0.01 with condim 6, solref
// (-5000, -20) and priority 1 (its world.xml: the ball's parameters rule its contacts), air 1.2 kg/m^3
// (shared/protocols/rcssservermj.md). Rolling friction bounds the rolling torque by 0.01 m x the normal force, so
// a slow ball (air drag negligible) slows at most at 0.01 g / (1.4 r) = 0.64 m/s^2; MuJoCo's soft constraint
// reaches most of it (measured 0.59 m/s^2 in MuJoCo 2.2.2; without the priority the ground's softer solref mixes
// in and it is 0.26). RCSSServerMJ runs MuJoCo 3.4, not in Debian 12: its own figure is not measured here.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/legged/legged_mjcf.h"
#include "core/legged/legged_world.h"
#include "loader/legged_scene_yaml.h"

namespace turf {
namespace {

LeggedScene Shipped(const std::string& file) {
  LeggedSceneLoadResult r = LoadLeggedSceneFile(TURF_SOURCE_DIR "/configs/scenes/" + file);
  if (!r.scene) throw std::runtime_error(r.errors.front());
  return std::move(*r.scene);
}

// Steps until the simulation time reaches `t` s; the ball's speed on the ground plane then.
double BallSpeedAt(LeggedWorld& w, double t) {
  while (w.State().time_ns < std::llround(t * 1e9)) w.Step();
  const LeggedWorldState s = w.State();
  return std::hypot(s.ball_velocity[0], s.ball_velocity[1]);
}

TEST(Ball, SimSparkBallRollsOutWithTheReferencesDrag) {
  LeggedWorld w(Shipped("simspark_match.yaml"));
  const double r = 0.042;
  ASSERT_EQ(w.PlaceBall({0.0, 5.0, r}, {2.0, 0.0, 0.0}), PlacementError::kOk);
  const double v1 = BallSpeedAt(w, 0.5);  // sliding has turned into rolling
  const double v2 = BallSpeedAt(w, 1.5);
  const double k = (0.01 + 0.00005 / (r * r)) / (1.4 * 0.026);
  std::printf("SimSpark ball: %.3f m/s at 0.5 s, %.3f at 1.5 s: decay %.3f /s (reference %.3f /s)\n", v1, v2,
              std::log(v1 / v2), k);
  ASSERT_GT(v1, 0.5);
  EXPECT_NEAR(std::log(v1 / v2), k, 0.05 * k);
  const double x = w.State().ball_position[0];
  for (int i = 0; i < 1000; ++i) w.Step();
  EXPECT_NEAR(w.State().ball_position[0] - x, v2 / k, 0.1 * v2 / k) << "what is left of the roll";
}

// rcssserver3d's ball surface (slip 0.6, mixed with the ground's 5e-3: 0.30 m/(s N), no Coulomb bound): a ball
// launched without spin turns to rolling (5/7 of its speed) within milliseconds, where MuJoCo's Coulomb friction
// (the larger of the ball's 0.6 and the ground's) lets it slide for up to 2/7 v / (mu g) = 0.1 s first. Both at a
// 6.67 ms step, where MuJoCo's slide shows (1.64 m/s at 50 ms; at 2 and 5 ms 1.48, its soft contact's impulses
// differ with the step); at the scene's 20 ms step its friction ends the slide within the first steps.
TEST(Ball, SimSparkBallTakesToRollingAtOnceOnItsSurface) {
  const auto speed_at_50ms = [](LeggedScene scene) -> double {
    scene.physics.step = 0.02 / 3;
    LeggedWorld w(std::move(scene));
    if (w.PlaceBall({0.0, 5.0, 0.042}, {2.0, 0.0, 0.0}) != PlacementError::kOk) return NAN;
    return BallSpeedAt(w, 0.05);
  };
  const double with_surface = speed_at_50ms(Shipped("simspark_match.yaml"));
  LeggedScene mujoco = Shipped("simspark_match.yaml");
  mujoco.contacts.ball = OdeSurface{};
  const double without = speed_at_50ms(mujoco);
  const double rolling = 2.0 * 5.0 / 7.0 * std::exp(-1.053 * 0.05);
  std::printf("SimSpark ball 50 ms after a 2 m/s launch: %.3f m/s (rolling %.3f); MuJoCo's friction: %.3f\n",
              with_surface, rolling, without);
  EXPECT_NEAR(with_surface, rolling, 0.03 * rolling);
  EXPECT_GT(without, rolling + 0.15) << "still sliding";
}

// ball.rsg's bounce (0.8 above 0.8 m/s; the ground sets none, so the ball's holds): dropped from 1 m, the ball
// leaves the ground at 0.8 of the speed it hit it with; with MuJoCo's own contact it hardly bounces.
TEST(Ball, SimSparkBallBouncesAtEightTenths) {
  const auto rebound = [](LeggedScene scene) -> double {
    LeggedWorld w(std::move(scene));
    if (w.PlaceBall({0.0, 5.0, 1.0}, {0.0, 0.0, 0.0}) != PlacementError::kOk) return NAN;
    double down = 0.0;
    double up = 0.0;
    while (w.time_ns() < 800'000'000) {  // the fall takes 0.44 s
      w.Step();
      const double vz = w.State().ball_velocity[2];
      down = std::max(down, -vz);
      up = std::max(up, vz);
    }
    return up / down;
  };
  const double shipped = rebound(Shipped("simspark_match.yaml"));
  LeggedScene mujoco = Shipped("simspark_match.yaml");
  mujoco.contacts.ball = OdeSurface{};
  const double without = rebound(mujoco);
  std::printf("SimSpark ball dropped from 1 m: leaves at %.3f of its impact speed (MuJoCo's contact: %.3f)\n", shipped,
              without);
  EXPECT_NEAR(shipped, 0.8, 0.03);
  EXPECT_LT(without, 0.3);
}

// The deceleration of a slow ball (1.2 m/s at the start) over 0.5 s, m/s^2.
double SlowBallDeceleration(LeggedScene scene) {
  LeggedWorld w(std::move(scene));
  if (w.PlaceBall({0.0, 5.0, 0.11}, {1.2, 0.0, 0.0}) != PlacementError::kOk) return NAN;
  const double v1 = BallSpeedAt(w, 0.3);
  const double v2 = BallSpeedAt(w, 0.8);
  return (v1 - v2) / 0.5;
}

TEST(Ball, RcssServerMjBallSlowsByItsRollingFriction) {
  const double shipped = SlowBallDeceleration(Shipped("rcssservermj_fifa_1v1.yaml"));
  LeggedScene without = Shipped("rcssservermj_fifa_1v1.yaml");
  without.field.ball_condim = 3;  // no torsional or rolling friction
  const double sliding_only = SlowBallDeceleration(without);
  const double bound = 0.01 * 9.81 / (1.4 * 0.11);
  std::printf("RCSSServerMJ ball at 1.2 m/s: %.3f m/s^2 (condim 3: %.3f; a hard rolling bound would give %.3f)\n",
              shipped, sliding_only, bound);
  // MuJoCo's soft rolling constraint (solref -5000 -20) comes close to the bound of a hard one; the reference
  // (RCSSServerMJ's world on MuJoCo 3.5.1 and 3.14.0, the same ball placed and timed alike, measured with the
  // WebAssembly build as in docs/fidelity-booster.md) slows it at 0.586 m/s^2.
  EXPECT_NEAR(shipped, bound, 0.15 * bound);
  EXPECT_NEAR(shipped, 0.586, 0.005);
  EXPECT_LT(std::abs(sliding_only), 0.05) << "without rolling friction a slow ball keeps its speed";
}

// RCSSServerMJ's air on a ball in flight (LeggedWorld applies it itself, core/legged/body_forces.h): MuJoCo's
// inertia-box model gives a solid sphere the box of side r sqrt(2.4) and a drag 0.5 rho s^2 v^2 along each of the
// box's axes (the sphere's, which stay the world's with no spin), so a ball thrown level at v0 obeys
// dv/dt = -k v^2, k = 0.5 rho s^2 / m, and has v0 / (1 + k v0 t) after t. Viscosity adds 3 pi d mu v, under
// 0.1 % of it. Without the air the ball would keep its 10 m/s.
TEST(Ball, RcssServerMjBallInFlightSlowsByTheAirsDrag) {
  LeggedWorld w(Shipped("rcssservermj_fifa_1v1.yaml"));
  const double r = 0.11, m = 0.41, v0 = 10.0, t = 0.2;
  const double side = r * std::sqrt(2.4);
  const double k = 0.5 * 1.2 * side * side / m;
  ASSERT_EQ(w.PlaceBall({0.0, 0.0, 20.0}, {v0, 0.0, 0.0}), PlacementError::kOk);
  while (w.State().time_ns < std::llround(t * 1e9)) w.Step();
  const LeggedWorldState s = w.State();
  ASSERT_GT(s.ball_position[2], 1.0) << "still in flight";
  const double predicted = v0 / (1.0 + k * v0 * t);
  std::printf("ball thrown at %.1f m/s: %.4f m/s after %.1f s of flight (predicted %.4f)\n", v0, s.ball_velocity[0], t,
              predicted);
  EXPECT_NEAR(s.ball_velocity[0], predicted, 0.01);
  EXPECT_LT(s.ball_velocity[0], v0 - 0.5) << "the air slows it";
}

TEST(Ball, SceneFilesCarryTheBallsContactAndTheAir) {
  const std::string mj = ComposeLeggedMjcf(Shipped("rcssservermj_fifa_1v1.yaml")).xml;
  EXPECT_NE(mj.find(R"(friction="0.4 0.01 0.01" condim="6" solref="-5000 -20" priority="1")"), std::string::npos);
  EXPECT_NE(mj.find(R"(density="1.2" viscosity="2e-05")"), std::string::npos);
  const std::string ss = ComposeLeggedMjcf(Shipped("simspark_match.yaml")).xml;
  EXPECT_NE(ss.find(R"(density="0" viscosity="0")"), std::string::npos) << "no air in SimSpark";
}

}  // namespace
}  // namespace turf
