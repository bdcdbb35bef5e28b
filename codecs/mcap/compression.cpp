#include "codecs/mcap/compression.h"

#include <zstd.h>

namespace turf::mcap {

const char* CompressionField(Compression c) { return c == Compression::kZstd ? "zstd" : ""; }

std::optional<Compression> CompressionFromWord(std::string_view word) {
  if (word == "none") return Compression::kNone;
  if (word == "zstd") return Compression::kZstd;
  return std::nullopt;
}

std::string Compress(Compression c, std::string_view bytes, int zstd_level) {
  if (c == Compression::kNone) return std::string(bytes);
  std::string out(ZSTD_compressBound(bytes.size()), '\0');
  const size_t n = ZSTD_compress(out.data(), out.size(), bytes.data(), bytes.size(), zstd_level);
  if (ZSTD_isError(n)) return {};  // cannot happen with a bound-sized buffer
  out.resize(n);
  return out;
}

ReadError Decompress(std::string_view compression, std::string_view bytes, uint64_t uncompressed_size, std::string* out,
                     std::string* why) {
  if (compression.empty()) {
    if (bytes.size() != uncompressed_size) {
      *why = "uncompressed chunk holds " + std::to_string(bytes.size()) + " bytes, its header says " +
             std::to_string(uncompressed_size);
      return ReadError::kMalformed;
    }
    out->assign(bytes);
    return ReadError::kOk;
  }
  if (compression != "zstd") {
    *why = "chunk compression \"" + std::string(compression) + "\" is not supported (only none and zstd)";
    return ReadError::kUnknownCompression;
  }
  out->assign(static_cast<size_t>(uncompressed_size), '\0');
  const size_t n = ZSTD_decompress(out->data(), out->size(), bytes.data(), bytes.size());
  if (ZSTD_isError(n) || n != uncompressed_size) {
    *why = ZSTD_isError(n) ? std::string("zstd: ") + ZSTD_getErrorName(n)
                           : "zstd chunk decompresses to " + std::to_string(n) + " bytes, its header says " +
                                 std::to_string(uncompressed_size);
    out->clear();
    return ReadError::kMalformed;
  }
  return ReadError::kOk;
}

}  // namespace turf::mcap
