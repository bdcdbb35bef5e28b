// A turf-record MCAP file as the viewer shows it (turf-viewer --recording): the samples of the topics the live
// viewer reads (world_state, clock, ssl/field, ssl/camera, stats, legged/scene, robots/links), kept in memory as
// their recorded CDR bytes, each with its simulation time (MCAP publish_time), sorted by it per topic.
// What the page shows at slider time t goes through the live viewer's own code: the samples are deserialized
// with the generated PubSubTypes and fed to a fresh ViewerModel (viewer_model.h), whose JSON is the live one:
//   state  the newest world_state at or before t, with the newest clock at or before t, the camera frames of
//          the kMaxFrameAgeNs before it; in a legged scene every robot's newest robots/links sample at or
//          before t (within kLinkWindowNs)
//   stats  the newest stats sample at or before t
//   field  the newest SSL field or legged scene in the file (latched topics carry no simulation time)
// Channels are matched as turf-replay does: the topic name ends with "/<table topic>" and the schema names its
// DDS type. A sample that does not deserialize or that the model refuses is skipped and counted.
// Memory: every shown sample's bytes, uncompressed (about the recording's uncompressed size of these topics);
// not bounded. Once loaded it is read-only: the const methods may be called from any thread.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "codecs/mcap/damage.h"
#include "codecs/mcap/reader.h"

namespace turf::viewer {

class ViewerModel;

inline constexpr int64_t kLinkWindowNs = 200'000'000;  // robots/links older than this at t are not shown

class Recording {
 public:
  // The topics kept, in this order.
  enum Kind { kState, kClock, kField, kCamera, kStats, kLegged, kLinks, kKinds };
  struct Sample {
    int64_t t_ns = 0;    // simulation time (MCAP publish_time)
    uint64_t order = 0;  // position in the file, for the latched topics
    std::string cdr;     // encapsulation header first
  };

  // Reads every message of `source` up to its end or its damage (damage() says where).
  explicit Recording(const mcap::ByteSource& source);

  const mcap::Damage& damage() const { return damage_; }
  // kBadMagic or kNewerVersion: nothing could be read at all.
  bool refused() const;
  size_t count(Kind kind) const { return samples_[kind].size(); }
  uint64_t skipped() const { return skipped_; }  // messages of other topics or that were no sample of their type
  // The span of simulation time the world can be shown for (world states, or robots/links in a legged scene).
  std::optional<std::pair<int64_t, int64_t>> Span() const;

  // The JSON messages of viewer_json.h; empty when there is nothing to show at that time.
  std::string FieldJson() const;
  std::string StateJsonAt(int64_t t_ns) const;
  std::string StatsJsonAt(int64_t t_ns) const;
  // {"type":"recording", start, end (s, to the microsecond), states (in the span), damage ("" or where it is)}.
  std::string InfoJson(const std::string& file) const;

 private:
  void Keep(Kind kind, const mcap::Message& message, uint64_t order);
  const Sample* NewestAtOrBefore(Kind kind, int64_t t_ns) const;
  void FeedScene(ViewerModel& model) const;

  std::array<std::vector<Sample>, kKinds> samples_;
  mcap::Damage damage_;
  uint64_t skipped_ = 0;
};

// "t=12.5" (seconds, finite, within a day) in a request target's query, as ns; nullopt if absent or malformed.
std::optional<int64_t> QueryTime(std::string_view target);

}  // namespace turf::viewer
