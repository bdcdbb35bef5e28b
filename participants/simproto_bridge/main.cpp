// turf-simproto-bridge: the SSL simulation protocol (control, team and sync
// ports; ER-Force's and grSim's UDP protocol) in front of turf-sim, for team
// software and tools that speak it. Ports, topics and choices: simproto_bridge.h.
#include <chrono>

#include "participants/common/participant_main.h"
#include "participants/common/process.h"
#include "participants/simproto_bridge/simproto_bridge.h"

int main(int argc, char** argv) {
  turf::ParticipantMain participant(
      "turf-simproto-bridge", "turf-simproto-bridge: the SSL simulation protocol (UDP) in front of turf-sim (DDS)");
  CLI::App& app = participant.app();
  turf::SimprotoBridgeOptions options;
  int reply_timeout_ms = static_cast<int>(options.reply_timeout.count());
  participant.AddCommonFlags(options);
  app.add_option("--listen", options.listen, "IPv4 address the UDP ports bind to")->capture_default_str();
  app.add_option("--control-port", options.control_port,
                 "UDP port for SimulatorCommand -> SimulatorResponse (teleports, speed, config; 0: off)")
      ->capture_default_str();
  app.add_option("--blue-port", options.blue_port, "UDP port for the blue team's RobotControl (0: off)")
      ->capture_default_str();
  app.add_option("--yellow-port", options.yellow_port, "UDP port for the yellow team's RobotControl (0: off)")
      ->capture_default_str();
  app.add_option("--sync-port", options.sync_port,
                 "UDP port for SimulationSyncRequest (lockstep: apply, step sim_step, answer with detections); "
                 "robot ids 0..15 are blue, 16..31 yellow (0: off)")
      ->capture_default_str();
  app.add_flag("--sync", options.sync,
               "allow synchronous mode: a SimulationSyncRequest switches turf-sim to lockstep (vision stops for "
               "every team until someone resumes); off: such requests are answered TURF_SYNC_DISABLED");
  app.add_option("--sync-listen", options.sync_listen, "IPv4 address the sync port binds to")->capture_default_str();
  app.add_option("--reply-timeout-ms", reply_timeout_ms, "how long to wait for turf-sim's reply to a request")
      ->capture_default_str()
      ->check(CLI::Range(10, 60000));
  return participant.Run(argc, argv, [&] {
    options.reply_timeout = std::chrono::milliseconds(reply_timeout_ms);
    turf::SimprotoBridge(options).Run(turf::StopRequested);
    return turf::kExitClean;
  });
}
