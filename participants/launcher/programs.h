// The programs `turf launch` knows: a profile's process names, the executable
// each runs and where the build tree puts it. The one list of them (profiles,
// the launcher, tests and docker/compose.yaml are checked against it).
#pragma once

#include <string_view>

namespace turf::launch {

// The scenes a program works with (a profile's bridges must fit its scene).
enum class Scenes { kAny, kSsl, kLegged };

struct Program {
  std::string_view name;       // in profiles, --only, --set and log prefixes
  std::string_view binary;     // executable name
  std::string_view build_dir;  // under <build>/participants/; empty: a system tool found on PATH
  Scenes scenes = Scenes::kAny;
  std::string_view identity = "";  // with `turf launch --security DIR`: it runs as DIR/<identity> (security_policy.h)
};

inline constexpr Program kPrograms[] = {
    {"discovery", "fast-discovery-server", ""},  // Fast DDS discovery server (Debian: fastdds-tools)
    {"sim", "turf-sim", "sim", Scenes::kAny, "sim"},
    {"grsim", "turf-grsim-bridge", "grsim_bridge", Scenes::kSsl, "grsim-bridge"},
    {"vision", "turf-vision-bridge", "vision_bridge", Scenes::kSsl, "vision-bridge"},
    {"simproto", "turf-simproto-bridge", "simproto_bridge", Scenes::kSsl, "simproto-bridge"},
    // Steps turf-sim itself (switches it to lockstep).
    {"simspark", "turf-simspark-bridge", "simspark_bridge", Scenes::kLegged, "simspark-bridge"},
    // Steps turf-sim itself, as the SimSpark bridge: under DDS Security it runs with that bridge's identity (the
    // same rights: lockstep control and the legged topics).
    {"hlvs", "turf-hlvs-bridge", "hlvs_bridge", Scenes::kLegged, "simspark-bridge"},
    // The web view (not a bridge, but started like one: listed under a profile's `bridges:`); it pauses and
    // teleports, as the operator.
    {"viewer", "turf-viewer", "viewer", Scenes::kAny, "operator"},
    // The robots' cameras (legged scenes; given the profile's scene, as turf-sim).
    {"render", "turf-render", "render", Scenes::kLegged, "render"},
};

// Bridges a profile may list under `bridges:` (every program but discovery and sim).
inline bool IsBridge(std::string_view name) { return name != "discovery" && name != "sim"; }

inline const Program* FindProgram(std::string_view name) {
  for (const Program& p : kPrograms) {
    if (p.name == name) return &p;
  }
  return nullptr;
}

}  // namespace turf::launch
