// `turf log info FILE`: what an MCAP recording holds, as `mcap info` prints it: messages, duration (receive
// time) and simulation time span, chunks and compression, and per channel the topic, count, rate, bytes and
// schema. Counts and sizes come from a scan of the whole file (so a cut or damaged file shows what it holds up
// to the damage, and the damage with its offset); the summary section is checked and reported too.
#pragma once

#include <cstdint>
#include <string>

#include "codecs/mcap/reader.h"

namespace turf::launch {

struct LogInfo {
  std::string path;
  uint64_t file_bytes = 0;
  mcap::FileInfo scanned;
  mcap::Damage scan;     // ok: read to the end
  mcap::Damage summary;  // ok: the summary section is there and agrees (checked against the scan)
  uint64_t first_publish_time = 0, last_publish_time = 0;  // simulation time, ns (publish_time)
};

// Reads the file at `source` (scan and summary).
LogInfo ReadLogInfo(const std::string& path, const mcap::ByteSource& source);
// The report, several lines.
std::string FormatLogInfo(const LogInfo& info);

}  // namespace turf::launch
