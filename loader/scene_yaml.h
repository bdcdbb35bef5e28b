// The scene compiler: YAML scene files (configs/scenes/*.yaml) to a validated
// turf::Scene. Input is untrusted; every problem comes back as an error naming
// its key path (and line), never as an exception.
//
// Schema (every key optional; absent keys keep the defaults of core/scene.h;
// SI units and the member names of scene.h, except angles, which are degrees
// in keys ending in _deg):
//   name: ssl-div-a                 seed: 1             robots_per_team: 16
//   physics: {step, solver_iterations}
//   rates: {world_state_hz, command_timeout}
//   field: {division: A|B, length, width, ...}   division picks the
//       FieldForDivision defaults first, the other field keys override them
//   ball: {start: [x, y], radius, mass, acc_slide, acc_roll, k_switch, ...}
//   robot: {radius, height, mass, center_to_dribbler, friction,
//           drive: {..., wheel_angles_deg: [front_right, back_right, back_left, front_left]},
//           kicker: {..., default_chip_angle_deg}, dribbler: {...}}
//   teams: {blue: [{id: 0, x: -5.5, y: 0, theta_deg: 0, on_field: true}, ...], yellow: [...]}
//       ids 0..robots_per_team-1 exist; ids not listed start off the field;
//       x and y are required unless on_field is false
//   cameras: {rate_hz, height, overlap, focal_length, image_width, image_height}
//   realism: ideal|realistic|harsh (a preset in configs/realism/), a file (relative: to the scene's
//       directory) or a map as in loader/realism_yaml.h
#pragma once

#include <string>

#include "core/scene.h"
#include "loader/load_result.h"

namespace turf {

using SceneLoadResult = LoadResult<Scene>;

// Parses a scene from YAML text, then runs ValidateScene. A realism file the scene names by a relative path is
// read relative to `base_dir` (the scene file's directory; empty: the current one). Never throws.
SceneLoadResult ParseSceneYaml(const std::string& yaml_text, const std::string& base_dir = "");

// Reads and parses a scene file; a missing or unreadable file is an error
// (each error is prefixed with the path). Never throws.
SceneLoadResult LoadSceneFile(const std::string& path);

}  // namespace turf
