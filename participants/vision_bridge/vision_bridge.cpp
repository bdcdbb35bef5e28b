#include "participants/vision_bridge/vision_bridge.h"

#include <spdlog/spdlog.h>
#include <turf/idl/ClockPubSubTypes.h>
#include <turf/idl/SslVisionPubSubTypes.h>
#include <turf/idl/WorldStatePubSubTypes.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <map>
#include <mutex>
#include <optional>
#include <random>
#include <stdexcept>

#include "codecs/ssl_vision/detection.h"
#include "codecs/ssl_vision/geometry.h"
#include "codecs/ssl_vision/tracked.h"
#include "dds/participant.h"
#include "participants/common/overflow_watch.h"
#include "participants/common/process.h"
#include "participants/common/protobuf_log.h"
#include "participants/common/stalled_authentication.h"
#include "participants/common/udp.h"
#include "participants/common/wakeup.h"

namespace turf {

namespace {

constexpr size_t kMaxDatagram = 65507;  // IPv4 UDP payload limit

bool IsMulticast(const UdpEndpoint& e) { return (e.ip() >> 28) == 0xE; }  // 224.0.0.0/4

UdpEndpoint Endpoint(const std::string& ip, uint16_t port, const char* flag) {
  const std::optional<UdpEndpoint> e = MakeEndpoint(ip, port);
  if (!e) throw std::invalid_argument(fmt::format("{}: not a dotted IPv4 address: '{}'", flag, ip));
  return *e;
}

double UnixNow() { return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count(); }

// A random RFC 4122 version 4 UUID: identifies this tracker run to receivers.
std::string RandomUuid() {
  std::random_device device;
  std::mt19937_64 gen((static_cast<uint64_t>(device()) << 32) ^ device());
  const uint64_t hi = (gen() & ~0xF000ull) | 0x4000ull;            // version 4
  const uint64_t lo = (gen() & ~(0x3ull << 62)) | (0x2ull << 62);  // variant 10
  return fmt::format("{:08x}-{:04x}-{:04x}-{:04x}-{:012x}", hi >> 32, (hi >> 16) & 0xFFFF, hi & 0xFFFF, lo >> 48,
                     lo & 0xFFFFFFFFFFFFull);
}

}  // namespace

class VisionBridge::Impl {
 public:
  explicit Impl(VisionBridgeOptions options)
      : options_(std::move(options)),
        wire_clock_(options_.clock),
        target_(Endpoint(options_.address, options_.port, "--address")),
        tracked_target_(Endpoint(options_.tracked_address, options_.tracked_port, "--tracked-address")),
        socket_(OpenSocket()),
        participant_(DdsOptions(options_)),
        camera_reader_(
            participant_.MakeReader<idl::CameraFramePubSubType>(dds::Topic::kSslCamera, [this] { wakeup_.Notify(); })),
        field_reader_(
            participant_.MakeReader<idl::SslFieldPubSubType>(dds::Topic::kSslField, [this] { wakeup_.Notify(); })),
        rejects_("input"),
        send_errors_log_("datagram") {
    if (options_.clock == vision::ClockMode::kRun) {
      clock_reader_ = participant_.MakeReader<idl::ClockPubSubType>(dds::Topic::kClock, [this] { wakeup_.Notify(); });
    }
    if (options_.tracked) {
      state_reader_ =
          participant_.MakeReader<idl::WorldStatePubSubType>(dds::Topic::kWorldState, [this] { wakeup_.Notify(); });
      source_.uuid = options_.tracked_uuid.empty() ? RandomUuid() : options_.tracked_uuid;
      source_.source_name = "turf";
    }
  }

  void Run(const std::function<bool()>& stop) {
    ReportStartup();
    auto next_status = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (!stop()) {
      wakeup_.WaitFor(std::chrono::milliseconds(50));
      HandleField();
      // The clock before the frames: turf-sim writes a reset's epoch before its frames.
      HandleClock();
      HandleCameras();
      HandleClock();
      HandleStates();
      HandleOverflow();
      if (restart_.Check(participant_.AuthenticationsNow(), !receiving_)) break;
      const auto now = std::chrono::steady_clock::now();
      if (now >= next_status) {
        ReportStatus();
        next_status = now + std::chrono::seconds(10);
      }
    }
    ReportStatus();
  }

  VisionBridgeStats Stats() const {
    return {detections_sent_.load(), geometry_sent_.load(), tracked_sent_.load(),
            rejects_.Total(),        send_errors_.load(),   no_epoch_.load()};
  }
  uint64_t Rejected(const std::string& kind) const {
    std::lock_guard<std::mutex> lock(no_epoch_mutex_);
    const auto waited = no_epoch_counts_.find(kind);
    return rejects_.Count(kind) + (waited == no_epoch_counts_.end() ? 0 : waited->second);
  }

