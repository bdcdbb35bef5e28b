// Camera images between turf's rendered rgb8 pixels and the encodings a camera topic carries: YUYV (yuv422, as
// the Nao and the AIBO deliver) and baseline JPEG (libjpeg-turbo). Pure functions: bytes in, bytes out, with
// named errors for sizes that do not fit (core/errors.h). Rows are top-down, no padding.
#pragma once

#include <cstdint>
#include <vector>

#include "core/errors.h"

namespace turf::image {

struct Encoded {
  Error error = Error::kOk;
  std::vector<uint8_t> bytes;
};

// rgb8 (3 bytes a pixel) to YUYV: per two pixels Y0 U Y1 V, BT.601 full range (JFIF's: Y = 0.299 R + 0.587 G +
// 0.114 B, U and V centred on 128) with U and V of the pair's mean colour. `width` must be even.
// kBadSize for an odd or zero size, kMalformed when rgb.size() != width * height * 3.
Encoded RgbToYuyv(const std::vector<uint8_t>& rgb, int width, int height);
// And back (for tests and viewers): each pixel from its Y and its pair's U and V, clamped to 0..255.
Encoded YuyvToRgb(const std::vector<uint8_t>& yuyv, int width, int height);

// rgb8 to a baseline JPEG (4:2:0, `quality` 1..100). kBadSize for a bad size, kOutOfRange for a bad quality, kMalformed
// for a buffer of the wrong size.
Encoded EncodeJpeg(const std::vector<uint8_t>& rgb, int width, int height, int quality);
// A JPEG of at most `max_pixels` pixels to rgb8, for tests and viewers; kMalformed for anything libjpeg refuses,
// kTooLarge beyond max_pixels. Never exits the process (libjpeg's error exit is caught).
Encoded DecodeJpeg(const std::vector<uint8_t>& jpeg, int max_pixels, int* width, int* height);

}  // namespace turf::image
