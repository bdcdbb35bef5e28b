// The first request id of a control client (SimControl.request_id). Replies
// are durable (turf.reply, TRANSIENT_LOCAL), so a client that restarts under
// the same name is handed its predecessor's last replies: a random start per
// process keeps them from matching its own requests.
#pragma once

#include <cstdint>
#include <random>

namespace turf::dds {

inline uint64_t FirstRequestId() {
  std::random_device device;
  return (static_cast<uint64_t>(device()) << 32 | device()) & 0x7fffffffffff0000ULL;
}

}  // namespace turf::dds
