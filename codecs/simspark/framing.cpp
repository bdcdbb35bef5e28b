#include "codecs/simspark/framing.h"

#include <cstdint>

namespace turf::simspark {

namespace {

constexpr size_t kPrefix = 4;

uint32_t ReadLength(const char* p) {
  const auto* b = reinterpret_cast<const unsigned char*>(p);
  return (uint32_t{b[0]} << 24) | (uint32_t{b[1]} << 16) | (uint32_t{b[2]} << 8) | uint32_t{b[3]};
}

}  // namespace

std::string Frame(std::string_view payload) {
  const auto n = static_cast<uint32_t>(payload.size());
  std::string out;
  out.reserve(kPrefix + payload.size());
  out.push_back(static_cast<char>((n >> 24) & 0xFF));
  out.push_back(static_cast<char>((n >> 16) & 0xFF));
  out.push_back(static_cast<char>((n >> 8) & 0xFF));
  out.push_back(static_cast<char>(n & 0xFF));
  out.append(payload);
  return out;
}

FrameDecoder::FrameDecoder(size_t max_payload) : max_payload_(max_payload) {}

void FrameDecoder::Feed(const char* data, size_t size) {
  if (error_ != FrameError::kOk || size == 0) return;
  partial_.append(data, size);
  size_t pos = 0;
  while (partial_.size() - pos >= kPrefix) {
    const size_t length = ReadLength(partial_.data() + pos);
    if (length > max_payload_) {
      error_ = FrameError::kTooLarge;
      partial_.clear();
      return;
    }
    if (partial_.size() - pos - kPrefix < length) break;
    if (length > 0) ready_.emplace_back(partial_, pos + kPrefix, length);
    pos += kPrefix + length;
  }
  partial_.erase(0, pos);
}

std::optional<std::string> FrameDecoder::Next() {
  if (ready_.empty()) return std::nullopt;
  std::string payload = std::move(ready_.front());
  ready_.pop_front();
  return payload;
}

}  // namespace turf::simspark
