// turf-bench-latency: the latency the DDS hop adds to the two SSL bridge
// paths, measured in one run against the same path without DDS.
//
//   command in:  UDP grSim packet -> decode -> [DDS SslRobotCommand] -> physics inbox
//   frame out:   camera frame -> [DDS CameraFrame] -> encode SSL_WrapperPacket -> UDP datagram received
//
// Both ends run in this process but talk through Fast DDS with intra-process
// delivery switched off, so samples take the same shared-memory transport as
// between two processes on one host. Prints p50/p99 of each path and their
// difference.
#include <spdlog/spdlog.h>
#include <turf/idl/SslRobotPubSubTypes.h>
#include <turf/idl/SslVisionPubSubTypes.h>
#include <unistd.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <mutex>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "bench/bench_qos.h"
#include "codecs/grsim/grsim_codec.h"
#include "codecs/proto/grsim.pb.h"
#include "codecs/ssl_vision/detection.h"
#include "dds/participant.h"
#include "participants/common/udp.h"

namespace {

using Clock = std::chrono::steady_clock;
using turf::dds::Topic;
namespace idl = turf::idl;

int Seq(const idl::SslRobotCommand& c) { return static_cast<int>(std::lround((c.velocity().x() - 1.0) / 1e-4)); }

int64_t NowNs() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now().time_since_epoch()).count();
}

// Latencies (ns) recorded from any thread.
class Samples {
 public:
  void Add(int64_t ns) {
    std::lock_guard<std::mutex> lock(mutex_);
    values_.push_back(ns);
  }
  size_t size() {
    std::lock_guard<std::mutex> lock(mutex_);
    return values_.size();
  }
  double Percentile(double p) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (values_.empty()) return 0.0;
    std::vector<int64_t> v = values_;
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, static_cast<size_t>(p * v.size()))] * 1e-3;  // us
  }

 private:
  std::mutex mutex_;
  std::vector<int64_t> values_;
};

std::string GrsimPacket(int seq) {
  turf::wire::grsim::grSim_Packet p;
  auto* c = p.mutable_commands();
  c->set_timestamp(0);
  c->set_isteamyellow(false);
  auto* r = c->add_robot_commands();
  r->set_id(0);
  r->set_kickspeedx(0);
  r->set_kickspeedz(0);
  r->set_veltangent(static_cast<float>(1.0 + seq * 1e-4));  // carries the sequence number
  r->set_velnormal(0);
  r->set_velangular(0);
  r->set_spinner(false);
  r->set_wheelsspeed(false);
  return p.SerializeAsString();
}

struct PathResult {
  Samples direct, dds;
};

// Two loopback sockets: datagrams go from `tx` to `rx` (at `to`).
struct UdpPair {
  UdpPair() : rx(Bind()), tx(Bind()), to(*turf::MakeEndpoint("127.0.0.1", rx.LocalPort())) {}
  static turf::UdpSocket Bind() {
    std::string error;
    std::optional<turf::UdpSocket> s = turf::UdpSocket::Bind("127.0.0.1", 0, false, &error);
    if (!s) throw std::runtime_error("cannot bind a loopback UDP socket: " + error);
    return std::move(*s);
  }
  turf::UdpSocket rx;
  turf::UdpSocket tx;
  const turf::UdpEndpoint to;
};

