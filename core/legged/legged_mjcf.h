// LeggedScene -> one MJCF: the ground (or the 3D soccer field and ball) plus
// every robot instance, its robot file copied with every named element
// prefixed by "<robot name>/" so several instances of one model coexist.
//
// From a robot file, turf takes: <default> (as a class of its own, so it
// touches only that robot), <asset> without files, <worldbody> bodies, and
// <contact>, <equality>, <tendon>, <sensor>. It ignores <option>, <size> and
// <visual> (the scene decides) and <actuator> (joints are driven by the
// world's servos). The file must say <compiler angle="radian"/>; its
// top-level bodies may carry pos and quat, which the placement composes with.
#pragma once

#include <string>
#include <vector>

#include "core/legged/legged_scene.h"

struct mjModel_;
typedef struct mjModel_ mjModel;

namespace turf {

inline constexpr const char* kLeggedBall = "ball";
inline constexpr const char* kLeggedFloor = "floor";

// "<robot>/<element>": the name of a robot's element in the composed model.
std::string LeggedElementName(const std::string& robot, const std::string& element);

struct LeggedMjcf {
  std::string xml;                  // empty when there are errors
  std::vector<std::string> errors;  // each names the robot
};

LeggedMjcf ComposeLeggedMjcf(const LeggedScene& scene);

// Compiles composed MJCF text (through MuJoCo's virtual file system); the caller owns the model (mj_deleteModel,
// or core/mj_state.h's MjModelPtr). Throws std::invalid_argument with MuJoCo's message if it does not compile.
mjModel* CompileLeggedMjcf(const std::string& xml);

}  // namespace turf
