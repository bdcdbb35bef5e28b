#include "participants/simproto_bridge/simproto_bridge.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <atomic>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>
#include <vector>

#include "codecs/ssl_simulation/errors.h"
#include "codecs/ssl_simulation/robot_control.h"
#include "codecs/ssl_simulation/simulator_command.h"
#include "codecs/ssl_simulation/step_planner.h"
#include "codecs/ssl_simulation/sync.h"
#include "core/enum_names.h"
#include "kernel/time_control.h"
#include "participants/common/process.h"
#include "participants/common/protobuf_log.h"
#include "participants/common/stalled_authentication.h"
#include "participants/common/udp.h"
#include "participants/simproto_bridge/sim_link.h"

namespace turf {

namespace {

using namespace std::chrono_literals;
namespace sp = simproto;

constexpr size_t kReceiveBytes = 65536;  // any UDP datagram; the codec refuses what is too large

enum class Kind { kControl, kBlue, kYellow, kSync };
constexpr const char* kKindNames[] = {"control", "blue", "yellow", "sync"};
constexpr const char* kKindMessages[] = {"SimulatorCommand -> SimulatorResponse",
                                         "RobotControl (blue robots) -> RobotControlResponse",
                                         "RobotControl (yellow robots) -> RobotControlResponse",
                                         "SimulationSyncRequest -> SimulationSyncResponse (ids 16..31: yellow)"};

const char* Name(Kind kind) { return kKindNames[static_cast<int>(kind)]; }

// On `bus`, or (null) on a DDS participant of the link's own.
SimLink MakeLink(const SimprotoBridgeOptions& o, dds::Bus* bus) {
  if (bus != nullptr) return SimLink(*bus, o.name);
  return SimLink(DdsOptions(o));
}

const sp::SimError kNotAvailable{sp::kSimNotAvailable, "turf-sim has not been seen yet (field, world state, clock)"};
const sp::SimError kSyncDisabled{sp::kSyncDisabled,
                                 "synchronous mode is off in this match: whoever starts it enables it "
                                 "(turf-simproto-bridge --sync, turf-sim --simproto-sync, --set simproto.sync=true)"};

}  // namespace

class SimprotoBridge::Impl {
 public:
  Impl(SimprotoBridgeOptions options, dds::Bus* bus)
      : options_(std::move(options)), link_(MakeLink(options_, bus)), gates_(options_.allow), rejects_("datagram") {
    if (!MakeEndpoint(options_.listen, 0))
      throw std::invalid_argument("--listen is not an IPv4 address: " + options_.listen);
    if (!MakeEndpoint(options_.sync_listen, 0))
      throw std::invalid_argument("--sync-listen is not an IPv4 address: " + options_.sync_listen);
    const uint16_t ports[] = {options_.control_port, options_.blue_port, options_.yellow_port, options_.sync_port};
    for (int k = 0; k < 4; ++k) {
      if (ports[k] == 0) continue;
      std::string error;
      const std::string& ip = static_cast<Kind>(k) == Kind::kSync ? options_.sync_listen : options_.listen;
      std::optional<UdpSocket> s = UdpSocket::Bind(ip, ports[k], false, &error);
      if (!s) throw std::runtime_error(std::string("cannot bind the ") + kKindNames[k] + " port: " + error);
      const auto kind = static_cast<Kind>(k);
      sockets_.push_back({kind, std::move(*s), &Gate(kind), fmt::format("{}.not_allowed", Name(kind))});
    }
  }

  void Run(const std::function<bool()>& stop) {
    ReportStartup();
    std::vector<std::thread> threads;
    for (Socket& s : sockets_) threads.emplace_back([this, &s] { Serve(s); });
    bool seen = false;
    auto next_status = std::chrono::steady_clock::now() + 10s;
    SimprotoBridgeStats last{};
    while (!stop()) {
      std::this_thread::sleep_for(50ms);
      if (!seen) seen = ReportSim();
      if (restart_.Check(link_.AuthenticationsNow(), !seen)) break;
      if (std::chrono::steady_clock::now() >= next_status) {
        next_status += 10s;
        const SimprotoBridgeStats s = Stats();
        if (s.datagrams != last.datagrams)
          spdlog::info("datagrams={} answered={} commands={} requests={} refused={} not_allowed={}", s.datagrams,
                       s.answered, s.commands, s.requests, s.rejected, s.not_allowed);
        last = s;
      }
    }
    stopping_.store(true);
    for (std::thread& t : threads) t.join();
  }

  SimprotoBridgeStats Stats() const {
    SimprotoBridgeStats s{datagrams_.load(), answered_.load(), commands_.load(), requests_.load(), rejects_.Total()};
    s.not_allowed = gates_.refused();
    return s;
  }

