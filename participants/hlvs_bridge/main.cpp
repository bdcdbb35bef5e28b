// turf-hlvs-bridge: the Humanoid League virtual season's robot API (one TCP server per robot: red 10001-10004, blue
// 10021-10024) in front of turf-sim running a legged scene (configs/scenes/hlvs.yaml). Ports, time and choices:
// hlvs_bridge.h.
#include <memory>

#include "participants/common/participant_main.h"
#include "participants/common/process.h"
#include "participants/hlvs_bridge/dds_camera_source.h"
#include "participants/hlvs_bridge/hlvs_bridge.h"
#include "participants/hlvs_bridge/hlvs_flags.h"

int main(int argc, char** argv) {
  turf::ParticipantMain participant(
      "turf-hlvs-bridge: the HLVS robot API (TCP, one port per robot: red_<n> on 10001.., blue_<n> on 10021..) in "
      "front of turf-sim running a legged scene (configs/scenes/hlvs.yaml)");
  turf::HlvsBridgeOptions options;
  bool no_images = false;
  turf::AddHlvsBridgeFlags(participant, options, no_images);
  return participant.Run(argc, argv, [&] {
    std::unique_ptr<turf::DdsCameraSource> images;  // outlives the bridge
    if (!no_images)
      images = std::make_unique<turf::DdsCameraSource>(
          turf::CameraSourceOptions{options.domain, options.prefix, options.security, options.name});
    turf::HlvsBridge bridge(options);
    bridge.SetCameraSource(images.get());
    return bridge.Run(turf::StopRequested) ? turf::kExitClean : turf::kExitFailure;
  });
}
