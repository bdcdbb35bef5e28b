#include "participants/viewer/recording.h"

#include <fastdds/rtps/common/SerializedPayload.h>
#include <turf/idl/ClockPubSubTypes.h>
#include <turf/idl/JointsPubSubTypes.h>
#include <turf/idl/SensorStatsPubSubTypes.h>
#include <turf/idl/SslVisionPubSubTypes.h>
#include <turf/idl/WorldStatePubSubTypes.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <map>

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

Recording::Recording(const mcap::ByteSource& source) {
  mcap::FileInfo info;
  std::map<uint16_t, Kind> kinds;
  uint64_t order = 0;
  damage_ = mcap::Scan(source, {}, &info, [&](const mcap::Channel& c, const mcap::Message& m) {
    auto it = kinds.find(c.id);
    if (it == kinds.end()) it = kinds.emplace(c.id, KindOf(info, c)).first;
    if (it->second == kKinds) {
      ++skipped_;
      return;
    }
    Keep(it->second, m, order++);
  });
  for (auto& samples : samples_)
    std::stable_sort(samples.begin(), samples.end(), [](const Sample& a, const Sample& b) { return a.t_ns < b.t_ns; });
}

void Recording::Keep(Kind kind, const mcap::Message& m, uint64_t order) {
  // Only samples the model takes are kept, so what is shown at t never falls back past a bad one silently.
  ViewerModel probe("", "");
  if (!Feed(probe, kind, m.data)) {
    ++skipped_;
    return;
  }
  samples_[kind].push_back({ToNs(m.publish_time), order, std::string(m.data)});
}

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
    Feed(model, kField, field->cdr);
  } else if (legged) {
    Feed(model, kLegged, legged->cdr);
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
  if (const Sample* s = NewestAtOrBefore(kState, t_ns)) Feed(model, kState, s->cdr);
  if (const Sample* s = NewestAtOrBefore(kClock, t_ns)) Feed(model, kClock, s->cdr);
  // The samples of the windows before t, oldest first, so the newest of each camera and robot wins.
  auto window = [&](Kind kind, int64_t span) {
    const auto& s = samples_[kind];
    auto it = std::lower_bound(s.begin(), s.end(), t_ns - span, [](const Sample& x, int64_t t) { return x.t_ns < t; });
    for (; it != s.end() && it->t_ns <= t_ns; ++it) Feed(model, kind, it->cdr);
  };
  window(kCamera, kMaxFrameAgeNs);
  if (model.is_legged()) window(kLinks, kLinkWindowNs);
  return model.State();
}

std::string Recording::StatsJsonAt(int64_t t_ns) const {
  ViewerModel model("", "");
  if (const Sample* s = NewestAtOrBefore(kStats, t_ns)) Feed(model, kStats, s->cdr);
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
