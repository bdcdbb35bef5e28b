// dds::MemoryBus: a Bus (bus.h) inside one process, without DDS: no domain, no ports, no discovery, so no
// waiting for it. For tests of participants (turf-sim's node and its control client on one bus, stepped in
// lockstep) and for an in-process front-end.
//
// What it does:
//  - a Write copies the sample synchronously, on the writer's thread, into the queue of every reader of the
//    same topic on this bus, then calls the on_data of each reader that queued it (outside the bus's lock);
//  - Matched() counts the other side's endpoints of the topic on this bus, at once;
//  - latched topics (Direction::kLatched in topics.h) keep each writer's last sample while the writer lives,
//    and a reader made later gets them (in the writers' creation order) before MakeReader returns;
//  - readers' queues are bounded as over DDS (Reader::kMaxQueued, then Overflowed() counts);
//  - thread-safe: writers, readers and their owners may be on different threads. Samples of one topic reach
//    each reader in the order the bus took the writes.
// What it does not model: QoS (reliability, history depth, deadlines: DeadlinesMissed() is always 0,
// lifespan), keyed instances (a latched writer keeps one sample, not one per key), loss, latency, source
// timestamps (accepted and dropped), other processes, and the transient-local history of non-latched topics
// that a DDS profile may give (turf.reply): a reader made after a write does not get it.
//
// on_data runs on the writing thread; it may write (to this bus too) and take, but must not destroy its own
// reader. The bus must outlive its writers and readers.
#pragma once

#include <array>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "dds/bus.h"

namespace turf::dds {

class MemoryBus final : public Bus {
 public:
  explicit MemoryBus(std::string prefix = "turf");
  ~MemoryBus() override;

  std::string Describe() const override;

  // True while this thread delivers a sample it wrote on a MemoryBus (inside that Write, in a reader's on_data):
  // the writer waits for the call, so an on_data may serve the sample right there instead of waking another thread
  // (turf-sim serves an in-process front-end's control request so, participants/sim/control_loop.h).
  static bool DeliveringOnThisThread();

 protected:
  std::unique_ptr<WriterEndpoint> OpenWriter(Topic topic, const SampleOps& ops) override;
  std::unique_ptr<ReaderEndpoint> OpenReader(Topic topic, const SampleOps& ops, SampleSink& sink) override;

 private:
  class MemoryWriter;
  class MemoryReader;
  struct Slot;  // a reader as the bus sees it, shared with the writes that are waking it

  struct TopicEndpoints {
    std::vector<MemoryWriter*> writers;  // creation order
    std::vector<std::shared_ptr<Slot>> readers;
  };

  bool Write(Topic topic, MemoryWriter& writer, const void* sample);
  void Close(Topic topic, MemoryWriter& writer);
  void Close(Topic topic, const std::shared_ptr<Slot>& slot);
  int Count(Topic topic, Endpoint endpoint) const;

  mutable std::mutex mutex_;
  std::array<TopicEndpoints, kTopicCount> topics_;
};

}  // namespace turf::dds
