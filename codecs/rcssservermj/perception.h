// Server -> agent messages of the RCSSServerMJ agent port
// (shared/protocols/rcssservermj.md, "Perception message"): time, GS, the
// torso's quat, pos, GYR, ACC, every HJ in model order, TCH, then See on
// vision cycles; no spaces between top-level items; `(syn)` when there is
// nothing to say. Numbers are the reference's: the value truncated toward
// zero to 2 or 3 decimals, then printed as Python prints a float (shortest
// round-trip digits: `0.0`, `-0.0`, `1.5`, `1e+16`). Names (teams, joints) are
// written as given: valid atoms.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "kernel/rcssservermj/vision.h"

namespace turf::rcssservermj {

// Python's repr() of a double (shortest digits that read back the same).
// A non-finite value is written `0.0` (the wire has no nan).
std::string PythonFloat(double v);
// The reference's number: trunc(v * 10^decimals) / 10^decimals, sign kept; a product within 1e-6 of an integer
// counts as that integer (binary representation error, e.g. 0.58 * 100).
double Truncate(double v, int decimals);
// PythonFloat(Truncate(v, decimals)), appended.
void AppendNumber(std::string* out, double v, int decimals);

struct JointReading {
  std::string name;     // HJ name (q_hj1)
  double position = 0;  // rad
  double velocity = 0;  // rad/s
};

struct GameStateReading {
  double play_time = 0;  // s
  std::string play_mode;
  std::optional<std::string> team_left, team_right;
  int score_left = 0, score_right = 0;
};

struct MjPerception {
  double time = 0;  // s
  GameStateReading game;
  // Absent before the agent has a robot (only time and GS are sent then).
  bool has_robot = false;
  std::array<double, 4> quat{1, 0, 0, 0};  // w x y z, torso in world
  std::array<double, 3> pos{};             // m, world
  std::array<double, 3> gyro{};            // rad/s, torso frame (written in deg/s)
  std::array<double, 3> acc{};             // m/s^2, torso frame
  std::vector<JointReading> joints;        // HJ order
  std::optional<SeeItems> see;
};

std::string FormatPerception(const MjPerception& p);

}  // namespace turf::rcssservermj
