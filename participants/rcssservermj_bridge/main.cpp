// turf-rcssservermj-bridge: the 2026 RoboCup 3D soccer simulation server's agent protocol (RCSSServerMJ, TCP 60000)
// and monitor commands (TCP 60001) in front of turf-sim running a legged scene of T1/K1 robots. Ports, modes and
// choices: rcssservermj_bridge.h. turf-sim --rcssservermj serves the same in turf-sim's own process.
#include "participants/common/cli_checks.h"
#include "participants/common/participant_main.h"
#include "participants/common/process.h"
#include "participants/rcssservermj_bridge/rcssservermj_bridge.h"
#include "participants/rcssservermj_bridge/rcssservermj_flags.h"

int main(int argc, char** argv) {
  turf::ParticipantMain participant(
      "turf-rcssservermj-bridge: RCSSServerMJ agents (TCP 60000) and monitor commands (TCP 60001) in front of "
      "turf-sim running a legged scene (configs/scenes/rcssservermj_fifa.yaml)");
  CLI::App& app = participant.app();
  turf::RcssServerMjOptions options;
  participant.AddCommonFlags(options);
  app.add_option("--listen", options.listen, "IPv4 address both TCP ports bind to")->capture_default_str();
  turf::AddRcssServerMjFlags(app, options);
  app.add_option("--seed", options.seed, "seed of the random kick-off side")->capture_default_str();
  app.add_option("--duration", options.duration, "stop after this many simulated seconds (0: run until Ctrl-C)")
      ->check(turf::FiniteAtLeastZero());
  return participant.Run(argc, argv, [&] {
    return turf::RcssServerMjBridge(options).Run(turf::StopRequested) ? turf::kExitClean : turf::kExitFailure;
  });
}
