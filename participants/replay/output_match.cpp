#include "participants/replay/output_match.h"

#include <fmt/format.h>

#include <algorithm>

namespace turf {
namespace {

constexpr uint64_t kMaxKeptUnmatched = 4096;

size_t CommonPrefix(const std::string& a, const std::string& b) {
  const auto diff =
      std::mismatch(a.begin(), a.begin() + static_cast<std::ptrdiff_t>(std::min(a.size(), b.size())), b.begin());
  return static_cast<size_t>(diff.first - a.begin());
}

}  // namespace

void OutputMatch::Recorded(const std::string& topic, uint64_t sim_time_ns, std::string bytes) {
  recorded_by_topic_[topic][sim_time_ns].push_back({std::move(bytes), recorded_, count_by_topic_[topic]++, false});
  ++recorded_;
  last_time_ = std::max(last_time_, sim_time_ns);
}

void OutputMatch::Resimulated(const std::string& topic, uint64_t sim_time_ns, std::string bytes) {
  const auto by_topic = recorded_by_topic_.find(topic);
  if (by_topic != recorded_by_topic_.end()) {
    const auto at = by_topic->second.find(sim_time_ns);
    if (at != by_topic->second.end()) {
      for (Message& m : at->second) {
        if (m.reproduced || m.bytes != bytes) continue;
        m.reproduced = true;
        ++reproduced_;
        return;
      }
    }
  }
  ++unrecorded_;
  if (kept_unmatched_ < kMaxKeptUnmatched) {
    unmatched_[topic][sim_time_ns].push_back(std::move(bytes));
    ++kept_unmatched_;
  }
}

uint64_t OutputMatch::ContiguousEnd(uint64_t max_gap_ns) const {
  std::vector<uint64_t> times;
  for (const auto& [topic, by_time] : recorded_by_topic_)
    for (const auto& [time, messages] : by_time) times.push_back(time);
  std::sort(times.begin(), times.end());
  uint64_t end = 0;
  for (const uint64_t t : times) {
    if (t - end > max_gap_ns) break;
    end = t;
  }
  return end;
}

OutputMatch::Difference OutputMatch::FirstDifference() const {
  const Message* first = nullptr;
  Difference d;
  for (const auto& [topic, by_time] : recorded_by_topic_) {
    for (const auto& [time, messages] : by_time) {
      for (const Message& m : messages) {
        if (m.reproduced) continue;
        if (first == nullptr || time < d.sim_time_ns || (time == d.sim_time_ns && m.order < first->order)) {
          first = &m;
          d = {true, topic, m.index, time, ""};
        }
        break;  // later messages of this time and topic come after it in the file
      }
    }
  }
  if (first == nullptr) return d;
  std::string what = "no re-simulated sample of that topic and time is left to compare";
  const auto topic = unmatched_.find(d.topic);
  if (topic != unmatched_.end()) {
    const auto at = topic->second.find(d.sim_time_ns);
    if (at != topic->second.end() && !at->second.empty()) {
      const std::string* best = &at->second.front();
      for (const std::string& s : at->second)
        if (CommonPrefix(s, first->bytes) > CommonPrefix(*best, first->bytes)) best = &s;
      what = fmt::format("{} bytes recorded, {} re-simulated, first differing byte at offset {}", first->bytes.size(),
                         best->size(), CommonPrefix(*best, first->bytes));
    }
  }
  d.line = fmt::format("first difference: {} #{} (sim time {:.6f} s): {}", d.topic, d.index,
                       static_cast<double>(d.sim_time_ns) * 1e-9, what);
  return d;
}

}  // namespace turf