  uint64_t Rejected(const std::string& kind) const { return rejects_.Count(kind); }

 private:
  struct Socket {
    Kind kind;
    UdpSocket socket;
    SourceGate* gate;         // who may send to it
    std::string not_allowed;  // the refusal kind of a sender the gate does not allow
  };

  // The team ports' own team's list; control and sync (teleports, speed, steps) the operators'.
  SourceGate& Gate(Kind kind) {
    if (kind == Kind::kBlue) return gates_.blue;
    if (kind == Kind::kYellow) return gates_.yellow;
    return gates_.operators;
  }

  void Serve(Socket& s) {
    while (!stopping_.load()) {
      std::optional<Datagram> d = s.socket.Receive(kReceiveBytes, 50ms);
      if (!d) continue;
      ++datagrams_;
      std::vector<uint8_t> answer;
      if (!s.gate->Admit(d->from, rejects_, s.not_allowed))
        answer = NotAllowed(s.kind);
      else
        answer = Handle(s.kind, *d);
      std::string error;
      if (s.socket.SendTo(answer, d->from, &error))
        ++answered_;
      else
        Reject(fmt::format("{}.send_failed", Name(s.kind)), error);
    }
  }

  std::vector<uint8_t> Handle(Kind kind, const Datagram& d) {
    switch (kind) {
      case Kind::kControl:
        return HandleControl(d);
      case Kind::kBlue:
        return HandleTeam(sp::Port::kBlue, Kind::kBlue, d);
      case Kind::kYellow:
        return HandleTeam(sp::Port::kYellow, Kind::kYellow, d);
      case Kind::kSync:
        return HandleSync(d);
    }
    return {};
  }

  // The answer to a sender the port's allowlist refuses: nothing decoded, nothing done.
  static std::vector<uint8_t> NotAllowed(Kind kind) {
    const sp::SimError error{sp::kNotAllowed, "this address is not on the port's allowlist"};
    switch (kind) {
      case Kind::kControl:
        return sp::EncodeSimulatorResponse({error});
      case Kind::kBlue:
      case Kind::kYellow:
        return sp::EncodeRobotControlResponse({}, {}, {error});
      case Kind::kSync:
        return sp::EncodeSyncResponse({}, idl::SslField(), {}, {}, {error});
    }
    return {};
  }

  // --- Ports ---

  std::vector<uint8_t> HandleTeam(sp::Port port, Kind kind, const Datagram& d) {
    const SimLink::View view = link_.Now();
    if (!view.field) {
      Reject(fmt::format("{}.sim_not_available", Name(kind)), "from " + d.from.ToString());
      return sp::EncodeRobotControlResponse({}, {}, {kNotAvailable});
    }
    const sp::RobotControlDecode decoded =
        sp::DecodeRobotControl(d.bytes.data(), d.bytes.size(), port, view.field->robots_per_team());
    if (!Accepted(kind, decoded.error, decoded.errors, d)) return sp::EncodeRobotControlResponse(decoded, {});
    for (const idl::SslRobotCommand& c : decoded.commands) link_.Command(c);
    commands_ += decoded.commands.size();
    return sp::EncodeRobotControlResponse(decoded, *view.contacts);
  }

  std::vector<uint8_t> HandleControl(const Datagram& d) {
    const SimLink::View view = link_.Now();
    if (!view.field || !view.world) {
      Reject("control.sim_not_available", "from " + d.from.ToString());
      return sp::EncodeSimulatorResponse({kNotAvailable});
    }
    const sp::ControlContext context{&*view.field, &*view.world, false};
    const sp::SimulatorCommandDecode decoded = sp::DecodeSimulatorCommand(d.bytes.data(), d.bytes.size(), context);
    if (!Accepted(Kind::kControl, decoded.error, decoded.errors, d)) return sp::EncodeSimulatorResponse(decoded.errors);
    std::vector<sp::SimError> errors = decoded.errors;
    SendRequests(Kind::kControl, decoded.requests, &errors);
    return sp::EncodeSimulatorResponse(errors);
  }

