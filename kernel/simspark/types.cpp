#include "kernel/simspark/types.h"

namespace turf::simspark {

namespace {

constexpr const char* kPlayModeNames[] = {"BeforeKickOff",
                                          "KickOff_Left",
                                          "KickOff_Right",
                                          "PlayOn",
                                          "KickIn_Left",
                                          "KickIn_Right",
                                          "corner_kick_left",
                                          "corner_kick_right",
                                          "goal_kick_left",
                                          "goal_kick_right",
                                          "offside_left",
                                          "offside_right",
                                          "GameOver",
                                          "Goal_Left",
                                          "Goal_Right",
                                          "free_kick_left",
                                          "free_kick_right",
                                          "direct_free_kick_left",
                                          "direct_free_kick_right",
                                          "pass_left",
                                          "pass_right"};
static_assert(sizeof(kPlayModeNames) / sizeof(kPlayModeNames[0]) == static_cast<size_t>(PlayMode::kCount));

}  // namespace

const char* SideName(Side side) { return side == Side::kLeft ? "left" : "right"; }

const char* PlayModeName(PlayMode mode) {
  const int i = static_cast<int>(mode);
  return i >= 0 && i < static_cast<int>(PlayMode::kCount) ? kPlayModeNames[i] : "unknown";
}

std::optional<PlayMode> PlayModeFromName(const std::string& name) {
  for (int i = 0; i < static_cast<int>(PlayMode::kCount); ++i)
    if (name == kPlayModeNames[i]) return static_cast<PlayMode>(i);
  return std::nullopt;
}

std::optional<PlayMode> PlayModeFromIndex(int index) {
  if (index < 0 || index >= static_cast<int>(PlayMode::kCount)) return std::nullopt;
  return static_cast<PlayMode>(index);
}

}  // namespace turf::simspark
