// turf-viewer: a live web view of a turf match with grSim's controls (drag
// robots and the ball, pause, step, reset, speed), served from DDS to any
// browser. Topics and protocol: viewer_node.h, viewer_json.h, page_request.h.
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include <string>

#include "participants/common/process.h"
#include "participants/viewer/viewer_node.h"

int main(int argc, char** argv) {
  CLI::App app{"turf-viewer: a live web view of a turf match (DDS in, HTTP and WebSocket out) with controls"};
  turf::ViewerOptions options;
  options.web_root = TURF_VIEWER_WEB_ROOT;
  std::string log_level = "info";
  app.add_option("--listen", options.listen, "IP address to serve on (0.0.0.0 or :: to expose it to the network)")
      ->capture_default_str();
  app.add_option("--port", options.port, "TCP port of the page (0: any free port)")->capture_default_str();
  app.add_option("-d,--domain", options.domain, "DDS domain id of turf-sim")
      ->capture_default_str()
      ->check(CLI::Range(0, 232));
  app.add_option("-p,--prefix", options.prefix, "topic name prefix of turf-sim")->capture_default_str();
  app.add_option("--qos", options.qos_file, "Fast DDS XML QoS profiles (default: configs/qos/turf_qos.xml)");
  app.add_option("--web-root", options.web_root, "directory of the page's files (index.html, app.js, style.css)")
      ->capture_default_str();
  app.add_option("--rate", options.rate_hz, "state messages to the page per second, at most")
      ->capture_default_str()
      ->check(CLI::Range(1.0, 1000.0));
  app.add_option("--log-level", log_level, "trace, debug, info, warn, error")->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  if (!turf::SetupLogging("turf-viewer", log_level)) return 2;
  turf::InstallStopSignals();
  try {
    turf::ViewerNode viewer(options);
    viewer.Run([] { return turf::StopRequested(); });
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
