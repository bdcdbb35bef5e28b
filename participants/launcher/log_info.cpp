#include "participants/launcher/log_info.h"

#include <fmt/format.h>

#include <algorithm>

namespace turf::launch {
namespace {

std::string Bytes(uint64_t n) {
  if (n >= 10ull * 1024 * 1024) return fmt::format("{:.1f} MiB", static_cast<double>(n) / (1024.0 * 1024.0));
  if (n >= 10ull * 1024) return fmt::format("{:.1f} KiB", static_cast<double>(n) / 1024.0);
  return fmt::format("{} B", n);
}

double Seconds(uint64_t from, uint64_t to) { return to > from ? static_cast<double>(to - from) * 1e-9 : 0.0; }

// The summary must agree with what the scan counted.
mcap::Damage CheckSummary(const mcap::FileInfo& summary, const mcap::FileInfo& scanned) {
  const mcap::Statistics& a = summary.statistics;
  const mcap::Statistics& b = scanned.statistics;
  if (a.message_count != b.message_count || a.channel_message_counts != b.channel_message_counts ||
      a.chunk_count != b.chunk_count || summary.chunk_indexes.size() != a.chunk_count)
    return mcap::MakeDamage(mcap::ReadError::kMalformed, 0, "the summary's statistics disagree with the file's data");
  return {};
}

}  // namespace

LogInfo ReadLogInfo(const std::string& path, const mcap::ByteSource& source) {
  LogInfo info;
  info.path = path;
  info.file_bytes = source.Size();
  bool first = true;
  info.scan = mcap::Scan(source, {}, &info.scanned, [&](const mcap::Channel&, const mcap::Message& m) {
    info.first_publish_time = first ? m.publish_time : std::min(info.first_publish_time, m.publish_time);
    info.last_publish_time = first ? m.publish_time : std::max(info.last_publish_time, m.publish_time);
    first = false;
  });
  mcap::FileInfo summary;
  info.summary = mcap::ReadSummary(source, {}, &summary);
  if (info.summary.ok() && info.scan.ok()) info.summary = CheckSummary(summary, info.scanned);
  return info;
}

std::string FormatLogInfo(const LogInfo& info) {
  const mcap::FileInfo& f = info.scanned;
  const mcap::Statistics& s = f.statistics;
  std::string out = fmt::format("file:        {} ({})\n", info.path, Bytes(info.file_bytes));
  out += fmt::format("library:     {}\nprofile:     {}\n", f.header.library, f.header.profile);
  out += fmt::format("messages:    {}\n", s.message_count);
  const double duration = Seconds(s.message_start_time, s.message_end_time);
  out += fmt::format("duration:    {:.3f} s (receive time)\n", duration);
  out += fmt::format("sim time:    {:.3f} s to {:.3f} s\n", static_cast<double>(info.first_publish_time) * 1e-9,
                     static_cast<double>(info.last_publish_time) * 1e-9);
  std::string kinds;
  for (const auto& [compression, n] : f.chunks_by_compression)
    kinds += fmt::format("{}{}: {}", kinds.empty() ? "" : ", ", compression.empty() ? "none" : compression, n);
  out += fmt::format("chunks:      {}{}\n", s.chunk_count, kinds.empty() ? "" : " (" + kinds + ")");
  out += fmt::format("channels:    {}\n", f.channels.size());
  for (const auto& [id, c] : f.channels) {
    const uint64_t n = s.channel_message_counts.count(id) ? s.channel_message_counts.at(id) : 0;
    const uint64_t bytes = f.channel_bytes.count(id) ? f.channel_bytes.at(id) : 0;
    const auto schema = f.schemas.find(c.schema_id);
    out += fmt::format("  {:>5} {:<28} {:>9} msgs ({:.1f} Hz) {:>11}  {} [{}] {}\n", fmt::format("({})", id), c.topic,
                       n, duration > 0 ? static_cast<double>(n) / duration : 0.0, Bytes(bytes),
                       schema == f.schemas.end() ? "no schema" : schema->second.name,
                       schema == f.schemas.end() ? "" : schema->second.encoding, c.message_encoding);
  }
  out += fmt::format("summary:     {}\n", info.summary.ok() ? "ok" : info.summary.Describe());
  out += fmt::format(
      "read:        {}\n",
      info.scan.ok() ? "the whole file" : "up to offset " + std::to_string(f.read_up_to) + ", " + info.scan.Describe());
  return out;
}

}  // namespace turf::launch
