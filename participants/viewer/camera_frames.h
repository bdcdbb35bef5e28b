// The viewer's camera panel: the newest image of each robot camera a page asks for, as JPEG at
// GET /camera/<robot>/<camera>.jpg (the page polls it). On the first request for a camera the viewer subscribes to
// turf-render's rt/<prefix>/<robot>/<camera>/image_raw and .../image_raw/compressed (on a participant of its own for
// large samples, made at the first request: no cost while no page shows a camera); raw frames (rgb8, yuv422_yuy2)
// are encoded to JPEG when asked for, once per frame, compressed ones passed as they are. The viewer only watches:
// a camera must be on in turf-render (declared on, or switched on by cameras/control).
//
// Untrusted input: a target that is not /camera/<token>/<token>.jpg (tokens [A-Za-z0-9_], 1..64 bytes) is refused;
// at most kMaxCameras cameras are followed (a request for another one stops following the one asked for least
// recently: names that are no camera cannot use up the slots for good); an image whose sizes do not add up, above
// kMaxImageSide, in another encoding or format, or a compressed one above 8 MiB is dropped. Each refusal is counted
// by kind and logged rate-limited ("camera panel input").
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "participants/viewer/http_rules.h"

namespace turf::viewer {

struct CameraFramesOptions {
  int domain = 0;
  std::string prefix = "turf";
  std::string security;
  std::string name = "turf-viewer";
};

class CameraFrames {
 public:
  static constexpr size_t kMaxCameras = 16;

  explicit CameraFrames(CameraFramesOptions options);
  ~CameraFrames();

  // The newest image of the camera `target` names, as JPEG; nullopt if the target is refused or no image has come
  // yet (then it subscribes). Thread-safe; quick but for encoding one frame.
  std::optional<std::string> Jpeg(std::string_view target);
  uint64_t refused() const;  // targets and images
  uint64_t served() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace turf::viewer
