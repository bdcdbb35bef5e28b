#include "participants/vision_bridge/vision_bridge_flags.h"

#include "participants/common/cli_checks.h"

namespace turf {

void AddVisionBridgeFlags(ParticipantMain& participant, VisionBridgeOptions& options, std::string& clock) {
  CLI::App& app = participant.app();
  participant.AddCommonFlags(options);
  app.add_option("--address", options.address,
                 "where detections and geometry go: a multicast group, or a unicast address")
      ->capture_default_str();
  participant.AddPort("--port", options.port, "UDP port for detections and geometry (SSL-Vision: 10006)");
  app.add_option("--interface", options.interface_ip,
                 "IPv4 address of the network interface to multicast from (default: the system's choice)");
  app.add_option("--ttl", options.ttl, "multicast time to live (hops)")
      ->capture_default_str()
      ->check(CLI::Range(0, 255));
  app.add_option("--geometry-every", options.geometry_every,
                 "send geometry every N capture rounds (also once as soon as the field is known; 0: only then)")
      ->capture_default_str()
      ->check(FiniteAtLeastZero());
  app.add_option("--clock", clock,
                 "time stamps: 'run' (Unix time at which turf-sim's run started + simulation time: Unix-looking, "
                 "exact at any speed, monotonic across resets), 'unix' (wall clock at sending) or 'sim' "
                 "(simulation seconds)")
      ->capture_default_str()
      ->check(CLI::IsMember({"run", "unix", "sim"}));
  app.add_flag("--tracked", options.tracked, "also send TrackerWrapperPacket (ground truth) per world state");
  app.add_option("--tracked-address", options.tracked_address, "where tracked packets go")->capture_default_str();
  participant.AddPort("--tracked-port", options.tracked_port, "UDP port for tracked packets");
}

}  // namespace turf
