// The reader against the writer: what was written is read back, by the summary and by a scan, with and without
// zstd; the chunk indexes point at Chunk records and the message indexes at MessageIndex records.
#include <gtest/gtest.h>

#include "codecs/mcap/bytes.h"
#include "codecs/mcap/reader.h"
#include "tests/codecs/mcap/mcap_test_file.h"

namespace turf::mcap {
namespace {

using fixture::Sent;

class McapRoundTrip : public ::testing::TestWithParam<Compression> {};

TEST_P(McapRoundTrip, ScanGivesBackEveryMessageInOrder) {
  const std::vector<Sent> sent = fixture::SomeMessages(200);
  const std::string file = fixture::WriteFile(sent, GetParam(), 512);
  StringSource source(file);
  FileInfo info;
  std::vector<Sent> got;
  const Damage d = Scan(source, {}, &info, [&](const Channel& c, const Message& m) {
    got.push_back({c.id, m.sequence, m.log_time, m.publish_time, std::string(m.data)});
  });
  ASSERT_TRUE(d.ok()) << d.Describe();
  ASSERT_EQ(got.size(), sent.size());
  for (size_t i = 0; i < sent.size(); ++i) {
    EXPECT_EQ(got[i].channel, sent[i].channel);
    EXPECT_EQ(got[i].sequence, sent[i].sequence);
    EXPECT_EQ(got[i].log_time, sent[i].log_time);
    EXPECT_EQ(got[i].publish_time, sent[i].publish_time);
    EXPECT_EQ(got[i].data, sent[i].data);
  }
  EXPECT_EQ(info.read_up_to, file.size());
  EXPECT_EQ(info.header.library, "turf");
  EXPECT_EQ(info.schemas.at(1).name, "turf::idl::Clock");
  EXPECT_EQ(info.channels.at(2).metadata.at("qos"), "turf.state");
  EXPECT_GT(info.statistics.chunk_count, 5u);
  const char* field = CompressionField(GetParam());
  EXPECT_EQ(info.chunks_by_compression.at(field), info.statistics.chunk_count);
}

// Each message's chunk offset from a scan reads its chunk again alone, with the same messages in the same order;
// an offset that is no Chunk record is named.
TEST_P(McapRoundTrip, ReadChunkAtGivesBackTheChunkOfEachMessage) {
  const std::vector<Sent> sent = fixture::SomeMessages(200);
  const std::string file = fixture::WriteFile(sent, GetParam(), 512);
  StringSource source(file);
  FileInfo info;
  std::vector<std::pair<uint64_t, std::string>> scanned;  // (chunk offset, data)
  ASSERT_TRUE(Scan(source, {}, &info, [&](const Channel&, const Message& m) {
                scanned.emplace_back(m.chunk_offset, std::string(m.data));
              }).ok());
  size_t i = 0, chunks = 0;
  while (i < scanned.size()) {
    const uint64_t offset = scanned[i].first;
    ASSERT_GT(offset, 0u);
    FileInfo channels;
    channels.channels = info.channels;
    std::vector<std::string> again;
    const Damage d = ReadChunkAt(source, {}, offset, &channels, [&](const Channel&, const Message& m) {
      EXPECT_EQ(m.chunk_offset, offset);
      again.emplace_back(m.data);
    });
    ASSERT_TRUE(d.ok()) << d.Describe();
    for (const std::string& data : again) {
      ASSERT_LT(i, scanned.size());
      EXPECT_EQ(scanned[i].first, offset);
      EXPECT_EQ(data, scanned[i++].second);
    }
    ++chunks;
  }
  EXPECT_EQ(chunks, info.statistics.chunk_count);
  FileInfo channels;
  channels.channels = info.channels;
  const Damage header = ReadChunkAt(source, {}, 8, &channels, {});  // the Header record
  EXPECT_EQ(header.error, ReadError::kMalformed);
  EXPECT_NE(header.Describe().find("where a Chunk was expected"), std::string::npos) << header.Describe();
  EXPECT_EQ(ReadChunkAt(source, {}, file.size() + 5, &channels, {}).error, ReadError::kTruncated);
}

TEST_P(McapRoundTrip, SummaryMatchesTheScan) {
  const std::vector<Sent> sent = fixture::SomeMessages(200);
  const std::string file = fixture::WriteFile(sent, GetParam(), 512);
  StringSource source(file);
  FileInfo summary, scanned;
  ASSERT_TRUE(ReadSummary(source, {}, &summary).ok());
  ASSERT_TRUE(Scan(source, {}, &scanned).ok());
  EXPECT_EQ(summary.statistics.message_count, 200u);
  EXPECT_EQ(summary.statistics.message_start_time, 1000u);
  EXPECT_EQ(summary.statistics.message_end_time, 1000u + 10u * 199u);
  EXPECT_EQ(summary.statistics.channel_message_counts, scanned.statistics.channel_message_counts);
  EXPECT_EQ(summary.statistics.chunk_count, scanned.statistics.chunk_count);
  EXPECT_EQ(summary.statistics.schema_count, 1u);
  EXPECT_EQ(summary.statistics.channel_count, 3u);
  EXPECT_EQ(summary.channels.size(), 3u);
  EXPECT_EQ(summary.channels.at(3).schema_id, 0u);
  ASSERT_EQ(summary.chunk_indexes.size(), summary.statistics.chunk_count);
  uint64_t indexed = 0;
  for (const ChunkIndex& ci : summary.chunk_indexes) {
    EXPECT_EQ(file[ci.chunk_start_offset], static_cast<char>(Op::kChunk));
    Chunk chunk;
    ASSERT_TRUE(ParseChunk(
        std::string_view(file).substr(ci.chunk_start_offset + kRecordPrefix, ci.chunk_length - kRecordPrefix), &chunk));
    EXPECT_EQ(chunk.records.size(), ci.compressed_size);
    EXPECT_EQ(chunk.message_start_time, ci.message_start_time);
    uint64_t length = 0;
    for (const auto& [channel, offset] : ci.message_index_offsets) {
      ASSERT_EQ(file[offset], static_cast<char>(Op::kMessageIndex));
      MessageIndex index;
      Cursor c(std::string_view(file).substr(offset + 1));
      uint64_t content = 0;
      c.U64(&content);
      ASSERT_TRUE(ParseMessageIndex(std::string_view(file).substr(offset + kRecordPrefix, content), &index));
      EXPECT_EQ(index.channel_id, channel);
      indexed += index.entries.size();
      length += kRecordPrefix + content;
    }
    EXPECT_EQ(length, ci.message_index_length);
  }
  EXPECT_EQ(indexed, 200u);
}

TEST_P(McapRoundTrip, ABigMessageClosesItsChunk) {
  std::vector<Sent> sent = fixture::SomeMessages(3);
  sent[1].data = std::string(100000, 'x');
  const std::string file = fixture::WriteFile(sent, GetParam(), 4096);
  StringSource source(file);
  FileInfo info;
  ASSERT_TRUE(Scan(source, {}, &info).ok());
  EXPECT_EQ(info.statistics.chunk_count, 2u);  // the big one closes the first chunk
  EXPECT_EQ(info.channel_bytes.at(2), 100000u);
}

INSTANTIATE_TEST_SUITE_P(Compressions, McapRoundTrip,
                         ::testing::Values(Compression::kNone, Compression::kZstd, Compression::kLz4),
                         [](const auto& p) {
                           return std::string(p.param == Compression::kNone ? "none" : CompressionField(p.param));
                         });

TEST(McapRoundTripZstd, CompressesRepetitiveData) {
  std::vector<Sent> sent = fixture::SomeMessages(500);
  const std::string plain = fixture::WriteFile(sent, Compression::kNone, 64 * 1024);
  const std::string zstd = fixture::WriteFile(sent, Compression::kZstd, 64 * 1024);
  EXPECT_LT(zstd.size() * 3, plain.size() * 2);  // measured: about half
}

}  // namespace
}  // namespace turf::mcap
