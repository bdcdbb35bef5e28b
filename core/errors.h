// One taxonomy of refusals (Cyclone DDS's named errors): every input turf
// refuses, whatever carried it (a robot or joint command, a teleport, a
// control request, a snapshot), is refused with one of these. One X-macro
// gives the enum, the snake_case names (used in refusal counters such as
// "command.not_finite" and in logs) and the IDL's ControlError constants,
// which participants/sim/control_loop.cpp checks value for value at compile
// time (static_assert per entry). The codecs' and the viewer's errors
// (DecodeError, GrsimError, VisionError, EffectorError, SExprError, FrameError,
// PageError, SampleError) are this enum too, so a refusal counter's name
// ("grsim.malformed", "page.not_json") comes from this one table.
// New entries go at the end (the IDL order follows this one).
//   X(enumerator, name, IDL constant, meaning)
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

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
  X(kNoBall, "no_ball", CONTROL_NO_BALL, "the scene has no ball")                                  \
  /* Decoding a datagram, a frame or a page message (codecs, viewer). */                           \
  X(kEmpty, "empty", CONTROL_EMPTY, "zero bytes")                                                  \
  X(kOversized, "oversized", CONTROL_OVERSIZED, "a datagram above the codec's size limit")         \
  X(kTooLarge, "too_large", CONTROL_TOO_LARGE, "a frame or message above its size limit")          \
  X(kMalformed, "malformed", CONTROL_MALFORMED, "not a message of the expected type")              \
  X(kMissingRequired, "missing_required", CONTROL_MISSING_REQUIRED, "a required field is absent")  \
  X(kDuplicateRobot, "duplicate_robot", CONTROL_DUPLICATE_ROBOT, "one robot twice in one message") \
  /* SSL-Vision encoding and wire times (codecs/ssl_vision). */                                    \
  X(kNonPositiveSize, "non_positive_size", CONTROL_NON_POSITIVE_SIZE, "a size zero or negative")   \
  X(kBadRobotId, "bad_robot_id", CONTROL_BAD_ROBOT_ID, "a robot id above 15")                      \
  X(kUnknownTeam, "unknown_team", CONTROL_UNKNOWN_TEAM, "neither blue nor yellow")                 \
  X(kTooMany, "too_many", CONTROL_TOO_MANY, "more items than one message may carry")               \
  X(kTimeNotPositive, "time_not_positive", CONTROL_TIME_NOT_POSITIVE, "a time zero or negative")   \
  X(kTimeOrder, "time_order", CONTROL_TIME_ORDER, "sent before it was captured")                   \
  X(kNoEpoch, "no_epoch", CONTROL_NO_EPOCH, "no run epoch (yet) for this time")                    \
  X(kBadEpoch, "bad_epoch", CONTROL_BAD_EPOCH, "a run epoch that is no plausible Unix time")       \
  /* SimSpark S-expressions and effectors (codecs/simspark). */                                    \
  X(kParse, "parse", CONTROL_PARSE, "the payload is not S-expressions")                            \
  X(kUnknownEffector, "unknown_effector", CONTROL_UNKNOWN_EFFECTOR, "no such effector")            \
  X(kBadArguments, "bad_arguments", CONTROL_BAD_ARGUMENTS, "wrong number or form of arguments")    \
  X(kBadSay, "bad_say", CONTROL_BAD_SAY, "a say message not 1..20 printable characters")           \
  X(kBadRobotType, "bad_robot_type", CONTROL_BAD_ROBOT_TYPE, "a robot type outside 0..4")          \
  X(kUnbalancedOpen, "unbalanced_open", CONTROL_UNBALANCED_OPEN, "input ends inside a list")       \
  X(kUnbalancedClose, "unbalanced_close", CONTROL_UNBALANCED_CLOSE, "a ')' without its '('")       \
  X(kTooDeep, "too_deep", CONTROL_TOO_DEEP, "lists nested too deep")                               \
  X(kTooManyNodes, "too_many_nodes", CONTROL_TOO_MANY_NODES, "too many lists and atoms")           \
  X(kAtomTooLong, "atom_too_long", CONTROL_ATOM_TOO_LONG, "an atom above its length limit")        \
  X(kBadByte, "bad_byte", CONTROL_BAD_BYTE, "a byte neither printable ASCII nor white space")      \
  X(kTopLevelAtom, "top_level_atom", CONTROL_TOP_LEVEL_ATOM, "an atom outside any list")           \
  /* The viewer's page requests and DDS samples (participants/viewer). */                          \
  X(kNotJson, "not_json", CONTROL_NOT_JSON, "not parseable JSON")                                  \
  X(kNotObject, "not_object", CONTROL_NOT_OBJECT, "JSON, but not an object")                       \
  X(kUnknownKey, "unknown_key", CONTROL_UNKNOWN_KEY, "a key the request does not take")            \
  X(kMissingField, "missing_field", CONTROL_MISSING_FIELD, "a key the request needs")              \
  X(kWrongType, "wrong_type", CONTROL_WRONG_TYPE, "a value of the wrong JSON type")                \
  X(kNoField, "no_field", CONTROL_NO_FIELD, "the field is not known yet")                          \
  X(kUnknownPreset, "unknown_preset", CONTROL_UNKNOWN_PRESET, "no such realism preset")            \
  X(kUnknownMode, "unknown_mode", CONTROL_UNKNOWN_MODE, "no such time mode")                       \
  X(kBadSize, "bad_size", CONTROL_BAD_SIZE, "a size that cannot be drawn")                         \
  X(kDuplicate, "duplicate", CONTROL_DUPLICATE, "the same item twice")

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
// The error whose ErrorName is `name`; none for any other string.
std::optional<Error> ErrorFromName(std::string_view name);

// What core's inputs answer: the same taxonomy under the names the callers know.
using InputError = Error;
using JointCommandError = Error;
using PlacementError = Error;
inline const char* InputErrorName(Error e) { return ErrorName(e); }
inline const char* JointCommandErrorName(Error e) { return ErrorName(e); }
inline const char* PlacementErrorName(Error e) { return ErrorName(e); }

}  // namespace turf
