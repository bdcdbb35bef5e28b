// turf-simproto-bridge: the SSL simulation protocol (control, team and sync
// ports; ER-Force's and grSim's UDP protocol) in front of turf-sim, for team
// software and tools that speak it. Ports, topics and choices: simproto_bridge.h.
#include <chrono>

#include "participants/common/participant_main.h"
#include "participants/common/process.h"
#include "participants/common/writer_watch.h"
#include "participants/simproto_bridge/simproto_bridge.h"
#include "participants/simproto_bridge/simproto_flags.h"

int main(int argc, char** argv) {
  turf::ParticipantMain participant(
      "turf-simproto-bridge: the SSL simulation protocol (UDP) in front of turf-sim (DDS)");
  CLI::App& app = participant.app();
  turf::SimprotoBridgeOptions options;
  int reply_timeout_ms = static_cast<int>(options.reply_timeout.count());
  participant.AddCommonFlags(options);
  app.add_option("--listen", options.listen, "IPv4 address the UDP ports bind to")->capture_default_str();
  turf::AddSimprotoPortFlags(app, options);
  turf::AddSimprotoAllowFlags(app, options);
  app.add_option("--reply-timeout-ms", reply_timeout_ms, "how long to wait for turf-sim's reply to a request")
      ->capture_default_str()
      ->check(CLI::Range(10, 60000));
  return participant.Run(argc, argv, [&] {
    options.reply_timeout = std::chrono::milliseconds(reply_timeout_ms);
    const turf::BridgeWriterWatch watch(options);  // two simulators on the bridge's domain and prefix
    turf::SimprotoBridge(options).Run(turf::StopRequested);
    return turf::kExitClean;
  });
}
