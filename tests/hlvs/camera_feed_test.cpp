// The HLVS bridge's camera feed (participants/hlvs_bridge/camera_feed.h): ROS 2 images in turf-render's encodings
// to HLVS's B, G, R bytes, refused when their sizes do not add up, and the newest frame at or before a time, never
// the same frame twice.
#include "participants/hlvs_bridge/camera_feed.h"

#include <gtest/gtest.h>

#include "codecs/image/image_codec.h"

namespace turf {
namespace {

// A 2 x 2 rgb8 image: red, green / blue, white.
const std::vector<uint8_t> kRgb = {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255};

FeedFrame Frame(int64_t stamp, char fill) {
  FeedFrame f;
  f.stamp_ns = stamp;
  f.width = 1;
  f.height = 1;
  f.bgr.assign(3, fill);
  return f;
}

TEST(CameraFeed, Rgb8BecomesBgrRowsFromTheTop) {
  FeedFrame f;
  ASSERT_EQ(ToFeedFrame(7, 2, 2, "rgb8", 6, kRgb, &f), Error::kOk);
  EXPECT_EQ(f.stamp_ns, 7);
  EXPECT_EQ(f.width, 2u);
  EXPECT_EQ(f.height, 2u);
  const std::string expected("\x00\x00\xff\x00\xff\x00\xff\x00\x00\xff\xff\xff", 12);
  EXPECT_EQ(f.bgr, expected);
}

TEST(CameraFeed, RowPaddingIsDropped) {
  std::vector<uint8_t> padded = {255, 0, 0, 0, 255, 0, 9, 9, 0, 0, 255, 255, 255, 255, 9, 9};
  FeedFrame f;
  ASSERT_EQ(ToFeedFrame(0, 2, 2, "rgb8", 8, padded, &f), Error::kOk);
  EXPECT_EQ(f.bgr, std::string("\x00\x00\xff\x00\xff\x00\xff\x00\x00\xff\xff\xff", 12));
}

TEST(CameraFeed, YuyvIsDecodedToBgr) {
  std::vector<uint8_t> rgb(4 * 2 * 3);
  for (size_t i = 0; i < rgb.size(); i += 3) rgb[i + 1] = 200;  // all green
  const image::Encoded yuyv = image::RgbToYuyv(rgb, 4, 2);
  ASSERT_EQ(yuyv.error, Error::kOk);
  FeedFrame f;
  ASSERT_EQ(ToFeedFrame(0, 4, 2, "yuv422_yuy2", 8, yuyv.bytes, &f), Error::kOk);
  ASSERT_EQ(f.bgr.size(), 24u);
  for (size_t i = 0; i < f.bgr.size(); i += 3) {
    EXPECT_NEAR(static_cast<uint8_t>(f.bgr[i + 1]), 200, 3) << i;
    EXPECT_LT(static_cast<uint8_t>(f.bgr[i]), 10) << i;
    EXPECT_LT(static_cast<uint8_t>(f.bgr[i + 2]), 10) << i;
  }
}

TEST(CameraFeed, ImagesWhoseSizesDoNotAddUpAreRefused) {
  FeedFrame f;
  EXPECT_EQ(ToFeedFrame(0, 2, 2, "rgb8", 6, std::vector<uint8_t>(11), &f), Error::kMalformed);  // short
  EXPECT_EQ(ToFeedFrame(0, 2, 2, "rgb8", 5, kRgb, &f), Error::kMalformed);                      // step < row
  EXPECT_EQ(ToFeedFrame(0, 0, 2, "rgb8", 6, kRgb, &f), Error::kBadSize);
  EXPECT_EQ(ToFeedFrame(0, 5000, 1, "rgb8", 15000, std::vector<uint8_t>(15000), &f), Error::kBadSize);
  EXPECT_EQ(ToFeedFrame(0, 2, 2, "bgra8", 8, std::vector<uint8_t>(16), &f), Error::kUnknownEnum);
  EXPECT_EQ(ToFeedFrame(0, 2, 2, "yuv422_yuy2", 4, std::vector<uint8_t>(7), &f), Error::kMalformed);
  EXPECT_EQ(ToFeedFrame(0, 3, 1, "yuv422_yuy2", 6, std::vector<uint8_t>(6), &f), Error::kBadSize);  // odd width
}

TEST(CameraFeed, TakesTheNewestAtOrBeforeTheTimeAndNeverTwice) {
  CameraFeed feed;
  EXPECT_FALSE(feed.Take("r/c", 100).has_value());
  EXPECT_EQ(feed.Put("r/c", Frame(10, 'a'), 1000), Error::kOk);
  EXPECT_EQ(feed.Put("r/c", Frame(30, 'c'), 1000), Error::kOk);
  EXPECT_EQ(feed.Put("r/c", Frame(20, 'b'), 1000), Error::kOk);  // late, kept in its place in time
  EXPECT_FALSE(feed.Take("r/c", 5).has_value());
  EXPECT_FALSE(feed.Take("other/c", 100).has_value());
  auto f = feed.Take("r/c", 25);
  ASSERT_TRUE(f.has_value());
  EXPECT_EQ(f->stamp_ns, 20);
  EXPECT_FALSE(feed.Take("r/c", 25).has_value()) << "20 was taken, 10 is older";
  EXPECT_EQ(feed.Put("r/c", Frame(15, 'x'), 1000), Error::kOk);  // older than what was taken: never given out
  f = feed.Take("r/c", 100);
  ASSERT_TRUE(f.has_value());
  EXPECT_EQ(f->stamp_ns, 30);
  EXPECT_FALSE(feed.Take("r/c", 100).has_value());
}

TEST(CameraFeed, KeepsOnlyTheNewestFewFrames) {
  CameraFeed feed;
  for (int i = 1; i <= 10; ++i) EXPECT_EQ(feed.Put("r/c", Frame(i * 10, 'a'), 1000), Error::kOk);
  EXPECT_FALSE(feed.Take("r/c", 60).has_value()) << "frames up to 60 are gone: only the newest 4 are kept";
  auto f = feed.Take("r/c", 75);
  ASSERT_TRUE(f.has_value());
  EXPECT_EQ(f->stamp_ns, 70);
}

// Frames stamped far past the known time (a forged or broken renderer's) are refused; four of them pushed every real
// frame out for good (0 of 1000 real frames delivered afterwards).
TEST(CameraFeed, FramesStampedFarAheadAreRefusedAndPushNothingOut) {
  CameraFeed feed;
  const int64_t now = 5'000'000'000;
  for (int i = 0; i < 8; ++i)
    EXPECT_EQ(feed.Put("r/c", Frame(INT64_C(2147483647) * 1'000'000'000 + i, 'f'), now), Error::kOutOfRange);
  EXPECT_EQ(feed.Put("r/c", Frame(now + CameraFeed::kMaxAheadNs + 1, 'f'), now), Error::kOutOfRange);
  EXPECT_EQ(feed.Put("r/c", Frame(now + CameraFeed::kMaxAheadNs, 'g'), now), Error::kOk);  // at the bound: kept
  for (int i = 1; i <= 100; ++i) {
    const int64_t t = now - 100 + i;
    ASSERT_EQ(feed.Put("r/c", Frame(t, 'a'), t), Error::kOk);
    auto f = feed.Take("r/c", t);
    ASSERT_TRUE(f.has_value()) << "frame " << i;
    EXPECT_EQ(f->stamp_ns, t);
  }
}

}  // namespace
}  // namespace turf
