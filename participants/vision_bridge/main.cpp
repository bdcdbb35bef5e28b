// turf-vision-bridge: turf's simulated SSL cameras as SSL-Vision packets, for
// team software that listens to a vision system (and, with --tracked, to a
// tracker). Topics read and packets sent: see vision_bridge.h; flags:
// vision_bridge_flags.h.
#include <string>

#include "codecs/ssl_vision/timestamps.h"
#include "participants/common/participant_main.h"
#include "participants/common/process.h"
#include "participants/common/writer_watch.h"
#include "participants/vision_bridge/vision_bridge.h"
#include "participants/vision_bridge/vision_bridge_flags.h"

int main(int argc, char** argv) {
  turf::ParticipantMain participant(
      "turf-vision-bridge: turf's SSL cameras (DDS) out as SSL-Vision UDP packets (SSL_WrapperPacket)");
  turf::VisionBridgeOptions options;
  std::string clock = "run";
  turf::AddVisionBridgeFlags(participant, options, clock);
  return participant.Run(argc, argv, [&] {
    options.clock = *turf::vision::ParseClockMode(clock);
    const turf::BridgeWriterWatch watch(options);  // two simulators on the bridge's domain and prefix
    turf::VisionBridge(options).Run(turf::StopRequested);
    return turf::kExitClean;
  });
}
