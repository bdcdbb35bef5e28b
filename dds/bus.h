// A transport for turf's topics (topics.h): typed writers and readers, over one of two implementations:
//  - dds::Participant (participant.h): Fast DDS, one DomainParticipant; QoS from the profiles file;
//  - dds::MemoryBus (memory_bus.h): in-process, no DDS, for tests and an in-process front-end;
// and dds::FanoutBus (fanout_bus.h), one bus over two (turf-sim on DDS and on a MemoryBus at once).
// Code that only writes and reads topics takes a Bus&; whoever makes the bus picks the implementation.
//
// The typed API: bus.MakeWriter(dds::Topic::kClock) gives a Writer<idl::ClockPubSubType>, bus.MakeReader(topic,
// on_data) a Reader; the type comes with the topic, and naming another one does not compile. Templates cannot be
// virtual, so an implementation sees untyped endpoints (WriterEndpoint, ReaderEndpoint, SampleSink) and the
// typed Writer and Reader below are thin front-ends over them. This header needs no Fast DDS.
//
// RAII: a Writer or Reader closes its endpoint; the bus must outlive them (declare it first).
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "dds/topics.h"

namespace turf::dds {

// Copying and deleting a sample of one topic's type, made where the type is known (Bus::MakeWriter/MakeReader).
struct SampleOps {
  void* (*clone)(const void* sample) = nullptr;
  void (*destroy)(void* sample) = nullptr;

  template <class Sample>
  static SampleOps Of() {
    return {[](const void* s) -> void* { return new Sample(*static_cast<const Sample*>(s)); },
            [](void* s) { delete static_cast<Sample*>(s); }};
  }
};

// An implementation's writer. `sample` points to a sample of the topic's type.
class WriterEndpoint {
 public:
  virtual ~WriterEndpoint() = default;
  // `source_ns`: an explicit source timestamp (ns since the Unix epoch), where the transport carries one.
  virtual bool Write(const void* sample, std::optional<int64_t> source_ns) = 0;
  // Readers of the topic currently matched.
  virtual int Matched() const = 0;
};

// Where an implementation's reader puts what arrives: the typed Reader's queue.
class SampleSink {
 public:
  // Copies `sample` (the topic's type) into the queue; false if the queue was full (counted as overflowed).
  virtual bool Push(const void* sample) = 0;
  // After Push()es that returned true: wakes the reader's owner (its on_data), outside the queue's lock.
  virtual void Notify() = 0;

 protected:
  ~SampleSink() = default;
};

// An implementation's reader; it delivers into its SampleSink from any thread until it is destroyed.
class ReaderEndpoint {
 public:
  virtual ~ReaderEndpoint() = default;
  virtual int Matched() const = 0;
  // Instances whose Deadline QoS period passed without a sample, so far (0 where there is no such QoS).
  virtual int DeadlinesMissed() const = 0;
};

template <class PubSub>
class Writer {
 public:
  using Sample = SampleOf<PubSub>;
  explicit Writer(std::unique_ptr<WriterEndpoint> endpoint) : endpoint_(std::move(endpoint)) {}
  Writer(const Writer&) = delete;
  Writer& operator=(const Writer&) = delete;
  bool Write(const Sample& sample) { return endpoint_->Write(&sample, std::nullopt); }
  // With an explicit source timestamp (ns since the Unix epoch, wall clock).
  bool Write(const Sample& sample, int64_t source_ns) { return endpoint_->Write(&sample, source_ns); }
  // Number of readers currently matched.
  int Matched() const { return endpoint_->Matched(); }

 private:
  std::unique_ptr<WriterEndpoint> endpoint_;
};

// Takes samples as they arrive (on the transport's thread, or the writer's on a MemoryBus) into a bounded queue
// that the owner drains with Take(), and calls `on_data` so the owner can wake up.
template <class PubSub>
class Reader final : private SampleSink {
 public:
  using Sample = SampleOf<PubSub>;
  static constexpr size_t kMaxQueued = 4096;

  explicit Reader(std::function<void()> on_data) : on_data_(std::move(on_data)) {}
  // The endpoint goes first: no delivery runs past it.
  ~Reader() { endpoint_.reset(); }
  Reader(const Reader&) = delete;
  Reader& operator=(const Reader&) = delete;

  // Moves every queued sample into `out` (cleared first); false if none.
  bool Take(std::vector<Sample>* out) {
    out->clear();
    if (!pending_.load(std::memory_order_acquire)) return false;
    std::lock_guard<std::mutex> lock(mutex_);
    out->swap(queue_);
    pending_.store(false, std::memory_order_release);
    return !out->empty();
  }
  int DeadlinesMissed() const { return endpoint_->DeadlinesMissed(); }
  // Samples dropped because the owner did not drain the queue in time.
  uint64_t Overflowed() const { return overflowed_.load(); }
  int Matched() const { return endpoint_->Matched(); }

