#include "participants/viewer/recording.h"

#include <fastdds/rtps/common/SerializedPayload.h>
#include <turf/idl/ClockPubSubTypes.h>
#include <turf/idl/JointsPubSubTypes.h>
#include <turf/idl/SensorStatsPubSubTypes.h>
#include <turf/idl/SslVisionPubSubTypes.h>
#include <turf/idl/WorldStatePubSubTypes.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <list>
#include <map>
#include <mutex>

#include "dds/topics.h"
#include "participants/viewer/viewer_model.h"

namespace turf::viewer {

namespace {

constexpr size_t kMaxSample = 64u << 20;  // no turf sample comes near this
constexpr double kMaxQuerySeconds = 86400.0 * 365;

// The recorded CDR bytes (encapsulation header first) as a sample of `PubSub`'s type; false if they are none.
template <class PubSub, class Sample>
bool Decode(std::string_view cdr, Sample* out) {
  if (cdr.empty() || cdr.size() > kMaxSample) return false;
  eprosima::fastrtps::rtps::SerializedPayload_t payload(static_cast<uint32_t>(cdr.size()));
  std::memcpy(payload.data, cdr.data(), cdr.size());
  payload.length = static_cast<uint32_t>(cdr.size());
  PubSub type;
  try {
    return type.deserialize(&payload, out);
  } catch (...) {  // Fast CDR throws on bytes that end early
    return false;
  }
}

// Feeds one recorded sample to the model; false if it is no sample of its type or the model refused it.
bool Feed(ViewerModel& model, Recording::Kind kind, std::string_view cdr) {
  switch (kind) {
    case Recording::kState: {
      idl::WorldState s;
      return Decode<idl::WorldStatePubSubType>(cdr, &s) && model.OnWorldState(s) == SampleError::kOk;
    }
    case Recording::kClock: {
      idl::Clock s;
      return Decode<idl::ClockPubSubType>(cdr, &s) && model.OnClock(s) == SampleError::kOk;
    }
    case Recording::kField: {
      idl::SslField s;
      return Decode<idl::SslFieldPubSubType>(cdr, &s) && model.OnField(s) == SampleError::kOk;
    }
    case Recording::kCamera: {
      idl::CameraFrame s;
      return Decode<idl::CameraFramePubSubType>(cdr, &s) && model.OnCamera(s) == SampleError::kOk;
    }
    case Recording::kStats: {
      idl::SensorStats s;
      return Decode<idl::SensorStatsPubSubType>(cdr, &s) && model.OnStats(s) == SampleError::kOk;
    }
    case Recording::kLegged: {
      idl::LeggedSceneInfo s;
      return Decode<idl::LeggedSceneInfoPubSubType>(cdr, &s) && model.OnLeggedScene(s) == SampleError::kOk;
    }
    case Recording::kLinks: {
      idl::LinkState s;
      return Decode<idl::LinkStatePubSubType>(cdr, &s) && model.OnLinks(s) == SampleError::kOk;
    }
    default:
      return false;
  }
}

// The table topic of each kind, for matching channels.
const dds::TopicInfo& TopicOf(Recording::Kind kind) {
  static const dds::Topic topics[Recording::kKinds] = {
      dds::Topic::kWorldState, dds::Topic::kClock,       dds::Topic::kSslField,  dds::Topic::kSslCamera,
      dds::Topic::kStats,      dds::Topic::kLeggedScene, dds::Topic::kRobotLinks};
  return topics[kind].info();
}

// The kind a channel carries (kKinds: none the viewer shows), as turf-replay matches channels.
Recording::Kind KindOf(const mcap::FileInfo& info, const mcap::Channel& c) {
  const auto schema = info.schemas.find(c.schema_id);
  if (schema == info.schemas.end() || c.message_encoding != "cdr") return Recording::kKinds;
  for (int k = 0; k < Recording::kKinds; ++k) {
    const dds::TopicInfo& t = TopicOf(static_cast<Recording::Kind>(k));
    const std::string suffix = std::string("/") + t.suffix;
    const bool named =
        c.topic.size() > suffix.size() && c.topic.compare(c.topic.size() - suffix.size(), suffix.size(), suffix) == 0;
    if (named && schema->second.name == t.dds_type) return static_cast<Recording::Kind>(k);
  }
  return Recording::kKinds;
}

// To the microsecond, as the state messages' times (json_util.h).
double Seconds(int64_t ns) { return std::round(static_cast<double>(ns) * 1e-3) * 1e-6; }

int64_t ToNs(uint64_t publish_time) {
  return static_cast<int64_t>(std::min<uint64_t>(publish_time, static_cast<uint64_t>(INT64_MAX)));
}

}  // namespace

// The recently read chunks' messages, decompressed, least recently used first out; at most `budget` bytes (and
// always the chunk just read).
class Recording::ChunkCache {
 public:
  using Messages = std::shared_ptr<const std::vector<std::string>>;
  ChunkCache(const mcap::ByteSource& source, mcap::FileInfo channels, size_t budget)
      : source_(source), channels_(std::move(channels)), budget_(budget) {}

