#include "participants/recorder/recorder.h"

#include <fastdds/rtps/common/SerializedPayload.h>
#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <turf/idl/ClockPubSubTypes.h>
#include <turf/idl/JointsPubSubTypes.h>
#include <turf/idl/SensorStatsPubSubTypes.h>
#include <turf/idl/SimControlPubSubTypes.h>
#include <turf/idl/SimRecordPubSubTypes.h>
#include <turf/idl/SslRobotPubSubTypes.h>
#include <turf/idl/SslVisionPubSubTypes.h>
#include <turf/idl/WorldStatePubSubTypes.h>

#include <algorithm>
#include <stdexcept>
#include <string_view>
#include <tuple>
#include <type_traits>

#include "codecs/mcap/writer.h"
#include "dds/participant.h"
#include "participants/common/mcap_file.h"
#include "participants/common/wakeup.h"
#include "participants/recorder/idl_schema.h"
#include "participants/recorder/sim_time.h"

namespace turf {
namespace {

using record::SimTimeOf;

uint64_t UnixNowNs() {
  return static_cast<uint64_t>(
      std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch())
          .count());
}

bool Wanted(const RecorderOptions& o, dds::Topic topic) {
  return o.topics.empty() || std::find(o.topics.begin(), o.topics.end(), topic.info().suffix) != o.topics.end();
}

// One topic: its reader, its channel, and the CDR serializer of its type.
class Tap {
 public:
  virtual ~Tap() = default;
  // Writes what the reader holds; adds to `totals`.
  virtual void Drain(mcap::Writer& writer, uint64_t now_ns, RecorderTotals& totals) = 0;
  virtual uint64_t Overflowed() const = 0;
};

template <class PubSub>
class TypedTap final : public Tap {
 public:
  TypedTap(dds::Bus& bus, const dds::TopicDef<PubSub>& topic, uint16_t channel, Wakeup& wakeup)
      : reader_(bus.MakeReader(topic, [&wakeup] { wakeup.Notify(); })), channel_(channel) {}

  void Drain(mcap::Writer& writer, uint64_t now_ns, RecorderTotals& totals) override {
    if (!reader_->Take(&samples_)) return;
    for (auto& sample : samples_) {
      eprosima::fastrtps::rtps::SerializedPayload_t payload(pubsub_.getSerializedSizeProvider(&sample)());
      if (!pubsub_.serialize(&sample, &payload)) {
        ++totals.dropped;
        continue;
      }
      const uint64_t sim_time = SimTimeOf(sample);
      writer.Write(channel_, sequence_++, now_ns, sim_time,
                   std::string_view(reinterpret_cast<const char*>(payload.data), payload.length));
      ++totals.samples;
      totals.sim_time_ns = std::max(totals.sim_time_ns, static_cast<int64_t>(sim_time));
    }
  }
  uint64_t Overflowed() const override { return reader_->Overflowed(); }

 private:
  std::unique_ptr<dds::Reader<PubSub>> reader_;
  uint16_t channel_;
  PubSub pubsub_;
  std::vector<dds::SampleOf<PubSub>> samples_;
  uint32_t sequence_ = 0;
};

mcap::WriterOptions WriterOptionsOf(const RecorderOptions& o) {
  mcap::WriterOptions w;
  w.library = "turf-record";
  w.compression = o.compression;
  w.chunk_size = o.chunk_size;
  return w;
}

}  // namespace

std::string CheckTopicNames(const std::vector<std::string>& names) {
  for (const std::string& name : names) {
    bool known = false;
    std::string all;
    for (const dds::TopicInfo& t : dds::kTopics) {
      known = known || name == t.suffix;
      all += std::string(all.empty() ? "" : ", ") + t.suffix;
    }
    if (!known) return "--topics: no topic '" + name + "' (known: " + all + ")";
  }
  return {};
}

