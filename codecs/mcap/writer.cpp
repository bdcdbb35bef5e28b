#include "codecs/mcap/writer.h"

#include <algorithm>

#include "codecs/mcap/bytes.h"

namespace turf::mcap {

Writer::Writer(ByteSink* sink, WriterOptions options) : sink_(sink), options_(std::move(options)) {
  Emit(kMagic);
  Emit(EncodeHeader({options_.profile, options_.library}));
}

void Writer::Emit(std::string_view bytes) {
  sink_->Write(bytes);
  position_ += bytes.size();
  data_crc_ = Crc32(bytes, data_crc_);
}

uint16_t Writer::AddSchema(std::string name, std::string encoding, std::string data) {
  const uint16_t id = Keep(&schemas_, Schema{0, std::move(name), std::move(encoding), std::move(data)}, EncodeSchema);
  stats_.schema_count = static_cast<uint16_t>(schemas_.size());
  return id;
}

uint16_t Writer::AddChannel(uint16_t schema_id, std::string topic, std::string message_encoding,
                            std::map<std::string, std::string> metadata) {
  const uint16_t id =
      Keep(&channels_, Channel{0, schema_id, std::move(topic), std::move(message_encoding), std::move(metadata)},
           EncodeChannel);
  stats_.channel_count = static_cast<uint32_t>(channels_.size());
  return id;
}

bool Writer::Write(uint16_t channel_id, uint32_t sequence, uint64_t log_time, uint64_t publish_time,
                   std::string_view data) {
  if (closed_ || channel_id == 0 || channel_id > channels_.size()) return false;
  const bool first_in_chunk = chunk_records_.empty();
  chunk_index_[channel_id].emplace_back(log_time, chunk_records_.size());
  Message m;
  m.channel_id = channel_id;
  m.sequence = sequence;
  m.log_time = log_time;
  m.publish_time = publish_time;
  m.data = data;
  chunk_records_ += EncodeMessage(m);
  chunk_start_time_ = first_in_chunk ? log_time : std::min(chunk_start_time_, log_time);
  chunk_end_time_ = first_in_chunk ? log_time : std::max(chunk_end_time_, log_time);
  const bool first_ever = stats_.message_count == 0;
  stats_.message_start_time = first_ever ? log_time : std::min(stats_.message_start_time, log_time);
  stats_.message_end_time = first_ever ? log_time : std::max(stats_.message_end_time, log_time);
  ++stats_.message_count;
  ++stats_.channel_message_counts[channel_id];
  if (chunk_records_.size() >= options_.chunk_size) CloseChunk();
  return true;
}

void Writer::CloseChunk() {
  if (closed_ || chunk_records_.empty()) return;
  const std::string compressed = Compress(options_.compression, chunk_records_, options_.zstd_level);
  Chunk chunk;
  chunk.message_start_time = chunk_start_time_;
  chunk.message_end_time = chunk_end_time_;
  chunk.uncompressed_size = chunk_records_.size();
  chunk.uncompressed_crc = Crc32(chunk_records_);
  chunk.compression = CompressionField(options_.compression);
  chunk.records = compressed;
  ChunkIndex index;
  index.message_start_time = chunk_start_time_;
  index.message_end_time = chunk_end_time_;
  index.chunk_start_offset = position_;
  const std::string record = EncodeChunk(chunk);
  index.chunk_length = record.size();
  index.compression = chunk.compression;
  index.compressed_size = compressed.size();
  index.uncompressed_size = chunk_records_.size();
  Emit(record);
  const uint64_t indexes_start = position_;
  for (const auto& [channel_id, entries] : chunk_index_) {
    index.message_index_offsets[channel_id] = position_;
    Emit(EncodeMessageIndex({channel_id, entries}));
  }
  index.message_index_length = position_ - indexes_start;
  chunk_indexes_.push_back(std::move(index));
  ++stats_.chunk_count;
  chunk_records_.clear();
  chunk_index_.clear();
}

void Writer::Close() {
  if (closed_) return;
  CloseChunk();
  Emit(EncodeDataEnd(data_crc_));
  closed_ = true;
  WriteSummary();
}

void Writer::EmitGroup(Op op, const std::vector<std::string>& records, std::vector<SummaryOffset>* offsets) {
  if (records.empty()) return;
  SummaryOffset o;
  o.group_opcode = static_cast<uint8_t>(op);
  o.group_start = position_;
  for (const std::string& r : records) Emit(r);
  o.group_length = position_ - o.group_start;
  offsets->push_back(o);
}

void Writer::WriteSummary() {
  const uint64_t summary_start = position_;
  data_crc_ = 0;  // from here on: the summary CRC
  std::vector<SummaryOffset> offsets;
  std::vector<std::string> group;
  for (const Schema& s : schemas_) group.push_back(EncodeSchema(s));
  EmitGroup(Op::kSchema, group, &offsets);
  group.clear();
  for (const Channel& c : channels_) group.push_back(EncodeChannel(c));
  EmitGroup(Op::kChannel, group, &offsets);
  EmitGroup(Op::kStatistics, {EncodeStatistics(stats_)}, &offsets);
  group.clear();
  for (const ChunkIndex& c : chunk_indexes_) group.push_back(EncodeChunkIndex(c));
  EmitGroup(Op::kChunkIndex, group, &offsets);
  const uint64_t summary_offset_start = position_;
  for (const SummaryOffset& o : offsets) Emit(EncodeSummaryOffset(o));
  Footer footer;
  footer.summary_start = summary_start;
  footer.summary_offset_start = summary_offset_start;
  std::string record = EncodeFooter(footer);
  // The summary CRC covers the summary and summary offset sections and the Footer up to summary_crc.
  footer.summary_crc = Crc32(std::string_view(record).substr(0, record.size() - 4), data_crc_);
  Emit(EncodeFooter(footer));
  Emit(kMagic);
}

}  // namespace turf::mcap
