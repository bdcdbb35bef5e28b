// An MCAP writer (https://mcap.dev/spec): magic, Header, then Schema and Channel records in the data section as
// they are added, messages in chunks (optionally zstd), each chunk followed by its MessageIndex records, and on
// Close() DataEnd (with the data section's CRC-32), the summary section (Schemas, Channels, Statistics,
// ChunkIndexes), its SummaryOffsets, Footer and magic. Memory is bounded by one chunk plus one ChunkIndex per
// chunk written. Pure: bytes go to a ByteSink, no I/O here; the sink's owner decides when they reach a disk.
// A file cut after any chunk's MessageIndexes (a crash) reads up to that chunk (reader.h).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "codecs/mcap/compression.h"
#include "codecs/mcap/records.h"
#include "core/pinned.h"

namespace turf::mcap {

class ByteSink {
 public:
  virtual ~ByteSink() = default;
  virtual void Write(std::string_view bytes) = 0;
};

class StringSink final : public ByteSink {
 public:
  void Write(std::string_view bytes) override { bytes_.append(bytes); }
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
};

struct WriterOptions {
  std::string profile;  // the Header's profile ("" : none; "ros2" for ROS 2 messages)
  std::string library = "turf";
  Compression compression = Compression::kZstd;
  int zstd_level = 3;
  size_t chunk_size = 1024 * 1024;  // uncompressed bytes at which a chunk is closed
};

class Writer : Pinned {
 public:
  // Writes the magic and the Header at once.
  Writer(ByteSink* sink, WriterOptions options);
  // Ids start at 1 (0 means "no schema"); the records go into the data section now.
  uint16_t AddSchema(std::string name, std::string encoding, std::string data);
  uint16_t AddChannel(uint16_t schema_id, std::string topic, std::string message_encoding,
                      std::map<std::string, std::string> metadata = {});
  // Appends a message to the open chunk; closes the chunk when it reaches chunk_size. False (nothing written)
  // for a channel not added or after Close().
  bool Write(uint16_t channel_id, uint32_t sequence, uint64_t log_time, uint64_t publish_time, std::string_view data);
  // Writes the open chunk (if it holds a message) and its MessageIndexes.
  void CloseChunk();
  // Closes the chunk and writes DataEnd, the summary, Footer and magic. Idempotent.
  void Close();

  bool closed() const { return closed_; }
  uint64_t bytes_written() const { return position_; }
  const Statistics& statistics() const { return stats_; }
  size_t open_chunk_bytes() const { return chunk_records_.size(); }

 private:
  void Emit(std::string_view bytes);
  // Gives `record` the next id of `list`, writes it with `encode` (unless closed) and keeps it there.
  template <class Record>
  uint16_t Keep(std::vector<Record>* list, Record record, std::string (*encode)(const Record&)) {
    record.id = static_cast<uint16_t>(list->size() + 1);
    if (!closed_) Emit(encode(record));
    list->push_back(std::move(record));
    return list->back().id;
  }
  void WriteSummary();
  // Writes `records` as one group of the summary and remembers its SummaryOffset.
  void EmitGroup(Op op, const std::vector<std::string>& records, std::vector<SummaryOffset>* offsets);

  ByteSink* sink_;
  WriterOptions options_;
  uint64_t position_ = 0;
  uint32_t data_crc_ = 0;
  bool closed_ = false;
  std::vector<Schema> schemas_;
  std::vector<Channel> channels_;
  std::vector<ChunkIndex> chunk_indexes_;
  Statistics stats_;
  // The open chunk.
  std::string chunk_records_;
  uint64_t chunk_start_time_ = 0;
  uint64_t chunk_end_time_ = 0;
  std::map<uint16_t, std::vector<std::pair<uint64_t, uint64_t>>> chunk_index_;
};

}  // namespace turf::mcap
