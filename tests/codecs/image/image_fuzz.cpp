// libFuzzer target: JPEG decoding of untrusted bytes, and the encoders over sizes and pixels from the input.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "codecs/image/image_codec.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::vector<uint8_t> bytes(data, data + size);
  int w = 0, h = 0;
  turf::image::DecodeJpeg(bytes, 1 << 16, &w, &h);
  if (size >= 3) {
    const int width = data[0] % 33;
    const int height = data[1] % 17;
    std::vector<uint8_t> rgb(bytes.begin() + 3, bytes.end());
    rgb.resize(static_cast<size_t>(width) * static_cast<size_t>(height) * 3 + (data[2] & 1));
    turf::image::RgbToYuyv(rgb, width, height);
    turf::image::EncodeJpeg(rgb, width, height, data[2] % 102);
  }
  return 0;
}
