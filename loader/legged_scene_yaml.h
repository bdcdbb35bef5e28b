// Legged scene files (configs/scenes/*.yaml with `kind: legged`) to a
// validated turf::LeggedScene. Input is untrusted; every problem comes back as
// an error naming its key path (and line), never as an exception.
//
// Schema (absent keys keep the defaults of core/legged/legged_scene.h; SI
// units, angles in degrees in keys ending in _deg):
//   kind: legged                      (required: tells turf-sim which world to run)
//   name: simspark-3d   seed: 1   ground_friction: 1.0
//   physics: {step, solver_iterations, sensors_after_step, motor_impulse_window,
//             fluid_density, fluid_viscosity (MuJoCo's air on every body; default 0: none)}
//   rates: {joint_state_hz}
//   field: {length, width, goal_width, goal_depth, goal_height, goal_wall,
//           ball_radius, ball_mass, ball_start: [x, y], wall_distance,
//           ball_friction: [slide, torsion, roll], ball_condim, ball_solref: [a, b], ball_priority (the ball
//           geom's MuJoCo contact), ball_drag: [linear N s/m, angular N m s/rad] (a force -c v and torque -c w),
//           walls (default true: the four outer walls at wall_distance)}
//       present = the RoboCup 3D soccer field with goals and ball
//   robots:                            one entry per placed robot
//     - name: nao_1                    unique; prefixes its joints on the topics
//       id: 1
//       model: ../robots/nao.xml       MJCF file, relative to the scene file
//       x: -2.0   y: 0.0   yaw_deg: -90
//       z: 0.665                       optional: the root body's start height, m
//                                      (default: the robot file's)
//       motors: {max_torque, max_speed, velocity_kp, velocity_kd, position_kp,
//                position_kd, max_reference_lead}
//       joints:                        optional: start angles (rad) held by the
//         - {name: Left_Knee_Pitch, q: 0.4, kp: 350, kd: 5.5}    PD motor mode
//                                      with these gains until commanded; the
//                                      world refuses unknown joints and q
//                                      outside the joint's range
//       cameras:                       optional: every MJCF <camera> of the robot file is declared with the
//                                      defaults below; an entry overrides the one of its name or adds one
//         - {name: camera, body: head, pos: [x, y, z], xyaxes: [6 numbers: image right, image up],
//            width: 320, height: 240, hfov_deg: 60, rate_hz: 30, encoding: rgb8|yuv422|jpeg,
//            jpeg_quality: 80, noise_stddev: 0, enabled: true}
//                                      (hfov_deg default: the MJCF camera's fovy at this size; without an
//                                      MJCF camera of that name `body` is required)
#pragma once

#include <string>

#include "core/legged/legged_scene.h"
#include "loader/load_result.h"

namespace turf {

using LeggedSceneLoadResult = LoadResult<LeggedScene>;

// True if the YAML file's top level says `kind: legged` (false for SSL
// scenes, unreadable files and anything else).
bool IsLeggedSceneFile(const std::string& path);

// Parses YAML text; robot model paths are relative to `base_dir`. Never throws.
LeggedSceneLoadResult ParseLeggedSceneYaml(const std::string& yaml_text, const std::string& base_dir);

// Reads a scene file and the robot files it names. Never throws.
LeggedSceneLoadResult LoadLeggedSceneFile(const std::string& path);

}  // namespace turf
