// Sensor realism from YAML: the presets in configs/realism/ (ideal, realistic,
// harsh), a scene's `realism:` section and turf-sim's --realism. Run-time
// changes over the network are typed, not YAML (loader/realism_change.h); the
// keys are the dotted names of core/realism_fields.h's table (a test reads
// every row back through this loader). Every problem is an error naming its
// key; never throws.
//
// Schema (every key optional, absent = ideal; SI units):
//   camera:  {robot_position_stddev, robot_orientation_stddev, ball_position_stddev,
//             robot_vanish, ball_vanish, ball_occlusion, confidence_spread,
//             processing_delay, link: LINK}
//   command: LINK                      a team's radio link to its robots
//   encoder: {resolution, noise_stddev, link: LINK}   legged joint-state stream
//   imu:     {gyro_bias, gyro_noise_stddev, accel_bias, accel_noise_stddev, link: LINK}
//   touch:   {link: LINK}                              legged foot touch/force stream
//   LINK:    {latency, jitter, jitter_kind: gaussian|uniform|exponential, loss,
//             burst: {p_good_to_bad, p_bad_to_good, loss_good, loss_bad}}
//             (burst present: Gilbert-Elliott loss replaces `loss`)
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/sensor_realism.h"

namespace YAML {
class Node;
}

namespace turf {

struct RealismLoadResult {
  std::optional<SensorRealism> realism;
  std::vector<std::string> errors;
};

// The directory of the shipped presets.
std::string DefaultRealismDir();
// The presets in `dir` (its *.yaml files, without the extension), sorted: what an unknown name is told.
std::vector<std::string> RealismPresets(const std::string& dir = DefaultRealismDir());

// YAML text of a realism map; keys it leaves out keep their value in `base`.
RealismLoadResult ParseRealismYaml(const std::string& yaml_text, const SensorRealism& base = {});

// `spec` is a preset name (looked up as <dir>/<spec>.yaml), a path to a YAML
// file (unless `allow_paths` is false, as for requests from the network), or
// YAML text itself (if it contains a ':' or '{'). Presets and files are whole
// descriptions (absent keys are ideal); YAML text changes `base` only where it
// names a key.
RealismLoadResult LoadRealism(const std::string& spec, const std::string& dir = DefaultRealismDir(),
                              bool allow_paths = true, const SensorRealism& base = {});

// `spec` as LoadRealism reads it, a relative file path taken as relative to `base_dir` (the directory of the
// scene or profile that names it) rather than to the current directory; preset names and YAML text unchanged.
std::string RealismSpecFrom(const std::string& spec, const std::string& base_dir);

namespace yaml {
class MapReader;
}
// For the scene compiler: reads a realism map.
void ReadRealism(yaml::MapReader m, SensorRealism* realism);
// A scene's optional `realism:` key: a preset name (configs/realism/<name>.yaml), a file (a relative path is
// relative to `base_dir`, the scene's directory) or a map.
void ReadSceneRealism(yaml::MapReader& scene, const std::string& base_dir, SensorRealism* realism,
                      std::vector<std::string>* errors);

}  // namespace turf
