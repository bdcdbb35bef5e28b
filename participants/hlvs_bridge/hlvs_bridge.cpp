#include "participants/hlvs_bridge/hlvs_bridge.h"

#include <spdlog/spdlog.h>
#include <sys/socket.h>
#include <turf/idl/JointsPubSubTypes.h>
#include <turf/idl/SimControlPubSubTypes.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <stdexcept>

#include "codecs/hlvs/camera_source.h"
#include "codecs/hlvs/session.h"
#include "codecs/hlvs/wire.h"
#include "participants/common/address_allowlist.h"
#include "participants/common/front_end_server.h"
#include "participants/common/legged_lockstep.h"
#include "participants/common/process.h"
#include "participants/common/protobuf_log.h"
#include "participants/common/watched_stats.h"
#include "participants/hlvs_bridge/robot_binding.h"
#include "participants/lockstep_front_end/front_end_handle_impl.h"
#include "participants/lockstep_front_end/lockstep_world.h"

namespace turf {

namespace {

using Clock = std::chrono::steady_clock;
constexpr const char* kClient = "turf-hlvs-bridge";

// One robot port: its team and number, and once attached its robot, session and client.
struct Slot {
  std::string team;
  int player = 0;
  const AddressAllowlist* allow = nullptr;
  const hlvs::RobotModel* model = nullptr;  // null: no robot of this name in the scene
  std::string robot;
  std::optional<RobotBinding> binding;
  std::unique_ptr<hlvs::Session> session;
  std::unique_ptr<hlvs::NetworkQuota> quota;
  int fd = -1;  // the client's, -1: none
  std::vector<hlvs::ActuatorRequests> queued;
  bool camera_logged = false;
};

FrontEndServer::Options ServerOptions(const HlvsBridgeOptions& o) {
  FrontEndServer::Options s;
  s.listen = o.listen;
  std::vector<uint16_t> ports = o.red_ports;
  ports.insert(ports.end(), o.blue_ports.begin(), o.blue_ports.end());
  if (ports.empty()) throw std::invalid_argument("no HLVS ports");
  s.agent_port = ports.front();
  s.more_agent_ports.assign(ports.begin() + 1, ports.end());
  s.monitor = false;
  s.max_clients = ports.size() * 4;
  s.max_unsent = o.max_unsent;
  return s;
}

uint64_t UnixMs() {
  return static_cast<uint64_t>(
      std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::system_clock::now().time_since_epoch())
          .count());
}

// The network quota's clock: a step of the wall clock (NTP, by hand) must not close or open its window.
uint64_t SteadyMs() {
  return static_cast<uint64_t>(
      std::chrono::duration_cast<std::chrono::milliseconds>(Clock::now().time_since_epoch()).count());
}

// The slot's client is gone: its unapplied input dropped, its sensors off (cameras no longer drawn for it); the next
// client starts as a new connection does.
void Vacate(Slot* s) {
  s->fd = -1;
  s->queued.clear();
  s->camera_logged = false;
  if (s->session) s->session->ClientLeft();
}

// The client on `fd` has closed its side (its FIN is there, nothing unread before it): the reference would have
// accepted the next client by now, so a reconnecting client is not refused as "busy" for the old one.
bool PeerHasClosed(int fd) {
  char byte;
  const ssize_t n = recv(fd, &byte, 1, MSG_PEEK | MSG_DONTWAIT);
  return n == 0 || (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR);
}

// "k1" for a robot file label "../robots/k1.xml", upper case.
std::string ModelOf(const std::string& label) {
  std::string stem = label.substr(label.find_last_of('/') + 1);
  stem = stem.substr(0, stem.find('.'));
  std::transform(stem.begin(), stem.end(), stem.begin(), [](unsigned char c) { return std::toupper(c); });
  return stem;
}

}  // namespace

class HlvsBridgeImpl {
 public:
  HlvsBridgeImpl(HlvsBridgeOptions options, dds::Bus* bus)
      : options_(std::move(options)),
        red_allow_(options_.red_allow),
        blue_allow_(options_.blue_allow),
        rejects_("HLVS input"),
        link_(MakeLockstep(options_, bus, kClient, false)) {
    RouteProtobufLogs();  // a client's malformed request: libprotobuf's lines rate-limited, as the other bridges'
    for (size_t i = 0; i < options_.red_ports.size(); ++i) slots_.push_back(MakeSlot("red", i + 1, &red_allow_));
    for (size_t i = 0; i < options_.blue_ports.size(); ++i) slots_.push_back(MakeSlot("blue", i + 1, &blue_allow_));
    server_ = std::make_unique<FrontEndServer>(ServerOptions(options_), "HLVS client", &rejects_, MakeHooks());
    ports_ = server_->agent_ports();
  }

