// A DDS participant of turf: one DomainParticipant with one publisher and one
// subscriber, QoS from the profiles file, and typed writers and readers for
// the topics in topics.h: a topic constant carries its type, so a writer or
// reader of another type does not compile. RAII throughout: a Writer or Reader deletes its
// entity; the Participant must outlive them (declare it first).
//
// Fast DDS headers are heavy (~10 s a file): include this only in participant
// code, never in core or bridge codecs.
#pragma once

#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/DataReaderListener.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/topic/Topic.hpp>
#include <fastdds/dds/topic/TypeSupport.hpp>

#include <atomic>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "dds/topics.h"

namespace turf::dds {

namespace fdds = eprosima::fastdds::dds;
using ReturnCode = eprosima::fastrtps::types::ReturnCode_t;

struct ParticipantOptions {
  int domain = 0;
  std::string name = "turf";
  std::string prefix = "turf";  // topic names: <prefix>/<suffix>
  std::string qos_file;         // Fast DDS XML profiles; empty: built-in defaults
};

// The QoS profiles file shipped with turf, found next to the executable's
// install or source tree; empty if none is found.
std::string DefaultQosFile();

template <class PubSub>
class Writer {
 public:
  using Sample = typename PubSub::type;
  Writer(fdds::Publisher* publisher, fdds::DataWriter* writer) : publisher_(publisher), writer_(writer) {}
  ~Writer() { publisher_->delete_datawriter(writer_); }
  Writer(const Writer&) = delete;
  Writer& operator=(const Writer&) = delete;
  bool Write(const Sample& sample) { return writer_->write(const_cast<Sample*>(&sample)); }
  // With an explicit source timestamp (ns since the Unix epoch, wall clock).
  bool Write(const Sample& sample, int64_t source_ns) {
    eprosima::fastrtps::Time_t t(static_cast<int32_t>(source_ns / 1000000000),
                                 static_cast<uint32_t>(source_ns % 1000000000));
    return writer_->write_w_timestamp(const_cast<Sample*>(&sample), fdds::HANDLE_NIL, t) == ReturnCode::RETCODE_OK;
  }
  // Number of readers currently matched.
  int Matched() const {
    fdds::PublicationMatchedStatus status;
    writer_->get_publication_matched_status(status);
    return status.current_count;
  }

 private:
  fdds::Publisher* publisher_;
  fdds::DataWriter* writer_;
};

// Takes samples as they arrive (on Fast DDS's thread) into a bounded queue that
// the owner drains with Take(), and calls `on_data` so the owner can wake up.
template <class PubSub>
class Reader {
 public:
  using Sample = typename PubSub::type;
  static constexpr size_t kMaxQueued = 4096;

  Reader() = default;
  ~Reader() {
    if (reader_ != nullptr) subscriber_->delete_datareader(reader_);
  }
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
  // Instances whose Deadline QoS period passed without a sample, so far.
  int DeadlinesMissed() const {
    fdds::RequestedDeadlineMissedStatus status;
    reader_->get_requested_deadline_missed_status(status);
    return status.total_count;
  }
  // Samples dropped because the owner did not drain the queue in time.
  uint64_t Overflowed() const { return overflowed_.load(); }
  int Matched() const {
    fdds::SubscriptionMatchedStatus status;
    reader_->get_subscription_matched_status(status);
    return status.current_count;
  }
  fdds::DataReaderListener* listener() { return &listener_; }
  void Attach(fdds::Subscriber* subscriber, fdds::DataReader* reader, std::function<void()> on_data) {
    subscriber_ = subscriber;
    reader_ = reader;
    on_data_ = std::move(on_data);
  }

 private:
  class Listener : public fdds::DataReaderListener {
   public:
    explicit Listener(Reader* owner) : owner_(owner) {}
    void on_data_available(fdds::DataReader* reader) override { owner_->Drain(reader); }

   private:
    Reader* owner_;
  };

  void Drain(fdds::DataReader* reader) {
    Sample sample;
    fdds::SampleInfo info;
    bool any = false;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      while (reader->take_next_sample(&sample, &info) == ReturnCode::RETCODE_OK) {
        if (!info.valid_data) continue;
        if (queue_.size() >= kMaxQueued) {
          overflowed_.fetch_add(1);
          continue;
        }
        queue_.push_back(sample);
        any = true;
      }
      if (any) pending_.store(true, std::memory_order_release);
    }
    if (any && on_data_) on_data_();
  }

