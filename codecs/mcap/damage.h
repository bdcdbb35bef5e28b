// What the MCAP reader reports about a file it cannot read to the end: a named kind, the byte offset where the
// damage starts, and a sentence. Everything before that offset was read (a scan delivers every message of the
// complete chunks before it). These names are the reader's own taxonomy: they describe a file, not a refused
// input sample, so they are not in core/errors.h (that would add IDL ControlError constants no request can carry).
#pragma once

#include <cstdint>
#include <string>

namespace turf::mcap {

#define TURF_MCAP_READ_ERRORS(X)                                                              \
  X(kOk, "ok", "read to the end")                                                             \
  X(kBadMagic, "bad_magic", "not an MCAP file (no magic bytes)")                              \
  X(kNewerVersion, "newer_version", "an MCAP major version this reader does not know")        \
  X(kTruncated, "truncated", "the file ends inside a record or before its Footer")            \
  X(kMalformed, "malformed", "a record whose fields do not fit its length")                   \
  X(kBadCrc, "bad_crc", "a CRC-32 that does not match the bytes")                             \
  X(kTooLarge, "too_large", "a record or chunk above the reader's size limit")                \
  X(kUnknownCompression, "unknown_compression", "a chunk compression this build cannot read") \
  X(kNoSummary, "no_summary", "the file has no (valid) summary section")

enum class ReadError : uint8_t {
#define TURF_MCAP_ENUM(e, name, meaning) e,
  TURF_MCAP_READ_ERRORS(TURF_MCAP_ENUM)
#undef TURF_MCAP_ENUM
};

const char* ReadErrorName(ReadError error);

struct Damage {
  ReadError error = ReadError::kOk;
  uint64_t offset = 0;
  std::string message;

  bool ok() const { return error == ReadError::kOk; }
  // "truncated at offset 1234: ..." (or "ok").
  std::string Describe() const;
};

Damage MakeDamage(ReadError error, uint64_t offset, std::string message);

}  // namespace turf::mcap
