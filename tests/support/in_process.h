// Bridges in process, for the bridge tests: a participant's Run loop on a
// thread of its own next to turf-sim's node (SimUnderTest), the test's DDS
// settings copied into a participant's options, and loopback UDP sockets.
#pragma once

#include <atomic>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>

#include "dds/participant.h"
#include "participants/common/udp.h"
#include "tests/sim/sim_harness.h"

namespace turf::test {

// Runs `node.Run(stop)` on a thread until destroyed.
template <class Node>
class OnThread {
 public:
  explicit OnThread(std::unique_ptr<Node> node) : node_(std::move(node)) {
    thread_ = std::thread([this] { node_->Run([this] { return stop_.load(); }); });
  }
  ~OnThread() {
    stop_ = true;
    thread_.join();
  }
  OnThread(const OnThread&) = delete;
  OnThread& operator=(const OnThread&) = delete;
  Node& node() { return *node_; }

 private:
  std::unique_ptr<Node> node_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

// A participant's options (SimNodeOptions, a bridge's) on the test's domain,
// prefix and QoS file.
template <class Options>
Options OnDds(const dds::ParticipantOptions& dds) {
  Options o;
  o.domain = dds.domain;
  o.prefix = dds.prefix;
  o.qos_file = dds.qos_file;
  return o;
}

// A UDP socket on 127.0.0.1, on a port the kernel picked free.
inline UdpSocket BindLoopback() {
  std::string error;
  std::optional<UdpSocket> s = UdpSocket::Bind("127.0.0.1", 0, false, &error);
  if (!s) throw std::runtime_error(error);
  return std::move(*s);
}

}  // namespace turf::test