 private:
  UdpSocket OpenSocket() const {
    if (options_.ttl < 0 || options_.ttl > 255) throw std::invalid_argument("--ttl must be 0..255");
    if (options_.geometry_every < 0) throw std::invalid_argument("--geometry-every must be >= 0");
    std::string error;
    std::optional<UdpSocket> s = UdpSocket::Bind("0.0.0.0", 0, false, &error);
    if (!s) throw std::runtime_error("UDP socket: " + error);
    const bool multicast = IsMulticast(target_) || (options_.tracked && IsMulticast(tracked_target_));
    if (multicast) {
      if (!options_.interface_ip.empty() && !s->SetMulticastInterface(options_.interface_ip, &error))
        throw std::invalid_argument("--interface: " + error);
      if (!s->SetMulticastTtl(options_.ttl, &error) || !s->SetMulticastLoop(true, &error))
        throw std::runtime_error(error);
    }
    return std::move(*s);
  }

  void Reject(const std::string& kind, const std::string& detail) { rejects_.Reject(kind, detail); }

  // A frame that cannot be stamped yet (run clock): not bad input, but not sent
  // either. DDS does not order the camera and clock topics, so frames that
  // arrive before turf-sim's first clock sample are normal: counted, and told
  // once at info level, never as a warning.
  void Drop(const std::string& kind, const std::string& detail) {
    std::lock_guard<std::mutex> lock(no_epoch_mutex_);
    if (no_epoch_counts_[kind]++ == 0)
      spdlog::info("waiting for turf-sim's clock (run epoch): {} not sent yet ({}; counted as {})", kind, detail, kind);
    no_epoch_.fetch_add(1);
  }

  // A frame the wire clock refused: counted as bad input, or as a drop while the epoch is unknown.
  void RefuseTime(const char* what, vision::VisionError e, const std::string& detail) {
    const std::string kind = fmt::format("{}.{}", what, vision::VisionErrorName(e));
    if (e == vision::VisionError::kNoEpoch)
      Drop(kind, detail);
    else
      Reject(kind, detail);
  }

  bool Send(const std::vector<uint8_t>& bytes, const UdpEndpoint& to, const char* what) {
    if (bytes.size() > kMaxDatagram) {
      Reject(fmt::format("{}.too_large", what), fmt::format("{} bytes do not fit a datagram", bytes.size()));
      return false;
    }
    std::string error;
    if (socket_.SendTo(bytes, to, &error)) return true;
    send_errors_.fetch_add(1);
    send_errors_log_.Reject(what, error);
    return false;
  }

  // --- ssl/field ---

  void HandleField() {
    if (!field_reader_->Take(&field_inbox_)) return;
    for (const idl::SslField& f : field_inbox_) {
      std::vector<uint8_t> bytes;
      const vision::VisionError e = vision::EncodeGeometry(f, &bytes);
      if (e != vision::VisionError::kOk) {
        Reject(fmt::format("field.{}", vision::VisionErrorName(e)), "SslField cannot be encoded; keeping the last");
        continue;
      }
      if (!field_) {
        spdlog::info("field known: division {}, {} x {} m, {} cameras", f.division() == 2 ? "B" : "A", f.field_length(),
                     f.field_width(), f.cameras().size());
      }
      field_ = f;
      geometry_bytes_ = std::move(bytes);
      SendGeometry();
    }
  }

  void SendGeometry() {
    rounds_since_geometry_ = 0;
    if (Send(geometry_bytes_, target_, "geometry")) geometry_sent_.fetch_add(1);
  }

  // --- clock (run clock only) ---

  // Every sample's epoch goes to the wire clock, which keeps the distinct ones
  // (one per reset). The epoch is another participant's word: garbage is
  // refused, counted and logged, and the last good epoch stays.
  void HandleClock() {
    if (!clock_reader_ || !clock_reader_->Take(&clock_inbox_)) return;
    for (const idl::Clock& c : clock_inbox_) {
      const vision::VisionError e = wire_clock_.AddRunEpoch(c.run_epoch_unix_ns());
      if (e != vision::VisionError::kOk) {
        Reject(fmt::format("clock.{}", vision::VisionErrorName(e)),
               fmt::format("run_epoch_unix_ns {} at sim time {} ns is not a Unix time in 2000..2200",
                           c.run_epoch_unix_ns(), c.sim_time_ns()));
        continue;
      }
      if (!logged_epoch_ || *logged_epoch_ != c.run_epoch_unix_ns()) {
        spdlog::info("run epoch {:.3f} (Unix s) at sim time {:.3f} s", c.run_epoch_unix_ns() * 1e-9,
                     c.sim_time_ns() * 1e-9);
        logged_epoch_ = c.run_epoch_unix_ns();
      }
    }
  }

