// Scenes for tests, built in code so each test states what it relies on.
#pragma once

#include <cstdlib>

#include "core/scene.h"

namespace turf::test {

// The physics step of every test scene: the scene default, or TURF_TEST_PHYSICS_STEP (seconds), so the physics
// tests can show which larger steps keep the measured motion within their tolerances (tests/core/CMakeLists.txt
// runs them again at 4 ms, the step `import turf` offers for learning).
inline double TestPhysicsStep() {
  const char* step = std::getenv("TURF_TEST_PHYSICS_STEP");
  return step != nullptr ? std::atof(step) : PhysicsParams{}.step;
}

// Division A, no robots on the field, ball on the centre mark.
inline Scene EmptyDivA() {
  Scene s;
  s.name = "test";
  s.field = FieldForDivision(Division::kA);
  s.physics.step = TestPhysicsStep();
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
