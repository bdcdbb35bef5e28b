// What a durable writer of a topic turf-sim publishes over and over (world state, clock, stats, control replies:
// TRANSIENT_LOCAL, KEEP_LAST) is given while no reader is matched: the last `depth` samples, kept as the writer's
// history would have kept them, instead of being serialised into that history one by one. When a reader matches
// they are written, oldest first, so a late joiner gets what it would have got. Internal to dds/.
//
// The writer's listener keeps the matched count here (SetMatched, from Fast DDS's discovery thread) and the
// writer asks Matched() under the same mutex, so a sample cannot be held after the match that should have
// flushed it: either the write sees the new count, or the match callback sees the held sample.
//
// Latched topics (written once: the field, the legged scene, the run) are never held; they cost nothing per step.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include "dds/topics.h"

namespace turf::dds {

class HeldSamples {
 public:
  using WriteFn = std::function<void(const void* sample, std::optional<int64_t> source_ns)>;
  virtual ~HeldSamples() = default;

  // Writes `sample` now (a reader is matched: after any held ones) or holds it.
  void Write(const void* sample, std::optional<int64_t> source_ns, const WriteFn& write) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (matched_ <= 0) return Hold(sample, source_ns ? *source_ns : WallNs());
    FlushLocked(write);
    write(sample, source_ns);
  }
  // The writer's matched count changed to `count`; with a reader now matched the held samples go out.
  void SetMatched(int count, const WriteFn& write) {
    std::lock_guard<std::mutex> lock(mutex_);
    matched_ = count;
    if (matched_ > 0) FlushLocked(write);
  }

 protected:
  virtual void Hold(const void* sample, int64_t source_ns) = 0;
  // Writes the held samples, oldest first, and forgets them.
  virtual void FlushLocked(const WriteFn& write) = 0;

 private:
  static int64_t WallNs() {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch())
        .count();
  }

  std::mutex mutex_;
  int matched_ = 0;
};

// A ring of `depth` samples of the topic's type, copied into by assignment: a held world state reuses the robots'
// storage of the one it replaces (no allocation per write once the ring is full).
template <class Sample>
class HeldSamplesOf final : public HeldSamples {
 public:
  explicit HeldSamplesOf(size_t depth) : slots_(depth) {}

 private:
  void Hold(const void* sample, int64_t source_ns) override {
    if (count_ == slots_.size()) {
      first_ = (first_ + 1) % slots_.size();
      --count_;
    }
    Slot& slot = slots_[(first_ + count_++) % slots_.size()];
    slot.sample = *static_cast<const Sample*>(sample);
    slot.source_ns = source_ns;
  }
  void FlushLocked(const WriteFn& write) override {
    for (; count_ > 0; --count_, first_ = (first_ + 1) % slots_.size())
      write(&slots_[first_].sample, slots_[first_].source_ns);
  }

  struct Slot {
    Sample sample;
    int64_t source_ns = 0;
  };
  std::vector<Slot> slots_;
  size_t first_ = 0;  // the oldest held
  size_t count_ = 0;
};

}  // namespace turf::dds
