// turf-grsim-bridge: grSim's UDP command protocol to turf's DDS topics; see
// grsim_bridge.h for its ports and topics, grsim_bridge_flags.h for its flags.
#include <vector>

#include "participants/common/participant_main.h"
#include "participants/common/process.h"
#include "participants/common/writer_watch.h"
#include "participants/grsim_bridge/grsim_bridge.h"
#include "participants/grsim_bridge/grsim_bridge_flags.h"

int main(int argc, char** argv) {
  turf::ParticipantMain participant(
      "turf-grsim-bridge: lets team software that speaks grSim's UDP protocol (commands, replacement, robot status) "
      "drive turf-sim over DDS");
  turf::GrsimBridgeOptions options;
  std::vector<int> wheel_order = {4, 3, 2, 1};
  turf::AddGrsimBridgeFlags(participant, options, wheel_order);
  return participant.Run(argc, argv, [&] {
    turf::ApplyWheelOrder(wheel_order, options.codec);
    const turf::BridgeWriterWatch watch(options);  // two simulators on the bridge's domain and prefix
    turf::GrsimBridge(options).Run(turf::StopRequested);
    return turf::kExitClean;
  });
}
