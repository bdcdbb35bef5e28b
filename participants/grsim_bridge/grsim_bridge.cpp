#include "participants/grsim_bridge/grsim_bridge.h"

#include <spdlog/spdlog.h>
#include <turf/idl/SimControlPubSubTypes.h>
#include <turf/idl/SslRobotPubSubTypes.h>
#include <turf/idl/SslVisionPubSubTypes.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <vector>

#include "codecs/grsim/robot_status.h"
#include "dds/control_client.h"
#include "dds/participant.h"
#include "participants/common/process.h"
#include "participants/common/protobuf_log.h"
#include "participants/common/stalled_authentication.h"
#include "participants/common/udp.h"

namespace turf {

namespace {

using SteadyClock = std::chrono::steady_clock;
constexpr auto kReceiveTimeout = std::chrono::milliseconds(5);
constexpr auto kPresenceEvery = std::chrono::milliseconds(250);
constexpr auto kReportEvery = std::chrono::seconds(10);
constexpr auto kReplyTimeout = std::chrono::seconds(10);  // a teleport's reply, for the refusal log
constexpr const char* kTeamName[2] = {"blue", "yellow"};

}  // namespace

std::array<SourceGate*, 2> GatesFor(const grsim::GrsimRequests& requests, SourceGates& gates) {
  std::array<SourceGate*, 2> out{};
  if (requests.command_team) out[0] = &gates.team(static_cast<int>(*requests.command_team));
  if (!requests.controls.empty()) out[1] = &gates.operators;
  return out;
}

class GrsimBridge::Impl {
 public:
  explicit Impl(GrsimBridgeOptions options)
      : options_(CheckedOptions(std::move(options))),
        codec_(options_.codec),
        socket_(BindSocket(options_)),
        gates_(options_.allow),
        participant_(DdsOptions(options_)),
        command_writers_{participant_.MakeWriter<idl::SslRobotCommandPubSubType>(dds::Topic::kSslCommandBlue),
                         participant_.MakeWriter<idl::SslRobotCommandPubSubType>(dds::Topic::kSslCommandYellow)},
        control_(participant_, options_.name),
        feedback_readers_{participant_.MakeReader<idl::SslRobotFeedbackPubSubType>(dds::Topic::kSslFeedbackBlue),
                          participant_.MakeReader<idl::SslRobotFeedbackPubSubType>(dds::Topic::kSslFeedbackYellow)},
        field_reader_(participant_.MakeReader<idl::SslFieldPubSubType>(dds::Topic::kSslField)),
        rejects_("grSim datagram"),
        replacement_rejects_("replacement by turf-sim") {
    port_ = socket_.LocalPort();
  }

  void Run(const std::function<bool()>& stop) {
    ReportStartup();
    auto next_presence = SteadyClock::now();
    auto next_report = SteadyClock::now() + kReportEvery;
    while (!stop()) {
      // One byte more than allowed, so the codec sees an oversized datagram as such.
      if (auto datagram = socket_.Receive(codec_.max_datagram_size + 1, kReceiveTimeout)) HandleDatagram(*datagram);
      PollDds();
      const auto now = SteadyClock::now();
      if (now >= next_presence) {
        CheckPresence();
        if (restart_.Check(participant_.AuthenticationsNow(), !sim_present_.load())) break;
        next_presence = now + kPresenceEvery;
      }
      if (now >= next_report) {
        Report();
        next_report = now + kReportEvery;
      }
    }
    Report();
  }

  uint16_t port() const { return port_; }

  GrsimBridgeStats Stats() const {
    GrsimBridgeStats s;
    s.datagrams = datagrams_.load();
    s.refused = refused_.load();
    s.not_allowed = gates_.refused();
    s.commands = commands_.load();
    s.controls = controls_.load();
    s.status_packets = status_packets_.load();
    s.sim_present = sim_present_.load();
    s.field_known = field_known_.load();
    return s;
  }

  uint64_t Rejected(const std::string& kind) const {
    if (kind == "control_unanswered") return unanswered_.load();
    return rejects_.Count(kind) + replacement_rejects_.Count(kind);
  }

 private:
  static GrsimBridgeOptions CheckedOptions(GrsimBridgeOptions o) {
    const std::string why = grsim::CheckConfig(o.codec);
    if (!why.empty()) throw std::invalid_argument(why);
    if (o.blue_status_port == 0 || o.yellow_status_port == 0)
      throw std::invalid_argument("status ports must be 1..65535");
    return o;
  }

  static UdpSocket BindSocket(const GrsimBridgeOptions& o) {
    std::string error;
    std::optional<UdpSocket> s = UdpSocket::Bind(o.listen_ip, o.port, false, &error);
    if (!s) throw std::runtime_error("cannot listen for grSim packets: " + error);
    return std::move(*s);
  }

