// turf-sim's start-up, behind main.cpp: its own flags (the common ones:
// participant_main.h), --speed and --lockstep into a time mode, the scene and
// realism files, and the node that fits the scene (SSL: sim_node.h; `kind:
// legged`: sim_node.h).
#pragma once

#include <string>

#include "participants/booster_bridge/booster_sdk_bridge.h"
#include "participants/common/participant_main.h"
#include "participants/rcssservermj_bridge/rcssservermj_bridge.h"
#include "participants/sim/node_options.h"
#include "participants/simproto_bridge/simproto_bridge.h"
#include "participants/simspark_bridge/simspark_bridge.h"

namespace turf {

// What turf-sim's command line says, before it is checked and loaded.
struct SimCommandLine {
  std::string scene_path;   // -s, --scene; default: configs/scenes/ssl_div_a.yaml of the source tree
  std::string speed = "1";  // --speed: a multiple of real time, or "max"
  bool lockstep = false;    // --lockstep
  std::string realism;      // --realism: a preset or a file; empty: the scene's
  SimNodeOptions node;      // the common flags, --paused and --duration
  // --simproto [ADDRESS]: serve the SSL simulation protocol in this process (sim_host.h), on 127.0.0.1 unless an
  // address is given; --simproto-*-port as turf-simproto-bridge's port flags.
  bool simproto = false;
  SimprotoBridgeOptions simproto_options;
  // --simspark [ADDRESS]: serve SimSpark agents and monitors in this process (legged scenes), on 127.0.0.1 unless
  // an address is given; --simspark-agent-port, --simspark-monitor-port, --simspark-sync,
  // --simspark-sync-grace-cycles as turf-simspark-bridge's.
  bool simspark = false;
  SimSparkBridgeOptions simspark_options;
  // --rcssservermj [ADDRESS]: serve RCSSServerMJ agents and monitor commands in this process (legged scenes of
  // T1/K1 robots), on 127.0.0.1 unless an address is given; --rcssservermj-* as turf-rcssservermj-bridge's flags.
  bool rcssservermj = false;
  RcssServerMjOptions rcssservermj_options;
  // --booster-sdk [DOMAIN]: the Booster SDK's low-level topics for every T1 and K1 (legged scenes), the first robot
  // on DOMAIN (default 0); --booster-command-timeout.
  bool booster = false;
  BoosterSdkOptions booster_options;
};

// Declares turf-sim's flags on `participant`, in the order --help lists them.
void AddSimFlags(ParticipantMain& participant, SimCommandLine& command_line);

// Sets node.mode (and node.speed) from --speed and --lockstep; false (logged)
// if --speed is not a number in (0, 1000] or "max".
bool ApplyTimeMode(const std::string& speed, bool lockstep, SimNodeOptions& node);

// Checks the time mode, loads the scene and realism, then runs the SSL or the
// legged node until StopRequested(). Returns an ExitCode (participant_main.h):
// kExitBadConfig also when another simulator already writes world_state on the
// same domain and prefix (found in a 1.5 s discovery window, before the node runs).
int RunSim(SimCommandLine command_line);

}  // namespace turf
