// A turf-record MCAP file as the viewer shows it (turf-viewer --recording): the samples of the topics the live
// viewer reads (world_state, clock, ssl/field, ssl/camera, stats, legged/scene, robots/links), indexed by their
// simulation time (MCAP publish_time), sorted by it per topic; each sample's bytes are read again from its chunk
// when shown.
// What the page shows at slider time t goes through the live viewer's own code: the samples are deserialized
// with the generated PubSubTypes and fed to a fresh ViewerModel (viewer_model.h), whose JSON is the live one:
//   state  the newest world_state at or before t, with the newest clock at or before t, the camera frames of
//          the kMaxFrameAgeNs before it; in a legged scene every robot's newest robots/links sample at or
//          before t (within kLinkWindowNs)
//   stats  the newest stats sample at or before t
//   field  the newest SSL field or legged scene in the file (latched topics carry no simulation time)
// Channels are matched as turf-replay does: the topic name ends with "/<table topic>" and the schema names its
// DDS type. A sample that does not deserialize or that the model refuses is skipped and counted.
// Memory: an index entry per shown sample (about 40 bytes; a 2x11 SSL match has about 12,000 per simulated minute)
// and a cache of the most recently read chunks, decompressed, of at most kChunkCacheBytes (a chunk larger than
// that is held alone); the bytes of samples outside chunks (a file written without chunks) are kept. Once loaded
// the index is read-only: the const methods may be called from any thread (the cache has its own lock).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
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
  static constexpr size_t kChunkCacheBytes = 64u << 20;
  struct Sample {
    int64_t t_ns = 0;           // simulation time (MCAP publish_time)
    uint64_t order = 0;         // position in the file, for the latched topics
    uint64_t chunk_offset = 0;  // the chunk it is in (0: none, then `cdr` holds it)
    uint32_t index = 0;         // its position among the chunk's messages
    std::string cdr;            // outside chunks only: encapsulation header first
  };

  // Indexes every message of `source` up to its end or its damage (damage() says where); keeps `source` to read
  // the samples it shows.
  explicit Recording(std::unique_ptr<const mcap::ByteSource> source, size_t cache_bytes = kChunkCacheBytes);
  ~Recording();

  const mcap::Damage& damage() const { return damage_; }
  // kBadMagic or kNewerVersion: nothing could be read at all.
  bool refused() const;
  size_t count(Kind kind) const { return samples_[kind].size(); }
  uint64_t skipped() const { return skipped_; }  // messages of other topics or that were no sample of their type
  size_t cached_bytes() const;                   // the chunk cache's decompressed bytes now
  uint64_t chunk_reads() const;                  // chunks read (and decompressed) again to show a sample
  uint64_t reread_failures() const;              // chunks that could not be read again (the file changed)
  // The span of simulation time the world can be shown for (world states, or robots/links in a legged scene).
  std::optional<std::pair<int64_t, int64_t>> Span() const;

  // The JSON messages of viewer_json.h; empty when there is nothing to show at that time.
  std::string FieldJson() const;
  std::string StateJsonAt(int64_t t_ns) const;
  std::string StatsJsonAt(int64_t t_ns) const;
  // {"type":"recording", start, end (s, to the microsecond), states (in the span), damage ("" or where it is)}.
  std::string InfoJson(const std::string& file) const;

 private:
  class ChunkCache;
  void Keep(Kind kind, const mcap::Message& message, uint64_t order, uint32_t index);
  const Sample* NewestAtOrBefore(Kind kind, int64_t t_ns) const;
  void FeedScene(ViewerModel& model) const;
  // Feeds a sample's bytes (from its chunk) to the model; false if they could not be read or were refused.
  bool FeedSample(ViewerModel& model, Kind kind, const Sample& sample) const;

  std::unique_ptr<const mcap::ByteSource> source_;
  std::array<std::vector<Sample>, kKinds> samples_;
  mcap::Damage damage_;
  uint64_t skipped_ = 0;
  std::unique_ptr<ChunkCache> cache_;
};

// "t=12.5" (seconds, finite, within a day) in a request target's query, as ns; nullopt if absent or malformed.
std::optional<int64_t> QueryTime(std::string_view target);

}  // namespace turf::viewer
