#include "participants/launcher/log_diff.h"

#include <fmt/format.h>

#include <map>
#include <optional>
#include <vector>

namespace turf::launch {
namespace {

struct Sample {
  uint64_t hash = 0;
  uint64_t size = 0;
  uint64_t sim_time = 0;
};

using Topics = std::map<std::string, std::vector<Sample>>;

std::string WithoutPrefix(const std::string& topic) {
  const size_t slash = topic.find('/');
  return slash == std::string::npos ? topic : topic.substr(slash + 1);
}

uint64_t Fnv1a(std::string_view bytes) {
  uint64_t h = 1469598103934665603ull;
  for (char c : bytes) h = (h ^ static_cast<uint8_t>(c)) * 1099511628211ull;
  return h;
}

mcap::Damage Collect(const mcap::ByteSource& source, const DiffOptions& options, Topics* out) {
  mcap::FileInfo info;
  return mcap::Scan(source, {}, &info, [&](const mcap::Channel& c, const mcap::Message& m) {
    const std::string topic = WithoutPrefix(c.topic);
    if (!options.skip.count(topic) && m.publish_time <= options.until_ns)
      (*out)[topic].push_back({Fnv1a(m.data), m.data.size(), m.publish_time});
  });
}

// The data of sample `index` of `topic`.
std::string DataOf(const mcap::ByteSource& source, const DiffOptions& options, const std::string& topic, size_t index) {
  mcap::FileInfo info;
  size_t seen = 0;
  std::string data;
  mcap::Scan(source, {}, &info, [&](const mcap::Channel& c, const mcap::Message& m) {
    if (WithoutPrefix(c.topic) == topic && m.publish_time <= options.until_ns && seen++ == index) data.assign(m.data);
  });
  return data;
}

struct Difference {
  std::string topic;
  size_t index = 0;
  uint64_t sim_time = 0;
};

// The earliest (by sim time) index where the topic's samples differ or one side ends.
std::optional<Difference> FirstDifference(const Topics& a, const Topics& b) {
  std::optional<Difference> first;
  auto consider = [&](const std::string& topic, size_t index, uint64_t sim_time) {
    if (!first || sim_time < first->sim_time) first = Difference{topic, index, sim_time};
  };
  static const std::vector<Sample> kNone;
  for (const Topics* side : {&a, &b}) {
    for (const auto& [topic, unused] : *side) {
      const std::vector<Sample>& x = a.count(topic) ? a.at(topic) : kNone;
      const std::vector<Sample>& y = b.count(topic) ? b.at(topic) : kNone;
      size_t i = 0;
      while (i < x.size() && i < y.size() && x[i].hash == y[i].hash && x[i].size == y[i].size) ++i;
      if (i < x.size() || i < y.size()) consider(topic, i, i < x.size() ? x[i].sim_time : y[i].sim_time);
    }
  }
  return first;
}

}  // namespace

LogDiff DiffRecordings(const mcap::ByteSource& a, const mcap::ByteSource& b, const DiffOptions& options) {
  LogDiff out;
  Topics ta, tb;
  out.damage_a = Collect(a, options, &ta);
  out.damage_b = Collect(b, options, &tb);
  if (!out.damage_a.ok()) out.report += "A: compared up to " + out.damage_a.Describe() + "\n";
  if (!out.damage_b.ok()) out.report += "B: compared up to " + out.damage_b.Describe() + "\n";
  const std::optional<Difference> d = FirstDifference(ta, tb);
  if (!d) {
    size_t n = 0;
    for (const auto& [topic, samples] : ta) n += samples.size();
    out.same = true;
    out.report += fmt::format("same: {} samples on {} topics\n", n, ta.size());
    return out;
  }
  const size_t na = ta.count(d->topic) ? ta.at(d->topic).size() : 0;
  const size_t nb = tb.count(d->topic) ? tb.at(d->topic).size() : 0;
  out.report += fmt::format("first difference: {} sample #{} (sim time {:.6f} s): ", d->topic, d->index,
                            static_cast<double>(d->sim_time) * 1e-9);
  if (d->index >= na || d->index >= nb) {
    out.report += fmt::format("{} ends after {} samples, {} has {}\n", d->index >= na ? "A" : "B", d->index,
                              d->index >= na ? "B" : "A", d->index >= na ? nb : na);
    return out;
  }
  const std::string x = DataOf(a, options, d->topic, d->index);
  const std::string y = DataOf(b, options, d->topic, d->index);
  size_t at = 0;
  while (at < x.size() && at < y.size() && x[at] == y[at]) ++at;
  out.report += fmt::format("{} bytes in A, {} in B, first differing byte at offset {}\n", x.size(), y.size(), at);
  return out;
}

}  // namespace turf::launch
