// The newest rendered frames of each camera, for HLVS (pure: no DDS, no clock, no locks; the caller serialises).
// Put takes a ROS 2 Image's fields as turf-render writes them (rgb8 or yuv422_yuy2, rows top-down, `step` bytes a
// row) and keeps the frame in HLVS's byte order (B, G, R, no padding); Take gives the newest frame of a camera at or
// before a simulation time that was not taken before, so a client never gets one frame twice and never a frame of a
// state after its measurement's. Untrusted input: a frame whose sizes do not add up, above kMaxImageSide, or in
// another encoding is refused with a named error and not kept.
#pragma once

#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/errors.h"

namespace turf {

struct FeedFrame {
  int64_t stamp_ns = 0;  // simulation time of the state shown
  uint32_t width = 0, height = 0;
  std::string bgr;  // width * height * 3 bytes
};

// A ROS 2 Image's fields to a FeedFrame (kBadSize, kMalformed, kUnknownEnum for another encoding).
Error ToFeedFrame(int64_t stamp_ns, uint32_t width, uint32_t height, const std::string& encoding, uint32_t step,
                  const std::vector<uint8_t>& data, FeedFrame* out);

class CameraFeed {
 public:
  static constexpr size_t kKeep = 4;                     // frames kept per camera
  static constexpr int64_t kMaxAheadNs = 1'000'000'000;  // how far past the known time a frame may be stamped

  // Keeps `frame` of camera `key` ("<robot>/<camera>"); a frame older than one kept is kept in its place in time.
  // `now_ns` is the newest simulation time the caller knows: a frame stamped more than kMaxAheadNs after it is
  // refused (kOutOfRange), as a few such frames would push every real frame out for good.
  Error Put(const std::string& key, FeedFrame frame, int64_t now_ns);
  // The newest frame of `key` with stamp <= up_to_ns newer than the last one taken; it and older ones are dropped.
  std::optional<FeedFrame> Take(const std::string& key, int64_t up_to_ns);

 private:
  struct Camera {
    std::deque<FeedFrame> frames;  // by stamp, oldest first
    int64_t taken_ns = INT64_MIN;  // the stamp of the last frame taken
  };
  std::map<std::string, Camera> cameras_;
};

}  // namespace turf
