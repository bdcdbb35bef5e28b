// Determinism contract: the same scene and the same command stream give the
// same world, bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "core/world.h"
#include "tests/core/test_scenes.h"

namespace turf {
namespace {

// A busy scripted match: everyone drives, turns, dribbles and kicks.
std::vector<WorldSnapshot> RunScript(const Scene& scene, int steps) {
  World w(scene);
  std::vector<WorldSnapshot> out;
  for (int i = 0; i < steps; ++i) {
    if (i % 8 == 0) {
      for (const RobotSetup& r : scene.robots) {
        RobotCommand c;
        c.team = r.team;
        c.id = r.id;
        c.move = MoveKind::kLocalVelocity;
        c.velocity = {std::sin(0.001 * i + r.id), std::cos(0.002 * i * (r.id + 1)), std::sin(0.003 * i)};
        c.kick = (i / 8 + r.id) % 5 == 0 ? KickKind::kFlat : KickKind::kNone;
        c.kick_speed = 4.0;
        c.dribbler_speed = (r.id % 2) ? 1000 : 0;
        EXPECT_EQ(w.SetCommand(c), InputError::kOk);
      }
    }
    if (i == 300) {
      EXPECT_EQ(w.TeleportBall({{-2.0, 0.5, 0.0215}, {3.0, -1.0, 0.0}, false}), InputError::kOk);
    }
    w.Step();
    if (i % 50 == 0) out.push_back(w.Snapshot());
  }
  out.push_back(w.Snapshot());
  return out;
}

bool Identical(const WorldSnapshot& a, const WorldSnapshot& b) {
  if (a.frame != b.frame || a.robots.size() != b.robots.size()) return false;
  if (std::memcmp(&a.ball, &b.ball, sizeof(a.ball)) != 0) return false;
  for (size_t i = 0; i < a.robots.size(); ++i) {
    const RobotSnapshot &p = a.robots[i], &q = b.robots[i];
    if (p.x != q.x || p.y != q.y || p.yaw != q.yaw || p.vx != q.vx || p.vy != q.vy || p.omega != q.omega ||
        p.kick_count != q.kick_count)
      return false;
  }
  return true;
}

TEST(Determinism, SameSceneAndCommandsGiveIdenticalWorlds) {
  const Scene scene = test::Teams(11);
  const auto a = RunScript(scene, 3000);
  const auto b = RunScript(scene, 3000);
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) ASSERT_TRUE(Identical(a[i], b[i])) << "diverged at sample " << i;
  // The script really moved things (so the comparison means something).
  EXPECT_GT(std::abs(a.back().robots[0].x - a.front().robots[0].x), 0.1);
}

TEST(Determinism, ResetReplaysIdentically) {
  const Scene scene = test::Teams(6);
  World w(scene);
  auto run = [&] {
    RobotCommand c;
    c.move = MoveKind::kGlobalVelocity;
    c.velocity = {1.0, 0.5, 2.0};
    for (int i = 0; i < 1000; ++i) {
      if (i % 8 == 0) {
        EXPECT_EQ(w.SetCommand(c), InputError::kOk);
      }
      w.Step();
    }
    return w.Snapshot();
  };
  const WorldSnapshot first = run();
  w.Reset();
  const WorldSnapshot second = run();
  EXPECT_TRUE(Identical(first, second));
}

TEST(Determinism, DifferentCommandsGiveDifferentWorlds) {
  Scene scene = test::Teams(2);
  const auto a = RunScript(scene, 600);
  scene.robots[0].pose.x += 0.01;
  const auto b = RunScript(scene, 600);
  EXPECT_FALSE(Identical(a.back(), b.back()));
}

}  // namespace
}  // namespace turf
