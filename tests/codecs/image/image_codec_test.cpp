// Camera image encodings (codecs/image): YUYV golden bytes, JPEG round trips, refusals by name.
#include "codecs/image/image_codec.h"

#include <gtest/gtest.h>

#include <cstdlib>

namespace turf::image {
namespace {

TEST(Yuyv, GoldenBytesOfTwoPixelPairs) {
  // White and black, then pure red twice: BT.601 full range (JFIF).
  const std::vector<uint8_t> rgb = {255, 255, 255, 0, 0, 0, 255, 0, 0, 255, 0, 0};
  const Encoded e = RgbToYuyv(rgb, 4, 1);
  ASSERT_EQ(e.error, Error::kOk);
  const std::vector<uint8_t> golden = {
      255, 128, 0,  128,  // Y0 = 255, U = 128 (grey pair mean), Y1 = 0, V = 128
      76,  85,  76, 255,  // red: Y = 0.299 * 255 = 76.2, U = 128 - 43.03 = 84.97, V = 128 + 127.5 = 255.5 (clamped)
  };
  EXPECT_EQ(e.bytes, golden);
}

TEST(Yuyv, RoundTripOfFlatColoursIsWithinOneStep) {
  std::vector<uint8_t> rgb;
  const uint8_t colours[][3] = {{20, 120, 40}, {255, 128, 0}, {230, 230, 230}, {0, 0, 255}};
  for (const auto& c : colours)
    for (int i = 0; i < 2; ++i) rgb.insert(rgb.end(), c, c + 3);
  const Encoded y = RgbToYuyv(rgb, 8, 1);
  ASSERT_EQ(y.error, Error::kOk);
  const Encoded back = YuyvToRgb(y.bytes, 8, 1);
  ASSERT_EQ(back.error, Error::kOk);
  ASSERT_EQ(back.bytes.size(), rgb.size());
  for (size_t i = 0; i < rgb.size(); ++i) EXPECT_LE(std::abs(back.bytes[i] - rgb[i]), 2) << i;
}

TEST(Yuyv, RefusesOddWidthsAndWrongSizes) {
  EXPECT_EQ(RgbToYuyv(std::vector<uint8_t>(9), 3, 1).error, Error::kBadSize);
  EXPECT_EQ(RgbToYuyv(std::vector<uint8_t>(11), 2, 2).error, Error::kMalformed);
  EXPECT_EQ(RgbToYuyv({}, 0, 0).error, Error::kBadSize);
  EXPECT_EQ(YuyvToRgb(std::vector<uint8_t>(7), 2, 2).error, Error::kMalformed);
}

TEST(Jpeg, RoundTripKeepsAFlatOrangeWithinTolerance) {
  const int w = 64, h = 48;
  std::vector<uint8_t> rgb;
  for (int i = 0; i < w * h; ++i) rgb.insert(rgb.end(), {255, 128, 0});
  const Encoded j = EncodeJpeg(rgb, w, h, 90);
  ASSERT_EQ(j.error, Error::kOk);
  ASSERT_GT(j.bytes.size(), 4u);
  EXPECT_EQ(j.bytes[0], 0xFF);  // SOI
  EXPECT_EQ(j.bytes[1], 0xD8);
  EXPECT_EQ(j.bytes[j.bytes.size() - 2], 0xFF);  // EOI
  EXPECT_EQ(j.bytes.back(), 0xD9);
  int dw = 0, dh = 0;
  const Encoded d = DecodeJpeg(j.bytes, w * h, &dw, &dh);
  ASSERT_EQ(d.error, Error::kOk);
  EXPECT_EQ(dw, w);
  EXPECT_EQ(dh, h);
  for (size_t i = 0; i < rgb.size(); ++i) EXPECT_LE(std::abs(d.bytes[i] - rgb[i]), 4) << i;
}

TEST(Jpeg, RefusesBadArgumentsAndGarbage) {
  EXPECT_EQ(EncodeJpeg(std::vector<uint8_t>(12), 2, 2, 0).error, Error::kOutOfRange);
  EXPECT_EQ(EncodeJpeg(std::vector<uint8_t>(12), 2, 2, 101).error, Error::kOutOfRange);
  EXPECT_EQ(EncodeJpeg(std::vector<uint8_t>(11), 2, 2, 80).error, Error::kMalformed);
  EXPECT_EQ(EncodeJpeg({}, 0, 2, 80).error, Error::kBadSize);
  int w = 0, h = 0;
  EXPECT_EQ(DecodeJpeg({}, 100, &w, &h).error, Error::kEmpty);
  EXPECT_EQ(DecodeJpeg({1, 2, 3, 4, 5}, 100, &w, &h).error, Error::kMalformed);
  const Encoded j = EncodeJpeg(std::vector<uint8_t>(16 * 16 * 3, 7), 16, 16, 50);
  ASSERT_EQ(j.error, Error::kOk);
  EXPECT_EQ(DecodeJpeg(j.bytes, 100, &w, &h).error, Error::kTooLarge);
  std::vector<uint8_t> cut(j.bytes.begin(), j.bytes.begin() + static_cast<long>(j.bytes.size() / 3));
  const Encoded c = DecodeJpeg(cut, 1000, &w, &h);  // libjpeg fills a cut file with grey and warns: no crash
  EXPECT_TRUE(c.error == Error::kOk || c.error == Error::kMalformed);
}

}  // namespace
}  // namespace turf::image
