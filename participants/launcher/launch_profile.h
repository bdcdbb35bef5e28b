// A league launch profile (configs/launch/*.yaml): the scene, the sensor
// realism, the DDS domain and prefix, and which bridges run with which flags.
// Untrusted input: unknown keys, wrong types and bad values come back as
// errors that name the key (and line); nothing throws.
//
// Schema (only `scene` is required):
//   name: ssl_div_a                    shown in logs (default: the file's name)
//   scene: ../scenes/ssl_div_a.yaml    turf-sim --scene; relative to the profile's directory
//   realism: realistic                 turf-sim --realism: a preset of configs/realism/ or a YAML
//                                      file (relative to the profile); absent: the scene's.
//                                      SSL scenes only (refused for a `kind: legged` scene)
//   domain: 0                          DDS domain of every process (0..232)
//   prefix: turf                       topic prefix of every process
//   qos: FILE                          --qos of every process (absent: the shipped profiles)
//   discovery:                         absent: multicast discovery (SIMPLE)
//     server: HOST:PORT                every process gets ROS_DISCOVERY_SERVER=HOST:PORT
//     start: false                     true: `turf launch` also runs fast-discovery-server there
//   sim: {FLAG: VALUE, ...}            more turf-sim flags (e.g. speed: 1)
//   bridges:                           the bridges to start, in order: grsim, vision, simproto for an
//                                      SSL scene, simspark for a legged one (programs.h)
//     grsim: {FLAG: VALUE, ...}        each with its flags ({} for the defaults)
//   restart: {max_restarts: 5, backoff_initial: 0.5, backoff_max: 8, stable_after: 10}
//   stop_grace: 5                      s from SIGTERM to SIGKILL when stopping
// FLAG is a long option without its dashes. A scalar VALUE is passed as
// written, true makes a bare flag, false leaves it out, a list is joined with
// commas. domain, prefix, qos (and for sim: scene, realism) are top-level keys
// and refused as flags.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace turf::launch {

struct Flag {
  std::string name;   // without dashes
  std::string value;  // empty and bare: a switch
  bool bare = false;
};

struct ProcessSpec {
  std::string name;  // a Program name (programs.h)
  std::vector<Flag> flags;
};

struct DiscoverySpec {
  std::string server;  // HOST:PORT; empty: multicast discovery
  bool start = false;  // run fast-discovery-server on `server`
};

// A profile file is read whole up to this size; every duration of a profile (and --grace) is at most an hour.
inline constexpr uintmax_t kMaxProfileBytes = 1 << 20;
inline constexpr double kMaxLaunchSeconds = 3600.0;

struct RestartPolicy {
  int max_restarts = 5;          // quick crashes in a row before giving up
  double backoff_initial = 0.5;  // s before the first restart; doubles per quick crash
  double backoff_max = 8.0;      // s
  double stable_after = 10.0;    // s of running that count as recovered (backoff resets)
};

struct LaunchProfile {
  std::string name;
  std::string path;     // the file it came from (empty: parsed from text)
  std::string scene;    // absolute path
  bool legged = false;  // the scene says `kind: legged`: the SSL bridges do not apply
  std::string realism;  // preset name or absolute path; empty: the scene's
  int domain = 0;
  std::string prefix = "turf";
  std::string qos;  // absolute path; empty: the shipped profiles
  DiscoverySpec discovery;
  ProcessSpec sim{"sim", {}};
  std::vector<ProcessSpec> bridges;
  RestartPolicy restart;
  double stop_grace = 5.0;  // s
};

struct ProfileLoadResult {
  std::optional<LaunchProfile> profile;  // set only when there are no errors
  std::vector<std::string> errors;
};

// Parses profile text; relative paths resolve against `base_dir`. A non-empty `scene` (a path, relative to the
// working directory) replaces the profile's scene, and the bridges are checked against it (`turf launch --scene`).
ProfileLoadResult ParseLaunchProfile(const std::string& yaml_text, const std::string& base_dir,
                                     const std::string& scene = "");

// `name_or_path`: a file, or a profile name looked up as <dir>/<name>.yaml.
ProfileLoadResult LoadLaunchProfile(const std::string& name_or_path, const std::string& dir,
                                    const std::string& scene = "");

// True if the scene file's top level says `kind: legged` (as
// loader/legged_scene_yaml.h's IsLeggedSceneFile, which would link the physics).
bool IsLeggedScene(const std::string& path);

// configs/launch/ of this source tree.
std::string DefaultProfileDir();

// Checks (and splits) "HOST:PORT"; HOST is an IPv4 address or a DNS name.
bool ParseHostPort(const std::string& text, std::string* host, int* port);
// A flag name: lowercase letters, digits and '-', starting with a letter.
bool ValidFlagName(const std::string& name);

}  // namespace turf::launch
