// Chunk compression of MCAP files: "" (none), "zstd" (Debian's libzstd) and "lz4" (an LZ4 frame, Debian's liblz4), the
// three the specification names. Another name is kUnknownCompression for a reader.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "codecs/mcap/damage.h"

namespace turf::mcap {

enum class Compression : uint8_t { kNone, kZstd, kLz4 };

// The Chunk record's compression field: "", "zstd" or "lz4".
const char* CompressionField(Compression c);
// "none", "zstd" or "lz4" (a command line's word); nullopt for anything else.
std::optional<Compression> CompressionFromWord(std::string_view word);

std::string Compress(Compression c, std::string_view bytes, int zstd_level);

// Decompresses a chunk's records into `out` (exactly uncompressed_size bytes). kOk, kUnknownCompression or
// kMalformed (the bytes do not decompress to that size); `why` says more.
ReadError Decompress(std::string_view compression, std::string_view bytes, uint64_t uncompressed_size, std::string* out,
                     std::string* why);

}  // namespace turf::mcap
