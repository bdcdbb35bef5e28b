// A bridge test's stack: turf-sim's node and the bridge under test, each on a
// thread of its own; and the UDP socket a test's team sends from.
#pragma once

#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "participants/common/udp.h"
#include "tests/support/in_process.h"

namespace turf::test {

// turf-sim (SimUnderTest: `mode` at `speed`) first, then `bridge` running.
template <class Bridge>
class SimAndBridge {
 public:
  SimAndBridge(Scene scene, const dds::ParticipantOptions& dds, TimeMode mode, double speed,
               std::unique_ptr<Bridge> bridge)
      : sim_(std::move(scene), dds, mode, speed), bridge_(std::move(bridge)) {}
  SimNode& sim() { return sim_.node(); }
  Bridge& bridge() { return bridge_.node(); }

 private:
  SimUnderTest sim_;
  OnThread<Bridge> bridge_;
};

// A UDP socket on `ip` (a loopback address, for tests of source allowlists),
// on a port the kernel picked free; throws if it cannot bind.
inline UdpSocket BindUdp(const std::string& ip) {
  std::string error;
  std::optional<UdpSocket> s = UdpSocket::Bind(ip, 0, false, &error);
  if (!s) throw std::runtime_error(error);
  return std::move(*s);
}

}  // namespace turf::test
