// Snapshot and restore reach the wire: the samples turf-sim publishes for a
// realistic SSL match (world state, camera frames, feedback, statistics),
// serialized as DDS sends them (CDR), are the same bytes after a restore.
#include <gtest/gtest.h>
#include <turf/idl/SensorStatsPubSubTypes.h>
#include <turf/idl/SslRobotPubSubTypes.h>
#include <turf/idl/SslVisionPubSubTypes.h>
#include <turf/idl/WorldStatePubSubTypes.h>

#include <string>

#include "kernel/ssl_kernel.h"
#include "participants/sim/convert.h"
#include "participants/sim/stats_report.h"
#include "tests/kernel/kernel_fixtures.h"
#include "tests/support/cdr.h"

namespace turf {
namespace {

// The CDR bytes of one sample, appended to `out`.
template <class PubSubType, class Sample>
void AppendCdr(const Sample& sample, std::string* out) {
  out->append(test::Cdr<PubSubType>(sample));
}

// Every sample the node would publish after each of `steps` steps.
std::string PublishedBytes(SslKernel& k, int steps) {
  std::string bytes;
  for (int i = 0; i < steps; ++i) {
    testing::DriveSsl(k);
    k.Step();
    idl::WorldState state;
    ToIdl(k.state(), &state);
    AppendCdr<idl::WorldStatePubSubType>(state, &bytes);
    for (const CameraFrame& f : k.camera_frames()) {
      idl::CameraFrame frame;
      ToIdl(f, &frame);
      AppendCdr<idl::CameraFramePubSubType>(frame, &bytes);
    }
    for (const RobotSnapshot& r : k.feedback())
      AppendCdr<idl::SslRobotFeedbackPubSubType>(FeedbackToIdl(r, k.time_ns()), &bytes);
    if (k.stats()) AppendCdr<idl::SensorStatsPubSubType>(StatsToIdl(*k.stats()), &bytes);
  }
  return bytes;
}

TEST(PublishedBytes, ARestoredRealisticMatchPublishesTheSameBytes) {
  SslKernel k(testing::SslMatch("realistic"));
  for (int i = 0; i < 250; ++i) {
    testing::DriveSsl(k);
    k.Step();
  }
  testing::BallBeforeBlueZero(k);
  const std::string snapshot = k.Save();
  const std::string first = PublishedBytes(k, 1500);
  ASSERT_GT(first.size(), 100'000u);

  SslKernel other(testing::SslMatch("realistic"));
  ASSERT_EQ(other.Restore(snapshot), "");
  EXPECT_TRUE(PublishedBytes(other, 1500) == first);

  SslKernel unrestored(testing::SslMatch("realistic"));  // control: the bytes do depend on the state
  EXPECT_FALSE(PublishedBytes(unrestored, 1500) == first);
}

}  // namespace
}  // namespace turf
