// turf-simspark-bridge: the SimSpark / rcssserver3d agent protocol (TCP 3100)
// and trainer protocol (TCP 3200) in front of turf-sim running a legged scene
// (configs/scenes/simspark_match.yaml), so RoboCup 3D soccer simulation teams
// run their agents unchanged.
//
// The bridge is the match's clock: it holds turf-sim in lockstep and steps it
// one SimSpark cycle (0.02 s) at a time. Real-time mode: a cycle every 20 ms
// of wall time (no catching up when late, like the reference). Sync mode: a
// cycle as soon as every agent with a robot has sent (syn), none while no agent
// has a robot, so a run depends on the agents' messages alone. Agents may connect
// at any time, all at once; each gets a parked robot of the scene at `scene`.
// The agent port listens from the start: agents that connect while turf-sim is
// still loading its scene (seconds on a busy machine) wait and are served once
// the bridge has attached (attach_timeout), so a team need not time its start.
//
// Untrusted input: a frame longer than 64 KiB, or a client that stops reading
// (more than max_unsent bytes waiting), drops that client; a malformed message or predicate
// is logged, counted and ignored; so is a trainer value out of range
// (codecs/simspark/trainer.h). Trainer commands that end, restart or rewrite
// the match (simspark::IsMatchControl) are accepted only from operators:
// monitor-port clients whose address is in operator_allow; anyone else's are
// refused ("trainer.not_operator"). A team's name is freed when its last agent
// leaves. Clients connecting and leaving are logged at most once a second per
// kind (with counts), so a connection flood cannot flood the log. Facts:
// shared/protocols/simspark.md; the trust model: README.md beside this file.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "participants/common/address_allowlist.h"
#include "participants/common/participant_options.h"
#include "participants/lockstep_front_end/front_end_handle.h"

namespace turf {

// The default operators: this machine only (the loopback ranges).
inline const std::vector<std::string> kDefaultOperatorAllow = {"127.0.0.0/8", "::1"};

struct SimSparkBridgeOptions : ParticipantOptions {
  SimSparkBridgeOptions() { name = "turf-simspark-bridge"; }
  std::string listen = "0.0.0.0";
  uint16_t agent_port = 3100;    // 0: any free port (tests)
  uint16_t monitor_port = 3200;  // 0: any free port
  bool sync_mode = false;
  // Sync mode: cycles after an agent's `scene` run without waiting for its (syn) (rcssserver3d waits from the first).
  int sync_grace_cycles = 5;
  uint64_t seed = 1;
  std::chrono::milliseconds attach_timeout{30000};  // waiting for turf-sim at start
  std::chrono::milliseconds step_timeout{5000};     // turf-sim's answer to one cycle
  // Sync mode: an agent that sends no (syn) for this long is dropped (0: wait forever).
  std::chrono::milliseconds sync_timeout{10000};
  size_t max_clients = 64;
  size_t max_unsent = 1 << 20;  // bytes a client may leave unread before it is dropped
  double duration = 0.0;        // stop after this many simulated seconds (0: run until stopped)
  // Operators' addresses, "ADDR" or "ADDR/PREFIX" (participants/common/address_allowlist.h); empty: nobody.
  std::vector<std::string> operator_allow = kDefaultOperatorAllow;
};

struct SimSparkBridgeStats : LeagueStats {};

class SimSparkBridgeImpl;  // simspark_bridge.cpp

// Binds the ports on construction (std::invalid_argument for a bad operator_allow entry); Run until stop() (polled),
// a trainer's (killsim) or a fatal DDS error (front_end_handle.h).
class SimSparkBridge : public LeagueHandle<SimSparkBridgeImpl, SimSparkBridgeOptions, SimSparkBridgeStats> {
 public:
  using LeagueHandle::LeagueHandle;
};

}  // namespace turf
