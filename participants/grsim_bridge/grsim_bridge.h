// turf-grsim-bridge: lets team software that speaks grSim's UDP protocol drive
// turf-sim. The codec is codecs/grsim/; this is the socket and DDS plumbing.
//
// UDP (wire facts: shared/protocols/grsim.md):
//   listens  <listen>:<port> (0.0.0.0:20011)   grSim_Packet: commands, replacement
//   sends    <sender ip>:<blue/yellow status port> (30011 / 30012)   Robots_Status,
//            to the address that last sent that team's commands, only when a
//            robot's infrared / flat_kick / chip_kick changes (as grSim does)
// DDS (topic names <prefix>/..., QoS profile in brackets, configs/qos/turf_qos.xml):
//   publishes   ssl/command/blue, .../yellow [turf.command]  SslRobotCommand: each decoded robot
//                                                            command, on its team's topic
//               control [turf.control]                       SimControl: a teleport per replaced
//                                                            robot, then the ball
//   subscribes  ssl/feedback/blue, .../yellow [turf.feedback] SslRobotFeedback -> robot status
//               ssl/field [turf.field, latched]              SslField: robots per team, wheel radius,
//                                                            kick limits (before it: the options)
//               control_reply [turf.reply]                   SimControlReply: refused teleports are
//                                                            logged, unanswered ones counted
//                                                            (requests and replies: dds/control_client.h)
// Rates: one command sample per robot per datagram (a team's frame, ~60 Hz); a
// control request per replacement; status on change. No watchdog here: teams
// are independent, and turf-sim's watchdog is per robot.
// Flags (main.cpp, --help): --listen, --port, --blue-status-port,
// --yellow-status-port, --blue-allow, --yellow-allow, --operator-allow, --domain,
// --prefix, --qos, --robots-per-team, --wheel-radius, --wheel-order,
// --dribbler-rpm, --max-datagram, --log-level.
// A refused datagram (see GrsimError) is dropped whole, counted per kind and
// logged at a limited rate; turf-sim never hears of it. So is one whose sender
// the source allowlists (participants/common/source_gate.h) do not allow: its
// commands' team's list, and for a replacement the operator list ("blue.not_allowed",
// "yellow.not_allowed", "operator.not_allowed"); nothing of it moves, and it does
// not redirect that team's robot status.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "codecs/grsim/grsim_codec.h"
#include "core/pinned.h"
#include "participants/common/participant_options.h"
#include "participants/common/source_gate.h"

namespace turf {

// `name` is the DDS participant's, and the `client` of its control requests.
struct GrsimBridgeOptions : ParticipantOptions {
  GrsimBridgeOptions() { name = "turf-grsim-bridge"; }
  std::string listen_ip = "0.0.0.0";
  uint16_t port = 20011;  // 0: any free port (see GrsimBridge::port())
  uint16_t blue_status_port = 30011;
  uint16_t yellow_status_port = 30012;
  grsim::GrsimCodecConfig codec;  // until ssl/field arrives
  SourceAllowlists allow;         // who may command each team, who may replace (empty: anyone)
};

// The allowlists a decoded packet must pass (null: none): its commands' team's, then the operator's when it
// replaces the ball or robots. A packet one of them refuses is refused whole. Pure.
std::array<SourceGate*, 2> GatesFor(const grsim::GrsimRequests& requests, SourceGates& gates);

struct GrsimBridgeStats {
  uint64_t datagrams = 0;       // received
  uint64_t refused = 0;         // datagrams refused, every kind
  uint64_t not_allowed = 0;     // of those, refused for their source (the allowlists)
  uint64_t commands = 0;        // robot commands published
  uint64_t controls = 0;        // teleport requests published
  uint64_t status_packets = 0;  // Robots_Status sent
  bool sim_present = false;     // turf-sim's command and control readers are matched
  bool field_known = false;     // ssl/field arrived
};

class GrsimBridge : Pinned {
 public:
  // Binds the socket and creates the DDS entities. Throws std::invalid_argument
  // for bad options, std::runtime_error for the socket or DDS.
  explicit GrsimBridge(GrsimBridgeOptions options);
  ~GrsimBridge();

  // Runs until `stop()` answers true (checked at least every 10 ms).
  void Run(const std::function<bool()>& stop);
  uint16_t port() const;  // the UDP port it listens on
  GrsimBridgeStats Stats() const;
  // Refusals of one kind: a GrsimErrorName, "<list>.not_allowed", "control_rejected" (turf-sim refused a teleport) or
  // "control_unanswered" (no turf-sim, or no reply within 10 s).
  uint64_t Rejected(const std::string& kind) const;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace turf
