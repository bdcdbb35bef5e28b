// Scenes for tests, built in code so each test states what it relies on.
#pragma once

#include <cstdio>
#include <cstdlib>

#include "core/scene.h"

namespace turf::test {

// The physics step and wall segments of every test scene: the scene defaults, or TURF_TEST_PHYSICS="STEP
// SEGMENTS" (seconds, boxes per wall), so the physics tests can show which configurations keep the measured
// motion within their tolerances (tests/core/CMakeLists.txt runs them again in the one `import turf` offers for
// learning).
inline PhysicsParams TestPhysics() {
  PhysicsParams p;
  if (const char* v = std::getenv("TURF_TEST_PHYSICS")) std::sscanf(v, "%lf %d", &p.step, &p.wall_segments);
  return p;
}

// Division A, no robots on the field, ball on the centre mark.
inline Scene EmptyDivA() {
  Scene s;
  s.name = "test";
  s.field = FieldForDivision(Division::kA);
  s.physics = TestPhysics();
  return s;
}

// One blue robot (id 0) at the origin facing +x, ball parked far away.
inline Scene OneRobot(double x = 0.0, double y = 0.0, double theta = 0.0) {
  Scene s = EmptyDivA();
  s.robots_per_team = 1;
  s.robots.push_back({Team::kBlue, 0, true, {x, y, theta}});
  s.ball_start_x = 5.0;
  s.ball_start_y = 4.0;
  return s;
}

// 2 x n robots in a kick-off-like spread over both halves.
inline Scene Teams(int per_team) {
  Scene s = EmptyDivA();
  s.robots_per_team = per_team;
  for (int team = 0; team < 2; ++team) {
    for (int id = 0; id < per_team; ++id) {
      const double side = team == 0 ? -1.0 : 1.0;
      s.robots.push_back({static_cast<Team>(team),
                          id,
                          true,
                          {side * (1.0 + 0.5 * (id % 8)), -3.5 + 1.0 * (id / 8) + 0.45 * (id % 8), 0.0}});
    }
  }
  return s;
}

}  // namespace turf::test
