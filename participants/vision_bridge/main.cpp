// turf-vision-bridge: turf's simulated SSL cameras as SSL-Vision packets, for
// team software that listens to a vision system (and, with --tracked, to a
// tracker). Topics read and packets sent: see vision_bridge.h.
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include <string>

#include "codecs/ssl_vision/timestamps.h"
#include "participants/common/process.h"
#include "participants/vision_bridge/vision_bridge.h"

int main(int argc, char** argv) {
  CLI::App app{"turf-vision-bridge: turf's SSL cameras (DDS) out as SSL-Vision UDP packets (SSL_WrapperPacket)"};
  turf::VisionBridgeOptions options;
  std::string clock = "run";
  std::string log_level = "info";
  app.add_option("-d,--domain", options.domain, "DDS domain id of turf-sim")
      ->capture_default_str()
      ->check(CLI::Range(0, 232));
  app.add_option("-p,--prefix", options.prefix, "topic name prefix of turf-sim")->capture_default_str();
  app.add_option("--qos", options.qos_file, "Fast DDS XML QoS profiles (default: configs/qos/turf_qos.xml)");
  app.add_option("--address", options.address,
                 "where detections and geometry go: a multicast group, or a unicast address")
      ->capture_default_str();
  app.add_option("--port", options.port, "UDP port for detections and geometry (SSL-Vision: 10006)")
      ->capture_default_str();
  app.add_option("--interface", options.interface_ip,
                 "IPv4 address of the network interface to multicast from (default: the system's choice)");
  app.add_option("--ttl", options.ttl, "multicast time to live (hops)")
      ->capture_default_str()
      ->check(CLI::Range(0, 255));
  app.add_option("--geometry-every", options.geometry_every,
                 "send geometry every N capture rounds (also once as soon as the field is known; 0: only then)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  app.add_option("--clock", clock,
                 "time stamps: 'run' (Unix time at which turf-sim's run started + simulation time: Unix-looking, "
                 "exact at any speed, monotonic across resets), 'unix' (wall clock at sending) or 'sim' "
                 "(simulation seconds)")
      ->capture_default_str()
      ->check(CLI::IsMember({"run", "unix", "sim"}));
  app.add_flag("--tracked", options.tracked, "also send TrackerWrapperPacket (ground truth) per world state");
  app.add_option("--tracked-address", options.tracked_address, "where tracked packets go")->capture_default_str();
  app.add_option("--tracked-port", options.tracked_port, "UDP port for tracked packets")->capture_default_str();
  app.add_option("--log-level", log_level, "trace, debug, info, warn, error")->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  if (!turf::SetupLogging("turf-vision-bridge", log_level)) return 2;
  options.clock = *turf::vision::ParseClockMode(clock);
  turf::InstallStopSignals();
  try {
    turf::VisionBridge bridge(options);
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
