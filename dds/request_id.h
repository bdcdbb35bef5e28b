// The first request id of a control client (SimControl.request_id). Replies
// are durable (turf.reply, TRANSIENT_LOCAL), so a client that restarts under
// the same name is handed its predecessor's last replies: a random start per
// process keeps them from matching its own requests.
#pragma once

#include <atomic>
#include <cstdint>
#include <random>

namespace turf::dds {

inline uint64_t FirstRequestId() {
  std::random_device device;
  return (static_cast<uint64_t>(device()) << 32 | device()) & 0x7fffffffffff0000ULL;
}

// A client on an in-process bus (turf-sim's own front-ends): no predecessor's replies can reach it there, so its
// ids need no random start, and a fixed one keeps a run's recorded control requests and replies the same bytes
// every time (the n-th such client of the process starts at n * 2^32).
inline uint64_t InProcessFirstRequestId() {
  static std::atomic<uint64_t> clients{0};
  return (clients.fetch_add(1) + 1) << 32;
}

}  // namespace turf::dds
