// turf-hlvs-bridge: the Humanoid League virtual season's robot API (one TCP server per robot: red 10001-10004, blue
// 10021-10024) in front of turf-sim running a legged scene (configs/scenes/hlvs.yaml). Ports, time and choices:
// hlvs_bridge.h.
#include <memory>

#include "participants/common/cli_checks.h"
#include "participants/common/participant_main.h"
#include "participants/common/process.h"
#include "participants/hlvs_bridge/dds_camera_source.h"
#include "participants/hlvs_bridge/hlvs_bridge.h"

int main(int argc, char** argv) {
  turf::ParticipantMain participant(
      "turf-hlvs-bridge",
      "turf-hlvs-bridge: the HLVS robot API (TCP, one port per robot: red_<n> on 10001.., blue_<n> on 10021..) in "
      "front of turf-sim running a legged scene (configs/scenes/hlvs.yaml)");
  CLI::App& app = participant.app();
  turf::HlvsBridgeOptions options;
  participant.AddCommonFlags(options);
  app.add_option("--listen", options.listen, "IPv4 address the robot ports bind to")->capture_default_str();
  app.add_option("--red-ports", options.red_ports, "TCP ports of red players 1, 2, ... (0: any free port)")
      ->capture_default_str()
      ->check(CLI::Range(0, 65535));
  app.add_option("--blue-ports", options.blue_ports, "TCP ports of blue players 1, 2, ... (0: any free port)")
      ->capture_default_str()
      ->check(CLI::Range(0, 65535));
  app.add_option("--red-allow", options.red_allow,
                 "a red robot's client may connect from this IPv4 address or range; repeatable; given, it replaces "
                 "the default (game.json's)")
      ->type_name("ADDR[/PREFIX]")
      ->check(turf::AddressRangeCheck(/*ipv4_only=*/true))
      ->capture_default_str();
  app.add_option("--blue-allow", options.blue_allow, "the same for blue robots' clients")
      ->type_name("ADDR[/PREFIX]")
      ->check(turf::AddressRangeCheck(/*ipv4_only=*/true))
      ->capture_default_str();
  app.add_option("--team-players", options.team_players,
                 "players per team: each robot's share of the 350 MB/s network and rendering quotas")
      ->check(CLI::Range(1, 11))
      ->capture_default_str();
  app.add_option("--realtime-factor", options.realtime_factor,
                 "at most this many times real time (game.json's maximum_real_time_factor); 0: as fast as possible")
      ->check(turf::FiniteAtLeastZero())
      ->capture_default_str();
  app.add_option("--duration", options.duration, "stop after this many simulated seconds (0: run until Ctrl-C)")
      ->check(turf::FiniteAtLeastZero());
  bool no_images = false;
  app.add_flag("--no-camera-images", no_images,
               "send no camera images (by default a camera a client enables is asked of turf-render, "
               "<prefix>/cameras/control, and its images taken from rt/<prefix>/<robot>/<camera>/image_raw)");
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
