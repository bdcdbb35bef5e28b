// turf-viewer --recording FILE: the viewer's page over a turf-record MCAP file instead of DDS, with a time slider.
// No DDS participant: the file is read once at start (recording.h: everything shown is kept in memory) and
// the page asks for the world at a simulation time over HTTP, so each page has its own slider, play/pause and
// speed (web/recording.js):
//   GET /recording/info        {"type":"recording", file, start, end (s of sim time), states, damage}
//   GET /recording/state?t=S   the live viewer's state message (viewer_json.h) for sim time S (s): the newest
//                              world state at or before S; 404 before the first
//   GET /recording/stats?t=S   the newest stats message at or before S; 404 before the first
// The WebSocket gives the page its hello and the field as live; every page message (teleport, pause, ...) is
// refused with kind "recording" (a recording cannot be changed).
// A file that is no MCAP or of a newer major version is refused (std::invalid_argument: exit 2); a damaged one is
// shown up to the damage, which is logged with its offset and told to the page in /recording/info.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "core/pinned.h"
#include "participants/viewer/viewer_node.h"

namespace turf {

class RecordingViewer : Pinned {
 public:
  // `options.recording` names the file; the DDS options are not used. Throws std::invalid_argument for a bad
  // option or a file that cannot be read at all, std::runtime_error if the port cannot be bound.
  explicit RecordingViewer(const ViewerOptions& options);
  ~RecordingViewer();

  // Serves until `stop()` answers true (checked every 50 ms).
  void Run(const std::function<bool()>& stop);
  uint16_t port() const;
  std::string Url() const;
  uint64_t requests() const;  // /recording/ requests answered

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace turf
