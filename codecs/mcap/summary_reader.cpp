// ReadSummary and the pieces both ways of reading share (reader.h).
#include <string>

#include "codecs/mcap/bytes.h"
#include "codecs/mcap/reader.h"

namespace turf::mcap {
namespace {

std::string N(uint64_t v) { return std::to_string(v); }

// A Footer's content length, 20, as a u64.
constexpr std::string_view kFooterLength{"\x14\0\0\0\0\0\0\0", 8};

// Adds one summary record to `out`; false if its content does not parse.
bool TakeSummaryRecord(uint8_t op, std::string_view content, FileInfo* out) {
  switch (static_cast<Op>(op)) {
    case Op::kSchema: {
      Schema s;
      if (!ParseSchema(content, &s)) return false;
      out->schemas[s.id] = s;
      return true;
    }
    case Op::kChannel: {
      Channel c;
      if (!ParseChannel(content, &c)) return false;
      out->channels[c.id] = c;
      return true;
    }
    case Op::kStatistics:
      return ParseStatistics(content, &out->statistics);
    case Op::kChunkIndex: {
      ChunkIndex c;
      if (!ParseChunkIndex(content, &c)) return false;
      ++out->chunks_by_compression[c.compression];
      out->chunk_indexes.push_back(c);
      return true;
    }
    default:
      return true;  // other summary records (and opcodes of later revisions) are not needed here
  }
}

Damage ReadHeaderRecord(const ByteSource& source, FileInfo* out) {
  std::string prefix;
  if (!source.Read(8, kRecordPrefix, &prefix)) return MakeDamage(ReadError::kTruncated, 8, "no Header record");
  Cursor c(prefix);
  uint8_t op = 0;
  uint64_t length = 0;
  c.U8(&op);
  c.U64(&length);
  std::string content;
  if (op != static_cast<uint8_t>(Op::kHeader) || length > source.Size() - 8 - kRecordPrefix ||
      !source.Read(8 + kRecordPrefix, static_cast<size_t>(length), &content) || !ParseHeader(content, &out->header))
    return MakeDamage(ReadError::kMalformed, 8, "the first record is no valid Header");
  return {};
}

}  // namespace

bool StringSource::Read(uint64_t offset, size_t n, std::string* out) const {
  if (offset > bytes_.size() || n > bytes_.size() - offset) return false;
  out->assign(bytes_.substr(static_cast<size_t>(offset), n));
  return true;
}

Damage CheckMagic(std::string_view bytes, uint64_t offset) {
  for (size_t i = 0; i < bytes.size() && i < kMagic.size(); ++i) {
    if (bytes[i] == kMagic[i]) continue;
    if (i == 5 && bytes[i] > '0' && bytes[i] <= '9')
      return MakeDamage(ReadError::kNewerVersion, offset + 5,
                        std::string("MCAP major version '") + bytes[i] + "': this reader reads version '0' only");
    return MakeDamage(ReadError::kBadMagic, offset + i,
                      "not the MCAP magic bytes (89 4D 43 41 50 30 0D 0A): not an MCAP file");
  }
  if (bytes.size() < kMagic.size())
    return MakeDamage(ReadError::kTruncated, offset + bytes.size(),
                      "the file ends inside the magic bytes (" + N(bytes.size()) + " of 8)");
  return {};
}

Damage ReadSummary(const ByteSource& source, const ReaderOptions& options, FileInfo* out) {
  const uint64_t size = source.Size();
  std::string bytes;
  source.Read(0, static_cast<size_t>(size < 8 ? size : 8), &bytes);
  if (Damage d = CheckMagic(bytes, 0); !d.ok()) return d;
  const uint64_t closing = kMagic.size() + kRecordPrefix + kFooterContent;
  if (size < kMagic.size() + closing || !source.Read(size - 8, 8, &bytes) || bytes != kMagic)
    return MakeDamage(ReadError::kTruncated, size, "no closing magic at the end: the file was not closed");
  const uint64_t footer_pos = size - closing;
  if (!source.Read(footer_pos, kRecordPrefix + kFooterContent, &bytes) || bytes[0] != static_cast<char>(Op::kFooter) ||
      std::string_view(bytes).substr(1, 8) != kFooterLength)
    return MakeDamage(ReadError::kMalformed, footer_pos, "no Footer record before the closing magic");
  Footer footer;
  ParseFooter(std::string_view(bytes).substr(kRecordPrefix), &footer);
  if (footer.summary_start == 0) return MakeDamage(ReadError::kNoSummary, footer_pos, "the Footer names no summary");
  const uint64_t end = footer.summary_offset_start != 0 ? footer.summary_offset_start : footer_pos;
  if (footer.summary_start < 8 + kRecordPrefix || footer.summary_start > end || end > footer_pos)
    return MakeDamage(ReadError::kMalformed, footer_pos,
                      "the Footer's summary offsets (" + N(footer.summary_start) + ", " +
                          N(footer.summary_offset_start) + ") lie outside the file's records");
  const uint64_t covered = footer_pos + kRecordPrefix + 16 - footer.summary_start;
  if (covered > options.max_record_bytes)
    return MakeDamage(ReadError::kTooLarge, footer.summary_start, "a summary of " + N(covered) + " bytes");
  std::string summary;
  source.Read(footer.summary_start, static_cast<size_t>(covered), &summary);
  if (footer.summary_crc != 0 && Crc32(summary) != footer.summary_crc)
    return MakeDamage(ReadError::kBadCrc, footer.summary_start, "the summary's CRC-32 does not match the Footer's");
  if (Damage d = ReadHeaderRecord(source, out); !d.ok()) return d;
  Cursor c(std::string_view(summary).substr(0, static_cast<size_t>(end - footer.summary_start)));
  while (c.remaining() > 0) {
    const uint64_t at = footer.summary_start + c.pos();
    uint8_t op = 0;
    uint64_t length = 0;
    std::string_view content;
    if (!c.U8(&op) || !c.U64(&length) || length > c.remaining() || !c.Take(static_cast<size_t>(length), &content))
      return MakeDamage(ReadError::kMalformed, at, "a summary record overruns the summary section");
    if (!TakeSummaryRecord(op, content, out))
      return MakeDamage(ReadError::kMalformed, at, std::string("a malformed ") + OpName(op) + " record");
  }
  return {};
}

}  // namespace turf::mcap
