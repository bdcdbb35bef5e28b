// A small MCAP file for the reader tests: three channels, messages spread over several chunks.
#pragma once

#include <string>
#include <vector>

#include "codecs/mcap/writer.h"

namespace turf::mcap::fixture {

struct Sent {
  uint16_t channel;
  uint32_t sequence;
  uint64_t log_time;
  uint64_t publish_time;
  std::string data;
};

inline std::vector<Sent> SomeMessages(int n) {
  std::vector<Sent> out;
  for (int i = 0; i < n; ++i) {
    const uint16_t channel = static_cast<uint16_t>(1 + i % 3);
    out.push_back({channel, static_cast<uint32_t>(i), 1000u + 10u * static_cast<uint64_t>(i),
                   static_cast<uint64_t>(i) * 2000000u,
                   std::string(static_cast<size_t>(5 + i % 7), char('a' + i % 26))});
  }
  return out;
}

inline std::string WriteFile(const std::vector<Sent>& messages, Compression compression, size_t chunk_size) {
  StringSink sink;
  WriterOptions options;
  options.compression = compression;
  options.chunk_size = chunk_size;
  Writer w(&sink, options);
  const uint16_t schema = w.AddSchema("turf::idl::Clock", "omgidl", "struct Clock { long long t; };");
  w.AddChannel(schema, "turf/clock", "cdr");
  w.AddChannel(schema, "turf/world_state", "cdr", {{"qos", "turf.state"}});
  w.AddChannel(0, "turf/stats", "cdr");
  for (const Sent& m : messages) w.Write(m.channel, m.sequence, m.log_time, m.publish_time, m.data);
  w.Close();
  return sink.bytes();
}

}  // namespace turf::mcap::fixture
