// turf-simspark-bridge: the RoboCup 3D soccer simulation server's agent and
// trainer protocols in front of turf-sim. Ports, modes and choices: simspark_bridge.h.
#include <chrono>

#include "participants/common/cli_checks.h"
#include "participants/common/participant_main.h"
#include "participants/common/process.h"
#include "participants/common/writer_watch.h"
#include "participants/simspark_bridge/simspark_bridge.h"
#include "participants/simspark_bridge/simspark_flags.h"

int main(int argc, char** argv) {
  turf::ParticipantMain participant(
      "turf-simspark-bridge",
      "turf-simspark-bridge: SimSpark/rcssserver3d agents (TCP 3100) and trainers (TCP 3200) in front of turf-sim "
      "running a legged scene (configs/scenes/simspark_match.yaml)");
  CLI::App& app = participant.app();
  turf::SimSparkBridgeOptions options;
  int sync_timeout_ms = static_cast<int>(options.sync_timeout.count());
  participant.AddCommonFlags(options);
  app.add_option("--listen", options.listen, "IPv4 address both TCP ports bind to")->capture_default_str();
  participant.AddPort("--agent-port", options.agent_port, "TCP port for agents (0: any free port)", true);
  participant.AddPort("--monitor-port", options.monitor_port, "TCP port for monitors and trainers (0: any free port)",
                      true);
  app.add_flag("--sync", options.sync_mode,
               "sync mode: a cycle as soon as every agent sent (syn), as fast as they answer (rcssserver3d's "
               "agentSyncMode); default: real time, one cycle per 20 ms");
  app.add_option("--sync-timeout-ms", sync_timeout_ms,
                 "sync mode: drop an agent that sends no (syn) for this long (0: wait forever)")
      ->capture_default_str()
      ->check(CLI::Range(0, 3600000));
  app.add_option("--seed", options.seed, "seed of beam noise and each agent's vision noise")->capture_default_str();
  app.add_option("--duration", options.duration, "stop after this many simulated seconds (0: run until Ctrl-C)")
      ->check(turf::FiniteAtLeastZero());
  turf::AddSimSparkOperatorFlag(app, options);
  return participant.Run(argc, argv, [&] {
    options.sync_timeout = std::chrono::milliseconds(sync_timeout_ms);
    const turf::BridgeWriterWatch watch(options);  // two simulators on the bridge's domain and prefix
    return turf::SimSparkBridge(options).Run(turf::StopRequested) ? turf::kExitClean : turf::kExitFailure;
  });
}
