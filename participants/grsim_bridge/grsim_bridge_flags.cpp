#include "participants/grsim_bridge/grsim_bridge_flags.h"

#include <fmt/format.h>

#include <cstddef>
#include <utility>

#include "participants/common/cli_checks.h"

namespace turf {

void AddGrsimBridgeFlags(ParticipantMain& participant, GrsimBridgeOptions& options, std::vector<int>& wheel_order) {
  CLI::App& app = participant.app();
  grsim::GrsimCodecConfig& codec = options.codec;
  app.add_option("--listen", options.listen_ip, "IPv4 address to receive grSim packets on")->capture_default_str();
  participant.AddPort("--port", options.port, "UDP port for grSim_Packet (commands and replacement; 0: any free port)",
                      /*zero_allowed=*/true);
  for (const auto& [team, port] :
       {std::pair{"blue", &options.blue_status_port}, {"yellow", &options.yellow_status_port}})
    participant.AddPort(fmt::format("--{}-status-port", team), *port,
                        fmt::format("Robots_Status for {0} goes to the {0} command sender's IP on this port", team));
  AddAllowOption(app, "--blue-allow", options.allow.blue,
                 "a packet commanding blue robots is taken only from this IPv4 address or range (else refused whole, "
                 "counted, logged)");
  AddAllowOption(app, "--yellow-allow", options.allow.yellow,
                 "a packet commanding yellow robots is taken only from this IPv4 address or range");
  AddAllowOption(app, "--operator-allow", options.allow.operators,
                 "a packet with a replacement (moves the ball and robots) is taken only from this IPv4 address or "
                 "range");
  participant.AddCommonFlags(options, {"DDS domain id", "topic name prefix (the one turf-sim uses)"});
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
}

void ApplyWheelOrder(const std::vector<int>& wheel_order, grsim::GrsimCodecConfig& codec) {
  for (size_t i = 0; i < 4; ++i) codec.wheel_source[i] = wheel_order[i] - 1;
}

}  // namespace turf
