// Scan (reader.h): every record from the start, in file order.
#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "codecs/mcap/bytes.h"
#include "codecs/mcap/compression.h"
#include "codecs/mcap/reader.h"

namespace turf::mcap {
namespace {

std::string N(uint64_t v) { return std::to_string(v); }

class Scanner {
 public:
  Scanner(const ByteSource& source, const ReaderOptions& options, FileInfo* out, const MessageFn& on_message)
      : source_(source), options_(options), out_(out), on_message_(on_message), size_(source.Size()) {}

  Damage Run() {
    std::string magic;
    source_.Read(0, static_cast<size_t>(size_ < 8 ? size_ : 8), &magic);
    if (Damage d = CheckMagic(magic, 0); !d.ok()) return d;
    crc_ = Crc32(magic);
    crc_after_magic_ = 0;
    uint64_t pos = kMagic.size();
    for (;;) {
      out_->read_up_to = pos;
      if (pos == size_)
        return MakeDamage(ReadError::kTruncated, pos,
                          "the file ends after " + N(pos) + " bytes without a Footer (it was not closed)");
      uint8_t op = 0;
      std::string record;
      if (Damage d = ReadRecord(pos, &op, &record); !d.ok()) return d;
      const std::string_view content = std::string_view(record).substr(kRecordPrefix);
      if (pos == kMagic.size() && op != static_cast<uint8_t>(Op::kHeader))
        return MakeDamage(ReadError::kMalformed, pos, std::string("the first record is ") + OpName(op) + ", no Header");
      bool done = false;
      if (Damage d = Take(pos, op, record, content, &done); !d.ok() || done) return d;
      pos += record.size();
    }
  }

  Damage RunChunk(uint64_t pos) {
    if (pos >= size_) return MakeDamage(ReadError::kTruncated, pos, "no record at offset " + N(pos));
    uint8_t op = 0;
    std::string record;
    if (Damage d = ReadRecord(pos, &op, &record); !d.ok()) return d;
    if (op != static_cast<uint8_t>(Op::kChunk))
      return MakeDamage(ReadError::kMalformed, pos,
                        std::string("a ") + OpName(op) + " record where a Chunk was expected");
    return TakeChunk(pos, std::string_view(record).substr(kRecordPrefix));
  }

 private:
  // The whole record at `pos` (prefix included) into `record`.
  Damage ReadRecord(uint64_t pos, uint8_t* op, std::string* record) {
    std::string prefix;
    if (size_ - pos < kRecordPrefix) {
      return MakeDamage(ReadError::kTruncated, pos,
                        "the file ends inside a record's opcode and length (" + N(size_ - pos) + " of 9 bytes)");
    }
    source_.Read(pos, kRecordPrefix, &prefix);
    Cursor c(prefix);
    uint64_t length = 0;
    c.U8(op);
    c.U64(&length);
    const uint64_t left = size_ - pos - kRecordPrefix;
    if (length > options_.max_record_bytes)
      return MakeDamage(ReadError::kTooLarge, pos,
                        std::string(OpName(*op)) + " record of " + N(length) + " bytes, above the limit");
    if (length > left)
      return MakeDamage(
          ReadError::kTruncated, pos,
          std::string(OpName(*op)) + " record declares " + N(length) + " bytes, the file holds " + N(left) + " more");
    if (!source_.Read(pos, static_cast<size_t>(kRecordPrefix + length), record))
      return MakeDamage(ReadError::kTruncated, pos, "cannot read the record");
    return {};
  }

