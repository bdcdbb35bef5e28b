#include "codecs/mcap/records.h"

#include "codecs/mcap/bytes.h"

namespace turf::mcap {
namespace {

// A map's or array's entries behind a u32 byte-length prefix.
void PutSized32(std::string* out, const std::string& entries) { PutPrefixed32(out, entries); }

std::string IdCountMap(const std::map<uint16_t, uint64_t>& map) {
  std::string entries;
  for (const auto& [id, value] : map) {
    PutU16(&entries, id);
    PutU64(&entries, value);
  }
  return entries;
}

bool ParseIdCountMap(Cursor* c, std::map<uint16_t, uint64_t>* out) {
  std::string_view bytes;
  if (!c->Prefixed32(&bytes)) return false;
  Cursor entries(bytes);
  out->clear();
  while (entries.remaining() > 0) {
    uint16_t id = 0;
    uint64_t value = 0;
    if (!entries.U16(&id) || !entries.U64(&value)) return false;
    (*out)[id] = value;
  }
  return true;
}

bool String(Cursor* c, std::string* out) {
  std::string_view v;
  if (!c->Prefixed32(&v)) return false;
  out->assign(v);
  return true;
}

}  // namespace

const char* OpName(uint8_t op) {
  static const char* const kNames[] = {"?",          "Header",        "Footer",          "Schema",
                                       "Channel",    "Message",       "Chunk",           "MessageIndex",
                                       "ChunkIndex", "Attachment",    "AttachmentIndex", "Statistics",
                                       "Metadata",   "MetadataIndex", "SummaryOffset",   "DataEnd"};
  return op < sizeof(kNames) / sizeof(kNames[0]) ? kNames[op] : "unknown";
}

std::string Record(Op op, std::string_view content) {
  std::string out;
  out.reserve(kRecordPrefix + content.size());
  PutU8(&out, static_cast<uint8_t>(op));
  PutU64(&out, content.size());
  out.append(content);
  return out;
}

std::string EncodeHeader(const Header& h) {
  std::string c;
  PutPrefixed32(&c, h.profile);
  PutPrefixed32(&c, h.library);
  return Record(Op::kHeader, c);
}

std::string EncodeFooter(const Footer& f) {
  std::string c;
  PutU64(&c, f.summary_start);
  PutU64(&c, f.summary_offset_start);
  PutU32(&c, f.summary_crc);
  return Record(Op::kFooter, c);
}

std::string EncodeSchema(const Schema& s) {
  std::string c;
  PutU16(&c, s.id);
  PutPrefixed32(&c, s.name);
  PutPrefixed32(&c, s.encoding);
  PutPrefixed32(&c, s.data);
  return Record(Op::kSchema, c);
}

std::string EncodeChannel(const Channel& ch) {
  std::string c;
  PutU16(&c, ch.id);
  PutU16(&c, ch.schema_id);
  PutPrefixed32(&c, ch.topic);
  PutPrefixed32(&c, ch.message_encoding);
  std::string entries;
  for (const auto& [key, value] : ch.metadata) {
    PutPrefixed32(&entries, key);
    PutPrefixed32(&entries, value);
  }
  PutSized32(&c, entries);
  return Record(Op::kChannel, c);
}

std::string EncodeMessage(const Message& m) {
  std::string c;
  PutU16(&c, m.channel_id);
  PutU32(&c, m.sequence);
  PutU64(&c, m.log_time);
  PutU64(&c, m.publish_time);
  c.append(m.data);
  return Record(Op::kMessage, c);
}

std::string EncodeChunk(const Chunk& ch) {
  std::string c;
  PutU64(&c, ch.message_start_time);
  PutU64(&c, ch.message_end_time);
  PutU64(&c, ch.uncompressed_size);
  PutU32(&c, ch.uncompressed_crc);
  PutPrefixed32(&c, ch.compression);
  PutU64(&c, ch.records.size());
  c.append(ch.records);
  return Record(Op::kChunk, c);
}

std::string EncodeMessageIndex(const MessageIndex& m) {
  std::string c;
  PutU16(&c, m.channel_id);
  std::string entries;
  for (const auto& [time, offset] : m.entries) {
    PutU64(&entries, time);
    PutU64(&entries, offset);
  }
  PutSized32(&c, entries);
  return Record(Op::kMessageIndex, c);
}

std::string EncodeChunkIndex(const ChunkIndex& ci) {
  std::string c;
  PutU64(&c, ci.message_start_time);
  PutU64(&c, ci.message_end_time);
  PutU64(&c, ci.chunk_start_offset);
  PutU64(&c, ci.chunk_length);
  PutSized32(&c, IdCountMap(ci.message_index_offsets));
  PutU64(&c, ci.message_index_length);
  PutPrefixed32(&c, ci.compression);
  PutU64(&c, ci.compressed_size);
  PutU64(&c, ci.uncompressed_size);
  return Record(Op::kChunkIndex, c);
}

std::string EncodeStatistics(const Statistics& s) {
  std::string c;
  PutU64(&c, s.message_count);
  PutU16(&c, s.schema_count);
  PutU32(&c, s.channel_count);
  PutU32(&c, s.attachment_count);
  PutU32(&c, s.metadata_count);
  PutU32(&c, s.chunk_count);
  PutU64(&c, s.message_start_time);
  PutU64(&c, s.message_end_time);
  PutSized32(&c, IdCountMap(s.channel_message_counts));
  return Record(Op::kStatistics, c);
}

std::string EncodeSummaryOffset(const SummaryOffset& s) {
  std::string c;
  PutU8(&c, s.group_opcode);
  PutU64(&c, s.group_start);
  PutU64(&c, s.group_length);
  return Record(Op::kSummaryOffset, c);
}

std::string EncodeDataEnd(uint32_t data_section_crc) {
  std::string c;
  PutU32(&c, data_section_crc);
  return Record(Op::kDataEnd, c);
}

bool ParseHeader(std::string_view content, Header* out) {
  Cursor c(content);
  return String(&c, &out->profile) && String(&c, &out->library);
}

bool ParseFooter(std::string_view content, Footer* out) {
  Cursor c(content);
  return c.U64(&out->summary_start) && c.U64(&out->summary_offset_start) && c.U32(&out->summary_crc);
}

bool ParseSchema(std::string_view content, Schema* out) {
  Cursor c(content);
  return c.U16(&out->id) && String(&c, &out->name) && String(&c, &out->encoding) && String(&c, &out->data);
}

bool ParseChannel(std::string_view content, Channel* out) {
  Cursor c(content);
  std::string_view map;
  if (!c.U16(&out->id) || !c.U16(&out->schema_id) || !String(&c, &out->topic) || !String(&c, &out->message_encoding) ||
      !c.Prefixed32(&map))
    return false;
  Cursor entries(map);
  out->metadata.clear();
  while (entries.remaining() > 0) {
    std::string key, value;
    if (!String(&entries, &key) || !String(&entries, &value)) return false;
    out->metadata[key] = value;
  }
  return true;
}

bool ParseMessage(std::string_view content, Message* out) {
  Cursor c(content);
  if (!c.U16(&out->channel_id) || !c.U32(&out->sequence) || !c.U64(&out->log_time) || !c.U64(&out->publish_time))
    return false;
  out->data = c.rest();
  return true;
}

bool ParseChunk(std::string_view content, Chunk* out) {
  Cursor c(content);
  uint64_t records_size = 0;
  if (!c.U64(&out->message_start_time) || !c.U64(&out->message_end_time) || !c.U64(&out->uncompressed_size) ||
      !c.U32(&out->uncompressed_crc) || !String(&c, &out->compression) || !c.U64(&records_size))
    return false;
  return records_size <= c.remaining() && c.Take(static_cast<size_t>(records_size), &out->records);
}

bool ParseMessageIndex(std::string_view content, MessageIndex* out) {
  Cursor c(content);
  std::string_view array;
  if (!c.U16(&out->channel_id) || !c.Prefixed32(&array) || array.size() % 16 != 0) return false;
  Cursor entries(array);
  out->entries.clear();
  while (entries.remaining() > 0) {
    uint64_t time = 0, offset = 0;
    entries.U64(&time);
    entries.U64(&offset);
    out->entries.emplace_back(time, offset);
  }
  return true;
}

bool ParseChunkIndex(std::string_view content, ChunkIndex* out) {
  Cursor c(content);
  return c.U64(&out->message_start_time) && c.U64(&out->message_end_time) && c.U64(&out->chunk_start_offset) &&
         c.U64(&out->chunk_length) && ParseIdCountMap(&c, &out->message_index_offsets) &&
         c.U64(&out->message_index_length) && String(&c, &out->compression) && c.U64(&out->compressed_size) &&
         c.U64(&out->uncompressed_size);
}

bool ParseStatistics(std::string_view content, Statistics* out) {
  Cursor c(content);
  return c.U64(&out->message_count) && c.U16(&out->schema_count) && c.U32(&out->channel_count) &&
         c.U32(&out->attachment_count) && c.U32(&out->metadata_count) && c.U32(&out->chunk_count) &&
         c.U64(&out->message_start_time) && c.U64(&out->message_end_time) &&
         ParseIdCountMap(&c, &out->channel_message_counts);
}

bool ParseSummaryOffset(std::string_view content, SummaryOffset* out) {
  Cursor c(content);
  return c.U8(&out->group_opcode) && c.U64(&out->group_start) && c.U64(&out->group_length);
}

bool ParseDataEnd(std::string_view content, uint32_t* data_section_crc) {
  Cursor c(content);
  return c.U32(data_section_crc);
}

}  // namespace turf::mcap
