// Chunk compression of MCAP files: "" (none) and "zstd" (Debian's libzstd). lz4 is named by the specification
// but not built here (liblz4-dev is not in scripts/setup.sh): a reader meets it as kUnknownCompression.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "codecs/mcap/damage.h"

namespace turf::mcap {

enum class Compression : uint8_t { kNone, kZstd };

// The Chunk record's compression field: "" or "zstd".
const char* CompressionField(Compression c);
// "none" or "zstd" (a command line's word); nullopt for anything else.
std::optional<Compression> CompressionFromWord(std::string_view word);

std::string Compress(Compression c, std::string_view bytes, int zstd_level);

// Decompresses a chunk's records into `out` (exactly uncompressed_size bytes). kOk, kUnknownCompression or
// kMalformed (the bytes do not decompress to that size); `why` says more.
ReadError Decompress(std::string_view compression, std::string_view bytes, uint64_t uncompressed_size, std::string* out,
                     std::string* why);

}  // namespace turf::mcap
