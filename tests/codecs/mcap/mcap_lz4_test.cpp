// lz4 chunks: a frame made by Debian's `lz4` tool (not by our writer) reads back; a frame that ends early, holds
// more than the chunk's header says, or is followed by other bytes is refused as malformed, never trusted.
#include <gtest/gtest.h>

#include <string>

#include "codecs/mcap/compression.h"

namespace turf::mcap {
namespace {

// `printf 'MCAP chunk records: turf turf turf turf turf turf turf turf' | lz4 -c -B4 --no-frame-crc` (lz4 1.9.4):
// magic 04 22 4d 18, frame descriptor (block independence, 64 KiB blocks) and its header checksum, one compressed
// block of 0x23 bytes (a literal run, then a match at offset 5 repeating "turf "), the end mark 00 00 00 00.
const unsigned char kLz4Tool[] = {0x04, 0x22, 0x4d, 0x18, 0x60, 0x40, 0x82, 0x23, 0x00, 0x00, 0x00, 0xff, 0x09,
                                  0x4d, 0x43, 0x41, 0x50, 0x20, 0x63, 0x68, 0x75, 0x6e, 0x6b, 0x20, 0x72, 0x65,
                                  0x63, 0x6f, 0x72, 0x64, 0x73, 0x3a, 0x20, 0x74, 0x75, 0x72, 0x66, 0x05, 0x00,
                                  0x0b, 0x50, 0x20, 0x74, 0x75, 0x72, 0x66, 0x00, 0x00, 0x00, 0x00};
const std::string kPlain = "MCAP chunk records: turf turf turf turf turf turf turf turf";

std::string ToolFrame() { return std::string(reinterpret_cast<const char*>(kLz4Tool), sizeof(kLz4Tool)); }

TEST(McapLz4, ReadsAFrameOfTheLz4Tool) {
  std::string out, why;
  ASSERT_EQ(Decompress("lz4", ToolFrame(), kPlain.size(), &out, &why), ReadError::kOk) << why;
  EXPECT_EQ(out, kPlain);
}

TEST(McapLz4, RoundTripsAndNamesItsField) {
  std::string big;
  for (int i = 0; i < 5000; ++i) big += "sample " + std::to_string(i % 17) + ";";
  const std::string packed = Compress(Compression::kLz4, big, 0);
  EXPECT_LT(packed.size(), big.size() / 2);
  std::string out, why;
  ASSERT_EQ(Decompress("lz4", packed, big.size(), &out, &why), ReadError::kOk) << why;
  EXPECT_EQ(out, big);
  EXPECT_STREQ(CompressionField(Compression::kLz4), "lz4");
  EXPECT_EQ(CompressionFromWord("lz4"), Compression::kLz4);
}

TEST(McapLz4, RefusesAFrameThatDoesNotFitTheChunkHeader) {
  std::string out, why;
  EXPECT_EQ(Decompress("lz4", ToolFrame(), kPlain.size() + 1, &out, &why), ReadError::kMalformed);
  EXPECT_NE(why.find("lz4"), std::string::npos) << why;
  EXPECT_EQ(Decompress("lz4", ToolFrame(), kPlain.size() - 1, &out, &why), ReadError::kMalformed);
  EXPECT_EQ(Decompress("lz4", ToolFrame() + "x", kPlain.size(), &out, &why), ReadError::kMalformed) << why;
  for (size_t cut = 0; cut < sizeof(kLz4Tool); ++cut)
    EXPECT_EQ(Decompress("lz4", ToolFrame().substr(0, cut), kPlain.size(), &out, &why), ReadError::kMalformed)
        << "cut at " << cut;
  std::string bad = ToolFrame();
  bad[0] = 0x05;  // not the frame magic
  EXPECT_EQ(Decompress("lz4", bad, kPlain.size(), &out, &why), ReadError::kMalformed);
  EXPECT_TRUE(out.empty());
}

}  // namespace
}  // namespace turf::mcap
