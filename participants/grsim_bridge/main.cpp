// turf-grsim-bridge: grSim's UDP command protocol to turf's DDS topics; see
// grsim_bridge.h for its ports and topics.
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "participants/common/process.h"
#include "participants/grsim_bridge/grsim_bridge.h"

int main(int argc, char** argv) {
  CLI::App app{
      "turf-grsim-bridge: lets team software that speaks grSim's UDP protocol (commands, replacement, robot status) "
      "drive turf-sim over DDS"};
  turf::GrsimBridgeOptions options;
  turf::grsim::GrsimCodecConfig& codec = options.codec;
  std::string log_level = "info";
  std::vector<int> wheel_order = {4, 3, 2, 1};
  app.add_option("--listen", options.listen_ip, "IPv4 address to receive grSim packets on")->capture_default_str();
  app.add_option("--port", options.port, "UDP port for grSim_Packet (commands and replacement)")->capture_default_str();
  app.add_option("--blue-status-port", options.blue_status_port,
                 "Robots_Status for blue goes to the blue command sender's IP on this port")
      ->capture_default_str()
      ->check(CLI::Range(1, 65535));
  app.add_option("--yellow-status-port", options.yellow_status_port,
                 "Robots_Status for yellow goes to the yellow command sender's IP on this port")
      ->capture_default_str()
      ->check(CLI::Range(1, 65535));
  app.add_option("-d,--domain", options.domain, "DDS domain id")->capture_default_str()->check(CLI::Range(0, 232));
  app.add_option("-p,--prefix", options.prefix, "topic name prefix (the one turf-sim uses)")->capture_default_str();
  app.add_option("--qos", options.qos_file, "Fast DDS XML QoS profiles (default: configs/qos/turf_qos.xml)");
  app.add_option("--robots-per-team", codec.robots_per_team,
                 "ids 0..N-1 are accepted until turf-sim's ssl/field says otherwise")
      ->capture_default_str()
      ->check(CLI::Range(0, 16));
  app.add_option("--wheel-radius", codec.wheel_radius,
                 "m, converts grSim wheel speeds (rad/s) to rim speeds until ssl/field gives the scene's")
      ->capture_default_str();
  app.add_option("--wheel-order", wheel_order,
                 "grSim wheel numbers (1..4) driving turf's front_right,back_right,back_left,front_left; grSim's "
                 "robot has wheel1..4 at 60,135,225,300 degrees from the kicker")
      ->expected(4)
      ->delimiter(',')
      ->capture_default_str();
  app.add_option("--dribbler-rpm", codec.dribbler_rpm, "dribbler speed for spinner = true")->capture_default_str();
  app.add_option("--max-datagram", codec.max_datagram_size, "bytes; larger datagrams are refused")
      ->capture_default_str();
  app.add_option("--log-level", log_level, "trace, debug, info, warn, error")->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  if (!turf::SetupLogging("turf-grsim-bridge", log_level)) return 2;
  for (size_t i = 0; i < 4; ++i) codec.wheel_source[i] = wheel_order[i] - 1;
  turf::InstallStopSignals();
  try {
    turf::GrsimBridge bridge(options);
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
