// libFuzzer target for the MCAP reader: any bytes give a summary, a scan or a named Damage at an offset inside
// the input, without a crash, a sanitizer report or an allocation beyond the limits.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "codecs/mcap/reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace turf::mcap;
  const StringSource source(std::string_view(reinterpret_cast<const char*>(data), size));
  ReaderOptions options;
  options.max_record_bytes = 1 << 20;
  options.max_chunk_bytes = 4 << 20;
  FileInfo summary, scanned;
  const Damage s = ReadSummary(source, options, &summary);
  uint64_t delivered = 0;
  const Damage d = Scan(source, options, &scanned, [&](const Channel& c, const Message& m) {
    if (!scanned.channels.count(c.id) || m.data.size() > size + (4u << 20)) std::abort();
    ++delivered;
  });
  if (delivered != scanned.statistics.message_count) std::abort();
  if (!d.ok() && (d.offset > size || d.message.empty())) std::abort();
  if (!s.ok() && s.message.empty()) std::abort();
  return 0;
}
