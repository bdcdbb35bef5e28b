// The legged kernel without DDS: snapshot and restore continue a Nao match bit
// for bit, sensor noise is a function of the frame (reading more often changes
// nothing), and every sensor stream has its modelled latency and loss.
#include "kernel/legged_kernel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "tests/kernel/kernel_fixtures.h"

namespace turf {
namespace {

using testing::DriveLegged;
using testing::LeggedMatch;

// Latency, jitter and loss on all three legged streams.
LeggedScene LinkedMatch() {
  LeggedScene s = LeggedMatch("realistic");
  s.realism.encoder.link.latency = 0.010;
  s.realism.encoder.link.jitter = 0.002;
  s.realism.encoder.link.loss = 0.05;
  s.realism.imu.link.latency = 0.004;
  s.realism.imu.link.loss = 0.02;
  s.realism.touch.link = LinkParams{};
  s.realism.touch.link.latency = 0.020;
  return s;
}

// The fields a stream carries (all three for the measured frame).
void RecordRobot(const LeggedRobotState& r, StateWriter& out, std::optional<LeggedStream> only = std::nullopt) {
  if (!only || *only == LeggedStream::kJoints) {
    for (const auto* v : {&r.joint_positions, &r.joint_velocities, &r.joint_efforts}) out.Doubles(*v);
  }
  if (!only || *only == LeggedStream::kImu) {
    for (double x : r.gyro) out.Put(x);
    for (double x : r.accelerometer) out.Put(x);
    for (double x : r.base_position) out.Put(x);
  }
  if (!only || *only == LeggedStream::kTouch) {
    for (const ForceReading& f : r.forces) {
      out.Doubles(f.values);
      for (double x : f.force) out.Put(x);
    }
  }
}

// Every output of a step: the measured frame and the released samples.
void RecordOutputs(const LeggedKernel& k, StateWriter& out) {
  LeggedWorldState s;
  k.Measure(&s);
  out.Put(s.frame);
  for (const LeggedRobotState& r : s.robots) RecordRobot(r, out);
  for (const LeggedSample& sample : k.released()) {
    out.Put(sample.stream);
    out.Put(sample.robot);
    out.Put(sample.time_ns);
    RecordRobot(sample.robot_state, out, sample.stream);
  }
}

std::pair<std::string, std::string> Continue(LeggedKernel& k, int steps, bool extra_reads) {
  StateWriter out;
  for (int i = 0; i < steps; ++i) {
    DriveLegged(k);
    k.Step();
    if (extra_reads) {  // as a viewer's refused requests made the node publish
      LeggedWorldState ignored;
      for (int n = 0; n < 3; ++n) k.Measure(&ignored);
    }
    RecordOutputs(k, out);
  }
  return {out.Take(), k.Save()};
}

TEST(LeggedKernelTest, RestoreContinuesANaoMatchByteForByte) {
  LeggedKernel k(LinkedMatch());
  for (int i = 0; i < 200; ++i) {
    DriveLegged(k);
    k.Step();
  }
  const std::string snapshot = k.Save();
  const auto first = Continue(k, 600, false);
  ASSERT_EQ(k.Restore(snapshot), "");
  const auto again = Continue(k, 600, false);
  EXPECT_TRUE(again.first == first.first) << "outputs differ after restore";
  EXPECT_TRUE(again.second == first.second) << "state differs after restore";

  LeggedKernel fresh(LinkedMatch());
  ASSERT_EQ(fresh.Restore(snapshot), "");
  const auto elsewhere = Continue(fresh, 600, false);
  EXPECT_TRUE(elsewhere.first == first.first) << "outputs differ in a fresh kernel";
}

// A Booster T1 under PD commands (JointMode::kPd: q, dq, kp, kd, tau per
// joint) with realistic sensors: the snapshot holds the PD command state, so a
// restored kernel continues bit for bit, in place and in a fresh kernel.
TEST(LeggedKernelTest, RestoreContinuesAT1UnderPdCommandsByteForByte) {
  auto scene = [] {
    LeggedSceneLoadResult r = LoadLeggedSceneFile(TURF_SOURCE_DIR "/configs/scenes/t1_stand.yaml");
    if (!r.scene) throw std::runtime_error(r.errors.front());
    r.scene->realism = testing::Preset("realistic");
    return std::move(*r.scene);
  };
  auto drive = [](LeggedKernel& k, int steps) {
    StateWriter out;
    for (int i = 0; i < steps; ++i) {
      const double t = static_cast<double>(k.time_ns()) * 1e-9;
      std::vector<JointCommand> commands;
      for (const char* side : {"Left", "Right"}) {
        JointCommand hip{std::string(side) + "_Hip_Pitch", JointMode::kPd, -0.2 + 0.1 * std::sin(3 * t), 350, 7.5};
        hip.dq = 0.3 * std::cos(3 * t);
        hip.tau = std::sin(t);
        commands.push_back(hip);
      }
      if (k.frame() % 7 == 0) k.SetJointCommands(0, commands);  // held between: the snapshot must carry them
      k.Step();
      RecordOutputs(k, out);
    }
    return std::make_pair(out.Take(), k.Save());
  };
  LeggedKernel k(scene());
  drive(k, 200);
  const std::string snapshot = k.Save();
  const auto first = drive(k, 400);
  ASSERT_EQ(k.Restore(snapshot), "");
  const auto again = drive(k, 400);
  EXPECT_TRUE(again.first == first.first) << "outputs differ after restore";
  EXPECT_TRUE(again.second == first.second) << "state differs after restore";
  LeggedKernel fresh(scene());
  ASSERT_EQ(fresh.Restore(snapshot), "");
  EXPECT_TRUE(drive(fresh, 400).first == first.first) << "outputs differ in a fresh kernel";
  // Into a kernel of another seed: the snapshot's noise goes on (the readings were the other seed's, the ground truth
  // equal), and a reset brings the kernel's own seed back.
  LeggedScene other_scene = scene();
  other_scene.seed += 96;
  LeggedKernel other(other_scene);
  const auto own = drive(other, 400);
  other.Reset();
  ASSERT_EQ(other.Restore(snapshot), "");
  EXPECT_TRUE(drive(other, 400).first == first.first) << "outputs differ in a kernel of another seed";
  other.Reset();
  EXPECT_TRUE(drive(other, 400).first == own.first) << "a reset after the restore is the kernel's own seed again";
}

TEST(LeggedKernelTest, ReadingMoreOftenChangesNoReading) {
  LeggedKernel quiet(LinkedMatch());
  LeggedKernel busy(LinkedMatch());
  const auto a = Continue(quiet, 500, false);
  const auto b = Continue(busy, 500, true);
  EXPECT_TRUE(a.first == b.first);
  EXPECT_TRUE(a.second == b.second);
  // And the readings are noisy: the measured frame is not the exact state.
  LeggedWorldState exact;
  LeggedWorldState measured;
  quiet.world().State(&exact);
  quiet.Measure(&measured);
  EXPECT_NE(exact.robots[0].joint_positions, measured.robots[0].joint_positions);
}

TEST(LeggedKernelTest, EveryStreamArrivesWithItsLatencyAndLoss) {
  LeggedKernel k(LinkedMatch());
  const LeggedScene& s = k.scene();
  const int64_t frame_ns = k.world().step_ns() * k.sensor_every();
  size_t joints = 0;
  size_t touch = 0;
  double joint_delay = 0.0;
  uint64_t sent = 0, lost = 0;
  while (k.time_ns() < 20'000'000'000) {  // 20 s: 1000 sensor frames per robot
    k.Step();
    for (const LeggedSample& sample : k.released()) {
      const double delay = (k.time_ns() - sample.time_ns) * 1e-9;
      if (sample.stream == LeggedStream::kJoints) {
        ++joints;
        joint_delay += delay;
        EXPECT_GE(delay, 0.010 - 0.0025 * 4);  // latency minus 4 sigma of jitter
      } else if (sample.stream == LeggedStream::kTouch) {
        ++touch;
        EXPECT_GE(delay, 0.020 - 1e-9);                               // no jitter: at least the latency
        EXPECT_LT(delay, 0.020 + k.world().step_ns() * 1e-9 + 1e-9);  // released at the first step after it
      }
    }
    if (k.stats()) {
      for (const auto& [name, w] : k.stats()->streams) {
        if (name.find("/joint_state") == std::string::npos) continue;
        sent += w.sent;
        lost += w.lost;
      }
    }
  }
  const size_t frames = static_cast<size_t>(20'000'000'000 / frame_ns);
  const size_t robots = s.robots.size();
  // Touch: no loss, every frame arrives. Joints: 5 % loss, mean delay ~10 ms.
  EXPECT_NEAR(static_cast<double>(touch), static_cast<double>(frames * robots), 2.0 * robots);
  const double loss = 1.0 - static_cast<double>(joints) / (frames * robots);
  EXPECT_NEAR(loss, 0.05, 0.02);
  EXPECT_NEAR(joint_delay / joints, 0.010 + 0.5 * k.world().step_ns() * 1e-9, 0.002);
  ASSERT_GT(sent, 0u);
  EXPECT_NEAR(static_cast<double>(lost) / sent, 0.05, 0.02);  // the stats topic's view agrees
}

}  // namespace
}  // namespace turf
