// rcssserver3d's hinge stops (scene joint_stops: ODE's joint limit, tested
// only at the start of each 20 ms ODE step, stop ERP 0.8, bounce 1; and the
// HingeEffector's rule that a velocity command is taken only strictly inside
// the stops) against the reference's measured motion: rcssserver3d 0.7.3,
// a standing Nao, left elbow +3 rad/s into its +1 deg stop, right elbow
// -3 rad/s into its -1 deg stop, head pitch +3 rad/s into its 45 deg stop,
// commanded every cycle, then -1 / +1 / -1 rad/s out again. The reference's
// elbows alternate every cycle between 0.000 and 3.437 deg (3 rad/s x 20 ms
// beyond the stop, then thrown back), its head between 44.68 and 48.11 deg;
// after the reverse command each elbow moves 1.146 deg per cycle at once.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/legged/legged_world.h"
#include "tests/core/legged/nao_fixture.h"

namespace turf {
namespace {

constexpr double kDeg = M_PI / 180.0;
constexpr double kCycle = 0.02;  // s, one SimSpark cycle

class NaoStopTest : public ::testing::TestWithParam<double> {
 protected:
  NaoStopTest() : world_(Scene()) {}
  static LeggedScene Scene() {
    LeggedScene s = testing::NaoScene();
    s.physics.step = GetParam();
    s.joint_stops.enabled = true;
    return s;
  }
  // One cycle: the commands (every cycle, as an agent sends them), then 20 ms of physics.
  void Cycle(double elbows, double head) {
    ASSERT_EQ(world_.SetJointCommand(0, {"laj4", JointMode::kVelocity, elbows}), JointCommandError::kOk);
    ASSERT_EQ(world_.SetJointCommand(0, {"raj4", JointMode::kVelocity, -elbows}), JointCommandError::kOk);
    ASSERT_EQ(world_.SetJointCommand(0, {"hj2", JointMode::kVelocity, head}), JointCommandError::kOk);
    const int64_t end = world_.time_ns() + static_cast<int64_t>(std::llround(kCycle * 1e9));
    while (world_.time_ns() < end) world_.Step();
  }
  double Angle(const std::string& joint) const {
    return world_.State().robots[0].joint_positions[world_.JointIndex(0, joint)] / kDeg;
  }
  LeggedWorld world_;
};

TEST_P(NaoStopTest, JointDrivenIntoItsStopAlternatesAndObeysTheReverseCommandAsTheReferences) {
  for (int i = 0; i < 25; ++i) Cycle(0.0, 0.0);  // 0.5 s standing
  std::vector<double> left, right, head;
  for (int i = 0; i < 30; ++i) {
    Cycle(3.0, 3.0);
    left.push_back(Angle("laj4"));
    right.push_back(Angle("raj4"));
    head.push_back(Angle("hj2"));
  }
  // Elbows: from 0 (inside the 1 deg stop) a full cycle beyond (3.437 deg), thrown back to 0, and again.
  const double travel = 3.0 * kCycle / kDeg;
  for (int i = 0; i < 30; ++i) {
    const double expected = i % 2 == 0 ? travel : 0.0;
    EXPECT_NEAR(left[i], expected, 0.1) << "cycle " << i;
    EXPECT_NEAR(right[i], -expected, 0.1) << "cycle " << i;
  }
  // Head: 3.437 deg per cycle up to 44.68, then 48.11 / 44.68 alternating (the reference's values).
  for (int i = 12; i < 30; ++i) EXPECT_NEAR(head[i], i % 2 == 0 ? 44.68 : 48.11, 0.1) << "cycle " << i;
  std::printf("elbow at the stop: %.3f %.3f %.3f %.3f deg; head %.3f %.3f deg\n", left[26], left[27], left[28],
              left[29], head[28], head[29]);
  // Reverse, given while the joint is inside (at 0, as the reference's at that cycle): taken at once,
  // 1.146 deg per cycle.
  std::vector<double> back;
  for (int i = 0; i < 10; ++i) {
    Cycle(-1.0, -1.0);
    back.push_back(Angle("laj4"));
  }
  EXPECT_NEAR(back[0], -1.0 * kCycle / kDeg, 0.1);
  for (int i = 1; i < 10; ++i) EXPECT_NEAR(back[i] - back[i - 1], -1.0 * kCycle / kDeg, 0.05) << "cycle " << i;
}

// The HingeEffector's rule: a command given while the joint is beyond its
// stop is ignored, the old one stays (the stop throws the joint back inside
// and the old command drives it out again); without the rule it is taken.
TEST_P(NaoStopTest, CommandBeyondAStopIsIgnoredOnlyWithTheRule) {
  for (bool rule : {true, false}) {
    LeggedScene s = Scene();
    s.joint_stops.hold_commands_at_stop = rule;
    LeggedWorld w(std::move(s));
    const auto cycle = [&w] {
      const int64_t end = w.time_ns() + static_cast<int64_t>(std::llround(kCycle * 1e9));
      while (w.time_ns() < end) w.Step();
      return w.State().robots[0].joint_positions[w.JointIndex(0, "laj4")] / kDeg;
    };
    for (int i = 0; i < 25; ++i) cycle();
    ASSERT_EQ(w.SetJointCommand(0, {"laj4", JointMode::kVelocity, 3.0}), JointCommandError::kOk);
    ASSERT_NEAR(cycle(), 3.0 * kCycle / kDeg, 0.1);  // beyond the 1 deg stop
    ASSERT_EQ(w.SetJointCommand(0, {"laj4", JointMode::kVelocity, -1.0}), JointCommandError::kOk);
    EXPECT_NEAR(cycle(), 0.0, 0.1) << "rule " << rule;  // thrown back either way
    EXPECT_NEAR(cycle(), rule ? 3.0 * kCycle / kDeg : -1.0 * kCycle / kDeg, 0.1) << "rule " << rule;
  }
}

INSTANTIATE_TEST_SUITE_P(Steps, NaoStopTest, ::testing::Values(0.002, 0.005, 0.02 / 3),
                         [](const ::testing::TestParamInfo<double>& p) {
                           return std::to_string(static_cast<int>(std::lround(p.param * 1e6))) + "us";
                         });

}  // namespace
}  // namespace turf
