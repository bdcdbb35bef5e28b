// Agent -> server messages of the SimSpark agent port (shared/protocols/simspark.md,
// "Effectors"): `(scene ...)(init ...)(beam ...)(say ...)(syn)(pass)(<hinge> v)`.
// The decoder checks the grammar only; the participant decides what is allowed
// when (play mode, robot built, init once) and maps/clamps hinge velocities per
// robot type with nao_joints.h.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/errors.h"

namespace turf::simspark {

// `(scene rsg/agent/nao/nao.rsg)` = type 0; `(scene rsg/agent/nao/nao_hetero.rsg 3)`.
struct SceneEffector {
  std::string path;
  int type = 0;  // 0..4
};

// `(init (unum 1)(teamname FHO))`; unum missing -> 0 (lowest free number).
struct InitEffector {
  int unum = 0;  // 0..99
  std::string team;
};

// `(beam x y rot)` in the team's own frame.
struct BeamEffector {
  double x = 0, y = 0;  // m
  double rot_deg = 0;   // deg
};

// `(rle4 -2.5)`: raw effector name and target velocity in rad/s, unclamped.
struct HingeEffector {
  std::string effector;
  double velocity = 0;
};

// turf's one taxonomy (core/errors.h). Effectors answer kParse (nothing of the
// payload is applied), kUnknownEffector, kBadArguments (also unum outside 0..99),
// kNotFinite, kBadSay and kBadRobotType (scene type outside 0..4).
using EffectorError = turf::Error;
inline const char* EffectorErrorName(EffectorError error) { return turf::ErrorName(error); }

// A dropped predicate: why and which (its name, or the parse error and offset).
struct EffectorIssue {
  EffectorError error = EffectorError::kOk;
  std::string detail;
};

// What one message asks for. Each predicate is checked on its own; a bad one is
// dropped with an issue, the others apply. Repeated scene/init/beam/say: the
// last valid one counts; hinges are kept in message order (the last for a joint wins).
struct AgentMessage {
  std::optional<SceneEffector> scene;
  std::optional<InitEffector> init;
  std::optional<BeamEffector> beam;
  std::vector<HingeEffector> hinges;
  std::optional<std::string> say;
  bool syn = false;
  bool pass = false;
  std::vector<EffectorIssue> issues;
};

AgentMessage ParseAgentMessage(std::string_view payload);

// A say message the server would accept: 1..20 characters of 0x21-0x7E except '(' and ')'.
bool IsValidSayMessage(std::string_view message);

}  // namespace turf::simspark
