// Snapshots are untrusted input: a truncated, corrupted, foreign or
// mismatched snapshot is refused with a reason and changes nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>

#include "core/mj_state.h"
#include "core/rng.h"
#include "core/state_io.h"
#include "tests/kernel/kernel_fixtures.h"

namespace turf {
namespace {

using testing::LeggedMatch;
using testing::SslMatch;

template <class Kernel>
void ExpectRefusedAndUnchanged(Kernel& k, const std::string& bad, const char* what) {
  const std::string before = k.Save();
  EXPECT_NE(k.Restore(bad), "") << what;
  EXPECT_TRUE(k.Save() == before) << what << ": the kernel changed";
}

TEST(SnapshotTest, TruncatedOrExtendedSnapshotsAreRefused) {
  SslKernel k(SslMatch("realistic"));
  for (int i = 0; i < 50; ++i) k.Step();
  const std::string good = k.Save();
  for (int i = 0; i < 10; ++i) k.Step();
  for (size_t len : {size_t{0}, size_t{5}, size_t{13}, size_t{40}, good.size() / 2, good.size() - 1})
    ExpectRefusedAndUnchanged(k, good.substr(0, len), "truncated");
  ExpectRefusedAndUnchanged(k, good + "x", "trailing byte");
  std::string other_version = good;
  other_version[8] ^= 0x7f;
  ExpectRefusedAndUnchanged(k, other_version, "version");
}

TEST(SnapshotTest, SnapshotsOfAnotherSceneOrKindAreRefused) {
  SslKernel ssl(SslMatch("ideal"));
  LeggedKernel legged(LeggedMatch("ideal"));
  ExpectRefusedAndUnchanged(ssl, legged.Save(), "legged into SSL");
  ExpectRefusedAndUnchanged(legged, ssl.Save(), "SSL into legged");
  Scene smaller = SslMatch("ideal");
  smaller.robots_per_team = 6;
  smaller.robots.erase(
      std::remove_if(smaller.robots.begin(), smaller.robots.end(), [](const RobotSetup& r) { return r.id >= 6; }),
      smaller.robots.end());
  SslKernel other(smaller);
  ExpectRefusedAndUnchanged(ssl, other.Save(), "another SSL scene");
}

TEST(SnapshotTest, CorruptedValuesAreRefusedNotObeyed) {
  SslKernel k(SslMatch("realistic"));
  for (int i = 0; i < 100; ++i) k.Step();
  const std::string good = k.Save();
  // The realism and pending-command sections are at the end: an out-of-range
  // enum or probability there must fail the read.
  int refused = 0;
  for (size_t pos = good.size() - 1; pos > good.size() - 400; --pos) {
    std::string bad = good;
    bad[pos] = static_cast<char>(0xff);
    if (bad == good) continue;
    const std::string before = k.Save();
    if (!k.Restore(bad).empty()) {
      ++refused;
      EXPECT_TRUE(k.Save() == before);
    } else {
      ASSERT_EQ(k.Restore(good), "");  // accepted: a value that is valid after all
    }
  }
  EXPECT_GT(refused, 0);
}

// MuJoCo's state in a snapshot (core/mj_state.cpp) must be one MuJoCo can step from: a position made NaN or 1e76
// (one changed byte, the top of a double) was accepted, and the next step ended the process in MuJoCo's fatal
// error handler ("Rank-defficient Hessian"). Every such value is refused, the kernel unchanged, and it still steps.
TEST(SnapshotTest, NonFiniteOrHugeMujocoStateIsRefused) {
  SslKernel k(SslMatch("realistic"));
  for (int i = 0; i < 100; ++i) k.Step();
  const std::string good = k.Save();
  const size_t tag = good.find("MJDA");
  ASSERT_NE(tag, std::string::npos);
  // The tag, the model's fingerprint, time, then 8 warnings of two ints: qpos starts after them.
  const size_t time_at = tag + 4 + 8, qpos_at = time_at + 8 + 8 * 2 * 4;
  const auto with_double = [&](size_t at, double value) {
    std::string bad = good;
    std::memcpy(&bad[at], &value, sizeof(value));
    return bad;
  };
  ExpectRefusedAndUnchanged(k, with_double(time_at, std::nan("")), "NaN time");
  ExpectRefusedAndUnchanged(k, with_double(time_at, -1.0), "negative time");
  for (size_t i = 0; i < 60; ++i) {
    const size_t at = qpos_at + 8 * i;
    ExpectRefusedAndUnchanged(k, with_double(at, std::nan("")), "NaN state value");
    ExpectRefusedAndUnchanged(k, with_double(at, 1e76), "huge state value");
    std::string top_byte = good;
    top_byte[at + 7] = 0x4F;  // the reviewer's change: the value becomes ~1e76 or ~1e-77
    const std::string before = k.Save();
    if (k.Restore(top_byte).empty()) ASSERT_EQ(k.Restore(good), "") << i;  // a tiny value: valid after all
    EXPECT_TRUE(k.Restore(before).empty());
  }
  for (int i = 0; i < 10; ++i) k.Step();  // and the kernel still steps
  EXPECT_TRUE(std::isfinite(k.world().Snapshot().ball.position.x));
}

// Camera frames still on their way (a delayed link) are in the snapshot; one whose camera the scene does not have
// would index past the cameras' streams when released: refused. The frames are found in the bytes by what they
// hold (camera id, frame number, capture and send time, arrival 200 ms after capture).
TEST(SnapshotTest, AWaitingCameraFrameOfAnUnknownCameraIsRefused) {
  SslKernel k(SslMatch("ideal"));
  SensorRealism realism = k.realism();
  realism.camera.link.latency = 0.2;
  realism.camera.processing_delay = 0.0;
  ASSERT_EQ(k.SetRealism(realism), "");
  while (k.time_ns() < 50'000'000) k.Step();
  const std::string good = k.Save();
  std::string bad = good;
  int patched = 0;
  for (size_t i = 0; i + 36 <= bad.size(); ++i) {
    int64_t arrival = 0, capture = 0, sent = 0;
    int32_t camera = 0;
    uint64_t number = 0;
    std::memcpy(&arrival, &bad[i], 8);
    std::memcpy(&camera, &bad[i + 8], 4);
    std::memcpy(&number, &bad[i + 12], 8);
    std::memcpy(&capture, &bad[i + 20], 8);
    std::memcpy(&sent, &bad[i + 28], 8);
    if (camera < 0 || camera >= 4 || number < 1 || number > 100 || capture <= 0 || sent != capture ||
        arrival != capture + 200'000'000)
      continue;
    const int32_t unknown = 1000;
    std::memcpy(&bad[i + 8], &unknown, 4);
    ++patched;
  }
  ASSERT_GT(patched, 0) << "no waiting camera frame found in the snapshot";
  ExpectRefusedAndUnchanged(k, bad, "a waiting frame of camera 1000");
  EXPECT_EQ(k.Restore(good), "");
}

// `frame` written and read back through RestoreFrame: the value read and the reader's error ("" if none).
std::pair<uint64_t, std::string> ReadFrame(uint64_t frame, int64_t step_ns) {
  StateWriter out;
  out.Put(frame);
  const std::string bytes = out.Take();
  StateReader in(bytes);
  const uint64_t read = RestoreFrame(in, step_ns);
  return {read, in.error()};
}

// A world's frame counter whose time would pass 2^62 ns is refused and read as 0; the last one allowed reads back.
TEST(SnapshotTest, AFramePastTheLastTimeIsRefused) {
  const int64_t step_ns = 2'000'000;
  for (const uint64_t frame : {uint64_t{0}, uint64_t{12345}, MaxFrame(step_ns)})
    EXPECT_EQ(ReadFrame(frame, step_ns), std::make_pair(frame, std::string())) << frame;
  EXPECT_EQ(ReadFrame(MaxFrame(step_ns) + 1, step_ns), std::make_pair(uint64_t{0}, std::string("frame out of range")));
}

// An all-zero generator state is never reached from a seed and would make Normal() wait forever for a non-zero
// draw: a snapshot carrying one is refused (the SimSpark league snapshot's fuzzer found the hang).
TEST(SnapshotTest, AnAllZeroRandomStateIsRefused) {
  Rng rng(7);
  StateWriter zeros;
  for (int i = 0; i < 4; ++i) zeros.Put<uint64_t>(0);
  zeros.Put(false);
  zeros.Put(0.0);
  const std::string bytes = zeros.Take();
  StateReader in(bytes);
  const uint64_t next = Rng(rng).Next();
  rng.Restore(in);
  EXPECT_FALSE(in.ok());
  EXPECT_EQ(rng.Next(), next) << "a refused restore changes nothing";
}

}  // namespace
}  // namespace turf
