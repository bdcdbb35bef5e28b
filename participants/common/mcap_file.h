// MCAP files on disk for the codec in codecs/mcap (which does no I/O): a ByteSource that reads a file with
// pread, and a ByteSink that appends to one. The sink's Flush() hands what was written to the kernel, so a
// process killed after it (kill -9) leaves those bytes in the file.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "codecs/mcap/reader.h"
#include "codecs/mcap/writer.h"
#include "core/pinned.h"

namespace turf {

class McapFileSource final : public mcap::ByteSource, Pinned {
 public:
  // Check ok() (and error()) before use.
  explicit McapFileSource(const std::string& path);
  ~McapFileSource() override;
  bool ok() const { return fd_ >= 0; }
  const std::string& error() const { return error_; }
  uint64_t Size() const override { return size_; }
  bool Read(uint64_t offset, size_t n, std::string* out) const override;

 private:
  int fd_ = -1;
  uint64_t size_ = 0;
  std::string error_;
};

class McapFileSink final : public mcap::ByteSink, Pinned {
 public:
  // Creates or truncates `path`; check ok().
  explicit McapFileSink(const std::string& path);
  ~McapFileSink() override;
  bool ok() const { return fd_ >= 0 && error_.empty(); }
  const std::string& error() const { return error_; }
  void Write(std::string_view bytes) override;
  // Writes what is buffered (a write(2) each: the bytes are in the file once this returns).
  void Flush();

 private:
  int fd_ = -1;
  std::string buffer_;
  std::string error_;
};

}  // namespace turf