class Recorder::Impl {
 public:
  Impl(const RecorderOptions& o, dds::Bus* bus)
      : options_(o),
        sink_(o.file),
        writer_(&sink_, WriterOptionsOf(o)),
        own_bus_(bus != nullptr ? nullptr : std::make_unique<dds::Participant>(DdsOptions(o))),
        participant_(bus != nullptr ? *bus : *own_bus_) {
    if (!sink_.ok()) throw std::invalid_argument("cannot write " + o.file + ": " + sink_.error());
    std::apply([this](const auto&... topic) { (Add(topic), ...); }, dds::kTypedTopics);
    sink_.Flush();
    spdlog::info(
        "recording {} topics of DDS domain {}, prefix '{}', into {} ({} chunks of up to {} KiB, closed at "
        "least every {} s)",
        taps_.size(), o.domain, o.prefix, o.file,
        o.compression == mcap::Compression::kNone ? "uncompressed" : mcap::CompressionField(o.compression),
        o.chunk_size / 1024, o.chunk_interval_s);
    participant_.LogTopics();
  }

  void Run(const std::function<bool()>& stop) {
    using Clock = std::chrono::steady_clock;
    const auto chunk_every = std::chrono::duration<double>(options_.chunk_interval_s);
    const auto progress_every = std::chrono::duration<double>(options_.progress_interval_s);
    auto last_chunk = Clock::now();
    auto last_progress = Clock::now();
    while (!stop()) {
      wakeup_.WaitFor(std::chrono::milliseconds(100));
      DrainAll();
      if (Clock::now() - last_chunk >= chunk_every) {
        writer_.CloseChunk();
        last_chunk = Clock::now();
      }
      sink_.Flush();  // every closed chunk reaches the file at once
      if (!sink_.ok()) throw std::runtime_error("writing " + options_.file + ": " + sink_.error());
      if (Clock::now() - last_progress >= progress_every) {
        Progress("recording");
        last_progress = Clock::now();
      }
    }
    DrainAll();
    writer_.Close();
    sink_.Flush();
    Progress("closed");
  }

  RecorderTotals totals() const {
    RecorderTotals t = totals_;
    for (const auto& tap : taps_) t.dropped += tap->Overflowed();
    t.file_bytes = writer_.bytes_written();
    return t;
  }

 private:
  template <class PubSub>
  void Add(const dds::TopicDef<PubSub>& topic) {
    if (!Wanted(options_, topic)) return;
    const dds::TopicInfo& info = topic.info();
    const uint16_t schema = writer_.AddSchema(info.dds_type, "omgidl", record::IdlSchema(info.type));
    const uint16_t channel = writer_.AddChannel(schema, participant_.TopicName(topic), "cdr",
                                                {{"dds_type", info.dds_type},
                                                 {"qos_profile", info.profile},
                                                 {"direction", dds::DirectionName(info.direction)}});
    taps_.push_back(std::make_unique<TypedTap<PubSub>>(participant_, topic, channel, wakeup_));
  }

  void DrainAll() {
    const uint64_t now = UnixNowNs();
    for (auto& tap : taps_) tap->Drain(writer_, now, totals_);
  }

  void Progress(const char* what) const {
    const RecorderTotals t = totals();
    spdlog::info("{}: {} samples, {:.2f} MB in {}, sim time {:.3f} s, {} dropped", what, t.samples,
                 static_cast<double>(t.file_bytes) / 1e6, options_.file, static_cast<double>(t.sim_time_ns) * 1e-9,
                 t.dropped);
  }

  const RecorderOptions options_;
  McapFileSink sink_;
  mcap::Writer writer_;
  Wakeup wakeup_;
  std::unique_ptr<dds::Bus> own_bus_;  // after the writer and the wakeup its readers use; before the taps
  dds::Bus& participant_;
  std::vector<std::unique_ptr<Tap>> taps_;
  RecorderTotals totals_;
};

Recorder::Recorder(const RecorderOptions& options) : impl_(std::make_unique<Impl>(options, nullptr)) {}
Recorder::Recorder(const RecorderOptions& options, dds::Bus& bus) : impl_(std::make_unique<Impl>(options, &bus)) {}
Recorder::~Recorder() = default;
void Recorder::Run(const std::function<bool()>& stop) { impl_->Run(stop); }
RecorderTotals Recorder::totals() const { return impl_->totals(); }

}  // namespace turf