// UDP in -> decode -> (DDS or direct) -> inbox.
void CommandPath(turf::dds::Participant& bridge, turf::dds::Participant& sim, int count, PathResult* out) {
  std::string error;
  UdpPair udp;
  std::vector<int64_t> sent(count, 0);
  bool via_dds = false;
  auto writer = bridge.MakeWriter<idl::SslRobotCommandPubSubType>(Topic::kSslCommandBlue);
  std::unique_ptr<turf::dds::Reader<idl::SslRobotCommandPubSubType>> reader;
  reader = sim.MakeReader<idl::SslRobotCommandPubSubType>(Topic::kSslCommandBlue, [&] {
    std::vector<idl::SslRobotCommand> got;
    if (reader && reader->Take(&got))
      for (const auto& c : got) out->dds.Add(NowNs() - sent[Seq(c)]);
  });
  while (writer->Matched() == 0) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  turf::grsim::GrsimCodecConfig config;
  std::atomic<bool> done{false};
  std::thread bridge_thread([&] {
    while (!done) {
      auto d = udp.rx.Receive(65536, std::chrono::milliseconds(20));
      if (!d) continue;
      const auto decoded = turf::grsim::Decode(d->bytes.data(), d->bytes.size(), config);
      for (const auto& c : decoded.requests.commands) {
        if (via_dds) {
          writer->Write(c);
        } else {
          out->direct.Add(NowNs() - sent[Seq(c)]);
        }
      }
    }
  });
  for (int phase = 0; phase < 2; ++phase) {
    via_dds = phase == 1;
    for (int i = 0; i < count; ++i) {
      const std::string bytes = GrsimPacket(i);
      sent[i] = NowNs();
      udp.tx.SendTo(std::vector<uint8_t>(bytes.begin(), bytes.end()), udp.to, &error);
      std::this_thread::sleep_for(std::chrono::microseconds(2000));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  done = true;
  bridge_thread.join();
}

// Frame -> (DDS or direct) -> encode -> UDP -> received.
void FramePath(turf::dds::Participant& sim, turf::dds::Participant& bridge, int count, PathResult* out) {
  std::string error;
  UdpPair udp;
  std::vector<int64_t> sent(count, 0);
  std::atomic<bool> via_dds{false};
  auto send_encoded = [&](const idl::CameraFrame& f) {
    turf::vision::FrameTimes times{1.0 + f.frame_number(), 1.0 + f.frame_number()};
    const std::vector<uint8_t> bytes = turf::vision::EncodeDetection(f, times, nullptr);
    udp.tx.SendTo(bytes, udp.to, &error);
  };
  auto writer = sim.MakeWriter<idl::CameraFramePubSubType>(Topic::kSslCamera);
  std::unique_ptr<turf::dds::Reader<idl::CameraFramePubSubType>> reader;
  reader = bridge.MakeReader<idl::CameraFramePubSubType>(Topic::kSslCamera, [&] {
    std::vector<idl::CameraFrame> got;
    if (reader && reader->Take(&got))
      for (const auto& f : got) send_encoded(f);
  });
  while (writer->Matched() == 0) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  std::atomic<bool> done{false};
  std::thread receiver([&] {
    while (!done) {
      auto d = udp.rx.Receive(65536, std::chrono::milliseconds(20));
      if (!d) continue;
      turf::wire::vision::SSL_WrapperPacket p;
      if (!p.ParseFromArray(d->bytes.data(), static_cast<int>(d->bytes.size())) || !p.has_detection()) continue;
      const int seq = static_cast<int>(p.detection().frame_number());
      (via_dds ? out->dds : out->direct).Add(NowNs() - sent[seq]);
    }
  });
  idl::CameraFrame frame;
  frame.camera_id(0);
  frame.balls().resize(1);
  frame.robots().resize(11);
  for (auto& r : frame.robots()) r.id(1);
  for (int phase = 0; phase < 2; ++phase) {
    via_dds = phase == 1;
    for (int i = 0; i < count; ++i) {
      frame.frame_number(static_cast<uint64_t>(i));
      frame.capture_time_ns(1'000'000'000 + i);
      frame.sent_time_ns(1'000'000'000 + i);
      sent[i] = NowNs();
      if (via_dds) {
        writer->Write(frame);
      } else {
        send_encoded(frame);
      }
      std::this_thread::sleep_for(std::chrono::microseconds(2000));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  done = true;
  receiver.join();
}

void Row(const char* path, PathResult& r) {
  const double d50 = r.direct.Percentile(0.5), d99 = r.direct.Percentile(0.99);
  const double x50 = r.dds.Percentile(0.5), x99 = r.dds.Percentile(0.99);
  std::printf("| %-44s | %6zu | %7.0f | %7.0f | %7.0f | %7.0f | %+8.0f | %+8.0f |\n", path, r.dds.size(), d50, d99, x50,
              x99, x50 - d50, x99 - d99);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"turf-bench-latency: latency the DDS hop adds to the SSL bridge paths (loopback, one run)"};
  int count = 2000;
  app.add_option("--samples", count, "samples per path and variant")
      ->capture_default_str()
      ->check(CLI::Range(10, 100000));
  std::string security;
  app.add_option("--security", security,
                 "DDS Security: a `turf security init --prefix '*'` directory; the two ends run as its sim and "
                 "simproto-bridge identities");
  CLI11_PARSE(app, argc, argv);
  spdlog::set_level(spdlog::level::warn);
  const std::string qos = turf::bench::QosWithoutIntraprocess("latency");
  const int domain = 1 + static_cast<int>(getpid() % 99);
  const std::string prefix = "latency" + std::to_string(getpid());
  const auto identity = [&](const char* name) { return security.empty() ? "" : security + "/" + name; };
  turf::dds::Participant sim({domain, "bench-sim", prefix, qos, identity("sim")});
  turf::dds::Participant bridge({domain, "bench-bridge", prefix, qos, identity("simproto-bridge")});
  PathResult command, frame;
  CommandPath(bridge, sim, count, &command);
  FramePath(sim, bridge, count, &frame);
  std::remove(qos.c_str());
  std::printf("DDS hop latency on loopback, %d samples per variant at 500 Hz; microseconds; DDS Security: %s\n", count,
              security.empty() ? "off" : security.substr(security.find_last_of('/') + 1).c_str());
  std::printf("| %-44s | %6s | %7s | %7s | %7s | %7s | %8s | %8s |\n", "path", "n", "in p50", "in p99", "dds p50",
              "dds p99", "+p50", "+p99");
  std::printf("|%s|--------|---------|---------|---------|---------|----------|----------|\n",
              std::string(46, '-').c_str());
  Row("command: UDP -> decode -> DDS -> physics inbox", command);
  Row("frame: DDS -> encode -> UDP datagram received", frame);
  std::printf("in: the same path in-process without DDS; +: added by the DDS hop (target: +p99 <= 1000 us)\n");
  return 0;
}
