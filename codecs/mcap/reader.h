// An MCAP reader (https://mcap.dev/spec) for untrusted files. Two ways in:
//  - ReadSummary: the Footer, then the summary section it names (Schemas, Channels, Statistics, ChunkIndexes),
//    its CRC checked; fast, but only for a file that was closed.
//  - Scan: every record from the start, each chunk decompressed and its CRC checked before its messages are
//    delivered; the data section's CRC checked at DataEnd, the summary's at the Footer.
// Neither trusts a length: a record is read only when the file holds it and it is within the options' limits, so a
// cut, corrupted or hostile file gives a Damage (damage.h: the kind, the offset, a sentence) and never a crash.
// A scan of a file cut by a crash delivers every message of the chunks completed before the cut.
// A file whose major version is not '0' is refused (kNewerVersion). Pure: bytes come from a ByteSource.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "codecs/mcap/damage.h"
#include "codecs/mcap/records.h"

namespace turf::mcap {

class ByteSource {
 public:
  virtual ~ByteSource() = default;
  virtual uint64_t Size() const = 0;
  // Exactly `n` bytes at `offset` into `out`; false if they cannot be read.
  virtual bool Read(uint64_t offset, size_t n, std::string* out) const = 0;
};

class StringSource final : public ByteSource {
 public:
  explicit StringSource(std::string_view bytes) : bytes_(bytes) {}
  uint64_t Size() const override { return bytes_.size(); }
  bool Read(uint64_t offset, size_t n, std::string* out) const override;

 private:
  std::string_view bytes_;
};

// Every limit is a refusal (kTooLarge) of a file that would take memory out of proportion: a record is read whole,
// a chunk is unpacked whole.
struct ReaderOptions {
  uint64_t max_record_bytes = 1ull << 30;  // a record (or the summary) longer than this
  uint64_t max_chunk_bytes = 64ull << 20;  // a chunk's uncompressed size above this (turf-record's: 1 MiB)
  // A scan's chunks together unpack to at most this many times the file's size (or one chunk of max_chunk_bytes):
  // robot data compresses a few times, a crafted file a million times.
  uint64_t max_inflation = 100;
};

// What a file says about itself: from its summary (ReadSummary) or counted by a scan (Scan).
struct FileInfo {
  Header header;
  std::map<uint16_t, Schema> schemas;
  std::map<uint16_t, Channel> channels;
  Statistics statistics;
  std::vector<ChunkIndex> chunk_indexes;                  // ReadSummary only
  std::map<uint16_t, uint64_t> channel_bytes;             // Scan only: message payload bytes per channel
  std::map<std::string, uint64_t> chunks_by_compression;  // "" is none
  uint64_t read_up_to = 0;                                // Scan: the offset up to which records were read whole
};

using MessageFn = std::function<void(const Channel& channel, const Message& message)>;

Damage ReadSummary(const ByteSource& source, const ReaderOptions& options, FileInfo* out);
Damage Scan(const ByteSource& source, const ReaderOptions& options, FileInfo* out, const MessageFn& on_message = {});
// The messages of the one Chunk record at `offset` (a Message's chunk_offset from Scan), in file order, checked as
// Scan checks a chunk; `info` must hold the channels (Scan's FileInfo; counts in it grow). A record there that is no
// Chunk is kMalformed.
Damage ReadChunkAt(const ByteSource& source, const ReaderOptions& options, uint64_t offset, FileInfo* info,
                   const MessageFn& on_message);

// The magic bytes at `offset` (fewer than 8 when the file is shorter): kOk, kBadMagic, kNewerVersion or kTruncated.
Damage CheckMagic(std::string_view bytes, uint64_t offset);

}  // namespace turf::mcap
