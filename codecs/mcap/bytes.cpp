#include "codecs/mcap/bytes.h"

#include <array>

namespace turf::mcap {
namespace {

std::array<uint32_t, 256> MakeCrcTable() {
  std::array<uint32_t, 256> table{};
  for (uint32_t i = 0; i < 256; ++i) {
    uint32_t c = i;
    for (int k = 0; k < 8; ++k) c = (c & 1u) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
    table[i] = c;
  }
  return table;
}

void PutLe(std::string* out, uint64_t v, int bytes) {
  for (int i = 0; i < bytes; ++i) out->push_back(static_cast<char>((v >> (8 * i)) & 0xFFu));
}

}  // namespace

uint32_t Crc32(std::string_view bytes, uint32_t crc) {
  static const std::array<uint32_t, 256> table = MakeCrcTable();
  uint32_t c = crc ^ 0xFFFFFFFFu;
  for (char ch : bytes) c = table[(c ^ static_cast<uint8_t>(ch)) & 0xFFu] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

void PutU8(std::string* out, uint8_t v) { PutLe(out, v, 1); }
void PutU16(std::string* out, uint16_t v) { PutLe(out, v, 2); }
void PutU32(std::string* out, uint32_t v) { PutLe(out, v, 4); }
void PutU64(std::string* out, uint64_t v) { PutLe(out, v, 8); }

void PutPrefixed32(std::string* out, std::string_view bytes) {
  PutU32(out, static_cast<uint32_t>(bytes.size()));
  out->append(bytes);
}

bool Cursor::Fixed(size_t n, uint64_t* v) {
  if (remaining() < n) return false;
  uint64_t r = 0;
  for (size_t i = 0; i < n; ++i) r |= static_cast<uint64_t>(static_cast<uint8_t>(bytes_[pos_ + i])) << (8 * i);
  pos_ += n;
  *v = r;
  return true;
}

bool Cursor::U8(uint8_t* v) {
  uint64_t r = 0;
  if (!Fixed(1, &r)) return false;
  *v = static_cast<uint8_t>(r);
  return true;
}

bool Cursor::U16(uint16_t* v) {
  uint64_t r = 0;
  if (!Fixed(2, &r)) return false;
  *v = static_cast<uint16_t>(r);
  return true;
}

bool Cursor::U32(uint32_t* v) {
  uint64_t r = 0;
  if (!Fixed(4, &r)) return false;
  *v = static_cast<uint32_t>(r);
  return true;
}

bool Cursor::U64(uint64_t* v) { return Fixed(8, v); }

bool Cursor::Take(size_t n, std::string_view* out) {
  if (remaining() < n) return false;
  *out = bytes_.substr(pos_, n);
  pos_ += n;
  return true;
}

bool Cursor::Prefixed32(std::string_view* out) {
  const size_t start = pos_;
  uint32_t n = 0;
  if (!U32(&n) || !Take(n, out)) {
    pos_ = start;
    return false;
  }
  return true;
}

}  // namespace turf::mcap
