// The SSL kernel without DDS: snapshot and restore continue a realistic match
// bit for bit (state and every output), inputs are validated, the outputs are
// the node's old ones (cameras, feedback, statistics).
#include "kernel/ssl_kernel.h"

#include <gtest/gtest.h>

#include "core/state_fields.h"
#include "tests/kernel/kernel_fixtures.h"

namespace turf {
namespace {

using testing::DriveSsl;
using testing::SslMatch;

// Every output of a step as bytes: state, camera frames, feedback, statistics.
void RecordOutputs(const SslKernel& k, StateWriter& out) {
  const WorldSnapshot& s = k.state();
  out.Put(s.time_ns);
  out.Put(s.frame);
  for (double v : {s.ball.position.x, s.ball.position.y, s.ball.position.z, s.ball.velocity.x, s.ball.velocity.y,
                   s.ball.velocity.z})
    out.Put(v);
  for (const RobotSnapshot& r : s.robots) {
    for (double v : {r.x, r.y, r.yaw, r.vx, r.vy, r.omega}) out.Put(v);
    out.Put(r.on_field);
    out.Put(r.ball_contact);
    out.Put(r.kick_count);
  }
  for (const CameraFrame& f : k.camera_frames()) out(f);
  for (const RobotSnapshot& r : k.feedback()) {
    out.Put(r.id);
    out.Put(r.kick_count);
  }
  if (k.stats()) {
    for (const auto& [name, w] : k.stats()->streams) {
      out.Str(name);
      out.Put(w.sent);
      out.Put(w.lost);
      out.Put(w.latency_mean);
    }
  }
}

struct Recorded {
  std::string outputs;
  std::string final_state;
  size_t camera_frames = 0;
  uint32_t kicks = 0;
};

Recorded Continue(SslKernel& k, int steps) {
  StateWriter out;
  Recorded run;
  for (int i = 0; i < steps; ++i) {
    DriveSsl(k);
    k.Step();
    RecordOutputs(k, out);
    run.camera_frames += k.camera_frames().size();
  }
  for (const RobotSnapshot& r : k.state().robots) run.kicks += r.kick_count;
  run.outputs = out.Take();
  run.final_state = k.Save();
  return run;
}

TEST(SslKernelTest, RestoreContinuesARealisticMatchByteForByte) {
  SslKernel k(SslMatch("realistic"));
  for (int i = 0; i < 300; ++i) {  // 0.3 s: commands in flight, frames in the camera links
    if (i == 250) testing::BallBeforeBlueZero(k);
    DriveSsl(k);
    k.Step();
  }
  const std::string snapshot = k.Save();
  const Recorded first = Continue(k, 2000);
  ASSERT_GT(first.camera_frames, 400u);  // 2 s at 60 Hz and 4 cameras, minus losses
  ASSERT_GT(first.kicks, 0u);

  ASSERT_EQ(k.Restore(snapshot), "");
  const Recorded again = Continue(k, 2000);
  EXPECT_TRUE(again.outputs == first.outputs) << "outputs differ after restore";
  EXPECT_TRUE(again.final_state == first.final_state) << "state differs after restore";

  SslKernel fresh(SslMatch("realistic"));  // another kernel of the same scene
  ASSERT_EQ(fresh.Restore(snapshot), "");
  const Recorded elsewhere = Continue(fresh, 2000);
  EXPECT_TRUE(elsewhere.outputs == first.outputs) << "outputs differ in a fresh kernel";
  EXPECT_TRUE(elsewhere.final_state == first.final_state);
}

TEST(SslKernelTest, ARestoredSnapshotIsNotTheStartAgain) {
  SslKernel k(SslMatch("realistic"));
  const std::string start = k.Save();
  for (int i = 0; i < 100; ++i) {
    DriveSsl(k);
    k.Step();
  }
  EXPECT_NE(k.Save(), start);
  ASSERT_EQ(k.Restore(start), "");
  EXPECT_EQ(k.frame(), 0u);
  EXPECT_EQ(k.Save(), start);
}

TEST(SslKernelTest, CommandsAreValidatedBeforeTheRadio) {
  SslKernel k(SslMatch("ideal"));
  RobotCommand c;
  c.team = Team::kYellow;
  c.id = 1;
  EXPECT_EQ(k.Command(Team::kBlue, c), InputError::kTeamMismatch);
  c.id = 99;
  EXPECT_EQ(k.Command(Team::kYellow, c), InputError::kUnknownRobot);
  c.id = 1;
  c.move = MoveKind::kLocalVelocity;
  c.velocity.x = NAN;
  EXPECT_EQ(k.Command(Team::kYellow, c), InputError::kNotFinite);
  c.velocity.x = 1.0;
  EXPECT_EQ(k.Command(Team::kYellow, c), InputError::kOk);
  const std::string before = k.Save();
  c.velocity.x = NAN;
  k.Command(Team::kYellow, c);
  EXPECT_EQ(k.Save(), before);  // a refused command changes nothing
}

TEST(SslKernelTest, RealismIsCheckedAndStatisticsCloseEachSecond) {
  SslKernel k(SslMatch("ideal"));
  SensorRealism bad;
  bad.camera.link.loss = 2.0;
  EXPECT_NE(k.SetRealism(bad), "");
  EXPECT_EQ(k.SetRealism(testing::Preset("realistic")), "");
  int reports = 0;
  while (k.time_ns() < 2'000'000'000) {
    k.Step();
    if (!k.stats()) continue;
    ++reports;
    EXPECT_EQ(k.stats()->time_ns, k.time_ns());
    ASSERT_EQ(k.stats()->streams.size(), k.cameras().size() + kTeamCount);
    EXPECT_GT(k.stats()->streams[0].second.sent, 50u);  // 60 Hz
  }
  EXPECT_EQ(reports, 2);
}

}  // namespace
}  // namespace turf
