// Golden bytes: records laid out by hand from the MCAP specification (opcode, u64 little-endian content length,
// fields little-endian, strings with a u32 length), and a whole empty file with its offsets counted by hand.
#include <gtest/gtest.h>

#include <string>

#include "codecs/mcap/bytes.h"
#include "codecs/mcap/records.h"
#include "codecs/mcap/writer.h"
#include "tests/support/text.h"

namespace turf::mcap {
namespace {

using test::Bytes;

TEST(McapGolden, Crc32IsZlibs) {
  EXPECT_EQ(Crc32("123456789"), 0xCBF43926u);  // the standard check value
  EXPECT_EQ(Crc32(""), 0u);
  EXPECT_EQ(Crc32("56789", Crc32("1234")), 0xCBF43926u);  // continues
}

TEST(McapGolden, MagicAndHeader) {
  EXPECT_EQ(kMagic, Bytes({0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n'}));
  // profile "" (u32 0), library "x" (u32 1, 'x'): 9 bytes of content.
  EXPECT_EQ(EncodeHeader({"", "x"}), Bytes({0x01, 9, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 'x'}));
}

TEST(McapGolden, Footer) {
  Footer f;
  f.summary_start = 0x0102;
  f.summary_offset_start = 3;
  f.summary_crc = 0xAABBCCDD;
  EXPECT_EQ(EncodeFooter(f), Bytes({0x02, 20,   0,    0,   0, 0, 0, 0, 0,  // opcode, length 20
                                    0x02, 0x01, 0,    0,   0, 0, 0, 0,     // summary_start
                                    3,    0,    0,    0,   0, 0, 0, 0,     // summary_offset_start
                                    0xDD, 0xCC, 0xBB, 0xAA}));             // summary_crc
}

TEST(McapGolden, UncompressedMessage) {
  Message m;
  m.channel_id = 1;
  m.sequence = 2;
  m.log_time = 3;
  m.publish_time = 0x0400;
  m.data = "ab";
  EXPECT_EQ(EncodeMessage(m), Bytes({0x05, 24, 0, 0, 0, 0, 0, 0, 0,  // 2 + 4 + 8 + 8 + 2 bytes
                                     1,    0,                        // channel_id
                                     2,    0,  0, 0,                 // sequence
                                     3,    0,  0, 0, 0, 0, 0, 0,     // log_time
                                     0,    4,  0, 0, 0, 0, 0, 0,     // publish_time
                                     'a',  'b'}));
  const std::string record = EncodeMessage(m);
  Message back;
  ASSERT_TRUE(ParseMessage(std::string_view(record).substr(kRecordPrefix), &back));
  EXPECT_EQ(back.publish_time, 0x0400u);
  EXPECT_EQ(back.data, "ab");
}

TEST(McapGolden, SchemaAndChannel) {
  EXPECT_EQ(EncodeSchema({1, "T", "omgidl", "s"}),
            Bytes({0x03, 22, 0, 0, 0,   0,   0,   0,   0,   1,   0, 1, 0, 0, 0,  'T',
                   6,    0,  0, 0, 'o', 'm', 'g', 'i', 'd', 'l', 1, 0, 0, 0, 's'}));
  Channel c;
  c.id = 2;
  c.schema_id = 1;
  c.topic = "t";
  c.message_encoding = "cdr";
  c.metadata = {{"k", "v"}};
  EXPECT_EQ(EncodeChannel(c), Bytes({0x04, 30, 0, 0, 0,   0, 0, 0, 0,   2,   0,   1,   0,  // id, schema_id
                                     1,    0,  0, 0, 't', 3, 0, 0, 0,   'c', 'd', 'r',     // topic, message_encoding
                                     10,   0,  0, 0, 1,   0, 0, 0, 'k', 1,   0,   0,   0, 'v'}));  // map of 10 bytes
}

TEST(McapGolden, MessageIndexAndSummaryOffset) {
  EXPECT_EQ(EncodeMessageIndex({7, {{5, 9}}}),
            Bytes({0x07, 22, 0, 0, 0, 0, 0, 0, 0, 7, 0, 16, 0, 0, 0, 5, 0, 0, 0, 0, 0, 0, 0, 9, 0, 0, 0, 0, 0, 0, 0}));
  EXPECT_EQ(EncodeSummaryOffset({0x0B, 42, 55}),
            Bytes({0x0E, 17, 0, 0, 0, 0, 0, 0, 0, 0x0B, 42, 0, 0, 0, 0, 0, 0, 0, 55, 0, 0, 0, 0, 0, 0, 0}));
}

// An empty file, closed: magic, Header (library "turf"), DataEnd, the summary (one Statistics record), its
// SummaryOffset, Footer, magic. Offsets counted from the record sizes: 8, 21, 13, 55, 26, 29, 8.
TEST(McapGolden, EmptyFileLayout) {
  StringSink sink;
  WriterOptions options;
  options.compression = Compression::kNone;
  Writer writer(&sink, options);
  writer.Close();
  const std::string& f = sink.bytes();
  ASSERT_EQ(f.size(), 160u);
  EXPECT_EQ(f.substr(0, 8), kMagic);
  EXPECT_EQ(f.substr(8, 21), EncodeHeader({"", "turf"}));
  EXPECT_EQ(f.substr(29, 13), EncodeDataEnd(Crc32(f.substr(0, 29))));  // the data section, magic included
  Statistics empty;
  EXPECT_EQ(f.substr(42, 55), EncodeStatistics(empty));
  EXPECT_EQ(f.substr(97, 26), EncodeSummaryOffset({0x0B, 42, 55}));
  Footer footer{42, 97, 0};
  footer.summary_crc = Crc32(f.substr(42, 123 - 42 + 9 + 16));
  EXPECT_EQ(f.substr(123, 29), EncodeFooter(footer));
  EXPECT_EQ(f.substr(152), kMagic);
}

}  // namespace
}  // namespace turf::mcap
