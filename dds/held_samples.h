// What a durable writer of a topic turf-sim publishes over and over (world state, clock, stats, control replies:
// TRANSIENT_LOCAL, KEEP_LAST) is given while no reader is matched: the last `depth` samples, kept as the writer's
// history would have kept them, instead of being serialised into that history one by one. When a reader matches
// they are written, oldest first, so a late joiner gets what it would have got. Internal to dds/.
//
// The writer's listener keeps the matched count here (SetMatched, from Fast DDS's discovery thread) and the
// writer asks Matched() under the same mutex, so a sample cannot be held after the match that should have
// flushed it: either the write sees the new count, or the match callback sees the held sample.
//
// A keyed topic (a robot's joints, IMU, force, links) is held per instance, as a keyed writer's history keeps
// `depth` samples per instance; on a match every instance's samples go out in the order they were written.
//
// Latched topics (written once: the field, the legged scene, the run) are never held; they cost nothing per step.
#pragma once

#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <utility>
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
    if (matched_ <= 0 && Hold(sample, source_ns ? *source_ns : WallNs())) return;
    FlushLocked(write);
    write(sample, source_ns);
  }
  // The writer's matched count changed to `count`; with a reader now matched the held samples go out.
  void SetMatched(int count, const WriteFn& write) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (closed_) return;
    matched_ = count;
    if (matched_ > 0) FlushLocked(write);
  }
  // The writer is being deleted: SetMatched writes nothing from now on (one running now has finished on return).
  void Close() {
    std::lock_guard<std::mutex> lock(mutex_);
    closed_ = true;
  }

 protected:
  // Keeps `sample`; false if it cannot (then what is held and the sample are written, as if a reader matched).
  virtual bool Hold(const void* sample, int64_t source_ns) = 0;
  // Writes the held samples, oldest first, and forgets them.
  virtual void FlushLocked(const WriteFn& write) = 0;

 private:
  static int64_t WallNs() {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch())
        .count();
  }

  std::mutex mutex_;
  int matched_ = 0;
  bool closed_ = false;
};

// A ring of `depth` samples of the topic's type, copied into by assignment: a held world state reuses the robots'
// storage of the one it replaces (no allocation per write once the ring is full). Each sample keeps the sequence
// number it was held with, so that rings of several instances flush in writing order.
template <class Sample>
class HeldRing {
 public:
  explicit HeldRing(size_t depth) : slots_(depth) {}

  void Push(const Sample& sample, int64_t source_ns, uint64_t sequence) {
    if (count_ == slots_.size()) {
      first_ = (first_ + 1) % slots_.size();
      --count_;
    }
    Slot& slot = slots_[(first_ + count_++) % slots_.size()];
    slot.sample = sample;
    slot.source_ns = source_ns;
    slot.sequence = sequence;
  }
  // Calls `f(sample, source_ns, sequence)` for each held sample, oldest first.
  template <class F>
  void ForEach(F&& f) const {
    for (size_t i = 0; i < count_; ++i) {
      const Slot& slot = slots_[(first_ + i) % slots_.size()];
      f(slot.sample, slot.source_ns, slot.sequence);
    }
  }
  void Clear() { first_ = count_ = 0; }

 private:
  struct Slot {
    Sample sample;
    int64_t source_ns = 0;
    uint64_t sequence = 0;
  };
  std::vector<Slot> slots_;
  size_t first_ = 0;  // the oldest held
  size_t count_ = 0;
};

// An unkeyed topic: one ring.
template <class Sample>
class HeldSamplesOf final : public HeldSamples {
 public:
  explicit HeldSamplesOf(size_t depth) : ring_(depth) {}

 private:
  bool Hold(const void* sample, int64_t source_ns) override {
    ring_.Push(*static_cast<const Sample*>(sample), source_ns, 0);
    return true;
  }
  void FlushLocked(const WriteFn& write) override {
    ring_.ForEach([&](const Sample& s, int64_t ns, uint64_t) { write(&s, ns); });
    ring_.Clear();
  }

  HeldRing<Sample> ring_;
};

// A keyed topic: one ring per instance, at most `max_instances` of them (the writer's resource limit; a sample
// of one more instance is written, after everything held, as if a reader were matched). `key` gives a sample's instance
// key (the DDS instance handle).
template <class Sample>
class KeyedHeldSamplesOf final : public HeldSamples {
 public:
  using Key = std::array<uint8_t, 16>;
  using KeyFn = std::function<Key(const Sample&)>;
  KeyedHeldSamplesOf(size_t depth, size_t max_instances, KeyFn key)
      : depth_(depth), max_instances_(max_instances), key_(std::move(key)) {}

 private:
  bool Hold(const void* sample, int64_t source_ns) override {
    const Sample& s = *static_cast<const Sample*>(sample);
    const Key key = key_(s);
    auto it = rings_.find(key);
    if (it == rings_.end()) {
      if (rings_.size() >= max_instances_) return false;
      it = rings_.emplace(key, HeldRing<Sample>(depth_)).first;
    }
    it->second.Push(s, source_ns, next_sequence_++);
    return true;
  }
  void FlushLocked(const WriteFn& write) override {
    struct Held {
      uint64_t sequence;
      const Sample* sample;
      int64_t source_ns;
    };
    std::vector<Held> all;
    for (const auto& [key, ring] : rings_)
      ring.ForEach([&](const Sample& s, int64_t ns, uint64_t seq) { all.push_back({seq, &s, ns}); });
    std::sort(all.begin(), all.end(), [](const Held& a, const Held& b) { return a.sequence < b.sequence; });
    for (const Held& h : all) write(h.sample, h.source_ns);
    for (auto& [key, ring] : rings_) ring.Clear();
  }

  const size_t depth_;
  const size_t max_instances_;
  const KeyFn key_;
  std::map<Key, HeldRing<Sample>> rings_;
  uint64_t next_sequence_ = 0;
};

}  // namespace turf::dds
