// Little-endian bytes as MCAP lays them out (https://mcap.dev/spec, "Serialization"): integers little-endian,
// strings and byte arrays with a u32 length prefix. Appending to a std::string and a bounded cursor that never
// reads past its view. CRC-32 as zlib's (polynomial 0xEDB88320, reflected), which MCAP uses for chunks, the data
// section and the summary.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace turf::mcap {

// CRC-32 of `bytes`, continuing from `crc` (the CRC of what came before; 0 to start).
uint32_t Crc32(std::string_view bytes, uint32_t crc = 0);

void PutU8(std::string* out, uint8_t v);
void PutU16(std::string* out, uint16_t v);
void PutU32(std::string* out, uint32_t v);
void PutU64(std::string* out, uint64_t v);
// A u32 length prefix, then the bytes (strings and Schema data).
void PutPrefixed32(std::string* out, std::string_view bytes);

// Reads fields from a view; every read checks the bytes left and fails (false, nothing consumed) past the end.
class Cursor {
 public:
  explicit Cursor(std::string_view bytes) : bytes_(bytes) {}
  bool U8(uint8_t* v);
  bool U16(uint16_t* v);
  bool U32(uint32_t* v);
  bool U64(uint64_t* v);
  bool Take(size_t n, std::string_view* out);
  // A u32-length-prefixed string or byte array.
  bool Prefixed32(std::string_view* out);
  size_t remaining() const { return bytes_.size() - pos_; }
  size_t pos() const { return pos_; }
  std::string_view rest() const { return bytes_.substr(pos_); }

 private:
  bool Fixed(size_t n, uint64_t* v);
  std::string_view bytes_;
  size_t pos_ = 0;
};

}  // namespace turf::mcap