  std::vector<uint8_t> HandleSync(const Datagram& d) {
    const SimLink::View view = link_.Now();
    if (!options_.sync) {
      Reject("sync.disabled", "from " + d.from.ToString() + ": synchronous mode is off in this match");
      return sp::EncodeSyncResponse({}, view.field ? *view.field : idl::SslField(), {}, {}, {kSyncDisabled});
    }
    if (!view.field || !view.world || !view.clock) {
      Reject("sync.sim_not_available", "from " + d.from.ToString());
      return sp::EncodeSyncResponse({}, view.field ? *view.field : idl::SslField(), {}, {}, {kNotAvailable});
    }
    const idl::SslField& field = *view.field;
    const sp::ControlContext context{&field, &*view.world, true};
    const sp::SyncDecode request = sp::DecodeSyncRequest(d.bytes.data(), d.bytes.size(), context, view.clock->step_s());
    if (!Accepted(Kind::kSync, request.error, request.errors, d))
      return sp::EncodeSyncResponse({}, field, request, {}, {});

    std::vector<sp::SimError> errors;
    auto answer = [&](const sp::SyncFrames& frames) {
      return sp::EncodeSyncResponse(frames, field, request, *link_.Now().contacts, errors);
    };
    if (view.clock->mode() != idl::TIME_LOCKSTEP) {
      idl::SimControl lockstep;
      lockstep.op(idl::OP_SET_TIME_MODE);
      lockstep.time_mode(idl::TIME_LOCKSTEP);
      std::optional<idl::SimControlReply> switched;
      if (!SendRequests(Kind::kSync, {lockstep}, &errors, &switched)) return answer({});
      spdlog::info("sync request from {}: turf-sim switched to lockstep", d.from.ToString());
      // turf-sim ran on its own since the session's last step: a new session.
      // (The same frame: our clock sample was only late.)
      if (!switched || !sync_.last_frame || switched->frame() != *sync_.last_frame) sync_.Restart();
    }
    if (!SendRequests(Kind::kSync, request.command.requests, &errors)) return answer({});

    const uint32_t steps = sync_.planner.Plan(request.sim_step_ns, sp::ToNanoseconds(view.clock->step_s()));
    std::vector<idl::SslRobotCommand> commands = sync_.TakeHeld(request.robots.commands);
    if (steps == 0) {
      // turf-sim cannot step 0: the commands go with the session's next step,
      // the same simulation instant (no time passes in between).
      sync_.held = std::move(commands);
      if (spdlog::should_log(spdlog::level::debug))  // the address's text is not made for a line nobody logs
        spdlog::debug("sync request from {}: {} ns asked, 0 steps (carry {} ns)", d.from.ToString(),
                      request.sim_step_ns, sync_.planner.carry_ns());
      return answer({});
    }
    idl::SimControl step;
    step.op(idl::OP_STEP);
    step.step_count(steps);
    step.commands(std::move(commands));
    // turf-sim publishes a step's frames before its reply, on one participant:
    // the frames that arrive between here and the reply are the step's.
    const uint64_t cursor = link_.FrameCursor();
    std::optional<idl::SimControlReply> reply;
    if (!SendRequests(Kind::kSync, {step}, &errors, &reply) || !reply) {
      sync_.Restart();  // unknown how far turf-sim got
      return answer({});
    }
    commands_ += step.commands().size();
    if (sync_.last_frame && reply->frame() != *sync_.last_frame + steps) {
      spdlog::info(
          "sync: turf-sim is at frame {}, not {} (reset, restarted or stepped by another client): the "
          "step carry starts over",
          reply->frame(), *sync_.last_frame + steps);
      sync_.planner.Rebase(request.sim_step_ns, steps);
    }
    sync_.last_frame = reply->frame();
    if (spdlog::should_log(spdlog::level::debug))
      spdlog::debug("sync request from {}: {} ns asked, {} steps, now t = {} ns (carry {} ns)", d.from.ToString(),
                    request.sim_step_ns, steps, reply->sim_time_ns(), sync_.planner.carry_ns());
    return answer(link_.FramesSince(cursor));
  }

  // --- Helpers ---

  // Counts and logs what the codec refused or left out; false if the datagram is refused as a whole.
  bool Accepted(Kind kind, sp::DecodeError error, const std::vector<sp::SimError>& errors, const Datagram& d) {
    if (error != sp::DecodeError::kOk) {
      Reject(fmt::format("{}.{}", Name(kind), sp::DecodeErrorName(error)),
             fmt::format("from {}: {}", d.from.ToString(), errors.empty() ? "" : errors.front().message));
      return false;
    }
    for (const sp::SimError& e : errors)
      Reject(fmt::format("{}.unsupported", Name(kind)),
             fmt::format("from {}: {}: {}", d.from.ToString(), e.code, e.message));
    return true;
  }

  // Sends the requests and waits for their replies; each refusal or missing
  // reply becomes an error. False if any request did not succeed.
  // `last`, if given, receives the last request's reply.
  bool SendRequests(Kind kind, const std::vector<idl::SimControl>& requests, std::vector<sp::SimError>* errors,
                    std::optional<idl::SimControlReply>* last = nullptr) {
    if (requests.empty()) return true;
    requests_ += requests.size();
    const auto replies = link_.Control(requests, options_.reply_timeout, [this] { return stopping_.load(); });
    bool ok = true;
    for (const dds::ControlOutcome& r : replies) {
      if (!r.reply) {
        errors->push_back({sp::kNoReply, fmt::format("turf-sim did not answer within {} ms ({})",
                                                     options_.reply_timeout.count(), r.Describe())});
        Reject(fmt::format("{}.no_reply", Name(kind)), errors->back().message);
        ok = false;
      } else if (!r.ok()) {
        errors->push_back(sp::RejectedBySim(*r.reply));
        Reject(fmt::format("{}.rejected_by_sim", Name(kind)), errors->back().message);
        ok = false;
      }
    }
    if (last != nullptr && !replies.empty()) *last = replies.back().reply;
    return ok;
  }

