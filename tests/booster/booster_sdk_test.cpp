// The Booster SDK's topics served for a simulated T1 (participants/booster_bridge): a client written as the SDK's
// low-level examples are (shared/protocols/booster-sdk-dds.md) subscribes rt/low_state and commands rt/joint_ctrl on
// the robot's DDS domain; turf-sim runs in lockstep on a memory bus, stepped by the test, so simulated time is the
// test's. Waits are conditions with deadlines.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <mutex>
#include <optional>
#include <thread>

#include "dds/control_client.h"
#include "dds/memory_bus.h"
#include "dds/vendor_participant.h"
#include "loader/legged_scene_yaml.h"
#include "participants/booster_bridge/booster_sdk_bridge.h"
#include "tests/booster/booster_rig.h"
#include "tests/test_domain.h"
#include "turf/idl/BoosterLowLevelPubSubTypes.h"

namespace turf {
namespace {

namespace bi = booster_interface::msg::dds_;
using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

// The scene's standing pose (t1_stand.yaml: Menagerie's home pose) with the SDK's b1_low_sdk_example gains, index
// order, and head pitch commanded to 0.785 rad as in the SDK's low_level_publisher. (The example's own start pose,
// ankles at -0.35, tips the T1 over: the facts warn of it.)
bi::LowCmd_ StandWithHeadDown(size_t joints = 23) {
  const float q[23] = {0, 0.785f, 0,    -1.4f, 0, -0.4f, 0, 1.4f, 0,    0.4f,  0, -0.2f,
                       0, 0,      0.4f, -0.2f, 0, -0.2f, 0, 0,    0.4f, -0.2f, 0};
  const float kp[23] = {5,   5,   40,  50,  20,  10,  40,  50,  20,  10,  100, 350,
                        350, 180, 350, 550, 550, 350, 350, 180, 350, 550, 550};
  const float kd[23] = {0.1f, 0.1f, 0.5f, 1.5f, 0.2f, 0.2f, 0.5f, 1.5f, 0.2f, 0.2f, 5,   7.5f,
                        7.5f, 3,    5.5f, 1.5f, 1.5f, 7.5f, 7.5f, 3,    5.5f, 1.5f, 1.5f};
  bi::LowCmd_ cmd;
  cmd.cmd_type(bi::SERIAL);
  cmd.motor_cmd().resize(joints);
  for (size_t i = 0; i < joints && i < 23; ++i) {
    cmd.motor_cmd()[i].q(q[i]);
    cmd.motor_cmd()[i].kp(kp[i]);
    cmd.motor_cmd()[i].kd(kd[i]);
    cmd.motor_cmd()[i].weight(1);
  }
  return cmd;
}

class BoosterSdkTest : public ::testing::Test {
 protected:
  BoosterSdkTest() : rig_(test::IdealT1Stand(), domain_), program_(domain_, "sdk-program") {
    low_state_ = program_.MakeReader<bi::LowState_PubSubType>("rt/low_state", [this](const bi::LowState_& s, int64_t) {
      std::lock_guard<std::mutex> lock(mutex_);
      last_ = s;
      ++received_;
      arrived_.notify_all();
    });
    joint_ctrl_ = program_.MakeWriter<bi::LowCmd_PubSubType>("rt/joint_ctrl");
  }

  void Step(uint32_t frames) {
    const dds::ControlOutcome o = rig_.Step(frames);
    ASSERT_TRUE(o.ok()) << o.Describe();
  }

  // Steps one frame at a time until `done(last LowState)` holds, up to `max_frames` or 20 s of wall time.
  bool StepUntil(const std::function<bool(const bi::LowState_&)>& done, int max_frames) {
    const auto deadline = Clock::now() + 20s;
    for (int i = 0; i < max_frames && Clock::now() < deadline; ++i) {
      Step(1);
      std::unique_lock<std::mutex> lock(mutex_);
      arrived_.wait_for(lock, 5ms, [&] { return last_ && done(*last_); });
      if (last_ && done(*last_)) return true;
    }
    return false;
  }

