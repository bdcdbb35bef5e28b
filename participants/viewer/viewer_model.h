// What turf-viewer knows and shows, apart from DDS and sockets: the newest
// world state, clock, field, camera frames and sensor statistics in (or, for
// a legged scene, its scene info, every robot's newest body poses and the
// ball's world state); the JSON
// the page reads out (viewer_json.h); page messages in, as validated
// SimControl requests out (page_request.h). Single-threaded: its owner
// serialises the calls.
//
// DDS samples are untrusted too: one with a non-finite number, an unknown enum,
// or more entries than a match can have is refused with a named error and
// changes nothing.
#pragma once

#include <turf/idl/Clock.h>
#include <turf/idl/Joints.h>
#include <turf/idl/SensorStats.h>
#include <turf/idl/SimControl.h>
#include <turf/idl/SslVision.h>
#include <turf/idl/WorldState.h>

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>

#include "core/errors.h"
#include "participants/viewer/page_request.h"

namespace turf::viewer {

inline constexpr size_t kMaxRobots = 64;                // per world state or camera frame
inline constexpr size_t kMaxCameras = 32;               // distinct camera ids kept
inline constexpr size_t kMaxStreams = 64;               // per SensorStats
inline constexpr int64_t kMaxFrameAgeNs = 250'000'000;  // camera frames shown with a state
inline constexpr size_t kMaxLeggedRobots = 64;          // per legged scene, and robots with poses kept
inline constexpr size_t kMaxBodies = 256;               // geoms or links per legged robot
inline constexpr size_t kMaxNameLength = 128;           // robot, body and scene names

// turf's one taxonomy (core/errors.h): kNotFinite, kUnknownEnum, kTooMany, kBadSize, kDuplicate.
using SampleError = turf::Error;
inline const char* SampleErrorName(SampleError error) { return turf::ErrorName(error); }

class ViewerModel {
 public:
  // `client`: the name our control requests carry, to pick out our replies.
  ViewerModel(std::string client, std::string prefix);

  SampleError OnWorldState(const idl::WorldState& state);
  SampleError OnClock(const idl::Clock& clock);
  SampleError OnField(const idl::SslField& field);
  SampleError OnCamera(const idl::CameraFrame& frame);
  SampleError OnStats(const idl::SensorStats& stats);
  // A legged scene replaces the SSL field and the other way round: the page
  // draws the newest (turf-sim runs one kind of scene at a time).
  SampleError OnLeggedScene(const idl::LeggedSceneInfo& scene);
  SampleError OnLinks(const idl::LinkState& links);

  // A page message as a request ready to write, client set (the control
  // client numbers it), or the error; a refusal is counted in refused_pages().
  PageRequest OnPageMessage(std::string_view text);
  void CountRefusedPage() { ++refused_pages_; }  // refused before parsing (size, binary)
  // Whether turf-sim's control reader is matched (shown to the page).
  void SetControlMatched(bool matched) { control_matched_ = matched; }
  // turf-sim left at this Unix time (ms); 0: it is there (shown to the page, which marks what it shows as stale).
  void SetSimGoneSince(int64_t unix_ms) { sim_gone_since_unix_ms_ = unix_ms; }

  // A world state or, in a legged scene, a robot's poses has arrived.
  bool has_state() const { return state_.has_value() || (legged_ && !links_.empty()); }
  bool has_field() const { return field_.has_value(); }
  bool is_legged() const { return legged_.has_value(); }
  const std::optional<idl::SslField>& field() const { return field_; }
  const std::optional<idl::LeggedSceneInfo>& legged() const { return legged_; }
  uint64_t refused_pages() const { return refused_pages_; }

  std::string Hello() const;
  std::string Field() const;  // the SSL field or the legged scene; empty before either is known
  std::string State() const;  // empty before the first world state
  std::string Stats() const;  // empty before the first statistics

 private:
  std::string client_;
  std::string prefix_;
  uint64_t refused_pages_ = 0;
  bool control_matched_ = false;
  int64_t sim_gone_since_unix_ms_ = 0;
  std::optional<idl::WorldState> state_;
  std::optional<idl::Clock> clock_;
  std::optional<idl::SslField> field_;
  std::optional<idl::SensorStats> stats_;
  std::map<uint32_t, idl::CameraFrame> frames_;  // newest per camera
  std::optional<idl::LeggedSceneInfo> legged_;
  std::map<std::string, idl::LinkState> links_;  // newest per robot
};

}  // namespace turf::viewer
