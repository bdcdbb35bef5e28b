// Agent -> server messages of the RCSSServerMJ agent port
// (shared/protocols/rcssservermj.md, "Actions"): the first message `(init
// <model> <team> <player_no>)`, then per cycle any of `(<effector> q dq kp kd
// tau)` (degrees on the wire, radians here), `(beam x y theta)`, `(say ...)`
// and `(syn)`, concatenated. Pure functions: the S-expression parser and its
// limits are the SimSpark codec's (codecs/simspark/sexpr.h).
//
// Untrusted input: a motor command with a NaN/inf number, a value past the
// bounds below, an effector the robot model lacks, or the wrong number of
// numbers is refused with a named error (core/errors.h) and never applied; the
// rest of the message still counts. The reference applies unknown effectors
// (and crashes its handler); turf refuses them.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "codecs/rcssservermj/robots.h"
#include "core/errors.h"
#include "core/legged/placement_limits.h"

namespace turf::rcssservermj {

// The first message. player_no is |n| mod 100 as the reference takes it.
struct InitAction {
  std::string model;
  std::string team;
  int player_no = 0;
};

// kOk with `out` set, or kParse (not S-expressions), kBadArguments (not
// exactly one `(init a b n)` with an integer n), kNotFinite.
turf::Error ParseInit(std::string_view payload, InitAction* out);

// Bounds of a motor command's numbers (wire units); beyond them: kOutOfRange.
// Generous: the session clamps targets and torque to the joint's own limits.
inline constexpr double kMaxAbsQDeg = 3600.0;
inline constexpr double kMaxAbsDqDegS = 36000.0;
inline constexpr double kMaxKp = 1e4;  // N m / rad
inline constexpr double kMaxKd = 1e3;  // N m s / rad
inline constexpr double kMaxAbsTau = 1e3;
inline constexpr double kMaxAbsBeam = kMaxLeggedPlacement;  // m, x and y (deg for theta: any finite value)

struct MotorAction {
  int joint = -1;  // index into the model's joints
  double q = 0;    // rad
  double dq = 0;   // rad/s
  double kp = 0;   // N m / rad
  double kd = 0;   // N m s / rad
  double tau = 0;  // N m
};

struct BeamAction {
  double x = 0, y = 0;   // m
  double theta_deg = 0;  // 0 = facing +x
};

struct ActionIssue {
  turf::Error error = turf::Error::kOk;
  std::string detail;
};

struct ActionMessage {
  std::vector<MotorAction> motors;  // in message order; for one joint the last one wins
  std::optional<BeamAction> beam;   // the last valid beam
  bool say = false;                 // accepted, no effect (no hearing in the reference either)
  bool syn = false;
  std::vector<ActionIssue> issues;
};

// Every expression of one message; `model` decides which effectors exist.
ActionMessage ParseActions(std::string_view payload, const MjRobotModel& model);

}  // namespace turf::rcssservermj
