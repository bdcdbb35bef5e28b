// MCAP records (https://mcap.dev/spec, major version 0), written from the published specification: each record is
// an opcode (u8), the content length (u64) and the content. Encode* gives a whole record (opcode and length
// included); Parse* reads a record's content and accepts trailing bytes (fields a later minor revision may add),
// except where the content's last field is "the rest" (Message data). Pure functions: no I/O.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace turf::mcap {

// 0x89 'M' 'C' 'A' 'P' '0' '\r' '\n': the byte after "MCAP" is the major version ('0').
inline constexpr std::string_view kMagic{"\x89MCAP0\r\n", 8};
inline constexpr size_t kRecordPrefix = 9;  // opcode + u64 length
inline constexpr size_t kFooterContent = 20;

enum class Op : uint8_t {
  kHeader = 0x01,
  kFooter = 0x02,
  kSchema = 0x03,
  kChannel = 0x04,
  kMessage = 0x05,
  kChunk = 0x06,
  kMessageIndex = 0x07,
  kChunkIndex = 0x08,
  kAttachment = 0x09,
  kAttachmentIndex = 0x0A,
  kStatistics = 0x0B,
  kMetadata = 0x0C,
  kMetadataIndex = 0x0D,
  kSummaryOffset = 0x0E,
  kDataEnd = 0x0F,
};
const char* OpName(uint8_t op);

struct Header {
  std::string profile;
  std::string library;
};

struct Footer {
  uint64_t summary_start = 0;         // 0: no summary section
  uint64_t summary_offset_start = 0;  // 0: no summary offset section
  uint32_t summary_crc = 0;           // 0: not available
};

struct Schema {
  uint16_t id = 0;  // 0 is reserved (a channel without schema)
  std::string name;
  std::string encoding;
  std::string data;
};

struct Channel {
  uint16_t id = 0;
  uint16_t schema_id = 0;
  std::string topic;
  std::string message_encoding;
  std::map<std::string, std::string> metadata;
};

struct Message {
  uint16_t channel_id = 0;
  uint32_t sequence = 0;
  uint64_t log_time = 0;
  uint64_t publish_time = 0;
  std::string_view data;      // a view into the record it was parsed from
  uint64_t chunk_offset = 0;  // Scan: the file offset of the Chunk record it came in (ReadChunkAt); 0: none
};

// The fields of a Chunk record before its records; `records` views the (possibly compressed) bytes.
struct Chunk {
  uint64_t message_start_time = 0;
  uint64_t message_end_time = 0;
  uint64_t uncompressed_size = 0;
  uint32_t uncompressed_crc = 0;  // 0: not available
  std::string compression;        // "", "zstd", "lz4"
  std::string_view records;
};

struct MessageIndex {
  uint16_t channel_id = 0;
  std::vector<std::pair<uint64_t, uint64_t>> entries;  // (log_time, offset into the chunk's uncompressed records)
};

struct ChunkIndex {
  uint64_t message_start_time = 0;
  uint64_t message_end_time = 0;
  uint64_t chunk_start_offset = 0;
  uint64_t chunk_length = 0;  // the whole Chunk record, opcode and length included
  std::map<uint16_t, uint64_t> message_index_offsets;
  uint64_t message_index_length = 0;
  std::string compression;
  uint64_t compressed_size = 0;
  uint64_t uncompressed_size = 0;
};

struct Statistics {
  uint64_t message_count = 0;
  uint16_t schema_count = 0;
  uint32_t channel_count = 0;
  uint32_t attachment_count = 0;
  uint32_t metadata_count = 0;
  uint32_t chunk_count = 0;
  uint64_t message_start_time = 0;
  uint64_t message_end_time = 0;
  std::map<uint16_t, uint64_t> channel_message_counts;
};

struct SummaryOffset {
  uint8_t group_opcode = 0;
  uint64_t group_start = 0;
  uint64_t group_length = 0;
};

// Whole records (opcode, length, content).
std::string Record(Op op, std::string_view content);
std::string EncodeHeader(const Header& h);
std::string EncodeFooter(const Footer& f);
std::string EncodeSchema(const Schema& s);
std::string EncodeChannel(const Channel& c);
std::string EncodeMessage(const Message& m);
std::string EncodeChunk(const Chunk& c);
std::string EncodeMessageIndex(const MessageIndex& m);
std::string EncodeChunkIndex(const ChunkIndex& c);
std::string EncodeStatistics(const Statistics& s);
std::string EncodeSummaryOffset(const SummaryOffset& s);
std::string EncodeDataEnd(uint32_t data_section_crc);

// Content parsers: false when the content is too short or a length inside it overruns it.
bool ParseHeader(std::string_view content, Header* out);
bool ParseFooter(std::string_view content, Footer* out);
bool ParseSchema(std::string_view content, Schema* out);
bool ParseChannel(std::string_view content, Channel* out);
bool ParseMessage(std::string_view content, Message* out);
bool ParseChunk(std::string_view content, Chunk* out);
bool ParseMessageIndex(std::string_view content, MessageIndex* out);
bool ParseChunkIndex(std::string_view content, ChunkIndex* out);
bool ParseStatistics(std::string_view content, Statistics* out);
bool ParseSummaryOffset(std::string_view content, SummaryOffset* out);
bool ParseDataEnd(std::string_view content, uint32_t* data_section_crc);

}  // namespace turf::mcap