  // The messages of the chunk at `offset`, in file order; null if it cannot be read.
  Messages Get(uint64_t offset) {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto hit = chunks_.find(offset);
    if (hit != chunks_.end()) {
      lru_.splice(lru_.end(), lru_, hit->second.second);
      return hit->second.first;
    }
    auto messages = std::make_shared<std::vector<std::string>>();
    mcap::FileInfo info = channels_;
    size_t bytes = 0;
    const mcap::Damage d =
        mcap::ReadChunkAt(source_, {}, offset, &info, [&](const mcap::Channel&, const mcap::Message& m) {
          messages->emplace_back(m.data);
          bytes += m.data.size();
        });
    ++reads_;
    if (!d.ok()) {
      ++failures_;
      return nullptr;
    }
    lru_.push_back(offset);
    chunks_[offset] = {messages, std::prev(lru_.end())};
    sizes_[offset] = bytes;
    bytes_ += bytes;
    while (bytes_ > budget_ && lru_.size() > 1) Evict();
    return messages;
  }
  size_t bytes() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return bytes_;
  }
  uint64_t reads() const { return reads_; }
  uint64_t failures() const { return failures_; }

 private:
  void Evict() {
    const uint64_t oldest = lru_.front();
    lru_.pop_front();
    chunks_.erase(oldest);
    bytes_ -= sizes_[oldest];
    sizes_.erase(oldest);
  }

  const mcap::ByteSource& source_;
  const mcap::FileInfo channels_;
  const size_t budget_;
  mutable std::mutex mutex_;
  std::list<uint64_t> lru_;
  std::map<uint64_t, std::pair<Messages, std::list<uint64_t>::iterator>> chunks_;
  std::map<uint64_t, size_t> sizes_;
  size_t bytes_ = 0;
  std::atomic<uint64_t> reads_{0};
  std::atomic<uint64_t> failures_{0};
};

Recording::Recording(std::unique_ptr<const mcap::ByteSource> source, size_t cache_bytes) : source_(std::move(source)) {
  mcap::FileInfo info;
  std::map<uint16_t, Kind> kinds;
  uint64_t order = 0;
  uint64_t chunk = 0;
  uint32_t index = 0;  // of the message in its chunk
  damage_ = mcap::Scan(*source_, {}, &info, [&](const mcap::Channel& c, const mcap::Message& m) {
    if (m.chunk_offset != chunk) index = 0;
    chunk = m.chunk_offset;
    const uint32_t at = index++;
    auto it = kinds.find(c.id);
    if (it == kinds.end()) it = kinds.emplace(c.id, KindOf(info, c)).first;
    if (it->second == kKinds) {
      ++skipped_;
      return;
    }
    Keep(it->second, m, order++, at);
  });
  for (auto& samples : samples_)
    std::stable_sort(samples.begin(), samples.end(), [](const Sample& a, const Sample& b) { return a.t_ns < b.t_ns; });
  mcap::FileInfo channels;
  channels.schemas = info.schemas;
  channels.channels = info.channels;
  cache_ = std::make_unique<ChunkCache>(*source_, std::move(channels), cache_bytes);
}

Recording::~Recording() = default;

void Recording::Keep(Kind kind, const mcap::Message& m, uint64_t order, uint32_t index) {
  // Only samples the model takes are kept, so what is shown at t never falls back past a bad one silently.
  ViewerModel probe("", "");
  if (!Feed(probe, kind, m.data)) {
    ++skipped_;
    return;
  }
  Sample sample{ToNs(m.publish_time), order, m.chunk_offset, index, {}};
  if (m.chunk_offset == 0) sample.cdr = std::string(m.data);
  samples_[kind].push_back(std::move(sample));
}

