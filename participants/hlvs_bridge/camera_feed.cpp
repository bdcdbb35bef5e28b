#include "participants/hlvs_bridge/camera_feed.h"

#include <algorithm>

#include "codecs/image/image_codec.h"
#include "core/camera/camera_model.h"

namespace turf {

namespace {

// Rows of `step` bytes, the first width * 3 of each RGB: to B, G, R without padding.
void RgbRowsToBgr(const std::vector<uint8_t>& data, uint32_t width, uint32_t height, size_t step, std::string* bgr) {
  bgr->resize(size_t{width} * height * 3);
  char* out = bgr->data();
  for (uint32_t y = 0; y < height; ++y) {
    const uint8_t* row = data.data() + y * step;
    for (uint32_t x = 0; x < width; ++x, out += 3) {
      out[0] = static_cast<char>(row[3 * x + 2]);
      out[1] = static_cast<char>(row[3 * x + 1]);
      out[2] = static_cast<char>(row[3 * x]);
    }
  }
}

}  // namespace

Error ToFeedFrame(int64_t stamp_ns, uint32_t width, uint32_t height, const std::string& encoding, uint32_t step,
                  const std::vector<uint8_t>& data, FeedFrame* out) {
  if (width == 0 || height == 0 || width > kMaxImageSide || height > kMaxImageSide) return Error::kBadSize;
  const bool rgb = encoding == "rgb8";
  if (!rgb && encoding != "yuv422_yuy2") return Error::kUnknownEnum;
  const size_t row = size_t{width} * (rgb ? 3 : 2);
  if (step < row || data.size() < size_t{step} * (height - 1) + row) return Error::kMalformed;
  out->stamp_ns = stamp_ns;
  out->width = width;
  out->height = height;
  if (rgb) {
    RgbRowsToBgr(data, width, height, step, &out->bgr);
    return Error::kOk;
  }
  std::vector<uint8_t> packed;
  packed.reserve(row * height);
  for (uint32_t y = 0; y < height; ++y)
    packed.insert(packed.end(), data.begin() + y * size_t{step}, data.begin() + y * size_t{step} + row);
  const image::Encoded decoded = image::YuyvToRgb(packed, static_cast<int>(width), static_cast<int>(height));
  if (decoded.error != Error::kOk) return decoded.error;
  RgbRowsToBgr(decoded.bytes, width, height, size_t{width} * 3, &out->bgr);
  return Error::kOk;
}

Error CameraFeed::Put(const std::string& key, FeedFrame frame, int64_t now_ns) {
  if (now_ns < INT64_MAX - kMaxAheadNs && frame.stamp_ns > now_ns + kMaxAheadNs) return Error::kOutOfRange;
  Camera& c = cameras_[key];
  if (frame.stamp_ns <= c.taken_ns) return Error::kOk;  // older than what a client already has
  auto at = std::upper_bound(c.frames.begin(), c.frames.end(), frame.stamp_ns,
                             [](int64_t t, const FeedFrame& f) { return t < f.stamp_ns; });
  if (at != c.frames.begin() && std::prev(at)->stamp_ns == frame.stamp_ns) {
    *std::prev(at) = std::move(frame);  // the same state again (another renderer): the newer copy
  } else {
    c.frames.insert(at, std::move(frame));
  }
  while (c.frames.size() > kKeep) c.frames.pop_front();
  return Error::kOk;
}

std::optional<FeedFrame> CameraFeed::Take(const std::string& key, int64_t up_to_ns) {
  auto it = cameras_.find(key);
  if (it == cameras_.end()) return std::nullopt;
  Camera& c = it->second;
  auto end = std::upper_bound(c.frames.begin(), c.frames.end(), up_to_ns,
                              [](int64_t t, const FeedFrame& f) { return t < f.stamp_ns; });
  if (end == c.frames.begin()) return std::nullopt;
  FeedFrame out = std::move(*std::prev(end));
  c.frames.erase(c.frames.begin(), end);
  c.taken_ns = out.stamp_ns;
  return out;
}

}  // namespace turf