 private:
  friend class Bus;

  bool Push(const void* sample) override {
    std::lock_guard<std::mutex> lock(mutex_);
    if (queue_.size() >= kMaxQueued) {
      overflowed_.fetch_add(1);
      return false;
    }
    queue_.push_back(*static_cast<const Sample*>(sample));
    pending_.store(true, std::memory_order_release);
    return true;
  }
  void Notify() override {
    if (on_data_) on_data_();
  }

  std::function<void()> on_data_;
  std::mutex mutex_;
  std::vector<Sample> queue_;
  std::atomic<bool> pending_{false};
  std::atomic<uint64_t> overflowed_{0};
  std::unique_ptr<ReaderEndpoint> endpoint_;
};

// What Bus::MakeWriter and MakeReader return for a topic constant: WriterOf<Topic::kClock> is
// std::unique_ptr<Writer<idl::ClockPubSubType>>, its type taken from the topic table.
template <const auto& topic>
using WriterOf = std::unique_ptr<Writer<typename std::decay_t<decltype(topic)>::PubSubType>>;
template <const auto& topic>
using ReaderOf = std::unique_ptr<Reader<typename std::decay_t<decltype(topic)>::PubSubType>>;

class Bus {
 public:
  virtual ~Bus() = default;
  Bus(const Bus&) = delete;
  Bus& operator=(const Bus&) = delete;

  // Topic names are <prefix>/<suffix>.
  const std::string& prefix() const { return prefix_; }
  std::string TopicName(Topic topic) const { return dds::TopicName(prefix_, topic); }
  // One line for a start-up report: "DDS domain 3, QoS profiles <file>", "in-memory bus".
  virtual std::string Describe() const = 0;

  // MakeWriter<idl::ClockPubSubType>(dds::Topic::kClock), or MakeWriter(dds::Topic::kClock): the type
  // comes with the topic, and naming another one does not compile. Throws std::runtime_error on failure.
  template <class PubSub = void, class Carried>
  std::unique_ptr<Writer<Carried>> MakeWriter(const TopicDef<Carried>& topic) {
    static_assert(std::is_void_v<PubSub> || std::is_same_v<PubSub, Carried>,
                  "MakeWriter<T>(topic): T is not the topic's type (see dds/topics.h)");
    auto writer = std::make_unique<Writer<Carried>>(OpenWriter(topic, SampleOps::Of<SampleOf<Carried>>()));
    Created(Endpoint::kWriter, topic);
    return writer;
  }

  // MakeReader<idl::ClockPubSubType>(dds::Topic::kClock, on_data), or without the type; as MakeWriter.
  template <class PubSub = void, class Carried>
  std::unique_ptr<Reader<Carried>> MakeReader(const TopicDef<Carried>& topic, std::function<void()> on_data = {}) {
    static_assert(std::is_void_v<PubSub> || std::is_same_v<PubSub, Carried>,
                  "MakeReader<T>(topic): T is not the topic's type (see dds/topics.h)");
    auto reader = std::make_unique<Reader<Carried>>(std::move(on_data));
    reader->endpoint_ = OpenReader(topic, SampleOps::Of<SampleOf<Carried>>(), *reader);
    Created(Endpoint::kReader, topic);
    return reader;
  }

  // Every topic this bus has made a writer or reader for, once each, in creation order.
  std::vector<std::pair<Endpoint, Topic>> Endpoints() const;
  // One line per Endpoints() entry, with full name, DDS type and QoS profile (EndpointLine()).
  std::vector<std::string> TopicLines() const;
  // Logs TopicLines() at info: a participant's start-up list of its topics, from the table.
  void LogTopics() const;

 protected:
  explicit Bus(std::string prefix) : prefix_(std::move(prefix)) {}

  // The implementation's endpoints. A reader delivers into `sink` until its endpoint is destroyed; it may
  // deliver (and call sink.Notify()) before OpenReader returns.
  virtual std::unique_ptr<WriterEndpoint> OpenWriter(Topic topic, const SampleOps& ops) = 0;
  virtual std::unique_ptr<ReaderEndpoint> OpenReader(Topic topic, const SampleOps& ops, SampleSink& sink) = 0;

 private:
  friend class FanoutBus;  // opens endpoints on the buses it spans

  // Records the endpoint and logs its line at debug: the default (info) output keeps the participant's own
  // start-up lines, or LogTopics(); --log-level debug adds each endpoint's type and QoS profile as it is made.
  void Created(Endpoint endpoint, Topic topic);

  std::string prefix_;
  mutable std::mutex endpoints_mutex_;
  std::vector<std::pair<Endpoint, Topic>> endpoints_;
};

}  // namespace turf::dds
