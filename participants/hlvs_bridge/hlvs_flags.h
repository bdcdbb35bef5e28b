// turf-hlvs-bridge's flags (main.cpp): the common ones, where the robot ports listen and whom they admit, the
// quotas' team size, pacing and camera images. Header-only (CLI11).
#pragma once

#include <CLI/CLI.hpp>

#include "participants/common/cli_checks.h"
#include "participants/common/participant_main.h"
#include "participants/hlvs_bridge/hlvs_bridge.h"

namespace turf {

// `no_images`: --no-camera-images.
inline void AddHlvsBridgeFlags(ParticipantMain& participant, HlvsBridgeOptions& options, bool& no_images) {
  CLI::App& app = participant.app();
  participant.AddCommonFlags(options);
  app.add_option("--listen", options.listen, "IPv4 address the robot ports bind to")->capture_default_str();
  app.add_option("--red-ports", options.red_ports,
                 "TCP ports of red players 1, 2, ... (0: any free port; repeatable or comma-separated)")
      ->capture_default_str()
      ->delimiter(',')
      ->check(CLI::Range(0, 65535));
  app.add_option("--blue-ports", options.blue_ports,
                 "TCP ports of blue players 1, 2, ... (0: any free port; repeatable or comma-separated)")
      ->capture_default_str()
      ->delimiter(',')
      ->check(CLI::Range(0, 65535));
  app.add_option("--red-allow", options.red_allow,
                 "a red robot's client may connect from this IPv4 address or range; repeatable or comma-separated; "
                 "given, it replaces the default (game.json's)")
      ->type_name("ADDR[/PREFIX]")
      ->delimiter(',')
      ->check(AddressRangeCheck(/*ipv4_only=*/true))
      ->capture_default_str();
  app.add_option("--blue-allow", options.blue_allow, "the same for blue robots' clients")
      ->type_name("ADDR[/PREFIX]")
      ->delimiter(',')
      ->check(AddressRangeCheck(/*ipv4_only=*/true))
      ->capture_default_str();
  app.add_option("--team-players", options.team_players,
                 "players per team: each robot's share of the 350 MB/s network and rendering quotas")
      ->check(CLI::Range(1, 11))
      ->capture_default_str();
  app.add_option("--realtime-factor", options.realtime_factor,
                 "at most this many times real time (game.json's maximum_real_time_factor); 0: as fast as possible")
      ->check(FiniteAtLeastZero())
      ->capture_default_str();
  app.add_option("--duration", options.duration, "stop after this many simulated seconds (0: run until Ctrl-C)")
      ->check(FiniteAtLeastZero());
  app.add_flag("--no-camera-images", no_images,
               "send no camera images (by default a camera a client enables is asked of turf-render, "
               "<prefix>/cameras/control, and its images taken from rt/<prefix>/<robot>/<camera>/image_raw)");
}

}  // namespace turf
