// turf-render's command line (main.cpp): its options and the flags main turns into them once parsed.
// Header-only (CLI11).
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "participants/common/participant_main.h"
#include "participants/render/render_node.h"

namespace turf {

struct RenderCommandLine {
  RenderOptions options;
  std::vector<std::string> cameras;   // --cameras as given (comma-separated ids or `off`)
  std::vector<std::string> switches;  // --switch ROBOT/CAMERA=STATE
  bool no_team_colours = false;
};

inline void AddRenderFlags(ParticipantMain& participant, RenderCommandLine& c) {
  CLI::App& app = participant.app();
  RenderOptions& options = c.options;
  app.add_option("--scene", options.scene_file,
                 "the legged scene turf-sim runs (its robots' cameras); required but with --switch");
  app.add_option(
         "--switch", c.switches,
         "switch a camera of the running renderers and exit, no --scene needed: ROBOT/CAMERA=on, "
         "ROBOT/CAMERA=on@HZ (Hz of sim time) or ROBOT/CAMERA=off; repeatable (writes <prefix>/cameras/control)")
      ->type_name("ID=STATE");
  app.add_option("--cameras", c.cameras,
                 "cameras to render, as <robot>/<camera>, comma-separated or repeated (default: every camera of the "
                 "scene, on as declared); `off`: every camera starts off, to be switched on at run time "
                 "(<prefix>/cameras/control); several turf-render processes can split a scene's "
                 "cameras");
  app.add_flag("--list-cameras", options.list_cameras, "print the scene's cameras and exit");
  app.add_flag("--no-team-colours", c.no_team_colours,
               "robots keep their files' colours (by default a robot named red_*, blue_* or yellow_* has its trunk "
               "in that team's colour)");
  app.add_option("--brightness", options.brightness,
                 "every light this many times as bright (a simple lighting change: 0.5 dim, 1.5 bright)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 4.0));
  app.add_option("--status-every", options.status_every, "seconds between status lines")
      ->capture_default_str()
      ->check(CLI::Range(0.1, 3600.0));
  participant.AddCommonFlags(options);
}

}  // namespace turf