  void Reject(const std::string& kind, const std::string& detail) { rejects_.Reject(kind, detail); }

  void HandleDatagram(const Datagram& d) {
    datagrams_.fetch_add(1);
    grsim::GrsimDecodeResult r = grsim::Decode(d.bytes.data(), d.bytes.size(), codec_);
    if (!r.ok()) {
      refused_.fetch_add(1);
      Reject(grsim::GrsimErrorName(r.error), "from " + d.from.ToString() + ": " + r.detail);
      return;
    }
    if (!Admitted(r.requests, d.from)) {
      refused_.fetch_add(1);
      return;
    }
    if (r.requests.command_team) {
      const int team = static_cast<int>(*r.requests.command_team);
      SetStatusAddress(team, d.from);
      for (const idl::SslRobotCommand& c : r.requests.commands) command_writers_[team]->Write(c);
      commands_.fetch_add(r.requests.commands.size());
    }
    for (idl::SimControl& c : r.requests.controls)
      control_.Send(std::move(c), kReplyTimeout, [this](const dds::ControlOutcome& o) { OnReply(o); });
    controls_.fetch_add(r.requests.controls.size());
  }

  // The sender passes every list the packet needs (GatesFor); a refusal is counted and logged by its gate.
  bool Admitted(const grsim::GrsimRequests& requests, const UdpEndpoint& from) {
    for (SourceGate* gate : GatesFor(requests, gates_))
      if (gate != nullptr && !gate->Admit(from, rejects_)) return false;
    return true;
  }

  void SetStatusAddress(int team, const UdpEndpoint& from) {
    const uint16_t port = team == 0 ? options_.blue_status_port : options_.yellow_status_port;
    if (status_to_[team] && status_to_[team]->ip() == from.ip()) return;
    UdpEndpoint to = from;
    to.addr.sin_port = htons(port);
    status_to_[team] = to;
    spdlog::info("{} commands from {}: {} robot status goes to {}", kTeamName[team], from.ToString(), kTeamName[team],
                 to.ToString());
  }

  void PollDds() {
    if (field_reader_->Take(&fields_)) ApplyField(fields_.back());
    for (int team = 0; team < 2; ++team) {
      if (!feedback_readers_[team]->Take(&feedback_)) continue;
      for (const idl::SslRobotFeedback& f : feedback_) {
        if (static_cast<int>(f.team()) == team) tracker_.Feed(f);
      }
    }
    for (int team = 0; team < 2; ++team) {
      for (const auto& packet : tracker_.TakePackets(static_cast<idl::Team>(team))) SendStatus(team, packet);
    }
    control_.Dispatch();
  }

  // A teleport turf-sim refused is logged; one nobody answered (turf-sim not
  // there yet, or gone) only counted: bridges started first wait quietly.
  void OnReply(const dds::ControlOutcome& o) {
    if (o.ok()) return;
    const std::string detail = "request " + std::to_string(o.request_id) + ": " + o.Describe();
    if (o.error != dds::ControlCallError::kRefused) {
      unanswered_.fetch_add(1);
      spdlog::debug("replacement not done: {}", detail);
      return;
    }
    replacement_rejects_.Reject("control_rejected", detail);
  }

  // Status for a team no client has commanded yet has nowhere to go: dropped.
  void SendStatus(int team, const std::vector<grsim::RobotStatus>& robots) {
    if (!status_to_[team]) return;
    std::string error;
    if (socket_.SendTo(grsim::EncodeStatus(robots), *status_to_[team], &error)) {
      status_packets_.fetch_add(1);
    } else if (send_failures_++ % 100 == 0) {
      spdlog::warn("robot status not sent ({} failures so far): {}", send_failures_, error);
    }
  }

  void ApplyField(const idl::SslField& field) {
    grsim::GrsimCodecConfig next = codec_;
    next.robots_per_team = field.robots_per_team();
    next.wheel_radius = field.wheel_radius();
    next.max_flat_kick_speed = field.max_flat_kick_speed();
    next.max_chip_kick_speed = field.max_chip_kick_speed();
    next.wall_x = field.field_length() / 2 + field.boundary_width_goal_line();
    next.wall_y = field.field_width() / 2 + field.boundary_width();
    next.ball_radius = field.ball_radius();
    next.robot_radius = field.max_robot_radius();
    const std::string why = grsim::CheckConfig(next);
    if (!why.empty()) {
      spdlog::warn("ignoring {} from turf-sim: {}", participant_.TopicName(dds::Topic::kSslField), why);
      return;
    }
    codec_ = next;
    field_known_.store(true);
    spdlog::info("field from turf-sim: {} robots a team, wheel radius {} m, kicks up to {} m/s flat, {} m/s chip",
                 codec_.robots_per_team, codec_.wheel_radius, codec_.max_flat_kick_speed, codec_.max_chip_kick_speed);
  }