  void Reject(const std::string& kind, const std::string& detail) { rejects_.Reject(kind, detail); }

  // Logs turf-sim's arrival once; true once it has.
  bool ReportSim() {
    const SimLink::View view = link_.Now();
    if (!view.field || !view.world || !view.clock) return false;
    const idl::SslField& f = *view.field;
    spdlog::info("turf-sim is there: division {}, {} robots a team, {} cameras at {:.0f} Hz, step {} ms, time mode {}",
                 f.division() == 1 ? "A" : "B", static_cast<int>(f.robots_per_team()), f.cameras().size(),
                 f.camera_rate_hz(), view.clock->step_s() * 1e3, EnumName(view.clock->mode(), kTimeModeNames));
    return true;
  }

  void ReportStartup() const {
    gates_.ReportStartup("control and sync");
    for (const Socket& s : sockets_)
      spdlog::info("{} port {}:{}: {}", Name(s.kind), options_.listen, s.socket.LocalPort(),
                   kKindMessages[static_cast<int>(s.kind)]);
    auto name = [this](dds::Topic t) { return link_.TopicName(t); };
    spdlog::info("{}", link_.DescribeBus());
    spdlog::info("publishing {}, {}, {}", name(dds::Topic::kSslCommandBlue), name(dds::Topic::kSslCommandYellow),
                 name(dds::Topic::kControl));
    spdlog::info("subscribing {}, {}, {}, {}, {}, {}, {}", name(dds::Topic::kControlReply),
                 name(dds::Topic::kSslFeedbackBlue), name(dds::Topic::kSslFeedbackYellow), name(dds::Topic::kSslField),
                 name(dds::Topic::kClock), name(dds::Topic::kWorldState), name(dds::Topic::kSslCamera));
    spdlog::info("waiting for turf-sim; until then every datagram is answered with {}", sp::kSimNotAvailable);
  }

  // The sync port's session (its thread only): the step carry, commands of
  // zero-step requests waiting for the next step, turf-sim's frame after the
  // last step (to notice when its time did not continue from there).
  struct SyncSession {
    sp::StepPlanner planner;
    std::vector<idl::SslRobotCommand> held;
    std::optional<uint64_t> last_frame;

    void Restart() {
      planner.Reset();
      last_frame.reset();
    }
    // The held commands of robots `newer` does not command, then `newer`.
    std::vector<idl::SslRobotCommand> TakeHeld(const std::vector<idl::SslRobotCommand>& newer) {
      std::vector<idl::SslRobotCommand> out;
      for (idl::SslRobotCommand& h : held) {
        const bool replaced = std::any_of(newer.begin(), newer.end(), [&](const idl::SslRobotCommand& c) {
          return c.team() == h.team() && c.id() == h.id();
        });
        if (!replaced) out.push_back(std::move(h));
      }
      held.clear();
      out.insert(out.end(), newer.begin(), newer.end());
      return out;
    }
  };

  SimprotoBridgeOptions options_;
  SimLink link_;
  StalledAuthenticationRestart restart_;
  SyncSession sync_;
  std::vector<Socket> sockets_;
  std::atomic<bool> stopping_{false};
  std::atomic<uint64_t> datagrams_{0};
  std::atomic<uint64_t> answered_{0};
  std::atomic<uint64_t> commands_{0};
  std::atomic<uint64_t> requests_{0};
  SourceGates gates_;
  RejectLog rejects_;
};

SimprotoBridge::SimprotoBridge(SimprotoBridgeOptions options)
    : impl_(std::make_unique<Impl>(std::move(options), nullptr)) {
  RouteProtobufLogs();
}
SimprotoBridge::SimprotoBridge(SimprotoBridgeOptions options, dds::Bus& bus)
    : impl_(std::make_unique<Impl>(std::move(options), &bus)) {
  RouteProtobufLogs();
}
SimprotoBridge::~SimprotoBridge() = default;
void SimprotoBridge::Run(const std::function<bool()>& stop) { impl_->Run(stop); }
SimprotoBridgeStats SimprotoBridge::Stats() const { return impl_->Stats(); }
uint64_t SimprotoBridge::Rejected(const std::string& kind) const { return impl_->Rejected(kind); }

}  // namespace turf
