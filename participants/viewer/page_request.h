// Messages from the viewer's web page, decoded into turf SimControl requests.
// Pure: no sockets, no DDS. The page is untrusted (anything that can reach the
// port can send anything), so every message is checked and a bad one is refused
// with a named error; a refused message produces no request.
//
// Protocol (one JSON object per WebSocket text message, at most
// kMaxPageMessage bytes; every key not listed is refused):
//   {"op":"teleport_ball", "x":m, "y":m, ["z":m, "vx","vy","vz":m/s]}
//   {"op":"throw_ball", "x":m, "y":m, "vx":m/s, "vy":m/s}   the ball on the
//    ground at (x, y), rolling at (vx, vy), |v| <= kMaxThrowSpeed
//   {"op":"teleport_robot", "team":"blue"|"yellow", "id":n, "on_field":true,
//    "x":m, "y":m, "yaw":rad}                  place (and orient) a robot
//   {"op":"teleport_robot", "team":..., "id":n, "on_field":false}   take it off
//   {"op":"teleport_robot", "robot":name, "x":m, "y":m, "z":m,
//    "qw","qx","qy","qz"}          legged scenes: the root body's pose (the
//                                  quaternion, world <- root, is normalised)
//   {"op":"pause"} {"op":"resume"} {"op":"reset"}
//   {"op":"step", ["count":1..kMaxStepCount]}  needs a paused simulation
//   {"op":"time_mode", "mode":"realtime"|"scaled"|"free"|"lockstep",
//    ["speed":(0, kMaxSpeed], for "scaled" only]}
//   {"op":"realism", "preset":"ideal"|"realistic"|"harsh"}  (presets only:
//    the page can never send YAML or a path)
// Positions must be inside the field's walls (as turf-sim checks them), so the
// field (SslField) must be known before a teleport is accepted. In a legged
// scene (LeggedSceneInfo) they must be within kLeggedMargin of the 3D field's
// lines (robots park beside it), or kLeggedArea of the origin without a field;
// the ball needs a field (a scene without one has no ball), a robot a name in
// the scene.
#pragma once

#include <turf/idl/Joints.h>
#include <turf/idl/SimControl.h>
#include <turf/idl/SslVision.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "core/errors.h"

namespace turf::viewer {

inline constexpr size_t kMaxPageMessage = 4096;  // bytes
inline constexpr uint32_t kMaxStepCount = 1000;  // physics steps per request
inline constexpr double kMaxSpeed = 100.0;       // multiples of real time
inline constexpr double kMaxYaw = 100.0;         // rad, before normalising
inline constexpr double kLeggedMargin = 5.0;     // m beyond a legged scene's field lines
inline constexpr double kLeggedArea = 50.0;      // m from the origin, legged scenes without a field
// A throw from the page: about a hard SSL kick (6.5 m/s), far below what a
// teleport may carry (kMaxTeleportSpeed).
inline constexpr double kMaxThrowSpeed = 8.0;  // m/s

// turf's one taxonomy (core/errors.h). A page request is refused with kTooLarge
// (above kMaxPageMessage), kNotJson (also numbers JSON cannot hold, e.g. 1e999),
// kNotObject, kUnknownOp, kUnknownKey, kMissingField, kWrongType, kNotFinite,
// kOutOfRange (step count 0, speed 1e6, a throw above kMaxThrowSpeed), kUnknownTeam,
// kUnknownRobot, kOutsideField, kNoField (a teleport before the field is known),
// kUnknownPreset or kUnknownMode.
using PageError = turf::Error;
inline const char* PageErrorName(PageError error) { return turf::ErrorName(error); }

struct PageRequest {
  PageError error = PageError::kOk;
  std::string detail;       // for the log and the page: what was wrong
  std::string op;           // the page's op name, when known
  idl::SimControl control;  // valid only when error == kOk; client and request_id unset
};

// The scene turf-sim runs, as far as the viewer knows (at most one is set):
// what teleports are checked against. Neither: no teleport is accepted.
struct PageScene {
  const idl::SslField* ssl = nullptr;
  const idl::LeggedSceneInfo* legged = nullptr;
};

// Decodes one page message.
PageRequest ParsePageRequest(std::string_view text, const PageScene& scene);
// An SSL scene's field (nullopt: no teleport allowed).
PageRequest ParsePageRequest(std::string_view text, const std::optional<idl::SslField>& field);

}  // namespace turf::viewer
