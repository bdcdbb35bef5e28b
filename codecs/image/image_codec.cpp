#include "codecs/image/image_codec.h"

#include <jpeglib.h>

#include <algorithm>
#include <csetjmp>
#include <cstdio>
#include <cstring>

namespace turf::image {

namespace {

constexpr int kMaxSide = 16384;

bool SizeOk(int width, int height) { return width > 0 && height > 0 && width <= kMaxSide && height <= kMaxSide; }

uint8_t Clamp(double v) { return static_cast<uint8_t>(std::clamp(v + 0.5, 0.0, 255.0)); }

Encoded Fail(Error e) { return Encoded{e, {}}; }

// Both YUYV conversions: checks an even width within the limits and an input of `in_bytes` a pixel, then calls
// convert(in, out) for each pair of pixels (two pixels of input, two of output at `out_bytes` a pixel).
template <class Convert>
Encoded ConvertPairs(const std::vector<uint8_t>& in, size_t in_bytes, size_t out_bytes, int width, int height,
                     Convert convert) {
  if (!SizeOk(width, height) || width % 2 != 0) return Fail(Error::kBadSize);
  const size_t pixels = static_cast<size_t>(width) * static_cast<size_t>(height);
  if (in.size() != pixels * in_bytes) return Fail(Error::kMalformed);
  Encoded out;
  out.bytes.resize(pixels * out_bytes);
  for (size_t p = 0; p < pixels; p += 2) convert(&in[p * in_bytes], &out.bytes[p * out_bytes]);
  return out;
}

}  // namespace

Encoded RgbToYuyv(const std::vector<uint8_t>& rgb, int width, int height) {
  return ConvertPairs(rgb, 3, 2, width, height, [](const uint8_t* a, uint8_t* o) {
    const uint8_t* b = a + 3;
    auto y = [](const uint8_t* c) { return 0.299 * c[0] + 0.587 * c[1] + 0.114 * c[2]; };
    const double r = 0.5 * (a[0] + b[0]);
    const double g = 0.5 * (a[1] + b[1]);
    const double bl = 0.5 * (a[2] + b[2]);
    o[0] = Clamp(y(a));
    o[1] = Clamp(-0.168736 * r - 0.331264 * g + 0.5 * bl + 128.0);
    o[2] = Clamp(y(b));
    o[3] = Clamp(0.5 * r - 0.418688 * g - 0.081312 * bl + 128.0);
  });
}

Encoded YuyvToRgb(const std::vector<uint8_t>& yuyv, int width, int height) {
  return ConvertPairs(yuyv, 2, 3, width, height, [](const uint8_t* i, uint8_t* o) {
    const double u = i[1] - 128.0;
    const double v = i[3] - 128.0;
    for (int k = 0; k < 2; ++k) {
      const double y = i[2 * k];
      o[3 * k] = Clamp(y + 1.402 * v);
      o[3 * k + 1] = Clamp(y - 0.344136 * u - 0.714136 * v);
      o[3 * k + 2] = Clamp(y + 1.772 * u);
    }
  });
}

namespace {

// libjpeg reports errors through error_exit, which must not return: jump back to the caller.
struct JumpError {
  jpeg_error_mgr mgr;
  std::jmp_buf jump;
};

void JumpOnError(j_common_ptr info) { std::longjmp(reinterpret_cast<JumpError*>(info->err)->jump, 1); }
void Silent(j_common_ptr /*info*/, int /*level*/) {}

// The JPEG encoding itself; no C++ object with a destructor lives across setjmp here.
bool CompressInto(const uint8_t* rgb, int width, int height, int quality, unsigned char** buffer, unsigned long* size) {
  jpeg_compress_struct c;
  JumpError err;
  c.err = jpeg_std_error(&err.mgr);
  err.mgr.error_exit = JumpOnError;
  if (setjmp(err.jump) != 0) {
    jpeg_destroy_compress(&c);
    return false;
  }
  jpeg_create_compress(&c);
  jpeg_mem_dest(&c, buffer, size);
  c.image_width = static_cast<JDIMENSION>(width);
  c.image_height = static_cast<JDIMENSION>(height);
  c.input_components = 3;
  c.in_color_space = JCS_RGB;
  jpeg_set_defaults(&c);
  jpeg_set_quality(&c, quality, TRUE);
  jpeg_start_compress(&c, TRUE);
  const size_t stride = static_cast<size_t>(width) * 3;
  while (c.next_scanline < c.image_height) {
    JSAMPROW row = const_cast<JSAMPROW>(rgb + c.next_scanline * stride);
    jpeg_write_scanlines(&c, &row, 1);
  }
  jpeg_finish_compress(&c);
  jpeg_destroy_compress(&c);
  return true;
}

// Reads the header, checks the size against max_pixels, then decodes into `out` (resized by the caller after the
// header: the header pass and the decode share one libjpeg object).
Error DecompressInto(const std::vector<uint8_t>& jpeg, int max_pixels, int* width, int* height,
                     std::vector<uint8_t>* out) {
  jpeg_decompress_struct d;
  JumpError err;
  d.err = jpeg_std_error(&err.mgr);
  err.mgr.error_exit = JumpOnError;
  err.mgr.emit_message = Silent;
  if (setjmp(err.jump) != 0) {
    jpeg_destroy_decompress(&d);
    return Error::kMalformed;
  }
  jpeg_create_decompress(&d);
  jpeg_mem_src(&d, jpeg.data(), static_cast<unsigned long>(jpeg.size()));
  if (jpeg_read_header(&d, TRUE) != JPEG_HEADER_OK) {
    jpeg_destroy_decompress(&d);
    return Error::kMalformed;
  }
  const uint64_t pixels = static_cast<uint64_t>(d.image_width) * d.image_height;
  if (pixels == 0 || pixels > static_cast<uint64_t>(std::max(0, max_pixels))) {
    jpeg_destroy_decompress(&d);
    return Error::kTooLarge;
  }
  d.out_color_space = JCS_RGB;
  jpeg_start_decompress(&d);
  *width = static_cast<int>(d.output_width);
  *height = static_cast<int>(d.output_height);
  out->resize(static_cast<size_t>(pixels) * 3);
  const size_t stride = static_cast<size_t>(d.output_width) * 3;
  while (d.output_scanline < d.output_height) {
    JSAMPROW row = out->data() + d.output_scanline * stride;
    jpeg_read_scanlines(&d, &row, 1);
  }
  jpeg_finish_decompress(&d);
  jpeg_destroy_decompress(&d);
  return Error::kOk;
}

}  // namespace

Encoded EncodeJpeg(const std::vector<uint8_t>& rgb, int width, int height, int quality) {
  if (!SizeOk(width, height)) return Fail(Error::kBadSize);
  if (quality < 1 || quality > 100) return Fail(Error::kOutOfRange);
  if (rgb.size() != static_cast<size_t>(width) * static_cast<size_t>(height) * 3) return Fail(Error::kMalformed);
  unsigned char* buffer = nullptr;
  unsigned long size = 0;
  const bool ok = CompressInto(rgb.data(), width, height, quality, &buffer, &size);
  Encoded out;
  if (ok && buffer != nullptr) out.bytes.assign(buffer, buffer + size);
  std::free(buffer);
  if (!ok) out.error = Error::kMalformed;
  return out;
}

Encoded DecodeJpeg(const std::vector<uint8_t>& jpeg, int max_pixels, int* width, int* height) {
  *width = 0;
  *height = 0;
  if (jpeg.empty()) return Fail(Error::kEmpty);
  Encoded out;
  out.error = DecompressInto(jpeg, max_pixels, width, height, &out.bytes);
  if (out.error != Error::kOk) {
    out.bytes.clear();
    *width = 0;
    *height = 0;
  }
  return out;
}

}  // namespace turf::image
