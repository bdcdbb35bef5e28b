// turf-simproto-bridge: the SSL simulation protocol (control, team and sync
// ports; ER-Force's and grSim's UDP protocol) in front of turf-sim, for team
// software and tools that speak it. Ports, topics and choices: simproto_bridge.h.
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include <string>

#include "participants/common/process.h"
#include "participants/simproto_bridge/simproto_bridge.h"

int main(int argc, char** argv) {
  CLI::App app{"turf-simproto-bridge: the SSL simulation protocol (UDP) in front of turf-sim (DDS)"};
  turf::SimprotoBridgeOptions options;
  std::string log_level = "info";
  int reply_timeout_ms = static_cast<int>(options.reply_timeout.count());
  app.add_option("-d,--domain", options.domain, "DDS domain id of turf-sim")
      ->capture_default_str()
      ->check(CLI::Range(0, 232));
  app.add_option("-p,--prefix", options.prefix, "topic name prefix of turf-sim")->capture_default_str();
  app.add_option("--qos", options.qos_file, "Fast DDS XML QoS profiles (default: configs/qos/turf_qos.xml)");
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
  app.add_option("--reply-timeout-ms", reply_timeout_ms, "how long to wait for turf-sim's reply to a request")
      ->capture_default_str()
      ->check(CLI::Range(10, 60000));
  app.add_option("--log-level", log_level, "trace, debug, info, warn, error")->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  if (!turf::SetupLogging("turf-simproto-bridge", log_level)) return 2;
  options.reply_timeout = std::chrono::milliseconds(reply_timeout_ms);
  turf::InstallStopSignals();
  try {
    turf::SimprotoBridge bridge(options);
    bridge.Run([] { return turf::StopRequested(); });
  } catch (const std::invalid_argument& e) {
    spdlog::error("{}", e.what());
    return 2;
  } catch (const std::exception& e) {
    spdlog::critical("{}", e.what());
    return 1;
  }
  spdlog::info("stopped cleanly");
  return 0;
}