  // Writes `cmd` until the bridge has passed on (or refused) one more command, stepping meanwhile (best effort: the
  // first samples may go out before discovery has matched the reader).
  // `age`: the command's source timestamp that much in the past.
  // Writes `cmd` (best effort, as the SDK does: again each step) until the bridge took it, or, with `refused_as`,
  // until it refused one more under that kind; false at the deadline. Copies still in flight may be counted later.
  bool Send(const bi::LowCmd_& cmd, std::chrono::seconds age = 0s, const std::string& refused_as = "") {
    const BoosterSdkStats before = rig_.bridge().Stats();
    const auto deadline = Clock::now() + 20s;
    while (Clock::now() < deadline) {
      const int64_t now_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(
                                 std::chrono::system_clock::now().time_since_epoch() - age)
                                 .count();
      joint_ctrl_->Write(cmd, now_ns);
      Step(1);
      BoosterSdkStats now = rig_.bridge().Stats();
      if (refused_as.empty() ? now.commands > before.commands || now.refused > before.refused
                             : now.refused_by_kind[refused_as] > Count(before, refused_as))
        return true;
    }
    return false;
  }

  static uint64_t Count(const BoosterSdkStats& stats, const std::string& kind) {
    const auto it = stats.refused_by_kind.find(kind);
    return it == stats.refused_by_kind.end() ? 0 : it->second;
  }

  double Q(size_t joint) {
    std::lock_guard<std::mutex> lock(mutex_);
    return last_ ? last_->motor_state_serial().at(joint).q() : NAN;
  }

