// turf-simspark-bridge: the RoboCup 3D soccer simulation server's agent and
// trainer protocols in front of turf-sim. Ports, modes and choices: simspark_bridge.h.
#include <chrono>

#include "participants/common/participant_main.h"
#include "participants/common/process.h"
#include "participants/common/writer_watch.h"
#include "participants/simspark_bridge/simspark_bridge.h"
#include "participants/simspark_bridge/simspark_flags.h"

int main(int argc, char** argv) {
  turf::ParticipantMain participant(
      "turf-simspark-bridge: SimSpark/rcssserver3d agents (TCP 3100) and trainers (TCP 3200) in front of turf-sim "
      "running a legged scene (configs/scenes/simspark_match.yaml)");
  turf::SimSparkBridgeOptions options;
  int sync_timeout_ms = static_cast<int>(options.sync_timeout.count());
  turf::AddSimSparkBridgeFlags(participant, options, sync_timeout_ms);
  return participant.Run(argc, argv, [&] {
    options.sync_timeout = std::chrono::milliseconds(sync_timeout_ms);
    const turf::BridgeWriterWatch watch(options);  // two simulators on the bridge's domain and prefix
    return turf::SimSparkBridge(options).Run(turf::StopRequested) ? turf::kExitClean : turf::kExitFailure;
  });
}