  // --- ssl/camera ---

  void HandleCameras() {
    if (!camera_reader_->Take(&camera_inbox_)) return;
    if (!receiving_) {
      spdlog::info("receiving camera frames");
      receiving_ = true;
    }
    for (const idl::CameraFrame& frame : camera_inbox_) {
      const vision::VisionError e = vision::CheckCameraFrame(frame);
      if (e != vision::VisionError::kOk) {
        Reject(fmt::format("camera.{}", vision::VisionErrorName(e)), fmt::format("camera {}", frame.camera_id()));
        continue;
      }
      // A new capture time starts a round: geometry goes out ahead of its
      // frames, and the round's cameras share one wall-clock reading, so frames
      // captured together carry the same t_capture (as the sim captured them).
      // Rounds are remembered by capture time, not by arrival order: a reader
      // that fell behind takes several rounds' frames camera by camera.
      // A jump back by more than a second is a reset of the simulation: a new timeline.
      if (last_capture_ns_ && frame.capture_time_ns() + 1'000'000'000 < *last_capture_ns_) {
        round_unix_now_.clear();
        last_capture_ns_.reset();
      }
      auto round = round_unix_now_.find(frame.capture_time_ns());
      if (round == round_unix_now_.end()) {
        round = round_unix_now_.emplace(frame.capture_time_ns(), UnixNow()).first;
        if (round_unix_now_.size() > kRememberedRounds) round_unix_now_.erase(round_unix_now_.begin());
        if (!last_capture_ns_ || frame.capture_time_ns() > *last_capture_ns_) {
          last_capture_ns_ = frame.capture_time_ns();
          ++rounds_since_geometry_;
          if (field_ && options_.geometry_every > 0 && rounds_since_geometry_ >= options_.geometry_every)
            SendGeometry();
        }
      }
      vision::FrameTimes times{};
      const vision::VisionError te = wire_clock_.ForCamera(frame.camera_id(), frame.capture_time_ns(),
                                                           frame.sent_time_ns(), round->second, &times);
      if (te != vision::VisionError::kOk) {
        RefuseTime("camera", te,
                   fmt::format("camera {} captured at {} ns, sent at {} ns", frame.camera_id(), frame.capture_time_ns(),
                               frame.sent_time_ns()));
        continue;
      }
      const idl::CameraInfo* camera = field_ ? vision::FindCamera(*field_, frame.camera_id()) : nullptr;
      if (Send(vision::EncodeDetection(frame, times, camera), target_, "detection")) detections_sent_.fetch_add(1);
    }
  }

  // --- world_state ---

  void HandleStates() {
    if (!state_reader_ || !state_reader_->Take(&state_inbox_)) return;
    for (const idl::WorldState& s : state_inbox_) {
      double timestamp = 0.0;
      vision::VisionError e = wire_clock_.ForWorldState(s.sim_time_ns(), UnixNow(), &timestamp);
      if (e == vision::VisionError::kTimeNotPositive && options_.clock == vision::ClockMode::kSim) {
        continue;  // the state at sim time 0 (start, reset) has no valid sim-clock stamp: skip it quietly
      }
      if (e == vision::VisionError::kNoEpoch) {
        Drop("world_state.no_epoch", fmt::format("frame {} at sim time {} ns", s.frame(), s.sim_time_ns()));
        continue;
      }
      std::vector<uint8_t> bytes;
      if (e == vision::VisionError::kOk) e = vision::EncodeTracked(s, source_, timestamp, &bytes);
      if (e != vision::VisionError::kOk) {
        Reject(fmt::format("world_state.{}", vision::VisionErrorName(e)), fmt::format("frame {}", s.frame()));
        continue;
      }
      if (Send(bytes, tracked_target_, "tracked")) tracked_sent_.fetch_add(1);
    }
  }

  void HandleOverflow() {
    const uint64_t overflow = camera_reader_->Overflowed() + field_reader_->Overflowed() +
                              (state_reader_ ? state_reader_->Overflowed() : 0) +
                              (clock_reader_ ? clock_reader_->Overflowed() : 0);
    overflow_.Check(overflow, [this](const char* kind, const std::string& detail) { Reject(kind, detail); });
  }

  // --- reports ---

