// turf-simspark-bridge: the RoboCup 3D soccer simulation server's agent and
// trainer protocols in front of turf-sim. Ports, modes and choices: simspark_bridge.h.
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <string>

#include "participants/common/process.h"
#include "participants/simspark_bridge/simspark_bridge.h"

int main(int argc, char** argv) {
  CLI::App app{
      "turf-simspark-bridge: SimSpark/rcssserver3d agents (TCP 3100) and trainers (TCP 3200) in front of turf-sim "
      "running a legged scene (configs/scenes/simspark_match.yaml)"};
  turf::SimSparkBridgeOptions options;
  std::string log_level = "info";
  int sync_timeout_ms = static_cast<int>(options.sync_timeout.count());
  app.add_option("-d,--domain", options.domain, "DDS domain id of turf-sim")
      ->capture_default_str()
      ->check(CLI::Range(0, 232));
  app.add_option("-p,--prefix", options.prefix, "topic name prefix of turf-sim")->capture_default_str();
  app.add_option("--qos", options.qos_file, "Fast DDS XML QoS profiles (default: configs/qos/turf_qos.xml)");
  app.add_option("--listen", options.listen, "IPv4 address both TCP ports bind to")->capture_default_str();
  app.add_option("--agent-port", options.agent_port, "TCP port for agents")->capture_default_str();
  app.add_option("--monitor-port", options.monitor_port, "TCP port for monitors and trainers")->capture_default_str();
  app.add_flag("--sync", options.sync_mode,
               "sync mode: a cycle as soon as every agent sent (syn), as fast as they answer (rcssserver3d's "
               "agentSyncMode); default: real time, one cycle per 20 ms");
  app.add_option("--sync-timeout-ms", sync_timeout_ms,
                 "sync mode: drop an agent that sends no (syn) for this long (0: wait forever)")
      ->capture_default_str()
      ->check(CLI::Range(0, 3600000));
  app.add_option("--seed", options.seed, "seed of beam noise and each agent's vision noise")->capture_default_str();
  app.add_option("--duration", options.duration, "stop after this many simulated seconds (0: run until Ctrl-C)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--log-level", log_level, "trace, debug, info, warn, error")->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  if (!turf::SetupLogging("turf-simspark-bridge", log_level)) return 2;
  options.sync_timeout = std::chrono::milliseconds(sync_timeout_ms);
  turf::InstallStopSignals();
  try {
    turf::SimSparkBridge bridge(options);
    if (!bridge.Run([] { return turf::StopRequested(); })) return 1;
  } catch (const std::exception& e) {
    spdlog::critical("{}", e.what());
    return 1;
  }
  spdlog::info("stopped cleanly");
  return 0;
}