  const int domain_ = test::TestDomain(23);
  test::BoosterRig rig_;
  dds::VendorParticipant program_;
  std::unique_ptr<dds::VendorParticipant::RawReader> low_state_;
  std::unique_ptr<dds::VendorParticipant::Writer<bi::LowCmd_PubSubType>> joint_ctrl_;
  std::mutex mutex_;
  std::condition_variable arrived_;
  std::optional<bi::LowState_> last_;
  uint64_t received_ = 0;
};

TEST_F(BoosterSdkTest, LowStateCarriesTheT1AndJointCtrlMovesItsHead) {
  ASSERT_TRUE(StepUntil([](const bi::LowState_& s) { return s.motor_state_serial().size() == 23; }, 2000))
      << "no rt/low_state with 23 joints";
  Step(200);  // 1 s: the robot settles on its feet
  ASSERT_TRUE(StepUntil([](const bi::LowState_&) { return true; }, 10));
  ASSERT_EQ(rig_.bridge().Robots().size(), 1u);
  EXPECT_EQ(rig_.bridge().Robots()[0], "t1 (T1) on domain " + std::to_string(domain_));
  {
    std::lock_guard<std::mutex> lock(mutex_);
    EXPECT_EQ(last_->motor_state_parallel().size(), 23u);
    EXPECT_NEAR(last_->imu_state().acc()[2], 9.81, 0.5)
        << "acc " << last_->imu_state().acc()[0] << " " << last_->imu_state().acc()[1] << " rpy "
        << last_->imu_state().rpy()[0] << " " << last_->imu_state().rpy()[1];
    EXPECT_LT(std::abs(last_->imu_state().rpy()[0]), 0.05);
  }
  const double head_before = Q(1);
  EXPECT_GT(std::abs(head_before - 0.785), 0.5);  // far from the target at first
  ASSERT_TRUE(Send(StandWithHeadDown()));
  Step(400);  // 2 s
  // At rest the PD law holds: the motor's torque (tau_est) is kp (0.785 - q), here against the head's own weight,
  // within the joint's 0.1 N m of friction (0.02 rad at kp 5).
  auto settled = [](const bi::LowState_& s) {
    const bi::MotorState_& head = s.motor_state_serial()[1];
    return head.q() > 0.6 && std::abs(head.q() - (0.785 - head.tau_est() / 5.0)) < 0.03;
  };
  EXPECT_TRUE(StepUntil(settled, 200)) << "head pitch " << Q(1);
  EXPECT_GT(rig_.bridge().Stats().commands, 0u);
  EXPECT_EQ(rig_.bridge().Stats().refused, 0u);
  EXPECT_EQ(rig_.sim().Rejected("joint_command.out_of_range"), 0u);
  EXPECT_EQ(rig_.sim().Rejected("joint_command.unknown_joint"), 0u);
  EXPECT_EQ(rig_.sim().Rejected("joint_command.not_finite"), 0u);
  EXPECT_EQ(rig_.sim().Rejected("joint_command.unknown_robot"), 0u);
}

TEST_F(BoosterSdkTest, BadCommandsAreRefusedAndTheRobotHoldsItsLastCommand) {
  ASSERT_TRUE(StepUntil([](const bi::LowState_& s) { return s.motor_state_serial().size() == 23; }, 2000));
  ASSERT_TRUE(Send(StandWithHeadDown()));
  Step(400);
  const double held = Q(1);
  const uint64_t taken = rig_.bridge().Stats().commands;
  bi::LowCmd_ k1_sized = StandWithHeadDown(22);  // a K1's 22 joints for a T1
  EXPECT_TRUE(Send(k1_sized, 0s, "joint_ctrl.malformed"));
  bi::LowCmd_ nan = StandWithHeadDown();
  nan.motor_cmd()[1].q(std::nanf(""));
  EXPECT_TRUE(Send(nan, 0s, "joint_ctrl.not_finite"));
  EXPECT_TRUE(Send(StandWithHeadDown(), 10s, "joint_ctrl.stale"));       // a command 10 s old
  EXPECT_TRUE(Send(StandWithHeadDown(), -86400s, "joint_ctrl.future"));  // one dated a day ahead
  EXPECT_EQ(rig_.bridge().Stats().commands, taken);                      // none of them reached turf-sim
  bi::LowCmd_ beyond = StandWithHeadDown();
  // Garbage far past any joint (a target past the joint's range but within kMaxPdTarget is a command, as on a real
  // servo): turf-sim's validator refuses the whole message.
  beyond.motor_cmd()[1].q(1000.0f);
  ASSERT_TRUE(Send(beyond));
  Step(200);
  EXPECT_TRUE(
      StepUntil([&](const bi::LowState_&) { return rig_.sim().Rejected("joint_command.out_of_range") >= 1; }, 200));
  EXPECT_NEAR(Q(1), held, 0.02);  // still the last accepted command
}

// Every T1 and K1 of a scene on a DDS domain of its own, in scene order.
// t1_stand.yaml with a second T1, t1_b, 2 m along x.
LeggedScene TwoT1() {
  LeggedScene scene = test::LoadScene("t1_stand.yaml");
  LeggedRobot second = scene.robots[0];
  second.name = "t1_b";
  second.x = 2.0;
  scene.robots.push_back(second);
  return scene;
}

TEST(BoosterSdkRobots, EachRobotGetsTheNextDomain) {
  const int domain = test::TestDomain(41);
  test::BoosterRig rig(TwoT1(), domain);
  const auto deadline = Clock::now() + 20s;
  while (rig.bridge().Robots().size() < 2 && Clock::now() < deadline) ASSERT_TRUE(rig.Step(4).ok());
  const std::vector<std::string> robots = rig.bridge().Robots();
  ASSERT_EQ(robots.size(), 2u);
  EXPECT_EQ(robots[0], "t1 (T1) on domain " + std::to_string(domain));
  EXPECT_EQ(robots[1], "t1_b (T1) on domain " + std::to_string(domain + 1));
}

// Robots past DDS domain 232 are not served, and the process goes on: Fast DDS exited turf-sim (status 1, no log
// line of turf's) when it made the second robot's participant on domain 233.
TEST(BoosterSdkRobots, ARobotPastTheLastDomainIsNotServed) {
  test::BoosterRig rig(TwoT1(), 232);
  const auto deadline = Clock::now() + 20s;
  while (rig.bridge().Robots().empty() && Clock::now() < deadline) ASSERT_TRUE(rig.Step(4).ok());
  for (int i = 0; i < 5; ++i) ASSERT_TRUE(rig.Step(4).ok());
  const std::vector<std::string> robots = rig.bridge().Robots();
  ASSERT_EQ(robots.size(), 1u);
  EXPECT_EQ(robots[0], "t1 (T1) on domain 232");
}

}  // namespace
}  // namespace turf