  void ReportStartup() const {
    auto name = [this](dds::Topic t) { return participant_.TopicName(t); };
    spdlog::info("{}", participant_.Describe());
    spdlog::info("subscribing {} and {} (latched){}{}", name(dds::Topic::kSslCamera), name(dds::Topic::kSslField),
                 options_.tracked ? fmt::format(", {}", name(dds::Topic::kWorldState)) : "",
                 clock_reader_ ? fmt::format(", {} (run epoch)", name(dds::Topic::kClock)) : "");
    const std::string how = IsMulticast(target_)
                                ? fmt::format("multicast, ttl {}, interface {}", options_.ttl,
                                              options_.interface_ip.empty() ? "default" : options_.interface_ip)
                                : "unicast";
    spdlog::info("sending SSL_WrapperPacket to {} ({}) from UDP port {}: a detection per camera frame, geometry {}",
                 target_.ToString(), how, socket_.LocalPort(),
                 options_.geometry_every > 0
                     ? fmt::format("when the field is known and every {} capture rounds", options_.geometry_every)
                     : std::string("when the field is known"));
    if (options_.tracked) {
      spdlog::info("sending TrackerWrapperPacket to {} ({}) per world state, uuid {}", tracked_target_.ToString(),
                   IsMulticast(tracked_target_) ? "multicast" : "unicast", source_.uuid);
    }
    const char* meaning = "";
    switch (options_.clock) {
      case vision::ClockMode::kRun:
        meaning = "turf-sim's run epoch + simulation time, in Unix seconds";
        break;
      case vision::ClockMode::kUnix:
        meaning = "wall clock at sending, Unix seconds";
        break;
      case vision::ClockMode::kSim:
        meaning = "simulation seconds";
        break;
    }
    spdlog::info("times: {} clock ({})", vision::ClockModeName(options_.clock), meaning);
    spdlog::info("waiting for turf-sim on domain {} prefix '{}'", options_.domain, options_.prefix);
  }

  void ReportStatus() const {
    spdlog::info("sent detections={} geometry={} tracked={} refused={} no_epoch={} send_errors={}",
                 detections_sent_.load(), geometry_sent_.load(), tracked_sent_.load(), rejects_.Total(),
                 no_epoch_.load(), send_errors_.load());
  }

  VisionBridgeOptions options_;
  vision::WireClock wire_clock_;
  UdpEndpoint target_;
  UdpEndpoint tracked_target_;
  UdpSocket socket_;
  Wakeup wakeup_;
  dds::Participant participant_;
  std::unique_ptr<dds::Reader<idl::CameraFramePubSubType>> camera_reader_;
  std::unique_ptr<dds::Reader<idl::SslFieldPubSubType>> field_reader_;
  std::unique_ptr<dds::Reader<idl::WorldStatePubSubType>> state_reader_;
  std::unique_ptr<dds::Reader<idl::ClockPubSubType>> clock_reader_;  // run clock only
  vision::TrackedSource source_;

  std::optional<idl::SslField> field_;
  std::vector<uint8_t> geometry_bytes_;
  std::optional<int64_t> last_capture_ns_;
  static constexpr size_t kRememberedRounds = 32;
  std::map<int64_t, double> round_unix_now_;  // capture time (sim ns) -> wall-clock reading
  int rounds_since_geometry_ = 0;
  bool receiving_ = false;
  StalledAuthenticationRestart restart_;
  OverflowWatch overflow_;
  std::vector<idl::CameraFrame> camera_inbox_;
  std::vector<idl::SslField> field_inbox_;
  std::vector<idl::WorldState> state_inbox_;
  std::vector<idl::Clock> clock_inbox_;
  std::optional<int64_t> logged_epoch_;

  RejectLog rejects_;
  mutable std::mutex no_epoch_mutex_;
  std::map<std::string, uint64_t> no_epoch_counts_;  // frames held back before the first epoch, by kind
  RejectLog send_errors_log_;
  std::atomic<uint64_t> send_errors_{0};
  std::atomic<uint64_t> no_epoch_{0};
  std::atomic<uint64_t> detections_sent_{0};
  std::atomic<uint64_t> geometry_sent_{0};
  std::atomic<uint64_t> tracked_sent_{0};
};

VisionBridge::VisionBridge(VisionBridgeOptions options) : impl_(std::make_unique<Impl>(std::move(options))) {
  RouteProtobufLogs();
}
VisionBridge::~VisionBridge() = default;
void VisionBridge::Run(const std::function<bool()>& stop) { impl_->Run(stop); }
VisionBridgeStats VisionBridge::Stats() const { return impl_->Stats(); }
uint64_t VisionBridge::Rejected(const std::string& kind) const { return impl_->Rejected(kind); }

}  // namespace turf
