// turf-viewer: a live web view of a turf match with grSim's controls (drag
// robots and the ball, pause, step, reset, speed), served from DDS to any
// browser. Topics and protocol: viewer_node.h, viewer_json.h, page_request.h.
// With --recording FILE: a turf-record file with a time slider instead (recording_viewer.h).
#include "participants/common/participant_main.h"
#include "participants/common/process.h"
#include "participants/viewer/recording_viewer.h"
#include "participants/viewer/viewer_node.h"

int main(int argc, char** argv) {
  turf::ParticipantMain participant(
      "turf-viewer: a live web view of a turf match (DDS in, HTTP and WebSocket out) with controls");
  CLI::App& app = participant.app();
  turf::ViewerOptions options;
  options.web_root = TURF_VIEWER_WEB_ROOT;
  app.add_option("--listen", options.listen, "IP address to serve on (0.0.0.0 or :: to expose it to the network)")
      ->capture_default_str();
  participant.AddPort("--port", options.port, "TCP port of the page (0: any free port)", /*zero_allowed=*/true);
  participant.AddCommonFlags(options);
  app.add_option("--web-root", options.web_root, "directory of the page's files (index.html, app.js, style.css)")
      ->capture_default_str();
  app.add_option("--rate", options.rate_hz, "state messages to the page per second, at most")
      ->capture_default_str()
      ->check(CLI::Range(1.0, 1000.0));
  app.add_option("--allow-host", options.allow_hosts,
                 "with --listen other than loopback: a name the page may be reached by besides IP addresses, "
                 "localhost and this machine's name (repeatable or comma-separated; other names are refused: DNS "
                 "rebinding)")
      ->type_name("NAME")
      ->delimiter(',');
  app.add_option("--recording", options.recording,
                 "show this turf-record MCAP file instead of DDS, with a time slider (no DDS; see README)");
  return participant.Run(argc, argv, [&] {
    if (!options.recording.empty()) {
      turf::RecordingViewer(options).Run(turf::StopRequested);
      return turf::kExitClean;
    }
    turf::ViewerNode(options).Run(turf::StopRequested);
    return turf::kExitClean;
  });
}
