// turf's RCSSServerMJ front-end: the agent protocol of the 2026 RoboCup 3D soccer simulation server (TCP 60000)
// and its monitor commands (TCP 60001) in front of turf-sim running a legged scene of T1/K1 robots
// (configs/scenes/rcssservermj_fifa.yaml), so 3D-league agents run unchanged. Facts:
// shared/protocols/rcssservermj.md; the league's semantics: codecs/rcssservermj/session.h.
//
// The front-end is the match's clock: it holds turf-sim in lockstep and steps it one cycle (0.02 s, 4 physics steps
// of 5 ms) at a time.
//   real time (default): a cycle every 20 ms of wall time (no catching up when late, as the reference)
//   sync (--sync): a cycle needs exactly one message from every active agent (an agent silent for agent_timeout
//                  is dropped, as the reference's 5 s); with real time too, it also waits for the 20 ms
//   as fast as possible (realtime = false, implies sync): a cycle as soon as every agent has answered
//   sequential (--sequential, implies sync): actions act in the very next step (no cycle of latency)
// Agents that sent init are activated at the start of the next cycle; with none active and none waiting, a sync
// front-end idles. Robots: the scene's parked robots, one per agent, of the model the agent asked for; an agent's
// robot is parked again when it leaves.
//
// Monitor-port clients from addresses outside monitor_allow are refused (closed, counted). Untrusted input: a frame
// longer than 64 KiB, a first message that is not a valid init, a refused init, more than
// 16 messages waiting, or a client that stops reading drops that client only; malformed actions are logged,
// counted and ignored.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "participants/common/participant_options.h"
#include "participants/lockstep_front_end/front_end_handle.h"

namespace turf {

struct RcssServerMjOptions : ParticipantOptions {
  RcssServerMjOptions() { name = "turf-rcssservermj-bridge"; }
  std::string listen = "127.0.0.1";  // the reference's default bind address
  uint16_t agent_port = 60000;       // 0: any free port (tests)
  uint16_t monitor_port = 60001;
  bool sync_mode = false;
  bool sequential = false;
  bool realtime = true;        // false: as fast as the agents answer (implies sync)
  std::string rules = "fifa";  // fifa, ssim, ssim_2025, hl_adult, hl_adult_2025
  std::string field;           // empty: the rule book's
  uint64_t seed = 1;
  std::chrono::milliseconds attach_timeout{30000};
  std::chrono::milliseconds step_timeout{5000};
  std::chrono::milliseconds agent_timeout{5000};  // sync: an agent that sends nothing this long is dropped
  // Who may connect to the monitor port ("ADDR" or "ADDR/PREFIX"; participants/common/address_allowlist.h): its
  // commands move players and the ball, set play modes and stop the server. Default: this machine only.
  std::vector<std::string> monitor_allow = {"127.0.0.0/8", "::1"};
  size_t max_clients = 64;
  size_t max_unsent = 1 << 20;
  double duration = 0.0;  // simulated seconds, then Run returns (0: until stopped)
};

struct RcssServerMjStats : LeagueStats {
  int active_agents = 0;  // with a robot
};

class RcssServerMjBridgeImpl;  // rcssservermj_bridge.cpp

// Binds the ports on construction (std::invalid_argument for a bad rule book or field); Run until stop() (polled), a
// monitor's (killsim) or a fatal DDS error (front_end_handle.h).
class RcssServerMjBridge : public LeagueHandle<RcssServerMjBridgeImpl, RcssServerMjOptions, RcssServerMjStats> {
 public:
  using LeagueHandle::LeagueHandle;
};

}  // namespace turf
