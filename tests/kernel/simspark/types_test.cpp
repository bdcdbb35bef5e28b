#include "kernel/simspark/types.h"

#include <gtest/gtest.h>

namespace turf::simspark {

TEST(SimSparkTypes, PlayModeNamesRoundTripWithMonitorIndices) {
  EXPECT_STREQ(PlayModeName(PlayMode::kBeforeKickOff), "BeforeKickOff");
  EXPECT_STREQ(PlayModeName(PlayMode::kGoalLeft), "Goal_Left");
  EXPECT_STREQ(PlayModeName(PlayMode::kPassRight), "pass_right");
  EXPECT_EQ(PlayModeFromIndex(3), PlayMode::kPlayOn);
  EXPECT_EQ(PlayModeFromIndex(14), PlayMode::kGoalRight);
  EXPECT_FALSE(PlayModeFromIndex(21).has_value());
  EXPECT_FALSE(PlayModeFromIndex(-1).has_value());
  for (int i = 0; i < static_cast<int>(PlayMode::kCount); ++i) {
    const auto mode = static_cast<PlayMode>(i);
    EXPECT_EQ(PlayModeFromName(PlayModeName(mode)), mode);
  }
  EXPECT_FALSE(PlayModeFromName("PLAY_ON").has_value());  // the manual's upper-case names are wrong
  EXPECT_STREQ(PlayModeName(static_cast<PlayMode>(99)), "unknown");
}

}  // namespace turf::simspark
