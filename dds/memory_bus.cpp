#include "dds/memory_bus.h"

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <condition_variable>
#include <utility>

namespace turf::dds {

namespace {

thread_local int t_delivering = 0;  // MemoryBus::Write calls delivering on this thread (they may nest)

struct Delivering {
  Delivering() { ++t_delivering; }
  ~Delivering() { --t_delivering; }
  Delivering(const Delivering&) = delete;
  Delivering& operator=(const Delivering&) = delete;
};

}  // namespace

bool MemoryBus::DeliveringOnThisThread() { return t_delivering > 0; }

// The sink is reached under the bus's lock (Push) and, for on_data, while `open`, counted in `running`: closing a
// reader takes it out of the topic, clears `open` and waits for the on_data calls running, so no delivery
// outlives its endpoint. No lock is held while on_data runs (it may write, and wake other readers).
struct MemoryBus::Slot {
  explicit Slot(SampleSink& s) : sink(s) {}
  SampleSink& sink;
  std::mutex mutex;
  std::condition_variable idle;
  bool open = true;  // under mutex
  int running = 0;   // on_data calls running, under mutex

  void Notify() {
    {
      std::lock_guard<std::mutex> lock(mutex);
      if (!open) return;
      ++running;
    }
    sink.Notify();
    std::lock_guard<std::mutex> lock(mutex);
    if (--running == 0) idle.notify_all();
  }
  void Close() {
    std::unique_lock<std::mutex> lock(mutex);
    open = false;
    idle.wait(lock, [this] { return running == 0; });
  }
};

class MemoryBus::MemoryWriter final : public WriterEndpoint {
 public:
  MemoryWriter(MemoryBus& bus, Topic topic, const SampleOps& ops) : bus_(bus), topic_(topic), ops_(ops) {}
  ~MemoryWriter() override {
    bus_.Close(topic_, *this);
    if (last_ != nullptr) ops_.destroy(last_);
  }
  bool Write(const void* sample, std::optional<int64_t> /*source_ns*/) override {
    return bus_.Write(topic_, *this, sample);
  }
  int Matched() const override { return bus_.Count(topic_, Endpoint::kReader); }

  // The last sample of a latched topic; under the bus's lock.
  void Keep(const void* sample) {
    if (last_ != nullptr) ops_.destroy(last_);
    last_ = ops_.clone(sample);
  }
  const void* last() const { return last_; }

 private:
  MemoryBus& bus_;
  const Topic topic_;
  const SampleOps ops_;
  void* last_ = nullptr;
};

class MemoryBus::MemoryReader final : public ReaderEndpoint {
 public:
  MemoryReader(MemoryBus& bus, Topic topic, std::shared_ptr<Slot> slot)
      : bus_(bus), topic_(topic), slot_(std::move(slot)) {}
  ~MemoryReader() override { bus_.Close(topic_, slot_); }
  int Matched() const override { return bus_.Count(topic_, Endpoint::kWriter); }
  int DeadlinesMissed() const override { return 0; }

 private:
  MemoryBus& bus_;
  const Topic topic_;
  const std::shared_ptr<Slot> slot_;
};

MemoryBus::MemoryBus(std::string prefix) : Bus(std::move(prefix)) {}

MemoryBus::~MemoryBus() = default;

std::string MemoryBus::Describe() const { return "in-memory bus (no DDS), topic prefix " + prefix(); }

std::unique_ptr<WriterEndpoint> MemoryBus::OpenWriter(Topic topic, const SampleOps& ops) {
  auto writer = std::make_unique<MemoryWriter>(*this, topic, ops);
  std::lock_guard<std::mutex> lock(mutex_);
  topics_[static_cast<size_t>(topic.id())].writers.push_back(writer.get());
  return writer;
}

std::unique_ptr<ReaderEndpoint> MemoryBus::OpenReader(Topic topic, const SampleOps& /*ops*/, SampleSink& sink) {
  auto slot = std::make_shared<Slot>(sink);
  bool any = false;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    TopicEndpoints& t = topics_[static_cast<size_t>(topic.id())];
    t.readers.push_back(slot);
    for (const MemoryWriter* w : t.writers)
      if (w->last() != nullptr) any = sink.Push(w->last()) || any;
  }
  if (any) slot->Notify();
  return std::make_unique<MemoryReader>(*this, topic, std::move(slot));
}

bool MemoryBus::Write(Topic topic, MemoryWriter& writer, const void* sample) {
  boost::container::small_vector<std::shared_ptr<Slot>, 4> woken;  // no allocation for a few readers
  {
    std::lock_guard<std::mutex> lock(mutex_);
    TopicEndpoints& t = topics_[static_cast<size_t>(topic.id())];
    if (topic.info().direction == Direction::kLatched) writer.Keep(sample);
    for (const std::shared_ptr<Slot>& slot : t.readers)
      if (slot->sink.Push(sample)) woken.push_back(slot);
  }
  const Delivering delivering;
  for (const std::shared_ptr<Slot>& slot : woken) slot->Notify();
  return true;
}

void MemoryBus::Close(Topic topic, MemoryWriter& writer) {
  std::lock_guard<std::mutex> lock(mutex_);
  auto& writers = topics_[static_cast<size_t>(topic.id())].writers;
  writers.erase(std::remove(writers.begin(), writers.end(), &writer), writers.end());
}

void MemoryBus::Close(Topic topic, const std::shared_ptr<Slot>& slot) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    auto& readers = topics_[static_cast<size_t>(topic.id())].readers;
    readers.erase(std::remove(readers.begin(), readers.end(), slot), readers.end());
  }
  slot->Close();
}

int MemoryBus::Count(Topic topic, Endpoint endpoint) const {
  std::lock_guard<std::mutex> lock(mutex_);
  const TopicEndpoints& t = topics_[static_cast<size_t>(topic.id())];
  return static_cast<int>(endpoint == Endpoint::kWriter ? t.writers.size() : t.readers.size());
}

}  // namespace turf::dds
