// Server -> agent messages of the SimSpark agent port: one perception per cycle
// (shared/protocols/simspark.md, "Perceptors of the Nao"). Written exactly as
// rcssserver3d 0.7.3 writes them (SexpParser::PredicateToString): `(name p1 p2 ...)`,
// one space after the name even with no parameters (an empty See is `(See )`),
// one space between parameters, none between top-level predicates, numbers
// rounded to float and printed fixed with 2 decimals.
//
// Predicate order, the reference's (clients must not rely on it): time, GS,
// hear, GYR, ACC, HJ (in `joints_deg` order) with See right after hj2 and each
// foot's FRP right before the hinge of its body (rf before rlj6, lf1 before
// llj7); See and FRPs without those joints come after the HJs. Names (joints,
// teams, messages) are written as given: the caller passes valid atoms (no
// whitespace or parentheses).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "kernel/simspark/types.h"

namespace turf::simspark {

// `(FRP (n lf) (c x y z) (f x y z))`: foot frame, point m, force N.
struct ForcePerception {
  std::string name;  // lf, rf, lf1, rf1
  std::array<double, 3> point{};
  std::array<double, 3> force{};
};

struct Perception {
  double time = 0;  // (time (now T)), simulation time s
  // GS (unum n) (team left|right): only in the first GS after a successful init.
  std::optional<int> unum;
  std::optional<Side> side;
  int score_left = 0, score_right = 0;  // (sl) (sr)
  double game_time = 0;                 // (t)
  PlayMode play_mode = PlayMode::kBeforeKickOff;
  std::array<double, 3> gyro_deg_s{};                      // GYR rt, torso frame, deg/s
  std::array<double, 3> acc{};                             // ACC a, torso frame, m/s^2
  std::vector<std::pair<std::string, double>> joints_deg;  // HJ (n name) (ax deg)
  std::vector<ForcePerception> forces;                     // FRP, only feet touching something
  std::optional<SeeItems> see;                             // See, on vision cycles
  std::vector<Heard> heard;                                // hear, written in this order
};

// Fixed with exactly 2 decimals ("-0.00" may occur, as the server prints it); a non-finite value -> "0.00".
std::string FormatFloat(double v);
void AppendFloat(std::string* out, double v);  // the same, appended

// The whole message text (the payload of one frame).
std::string FormatPerception(const Perception& p);

}  // namespace turf::simspark