  Damage Take(uint64_t pos, uint8_t op, const std::string& record, std::string_view content, bool* done) {
    const auto bad = [&](const char* what) {
      return MakeDamage(ReadError::kMalformed, pos, std::string("a malformed ") + OpName(op) + " record" + what);
    };
    if (!data_ended_ && op != static_cast<uint8_t>(Op::kDataEnd)) {
      crc_ = Crc32(record, crc_);
      crc_after_magic_ = Crc32(record, crc_after_magic_);
    } else if (data_ended_ && op != static_cast<uint8_t>(Op::kFooter)) {
      summary_crc_ = Crc32(record, summary_crc_);
    }
    switch (static_cast<Op>(op)) {
      case Op::kHeader:
        return ParseHeader(content, &out_->header) ? Damage{} : bad("");
      case Op::kSchema:
      case Op::kChannel:
        return TakeDefinition(op, content) ? Damage{} : bad("");
      case Op::kMessage: {
        Message m;
        if (!ParseMessage(content, &m)) return bad("");
        if (!out_->channels.count(m.channel_id)) return bad(" (its channel was never defined)");
        Deliver(m);
        return {};
      }
      case Op::kChunk:
        return TakeChunk(pos, content);
      case Op::kDataEnd:
        return TakeDataEnd(pos, content);
      case Op::kFooter:
        *done = true;
        return TakeFooter(pos, record, content);
      default:
        return {};  // indexes, attachments, metadata, summary records, opcodes of later revisions
    }
  }

  bool TakeDefinition(uint8_t op, std::string_view content) {
    if (op == static_cast<uint8_t>(Op::kSchema)) {
      Schema s;
      if (!ParseSchema(content, &s)) return false;
      out_->schemas[s.id] = std::move(s);
      out_->statistics.schema_count = static_cast<uint16_t>(out_->schemas.size());
      return true;
    }
    Channel c;
    if (!ParseChannel(content, &c)) return false;
    out_->channels[c.id] = std::move(c);
    out_->statistics.channel_count = static_cast<uint32_t>(out_->channels.size());
    return true;
  }

  void Deliver(const Message& m) {
    Statistics& s = out_->statistics;
    const bool first = s.message_count == 0;
    s.message_start_time = first || m.log_time < s.message_start_time ? m.log_time : s.message_start_time;
    s.message_end_time = first || m.log_time > s.message_end_time ? m.log_time : s.message_end_time;
    ++s.message_count;
    ++s.channel_message_counts[m.channel_id];
    out_->channel_bytes[m.channel_id] += m.data.size();
    if (on_message_) on_message_(out_->channels.at(m.channel_id), m);
  }

  Damage TakeChunk(uint64_t pos, std::string_view content) {
    Chunk chunk;
    if (!ParseChunk(content, &chunk))
      return MakeDamage(ReadError::kMalformed, pos, "a malformed Chunk record (its records overrun it)");
    if (chunk.uncompressed_size > options_.max_chunk_bytes)
      return MakeDamage(ReadError::kTooLarge, pos, "a chunk of " + N(chunk.uncompressed_size) + " bytes uncompressed");
    // A small file of well-compressed chunks must not unpack to gigabytes: at most max_inflation times the file's
    // size (or one chunk of a small file), over the whole scan.
    inflated_ += chunk.uncompressed_size;
    const uint64_t budget = size_ > UINT64_MAX / std::max<uint64_t>(options_.max_inflation, 1)
                                ? UINT64_MAX
                                : std::max(options_.max_inflation * size_, options_.max_chunk_bytes);
    if (inflated_ > budget)
      return MakeDamage(ReadError::kTooLarge, pos,
                        "the chunks so far unpack to " + N(inflated_) + " bytes, more than " +
                            N(options_.max_inflation) + " times the file's " + N(size_));
    std::string records, why;
    if (ReadError e = Decompress(chunk.compression, chunk.records, chunk.uncompressed_size, &records, &why);
        e != ReadError::kOk)
      return MakeDamage(e, pos, "chunk: " + why);
    if (chunk.uncompressed_crc != 0 && Crc32(records) != chunk.uncompressed_crc)
      return MakeDamage(ReadError::kBadCrc, pos, "the chunk's CRC-32 does not match its records");
    if (Damage d = WalkChunk(pos, records, false); !d.ok()) return d;
    ++out_->statistics.chunk_count;
    ++out_->chunks_by_compression[chunk.compression];
    return WalkChunk(pos, records, true);
  }