bool Recording::FeedSample(ViewerModel& model, Kind kind, const Sample& sample) const {
  if (sample.chunk_offset == 0) return Feed(model, kind, sample.cdr);
  const ChunkCache::Messages chunk = cache_->Get(sample.chunk_offset);
  return chunk && sample.index < chunk->size() && Feed(model, kind, (*chunk)[sample.index]);
}

size_t Recording::cached_bytes() const { return cache_->bytes(); }
uint64_t Recording::chunk_reads() const { return cache_->reads(); }
uint64_t Recording::reread_failures() const { return cache_->failures(); }

bool Recording::refused() const {
  return damage_.error == mcap::ReadError::kBadMagic || damage_.error == mcap::ReadError::kNewerVersion;
}

std::optional<std::pair<int64_t, int64_t>> Recording::Span() const {
  const auto& s = samples_[kState].empty() ? samples_[kLinks] : samples_[kState];
  if (s.empty()) return std::nullopt;
  return std::make_pair(s.front().t_ns, s.back().t_ns);
}

const Recording::Sample* Recording::NewestAtOrBefore(Kind kind, int64_t t_ns) const {
  const auto& s = samples_[kind];
  const auto after = std::upper_bound(s.begin(), s.end(), t_ns, [](int64_t t, const Sample& x) { return t < x.t_ns; });
  return after == s.begin() ? nullptr : &*std::prev(after);
}

// The scene that came last in the file, SSL field or legged scene (latched topics have no simulation time).
void Recording::FeedScene(ViewerModel& model) const {
  const Sample* field = samples_[kField].empty() ? nullptr : &samples_[kField].back();
  const Sample* legged = samples_[kLegged].empty() ? nullptr : &samples_[kLegged].back();
  if (field && (!legged || field->order > legged->order)) {
    FeedSample(model, kField, *field);
  } else if (legged) {
    FeedSample(model, kLegged, *legged);
  }
}

std::string Recording::FieldJson() const {
  ViewerModel model("", "");
  FeedScene(model);
  return model.Field();
}

std::string Recording::StateJsonAt(int64_t t_ns) const {
  ViewerModel model("", "");
  FeedScene(model);
  if (const Sample* s = NewestAtOrBefore(kState, t_ns)) FeedSample(model, kState, *s);
  if (const Sample* s = NewestAtOrBefore(kClock, t_ns)) FeedSample(model, kClock, *s);
  // The samples of the windows before t, oldest first, so the newest of each camera and robot wins.
  auto window = [&](Kind kind, int64_t span) {
    const auto& s = samples_[kind];
    auto it = std::lower_bound(s.begin(), s.end(), t_ns - span, [](const Sample& x, int64_t t) { return x.t_ns < t; });
    for (; it != s.end() && it->t_ns <= t_ns; ++it) FeedSample(model, kind, *it);
  };
  window(kCamera, kMaxFrameAgeNs);
  if (model.is_legged()) window(kLinks, kLinkWindowNs);
  return model.State();
}

std::string Recording::StatsJsonAt(int64_t t_ns) const {
  ViewerModel model("", "");
  if (const Sample* s = NewestAtOrBefore(kStats, t_ns)) FeedSample(model, kStats, *s);
  return model.Stats();
}

std::string Recording::InfoJson(const std::string& file) const {
  nlohmann::json j = {{"type", "recording"},
                      {"file", file},
                      {"states", (samples_[kState].empty() ? samples_[kLinks] : samples_[kState]).size()},
                      {"damage", damage_.ok() ? std::string() : damage_.Describe()}};
  if (const auto span = Span()) {
    j["start"] = Seconds(span->first);
    j["end"] = Seconds(span->second);
  }
  return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::optional<int64_t> QueryTime(std::string_view target) {
  const size_t q = target.find('?');
  if (q == std::string_view::npos) return std::nullopt;
  std::string_view query = target.substr(q + 1);
  while (!query.empty()) {
    const size_t amp = query.find('&');
    const std::string_view pair = query.substr(0, amp);
    query = amp == std::string_view::npos ? std::string_view() : query.substr(amp + 1);
    if (pair.size() < 3 || pair.substr(0, 2) != "t=" || pair.size() > 40) continue;
    const std::string value(pair.substr(2));
    char* end = nullptr;
    const double seconds = std::strtod(value.c_str(), &end);
    if (end != value.c_str() + value.size() || !std::isfinite(seconds) || std::fabs(seconds) > kMaxQuerySeconds)
      return std::nullopt;
    return static_cast<int64_t>(std::llround(seconds * 1e9));
  }
  return std::nullopt;
}

}  // namespace turf::viewer
