// One taxonomy of refusals (Cyclone DDS's named errors): every input turf
// refuses, whatever carried it (a robot or joint command, a teleport, a
// control request, a snapshot), is refused with one of these. One X-macro
// gives the enum, the snake_case names (used in refusal counters such as
// "command.not_finite" and in logs) and the IDL's ControlError constants,
// which participants/sim/control_loop.cpp checks value for value at compile
// time (static_assert per entry).
//   X(enumerator, name, IDL constant, meaning)
#pragma once

#include <cstdint>

#define TURF_ERRORS(X)                                                                             \
  X(kOk, "ok", CONTROL_OK, "accepted")                                                             \
  X(kNotFinite, "not_finite", CONTROL_NOT_FINITE, "a NaN or infinite number")                      \
  X(kOutOfRange, "out_of_range", CONTROL_OUT_OF_RANGE, "a number past its limits")                 \
  X(kOutsideField, "outside_field", CONTROL_OUTSIDE_FIELD, "a teleport beyond the walls")          \
  X(kUnknownRobot, "unknown_robot", CONTROL_UNKNOWN_ROBOT, "no such robot in the scene")           \
  X(kUnknownJoint, "unknown_joint", CONTROL_UNKNOWN_JOINT, "no such joint on the robot")           \
  X(kUnknownEnum, "unknown_enum", CONTROL_UNKNOWN_ENUM, "an enum value this build does not know")  \
  X(kUnknownOp, "unknown_op", CONTROL_UNKNOWN_OP, "an operation this build does not know")         \
  X(kNotAllowed, "not_allowed", CONTROL_NOT_ALLOWED, "not in this state or this kind of scene")    \
  X(kInvalidRealism, "invalid_realism", CONTROL_INVALID_REALISM, "no preset and no valid realism") \
  X(kCancelled, "cancelled", CONTROL_CANCELLED, "dropped by a reset before it ran")                \
  X(kTeamMismatch, "team_mismatch", CONTROL_TEAM_MISMATCH, "a command on the other team's topic")  \
  X(kNoBall, "no_ball", CONTROL_NO_BALL, "the scene has no ball")

namespace turf {

enum class Error : uint8_t {
#define TURF_ERROR_ENUM(e, name, idl, meaning) e,
  TURF_ERRORS(TURF_ERROR_ENUM)
#undef TURF_ERROR_ENUM
      kCount
};

// "not_finite", ...; "?" for a value past kCount.
const char* ErrorName(Error error);
const char* ErrorMeaning(Error error);

// What core's inputs answer: the same taxonomy under the names the callers know.
using InputError = Error;
using JointCommandError = Error;
using PlacementError = Error;
inline const char* InputErrorName(Error e) { return ErrorName(e); }
inline const char* JointCommandErrorName(Error e) { return ErrorName(e); }
inline const char* PlacementErrorName(Error e) { return ErrorName(e); }

}  // namespace turf