  Listener listener_{this};
  fdds::Subscriber* subscriber_ = nullptr;
  fdds::DataReader* reader_ = nullptr;
  std::function<void()> on_data_;
  std::mutex mutex_;
  std::vector<Sample> queue_;
  std::atomic<bool> pending_{false};
  std::atomic<uint64_t> overflowed_{0};
};

class Participant {
 public:
  // Throws std::runtime_error if the participant cannot be created.
  explicit Participant(const ParticipantOptions& options);
  ~Participant();
  Participant(const Participant&) = delete;
  Participant& operator=(const Participant&) = delete;

  const ParticipantOptions& options() const { return options_; }
  std::string TopicName(Topic topic) const { return dds::TopicName(options_.prefix, topic); }

  // MakeWriter<idl::ClockPubSubType>(dds::Topic::kClock), or MakeWriter(dds::Topic::kClock): the type
  // comes with the topic, and naming another one does not compile.
  template <class PubSub = void, class Carried>
  std::unique_ptr<Writer<Carried>> MakeWriter(const TopicDef<Carried>& topic) {
    static_assert(std::is_void_v<PubSub> || std::is_same_v<PubSub, Carried>,
                  "MakeWriter<T>(topic): T is not the topic's type (see dds/topics.h)");
    fdds::Topic* t = GetTopic(topic, fdds::TypeSupport(new Carried()));
    fdds::DataWriter* w = publisher_->create_datawriter(t, WriterQos(topic));
    if (w == nullptr) Fail("data writer", topic);
    Created(Endpoint::kWriter, topic);
    return std::make_unique<Writer<Carried>>(publisher_, w);
  }

  // MakeReader<idl::ClockPubSubType>(dds::Topic::kClock, on_data), or without the type; as MakeWriter.
  template <class PubSub = void, class Carried>
  std::unique_ptr<Reader<Carried>> MakeReader(const TopicDef<Carried>& topic, std::function<void()> on_data = {}) {
    static_assert(std::is_void_v<PubSub> || std::is_same_v<PubSub, Carried>,
                  "MakeReader<T>(topic): T is not the topic's type (see dds/topics.h)");
    fdds::Topic* t = GetTopic(topic, fdds::TypeSupport(new Carried()));
    auto reader = std::make_unique<Reader<Carried>>();
    fdds::DataReader* r =
        subscriber_->create_datareader(t, ReaderQos(topic), reader->listener(), fdds::StatusMask::data_available());
    if (r == nullptr) Fail("data reader", topic);
    reader->Attach(subscriber_, r, std::move(on_data));
    Created(Endpoint::kReader, topic);
    return reader;
  }

  // Every topic this participant has made a writer or reader for, once each, in creation order.
  std::vector<std::pair<Endpoint, Topic>> Endpoints() const;
  // One line per Endpoints() entry, with full name, DDS type and QoS profile (EndpointLine()).
  std::vector<std::string> TopicLines() const;
  // Logs TopicLines() at info: a participant's start-up list of its topics, from the table.
  void LogTopics() const;

 private:
  fdds::Topic* GetTopic(Topic topic, fdds::TypeSupport type);
  fdds::DataWriterQos WriterQos(Topic topic) const;
  fdds::DataReaderQos ReaderQos(Topic topic) const;
  [[noreturn]] void Fail(const char* what, Topic topic) const;
  // Records the endpoint and logs its line at debug: the default (info) output keeps the participant's own
  // start-up lines, or LogTopics(); --log-level debug adds each endpoint's type and QoS profile as it is made.
  void Created(Endpoint endpoint, Topic topic);

  ParticipantOptions options_;
  fdds::DomainParticipant* participant_ = nullptr;
  fdds::Publisher* publisher_ = nullptr;
  fdds::Subscriber* subscriber_ = nullptr;
  std::map<std::string, fdds::Topic*> topics_;
  mutable std::mutex endpoints_mutex_;
  std::vector<std::pair<Endpoint, Topic>> endpoints_;
};

}  // namespace turf::dds
