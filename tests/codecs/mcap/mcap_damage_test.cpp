// Damaged files: cut at every byte offset, every byte flipped, a newer major version, hostile lengths. The
// reader never crashes, names the damage and its offset, and a scan delivers exactly the messages of the chunks
// completed before a cut.
#include <gtest/gtest.h>

#include "codecs/mcap/compression.h"
#include "codecs/mcap/reader.h"
#include "codecs/mcap/records.h"
#include "tests/codecs/mcap/mcap_test_file.h"

namespace turf::mcap {
namespace {

uint64_t MessagesBefore(const std::string& file, uint64_t cut) {
  // Count the messages of every chunk whose record ends at or before `cut`, scanning the whole file.
  StringSource source(file);
  FileInfo summary;
  ReadSummary(source, {}, &summary);
  uint64_t n = 0;
  size_t chunk = 0;
  FileInfo info;
  Scan(source, {}, &info, [&](const Channel&, const Message& m) {
    while (chunk < summary.chunk_indexes.size() && m.log_time > summary.chunk_indexes[chunk].message_end_time) ++chunk;
    const ChunkIndex& ci = summary.chunk_indexes[chunk];
    if (ci.chunk_start_offset + ci.chunk_length <= cut) ++n;
  });
  return n;
}

class McapCut : public ::testing::TestWithParam<Compression> {};

TEST_P(McapCut, EveryTruncationIsReadUpToTheLastCompleteChunk) {
  const std::string file = fixture::WriteFile(fixture::SomeMessages(40), GetParam(), 200);
  ASSERT_GT(file.size(), 500u);
  for (size_t cut = 0; cut < file.size(); ++cut) {
    const std::string part = file.substr(0, cut);
    StringSource source(part);
    FileInfo info, summary;
    uint64_t delivered = 0;
    const Damage d = Scan(source, {}, &info, [&](const Channel&, const Message&) { ++delivered; });
    ASSERT_FALSE(d.ok()) << "cut at " << cut;
    EXPECT_LE(d.offset, cut) << d.Describe();
    EXPECT_FALSE(d.message.empty());
    EXPECT_EQ(delivered, MessagesBefore(file, cut)) << "cut at " << cut << ": " << d.Describe();
    EXPECT_FALSE(ReadSummary(source, {}, &summary).ok()) << "cut at " << cut;
  }
}

TEST_P(McapCut, EveryFlippedByteIsReadOrNamed) {
  const std::string file = fixture::WriteFile(fixture::SomeMessages(12), GetParam(), 150);
  for (size_t i = 0; i < file.size(); ++i) {
    std::string bad = file;
    bad[i] = static_cast<char>(bad[i] ^ 0x5A);
    StringSource source(bad);
    FileInfo info, summary;
    const Damage d = Scan(source, {}, &info);
    ReadSummary(source, {}, &summary);  // must not crash; a flip in the data section leaves the summary good
    // The data section, the chunks and the summary carry CRCs: a scan notices every flipped byte.
    EXPECT_FALSE(d.ok()) << "flip at " << i;
    EXPECT_LE(d.offset, bad.size());
  }
}

INSTANTIATE_TEST_SUITE_P(Compressions, McapCut,
                         ::testing::Values(Compression::kNone, Compression::kZstd, Compression::kLz4),
                         [](const auto& p) {
                           return std::string(p.param == Compression::kNone ? "none" : CompressionField(p.param));
                         });

TEST(McapDamage, ANewerMajorVersionIsRefusedWithTheReason) {
  std::string file = fixture::WriteFile(fixture::SomeMessages(3), Compression::kNone, 1024);
  file[5] = '1';
  StringSource source(file);
  FileInfo info;
  const Damage d = Scan(source, {}, &info);
  EXPECT_EQ(d.error, ReadError::kNewerVersion);
  EXPECT_EQ(d.offset, 5u);
  EXPECT_NE(d.message.find("version '1'"), std::string::npos) << d.message;
  EXPECT_EQ(ReadSummary(source, {}, &info).error, ReadError::kNewerVersion);
}

TEST(McapDamage, NotAnMcapFile) {
  StringSource source("PK\x03\x04 something else entirely");
  FileInfo info;
  EXPECT_EQ(Scan(source, {}, &info).error, ReadError::kBadMagic);
  EXPECT_EQ(ReadSummary(source, {}, &info).error, ReadError::kBadMagic);
}

TEST(McapDamage, AChunkWithABadCrcDeliversNothingOfIt) {
  const std::string file = fixture::WriteFile(fixture::SomeMessages(6), Compression::kNone, 1 << 20);
  StringSource good(file);
  FileInfo summary;
  ASSERT_TRUE(ReadSummary(good, {}, &summary).ok());
  ASSERT_EQ(summary.chunk_indexes.size(), 1u);
  std::string bad = file;
  const uint64_t chunk = summary.chunk_indexes[0].chunk_start_offset;
  bad[chunk + summary.chunk_indexes[0].chunk_length - 1] ^= 1;  // the last byte of the last message's data
  StringSource source(bad);
  FileInfo info;
  int delivered = 0;
  const Damage d = Scan(source, {}, &info, [&](const Channel&, const Message&) { ++delivered; });
  EXPECT_EQ(d.error, ReadError::kBadCrc);
  EXPECT_EQ(d.offset, chunk);
  EXPECT_EQ(delivered, 0);
}

TEST(McapDamage, HostileLengthsAreRefusedBeforeAnyAllocation) {
  std::string file(kMagic);
  file += EncodeHeader({"", "x"});
  file += std::string("\x06\xff\xff\xff\xff\xff\xff\xff\x7f", 9);  // a Chunk claiming 2^63 bytes
  StringSource source(file);
  FileInfo info;
  EXPECT_EQ(Scan(source, {}, &info).error, ReadError::kTooLarge);
  ReaderOptions loose;
  loose.max_record_bytes = ~0ull;
  const Damage d = Scan(source, loose, &info);
  EXPECT_EQ(d.error, ReadError::kTruncated);
  EXPECT_EQ(d.offset, 8u + 9u + 9u);
  EXPECT_NE(d.message.find("Chunk record declares"), std::string::npos) << d.message;
}

// Chunks that unpack to far more than the file (a crafted file: zstd chunks of empty messages and no message
// indexes, so 100 bytes of file are megabytes of records) are refused once they pass max_inflation times the file's
// size, and the messages of the chunks before are delivered.
TEST(McapDamage, ChunksThatUnpackToMoreThanTheFileAllowsAreRefused) {
  constexpr int kChunks = 8;
  constexpr uint32_t kPerChunk = 400'000;  // 12.4 MB of records a chunk
  std::string records;
  for (uint32_t i = 0; i < kPerChunk; ++i) records += EncodeMessage({1, 0, 0, 0, "", 0});
  const std::string packed = Compress(Compression::kZstd, records, 3);
  std::string file(kMagic);
  file += EncodeHeader({"", "x"});
  file += EncodeChannel({1, 0, "t", "cdr", {}});
  for (int k = 0; k < kChunks; ++k) file += EncodeChunk({0, 0, records.size(), 0, "zstd", packed});
  file += EncodeDataEnd(0);
  StringSource source(file);
  FileInfo info;
  uint64_t delivered = 0;
  ReaderOptions options;
  options.max_chunk_bytes = 16 << 20;  // a small file may unpack to one such chunk
  const Damage d = Scan(source, options, &info, [&](const Channel&, const Message&) { ++delivered; });
  ASSERT_LT(file.size() * 100, records.size() * 2) << "the fixture compresses less than the test needs";
  EXPECT_EQ(d.error, ReadError::kTooLarge) << d.Describe();
  EXPECT_NE(d.message.find("times the file's"), std::string::npos) << d.message;
  EXPECT_EQ(delivered, kPerChunk);  // the first chunk: within the 16 MiB any file may unpack to
  options.max_inflation = 1'000'000;
  delivered = 0;
  const Damage all = Scan(source, options, &info, [&](const Channel&, const Message&) { ++delivered; });
  EXPECT_EQ(all.error, ReadError::kTruncated) << all.Describe();  // no summary and Footer: read to the end
  EXPECT_EQ(delivered, kChunks * kPerChunk);
}

TEST(McapDamage, AFileNeverClosedSaysSo) {
  StringSink sink;
  Writer w(&sink, {});
  w.AddChannel(0, "t", "cdr");
  w.Write(1, 0, 1, 1, "x");
  w.CloseChunk();
  StringSource source(sink.bytes());
  FileInfo info;
  int delivered = 0;
  const Damage d = Scan(source, {}, &info, [&](const Channel&, const Message&) { ++delivered; });
  EXPECT_EQ(d.error, ReadError::kTruncated);
  EXPECT_EQ(d.offset, sink.bytes().size());
  EXPECT_NE(d.message.find("without a Footer"), std::string::npos);
  EXPECT_EQ(delivered, 1);
  EXPECT_EQ(ReadSummary(source, {}, &info).error, ReadError::kTruncated);
}

}  // namespace
}  // namespace turf::mcap