  void SetCameraSource(hlvs::CameraSource* source) { cameras_ = source; }

  uint16_t port(const std::string& team, int player) const {
    for (size_t i = 0; i < slots_.size(); ++i)
      if (slots_[i].team == team && slots_[i].player == player) return ports_[i];
    return 0;
  }

  bool Run(const std::function<bool()>& stop) {
    if (!Attach(stop)) return stop();
    const auto period = options_.realtime_factor > 0
                            ? std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double, std::milli>(
                                  hlvs::kBasicStepMs / options_.realtime_factor))
                            : Clock::duration::zero();
    const int64_t end_steps =
        options_.duration > 0 ? std::llround(options_.duration * 1000.0 / hlvs::kBasicStepMs) : -1;
    auto next = Clock::now();
    auto next_status = Clock::now() + std::chrono::seconds(10);
    while (!stop()) {
      PollUntil(next, stop);
      if (stop()) break;
      if (!RunStep(stop)) return stop();
      next = std::max(next + period, Clock::now());  // late: no catching up
      if (Clock::now() >= next_status) {
        ReportStatus();
        next_status = Clock::now() + std::chrono::seconds(10);
      }
      if (end_steps >= 0 && static_cast<int64_t>(steps_done_) >= end_steps) break;
    }
    ReportStatus();
    return true;
  }

  const WatchedStats<HlvsBridgeStats>& stats() const { return stats_; }

 private:
  static Slot MakeSlot(const char* team, size_t player, const AddressAllowlist* allow) {
    Slot s;
    s.team = team;
    s.player = static_cast<int>(player);
    s.allow = allow;
    return s;
  }

  bool Attach(const std::function<bool()>& stop) {
    if (!link_->Attach(options_.attach_timeout, stop)) return false;
    if (cameras_ != nullptr) cameras_->Attached(link_->state().sim_time_ns());
    steps_ = static_cast<uint32_t>(std::max<long>(1, std::lround(hlvs::kBasicStepMs * 1e-3 / link_->step_s())));
    if (std::abs(steps_ * link_->step_s() - hlvs::kBasicStepMs * 1e-3) > 1e-9)
      throw std::invalid_argument(
          fmt::format("the scene's physics step ({} ms) does not divide HLVS's 8 ms step", link_->step_s() * 1e3));
    pending_.step_count(steps_);
    for (const idl::RobotDescription& r : link_->scene_info().robots()) BindSlot(r);
    LogStart();
    return true;
  }

  void BindSlot(const idl::RobotDescription& r) {
    for (size_t i = 0; i < slots_.size(); ++i) {
      Slot& s = slots_[i];
      if (r.robot() != fmt::format("{}_{}", s.team, s.player)) continue;
      const hlvs::RobotModel* model = hlvs::FindModel(ModelOf(r.model()));
      std::string error;
      if (model == nullptr) {
        spdlog::warn("robot '{}' ({}) is not served: HLVS tables exist for K1 and T1", r.robot(), r.model());
        return;
      }
      s.binding = BindRobot(link_->state(), r.robot(), *model, &error);
      if (!s.binding) throw std::invalid_argument(error);
      s.model = model;
      s.robot = r.robot();
      hlvs::SessionOptions o;
      o.robot = r.robot();
      o.model = model;
      o.limits = JointLimitsOf(*model);
      o.team_players = options_.team_players;
      o.cameras = cameras_;
      s.session = std::make_unique<hlvs::Session>(o);
      s.quota = std::make_unique<hlvs::NetworkQuota>(options_.team_players);
      return;
    }
  }

  void LogStart() {
    for (size_t i = 0; i < slots_.size(); ++i) {
      const Slot& s = slots_[i];
      if (s.model != nullptr) {
        spdlog::info("{} player {}: robot '{}' ({}) on TCP {}:{}; clients from {}", s.team, s.player, s.robot,
                     s.model->name, options_.listen, ports_[i], s.allow->Describe());
      } else {
        spdlog::info("{} player {}: no robot '{}_{}' in the scene; TCP {}:{} refuses its clients", s.team, s.player,
                     s.team, s.player, options_.listen, ports_[i]);
      }
    }
    spdlog::info("{} physics steps of {} ms per 8 ms step; {}; publishing {} (steps, joint commands)", steps_,
                 link_->step_s() * 1e3,
                 options_.realtime_factor > 0 ? fmt::format("real time x{}", options_.realtime_factor)
                                              : std::string("as fast as possible"),
                 link_->TopicName(dds::Topic::kControl));
    if (cameras_ == nullptr)
      spdlog::info("no camera image source: enabled cameras are accepted but no images are sent");
  }

  void PollUntil(Clock::time_point until, const std::function<bool()>& stop) {
    do {
      const auto wait = std::chrono::duration_cast<std::chrono::milliseconds>(until - Clock::now());
      server_->Poll(std::max(wait, std::chrono::milliseconds(0)));
    } while (Clock::now() < until && !stop());
  }

  bool RunStep(const std::function<bool()>& stop) {
    std::string error;
    std::vector<std::string> warnings;
    const bool commands = !pending_.joint_commands().empty();
    idl::SimControl bare = pending_;
    bare.joint_commands().clear();
    bool stepped = link_->Step(std::move(pending_), steps_, options_.step_timeout, stop, &error, &warnings);
    if (!stepped && commands && !stop() && error.rfind("turf-sim refused the step", 0) == 0) {
      // Joint commands this scene refuses (a motors.max_speed below the HLVS table's max_velocity): the match goes
      // on without them, counted.
      rejects_.Reject("step_refused", error);
      stepped = link_->Step(std::move(bare), steps_, options_.step_timeout, stop, &error, &warnings);
    }
    if (!stepped) {
      if (!stop()) spdlog::error("{}", error);
      return false;
    }
    for (const std::string& w : warnings) rejects_.Reject("refused_by_turf_sim", w);
    time_ms_ += hlvs::kBasicStepMs;
    ++steps_done_;
    pending_ = idl::SimControl();
    pending_.op(idl::OP_STEP);
    pending_.step_count(steps_);
    const uint64_t real = UnixMs();
    const uint64_t steady = SteadyMs();
    for (Slot& s : slots_) ServeSlot(&s, real, steady);
    server_->FlushDrops();
    stats_.Update([&](HlvsBridgeStats& s) {
      s.steps = steps_done_;
      s.time_ms = time_ms_;
      s.refused = rejects_.Total();
      s.refused_by_kind = rejects_.counts();
    });
    return true;
  }

  void ServeSlot(Slot* s, uint64_t real_ms, uint64_t steady_ms) {
    if (s->model == nullptr) return;
    const hlvs::RobotReading reading = ReadRobot(link_->state(), *s->binding);
    if (s->fd >= 0) {
      for (const hlvs::ActuatorRequests& r : s->queued) s->session->Apply(r, time_ms_);
      s->queued.clear();
      Send(s, s->session->Measure(reading, time_ms_, real_ms), steady_ms);
    }
    idl::JointCommand command;
    command.robot(s->robot);
    for (const hlvs::JointOutput& o : s->session->Commands(reading)) command.joints().push_back(ToJointTarget(o));
    if (!command.joints().empty()) pending_.joint_commands().push_back(std::move(command));
  }

  void Send(Slot* s, hlvs::SensorMeasurements m, uint64_t steady_ms) {
    if (s->session->camera_unavailable() && !s->camera_logged) {
      if (cameras_ == nullptr)
        spdlog::info("{}: a camera is enabled but there is no image source: no images are sent", s->robot);
      else
        spdlog::info(
            "{}: a camera was due and no new image of its size had come (not drawn yet; or is turf-render "
            "not running with this scene?): it is left out of such messages (logged once)",
            s->robot);
      s->camera_logged = true;
    }
    hlvs::EncodeResult framed = hlvs::FrameSensorMeasurements(m);
    if (framed.error == Error::kOk && !s->quota->Admit(framed.framed.size(), steady_ms)) {
      hlvs::SensorMeasurements over;
      over.time_ms = m.time_ms;
      over.real_time_ms = m.real_time_ms;
      over.messages.push_back({hlvs::MessageType::kError, s->quota->ExceededText()});
      framed = hlvs::FrameSensorMeasurements(over);
      rejects_.Reject("network_quota", fmt::format("{}: {}", s->robot, s->quota->ExceededText()));
    }
    if (framed.error != Error::kOk) {
      rejects_.Reject(std::string("measurement.") + ErrorName(framed.error), s->robot);
      return;
    }
    server_->Send(s->fd, framed.framed);
  }

  int SlotOfPort(uint16_t port) const {
    for (size_t i = 0; i < ports_.size(); ++i)
      if (ports_[i] == port) return static_cast<int>(i);
    return -1;
  }

  bool Refuse(FrontEndClient& c, const std::string& kind, const std::string& detail) {
    std::string error;
    c.peer->Write(std::string(hlvs::kRefused), &error);  // 8 bytes on a fresh socket; closed when c goes
    rejects_.Reject(kind, detail);
    stats_.Update([&](HlvsBridgeStats& s) { ++s.refused_clients; });
    return false;
  }

  FrontEndServer::Hooks MakeHooks() {
    FrontEndServer::Hooks h;
    h.admit = [this](FrontEndClient& c, const std::string& address, std::string* greeting) {
      const int i = SlotOfPort(c.port);
      if (i < 0) return Refuse(c, "no_robot", fmt::format("{} on port {}", address, c.port));
      Slot& s = slots_[i];
      if (!s.allow->Allows(address))
        return Refuse(c, "client_not_allowed",
                      fmt::format("{} on {} player {}: not in {}", address, s.team, s.player, s.allow->Describe()));
      if (s.model == nullptr)
        return Refuse(c, "no_robot", fmt::format("{}: no robot {}_{} (yet)", address, s.team, s.player));
      if (s.fd >= 0 && PeerHasClosed(s.fd)) {
        server_->MarkDrop(s.fd, "closed by the peer");
        Vacate(&s);
      }
      if (s.fd >= 0) return Refuse(c, "port_busy", fmt::format("{}: {} already has a client", address, s.robot));
      s.fd = c.peer->fd();
      s.queued.clear();
      c.agent = i;
      *greeting = std::string(hlvs::kWelcome);
      server_->connections().Reject("client_connected", fmt::format("{} for {}", address, s.robot));
      stats_.Update([&](HlvsBridgeStats& s) {
        ++s.welcomed;
        ++s.clients;
      });
      return true;
    };
    h.message = [this](FrontEndClient& c, const std::string& payload) {
      Slot& s = slots_[c.agent];
      if (s.fd != c.peer->fd()) return;  // already refused input: being dropped
      hlvs::DecodeResult r = hlvs::DecodeActuatorRequests(payload);
      if (r.error == Error::kOk) {
        s.queued.push_back(std::move(r.requests));
        return;
      }
      rejects_.Reject(std::string("request.") + ErrorName(r.error), fmt::format("{}: {}", s.robot, r.detail));
      Vacate(&s);  // nothing of this client's unapplied input moves the robot
      server_->MarkDrop(c.peer->fd(), "sent a refused request");
    };
    h.left = [this](const FrontEndClient& c) {
      if (c.agent < 0) return;
      Slot& s = slots_[c.agent];
      if (s.fd == c.peer->fd()) Vacate(&s);
      stats_.Update([&](HlvsBridgeStats& s) {
        ++s.dropped_clients;
        --s.clients;
      });
    };
    return h;
  }

  void ReportStatus() {
    int clients = 0;
    for (const Slot& s : slots_) clients += s.fd >= 0;
    spdlog::info("step {} time {} ms clients {} refused {}", steps_done_, time_ms_, clients, rejects_.Total());
  }

  HlvsBridgeOptions options_;
  AddressAllowlist red_allow_;
  AddressAllowlist blue_allow_;
  RejectLog rejects_;
  std::unique_ptr<LeggedLockstep> link_;
  std::vector<Slot> slots_;  // red players, then blue, as the ports
  std::unique_ptr<FrontEndServer> server_;
  std::vector<uint16_t> ports_;
  hlvs::CameraSource* cameras_ = nullptr;
  idl::SimControl pending_ = FirstStep();
  uint32_t steps_ = 1;
  uint32_t time_ms_ = 0;
  uint64_t steps_done_ = 0;
  WatchedStats<HlvsBridgeStats> stats_;

  static idl::SimControl FirstStep() {
    idl::SimControl c;
    c.op(idl::OP_STEP);
    return c;
  }
};

template class FrontEndHandle<HlvsBridgeImpl, HlvsBridgeOptions, HlvsBridgeStats>;

void HlvsBridge::SetCameraSource(hlvs::CameraSource* source) { impl_->SetCameraSource(source); }
uint16_t HlvsBridge::port(const std::string& team, int player) const { return impl_->port(team, player); }

}  // namespace turf
