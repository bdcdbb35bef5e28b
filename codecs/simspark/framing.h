// Message framing of both SimSpark ports (agent 3100, monitor 3200): a 4-byte
// unsigned big-endian payload length, then the payload, no terminator
// (shared/protocols/simspark.md). A zero-length frame is legal and carries
// nothing: the decoder skips it.
#pragma once

#include <cstddef>
#include <deque>
#include <optional>
#include <string>
#include <string_view>

#include "core/errors.h"

namespace turf::simspark {

// An agent message is well under 2 KB (a Nao's effectors); a trainer's too.
inline constexpr size_t kMaxAgentPayload = 64 * 1024;

// The framed bytes of `payload` (precondition: payload.size() < 2^32).
std::string Frame(std::string_view payload);

// turf's one taxonomy (core/errors.h): kOk, or kTooLarge (a length prefix above
// the decoder's max_payload: drop the connection).
using FrameError = turf::Error;
inline const char* FrameErrorName(FrameError error) { return turf::ErrorName(error); }

// Reassembles frames from a byte stream fed in arbitrary pieces. A length
// prefix above max_payload is an error as soon as its 4 bytes have arrived
// (its payload is never awaited or buffered). Frames completed before the bad
// prefix are still returned; every byte from the bad prefix on is discarded,
// and Feed ignores further input.
class FrameDecoder {
 public:
  explicit FrameDecoder(size_t max_payload = kMaxAgentPayload);

  void Feed(const char* data, size_t size);
  // The next complete non-empty payload in arrival order, nullopt when none is complete yet.
  std::optional<std::string> Next();

  FrameError error() const { return error_; }
  // Bytes of the incomplete frame waiting for the rest (prefix included).
  size_t buffered() const { return partial_.size(); }

 private:
  size_t max_payload_;
  std::string partial_;
  std::deque<std::string> ready_;
  FrameError error_ = FrameError::kOk;
};

}  // namespace turf::simspark
