// The comparison of turf replay --resimulate (resimulate.h): recorded output messages against re-simulated
// samples, matched by topic, simulation time and bytes.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace turf {

class OutputMatch {
 public:
  // A recorded message, in file order.
  void Recorded(const std::string& topic, uint64_t sim_time_ns, std::string bytes);
  // A re-simulated sample: reproduces the first unmatched recorded message of its topic and time with its bytes.
  void Resimulated(const std::string& topic, uint64_t sim_time_ns, std::string bytes);

  struct Difference {
    bool found = false;
    std::string topic;
    uint64_t index = 0;  // among the topic's recorded messages
    uint64_t sim_time_ns = 0;
    std::string line;  // "world_state #7 (sim time 0.080000 s): ..."
  };
  // The first recorded message not reproduced, by simulation time, then file order.
  Difference FirstDifference() const;

  uint64_t recorded() const { return recorded_; }
  uint64_t reproduced() const { return reproduced_; }
  uint64_t unrecorded() const { return unrecorded_; }
  uint64_t last_recorded_time() const { return last_time_; }
  // The recorded outputs' simulation time up to the first gap longer than `max_gap_ns` between two of them (a
  // file's times are untrusted: a forged one far past the rest would keep a re-simulation running for years).
  uint64_t ContiguousEnd(uint64_t max_gap_ns) const;

 private:
  struct Message {
    std::string bytes;
    uint64_t order = 0;  // in the file
    uint64_t index = 0;  // in its topic
    bool reproduced = false;
  };
  using ByTime = std::map<uint64_t, std::vector<Message>>;
  std::map<std::string, ByTime> recorded_by_topic_;
  std::map<std::string, uint64_t> count_by_topic_;
  // Re-simulated samples that reproduced nothing, kept (up to a bound) to name the first differing byte.
  std::map<std::string, std::map<uint64_t, std::vector<std::string>>> unmatched_;
  uint64_t kept_unmatched_ = 0;
  uint64_t recorded_ = 0;
  uint64_t reproduced_ = 0;
  uint64_t unrecorded_ = 0;
  uint64_t last_time_ = 0;
};

}  // namespace turf
