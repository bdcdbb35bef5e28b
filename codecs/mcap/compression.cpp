#include "codecs/mcap/compression.h"

#include <lz4frame.h>
#include <zstd.h>

#include <memory>

namespace turf::mcap {

namespace {

// Each compression's word on a command line and its Chunk record field, one table for both directions.
struct CompressionNames {
  Compression compression;
  const char* word;
  const char* field;
};
constexpr CompressionNames kCompressionNames[] = {
    {Compression::kNone, "none", ""},
    {Compression::kZstd, "zstd", "zstd"},
    {Compression::kLz4, "lz4", "lz4"},
};

}  // namespace

const char* CompressionField(Compression c) {
  for (const CompressionNames& n : kCompressionNames)
    if (n.compression == c) return n.field;
  return "";
}

std::optional<Compression> CompressionFromWord(std::string_view word) {
  for (const CompressionNames& n : kCompressionNames)
    if (word == n.word) return n.compression;
  return std::nullopt;
}

namespace {

std::string CompressLz4(std::string_view bytes) {
  std::string out(LZ4F_compressFrameBound(bytes.size(), nullptr), '\0');
  const size_t n = LZ4F_compressFrame(out.data(), out.size(), bytes.data(), bytes.size(), nullptr);
  if (LZ4F_isError(n)) return {};  // cannot happen with a bound-sized buffer
  out.resize(n);
  return out;
}

// One LZ4 frame into exactly `out->size()` bytes; never trusts the frame's own sizes.
ReadError DecompressLz4(std::string_view bytes, std::string* out, std::string* why) {
  LZ4F_dctx* raw = nullptr;
  if (LZ4F_isError(LZ4F_createDecompressionContext(&raw, LZ4F_VERSION))) {
    *why = "lz4: no decompression context";
    return ReadError::kMalformed;
  }
  const std::unique_ptr<LZ4F_dctx, LZ4F_errorCode_t (*)(LZ4F_dctx*)> ctx(raw, LZ4F_freeDecompressionContext);
  size_t in = 0, produced = 0, hint = 1;
  while (in < bytes.size() && hint != 0) {
    size_t dst = out->size() - produced, src = bytes.size() - in;
    hint = LZ4F_decompress(ctx.get(), out->data() + produced, &dst, bytes.data() + in, &src, nullptr);
    if (LZ4F_isError(hint)) {
      *why = std::string("lz4: ") + LZ4F_getErrorName(hint);
      return ReadError::kMalformed;
    }
    in += src;
    produced += dst;
    if (src == 0 && dst == 0) break;  // the output is full and the frame wants more
  }
  if (hint != 0 || in != bytes.size() || produced != out->size()) {
    *why = hint != 0 ? "lz4 chunk: the frame does not end within the chunk's size"
                     : "lz4 chunk decompresses to " + std::to_string(produced) + " bytes (" +
                           std::to_string(bytes.size() - in) + " bytes after the frame), its header says " +
                           std::to_string(out->size());
    return ReadError::kMalformed;
  }
  return ReadError::kOk;
}

}  // namespace

std::string Compress(Compression c, std::string_view bytes, int zstd_level) {
  if (c == Compression::kNone) return std::string(bytes);
  if (c == Compression::kLz4) return CompressLz4(bytes);
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
  if (compression == "lz4") {
    out->assign(static_cast<size_t>(uncompressed_size), '\0');
    const ReadError e = DecompressLz4(bytes, out, why);
    if (e != ReadError::kOk) out->clear();
    return e;
  }
  if (compression != "zstd") {
    *why = "chunk compression \"" + std::string(compression) + "\" is not supported (only none, zstd and lz4)";
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