  // The first walk (`deliver` false) checks the chunk and takes its definitions as they come; the second delivers
  // its messages, now known to be good. Two walks and no copy of the messages: a chunk's count of them is the
  // file's to choose.
  Damage WalkChunk(uint64_t pos, std::string_view records, bool deliver) {
    Cursor c(records);
    while (c.remaining() > 0) {
      const uint64_t at = c.pos();
      const auto where = [at] { return "chunk record at offset " + N(at) + " of the chunk's records"; };
      uint8_t op = 0;
      uint64_t length = 0;
      std::string_view content;
      if (!c.U8(&op) || !c.U64(&length) || length > c.remaining() || !c.Take(static_cast<size_t>(length), &content))
        return MakeDamage(ReadError::kMalformed, pos, where() + " overruns the chunk");
      if (op == static_cast<uint8_t>(Op::kSchema) || op == static_cast<uint8_t>(Op::kChannel)) {
        if (!deliver && !TakeDefinition(op, content))
          return MakeDamage(ReadError::kMalformed, pos, where() + " is malformed");
      } else if (op == static_cast<uint8_t>(Op::kMessage)) {
        Message m;
        if (!ParseMessage(content, &m) || !out_->channels.count(m.channel_id))
          return MakeDamage(ReadError::kMalformed, pos, where() + ": a malformed message or one of no channel");
        m.chunk_offset = pos;
        if (deliver) Deliver(m);
      } else {
        return MakeDamage(ReadError::kMalformed, pos, where() + std::string(" is a ") + OpName(op));
      }
    }
    return {};
  }

  Damage TakeDataEnd(uint64_t pos, std::string_view content) {
    uint32_t crc = 0;
    if (!ParseDataEnd(content, &crc)) return MakeDamage(ReadError::kMalformed, pos, "a malformed DataEnd record");
    // Writers differ on whether the leading magic is part of the data section: either is accepted.
    if (crc != 0 && crc != crc_ && crc != crc_after_magic_)
      return MakeDamage(ReadError::kBadCrc, pos, "the data section's CRC-32 does not match DataEnd's");
    data_ended_ = true;
    summary_start_ = pos + kRecordPrefix + content.size();
    return {};
  }

  Damage TakeFooter(uint64_t pos, std::string_view record, std::string_view content) {
    Footer footer;
    if (!ParseFooter(content, &footer)) return MakeDamage(ReadError::kMalformed, pos, "a malformed Footer record");
    if (footer.summary_crc != 0 && footer.summary_start != 0) {
      const uint32_t crc = Crc32(record.substr(0, kRecordPrefix + 16), summary_crc_);
      if (footer.summary_start != summary_start_ || crc != footer.summary_crc)
        return MakeDamage(
            ReadError::kBadCrc, pos,
            "the Footer's summary start or CRC-32 does not match the summary from offset " + N(summary_start_));
    }
    const uint64_t end = pos + record.size();
    out_->read_up_to = end;
    std::string magic;
    source_.Read(end, static_cast<size_t>(size_ - end < 8 ? size_ - end : 8), &magic);
    if (Damage d = CheckMagic(magic, end); !d.ok()) return d;
    if (size_ - end > 8) return MakeDamage(ReadError::kMalformed, end + 8, N(size_ - end - 8) + " bytes after the end");
    out_->read_up_to = size_;
    return {};
  }

  const ByteSource& source_;
  const ReaderOptions& options_;
  FileInfo* out_;
  const MessageFn& on_message_;
  const uint64_t size_;
  uint32_t crc_ = 0;
  uint32_t crc_after_magic_ = 0;
  uint32_t summary_crc_ = 0;
  bool data_ended_ = false;
  uint64_t summary_start_ = 0;
  uint64_t inflated_ = 0;  // the chunks' uncompressed bytes so far
};

}  // namespace

Damage Scan(const ByteSource& source, const ReaderOptions& options, FileInfo* out, const MessageFn& on_message) {
  return Scanner(source, options, out, on_message).Run();
}

Damage ReadChunkAt(const ByteSource& source, const ReaderOptions& options, uint64_t offset, FileInfo* info,
                   const MessageFn& on_message) {
  return Scanner(source, options, info, on_message).RunChunk(offset);
}

}  // namespace turf::mcap
