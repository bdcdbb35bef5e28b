// turf's DDS samples as the JSON messages the viewer's page reads. Pure
// functions; SI units (m, rad, s), numbers rounded to what a screen can show
// (0.1 mm, 1e-4 rad) to keep a 60 Hz stream small.
//
// Messages (every one has "type"):
//   hello   {version, prefix, presets[], max_message}           once per page
//   field   {division, length, width, boundary, boundary_goal, goal_width,
//            goal_depth, penalty_depth, penalty_width, center_radius, line,
//            ball_radius, robot_radius, robot_height, robots_per_team,
//            cameras:[{id, min:[x,y], max:[x,y]}]}
//   state   {t, frame, ball:{p:[x,y,z], v:[x,y,z]},
//            robots:[{team, id, on, p:[x,y], yaw, v:[x,y,w]}],
//            clock:{paused, mode, speed, rtf} (absent before the first Clock),
//            detections:[{camera, t, balls:[[x,y,z,conf]],
//                         robots:[{team, id, p:[x,y], yaw, conf}]}],
//            viewer:{refused, control, gone_since}}  control: turf-sim reads our requests;
//            gone_since (Unix ms): turf-sim left, the rest of the message is its last word
//   legged  a legged scene's robot shapes and 3D field (legged_json.h); a page
//           shows the SSL field or the legged scene, whichever came last
//   state (legged scenes) {t, frame, ball (absent without a field), robots:[],
//            detections:[], links:{<robot>: [poses]} (legged_json.h), clock, viewer}
//   stats   {t, window, streams:[{name, rate, sent, lost, loss, latency, jitter}]}
//   reply   {op, ok, error, reason, t}              turf-sim's answer, to the page that asked;
//                                                   error: core/errors.h's name ("out_of_range")
//   refused {kind, detail}                          to the page whose message was refused
#pragma once

#include <turf/idl/Clock.h>
#include <turf/idl/Joints.h>
#include <turf/idl/SensorStats.h>
#include <turf/idl/SimControl.h>
#include <turf/idl/SslVision.h>
#include <turf/idl/WorldState.h>

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/enum_names.h"

namespace turf::viewer {

inline constexpr int kProtocolVersion = 1;

std::string HelloJson(const std::string& prefix);
std::string FieldJson(const idl::SslField& field);
// The viewer's own condition, shown with every state.
struct ViewerInfo {
  uint64_t refused = 0;  // page messages refused so far
  bool control = false;  // a turf-sim control reader is matched: page actions can take effect
  // turf-sim was there and is gone (its control reader left): since when, Unix ms; 0 while present or never seen.
  int64_t gone_since_unix_ms = 0;
};

// `frames`: the newest frame of each camera to show with this state.
std::string StateJson(const idl::WorldState& state, const std::optional<idl::Clock>& clock,
                      const std::vector<const idl::CameraFrame*>& frames, const ViewerInfo& viewer);
// Legged scenes: `ball` null when there is none (a scene without a field) or
// before the first world state; `links`: the newest LinkState per robot.
std::string LeggedStateJson(const idl::WorldState* ball, const idl::LeggedSceneInfo& scene,
                            const std::map<std::string, idl::LinkState>& links, const std::optional<idl::Clock>& clock,
                            const ViewerInfo& viewer);
std::string StatsJson(const idl::SensorStats& stats);
std::string ReplyJson(const idl::SimControlReply& reply);
std::string RefusedJson(const std::string& kind, const std::string& detail);

// The page protocol's names of control operations and time modes, in the IDL enums' order (core/enum_names.h):
// what replies and the clock say, and what a page's "time_mode" request names.
inline constexpr const char* kPageOps[] = {"teleport_ball", "teleport_robot", "pause",     "resume",
                                           "step",          "reset",          "time_mode", "realism"};
inline constexpr const char* kPageTimeModes[] = {"realtime", "scaled", "free", "lockstep"};
const char* OpName(idl::ControlOp op);
const char* TimeModeName(idl::TimeMode mode);

}  // namespace turf::viewer
