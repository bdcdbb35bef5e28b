// Types shared by the SimSpark codecs (perception.h, vision.h, game.h,
// trainer.h). Facts: shared/protocols/simspark.md. Angles in these types are
// degrees where the wire uses degrees (marked), else radians; lengths metres.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace turf::simspark {

enum class Side { kLeft, kRight };
constexpr Side EnumCount(Side) { return static_cast<Side>(2); }  // snapshots (core/state_io.h)
const char* SideName(Side side);                                 // "left", "right" (GS)

// Play modes with the monitor's indices (shared/protocols/simspark.md).
enum class PlayMode {
  kBeforeKickOff = 0,
  kKickOffLeft,
  kKickOffRight,
  kPlayOn,
  kKickInLeft,
  kKickInRight,
  kCornerKickLeft,
  kCornerKickRight,
  kGoalKickLeft,
  kGoalKickRight,
  kOffsideLeft,
  kOffsideRight,
  kGameOver,
  kGoalLeft,
  kGoalRight,
  kFreeKickLeft,
  kFreeKickRight,
  kDirectFreeKickLeft,
  kDirectFreeKickRight,
  kPassLeft,
  kPassRight,
  kCount
};
const char* PlayModeName(PlayMode mode);  // "BeforeKickOff", "Goal_Left", "pass_right", ...
std::optional<PlayMode> PlayModeFromName(const std::string& name);
std::optional<PlayMode> PlayModeFromIndex(int index);

// A position as the restricted vision perceptor reports it.
struct Polar {
  double distance = 0.0;    // m
  double horizontal = 0.0;  // deg, positive = to the left
  double vertical = 0.0;    // deg, positive = up
};

struct SeeObject {
  std::string label;  // B, F1L, F2L, F1R, F2R, G1L, G2L, G1R, G2R
  Polar pol;
};

struct SeePart {
  std::string name;  // head, rlowerarm, llowerarm, rfoot, lfoot
  Polar pol;
};

struct SeePlayer {
  std::string team;  // the team's name (not its side)
  int id = 0;        // unum
  std::vector<SeePart> parts;
};

struct SeeLine {
  Polar begin;
  Polar end;
};

// One `See` predicate's content.
struct SeeItems {
  std::vector<SeeObject> objects;
  std::vector<SeePlayer> players;
  std::vector<SeeLine> lines;
};

// One message an agent hears (`hear`).
struct Heard {
  std::string team;        // the speaker's team name
  double game_time = 0.0;  // s
  bool self = false;       // true: the listener's own message ("self")
  double direction = 0.0;  // deg, when not self
  std::string message;
};

}  // namespace turf::simspark