  void CheckPresence() {
    const bool present =
        command_writers_[0]->Matched() > 0 && command_writers_[1]->Matched() > 0 && control_.ServerMatched();
    if (present == sim_present_.load()) return;
    sim_present_.store(present);
    if (present) {
      spdlog::info("turf-sim is listening");
    } else {
      spdlog::warn("turf-sim is gone; waiting for it (datagrams are still decoded, nobody hears them)");
    }
  }

  void ReportStartup() const {
    auto name = [this](dds::Topic t) { return participant_.TopicName(t); };
    spdlog::info("listening for grSim packets on {}:{} (UDP), datagrams up to {} bytes", options_.listen_ip, port_,
                 codec_.max_datagram_size);
    spdlog::info("robot status to each team's last command sender, ports {} (blue) and {} (yellow)",
                 options_.blue_status_port, options_.yellow_status_port);
    gates_.ReportStartup("replacement");
    spdlog::info("{}", participant_.Describe());
    spdlog::info("publishing {}, {}, {}", name(dds::Topic::kSslCommandBlue), name(dds::Topic::kSslCommandYellow),
                 name(dds::Topic::kControl));
    spdlog::info("subscribing {}, {}, {} (latched), {}", name(dds::Topic::kSslFeedbackBlue),
                 name(dds::Topic::kSslFeedbackYellow), name(dds::Topic::kSslField), name(dds::Topic::kControlReply));
    spdlog::info("until the field arrives: {} robots a team, wheel radius {} m; dribbler {} rpm; wheels 1..4 -> {}",
                 codec_.robots_per_team, codec_.wheel_radius, codec_.dribbler_rpm, WheelMapping());
    spdlog::info("waiting for turf-sim on domain {} with prefix '{}'", options_.domain, options_.prefix);
  }

  std::string WheelMapping() const {
    static const char* const kTurfWheel[4] = {"front_right", "back_right", "back_left", "front_left"};
    std::string out;
    for (int i = 0; i < 4; ++i) {
      if (i > 0) out += ", ";
      out += kTurfWheel[i] + std::string("=wheel") + std::to_string(codec_.wheel_source[i] + 1);
    }
    return out;
  }

  // A line every 10 s while datagrams arrive; quiet when idle.
  void Report() {
    const GrsimBridgeStats s = Stats();
    if (s.datagrams == reported_datagrams_) return;
    reported_datagrams_ = s.datagrams;
    spdlog::info("datagrams={} refused={} not_allowed={} commands={} replacements={} status_packets={}", s.datagrams,
                 s.refused, s.not_allowed, s.commands, s.controls, s.status_packets);
  }

  GrsimBridgeOptions options_;
  grsim::GrsimCodecConfig codec_;
  UdpSocket socket_;
  SourceGates gates_;
  uint16_t port_ = 0;
  dds::Participant participant_;
  std::unique_ptr<dds::Writer<idl::SslRobotCommandPubSubType>> command_writers_[2];
  dds::ControlClient control_;
  std::unique_ptr<dds::Reader<idl::SslRobotFeedbackPubSubType>> feedback_readers_[2];
  std::unique_ptr<dds::Reader<idl::SslFieldPubSubType>> field_reader_;

  grsim::StatusTracker tracker_;
  std::optional<UdpEndpoint> status_to_[2];
  uint64_t send_failures_ = 0;
  uint64_t reported_datagrams_ = 0;
  std::vector<idl::SslField> fields_;
  std::vector<idl::SslRobotFeedback> feedback_;

  RejectLog rejects_;              // datagrams this bridge refused
  RejectLog replacement_rejects_;  // teleports turf-sim refused
  std::atomic<uint64_t> datagrams_{0};
  std::atomic<uint64_t> refused_{0};
  std::atomic<uint64_t> commands_{0};
  std::atomic<uint64_t> controls_{0};
  std::atomic<uint64_t> unanswered_{0};  // teleports without a reply (no turf-sim, or a timeout)
  std::atomic<uint64_t> status_packets_{0};
  std::atomic<bool> sim_present_{false};
  StalledAuthenticationRestart restart_;
  std::atomic<bool> field_known_{false};
};

GrsimBridge::GrsimBridge(GrsimBridgeOptions options) : impl_(std::make_unique<Impl>(std::move(options))) {
  RouteProtobufLogs();
}
GrsimBridge::~GrsimBridge() = default;
void GrsimBridge::Run(const std::function<bool()>& stop) { impl_->Run(stop); }
uint16_t GrsimBridge::port() const { return impl_->port(); }
GrsimBridgeStats GrsimBridge::Stats() const { return impl_->Stats(); }
uint64_t GrsimBridge::Rejected(const std::string& kind) const { return impl_->Rejected(kind); }

}  // namespace turf
