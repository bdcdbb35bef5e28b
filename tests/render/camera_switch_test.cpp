// turf-render's run-time camera switch (participants/render/camera_switch.h) and its set at start (RenderSet:
// --cameras, --cameras off), without GL or DDS.
#include "participants/render/camera_switch.h"

#include <gtest/gtest.h>

#include <cmath>

#include "participants/render/render_node.h"

namespace turf {
namespace {

std::vector<CameraSpec> Three() {
  CameraSpec a, b, c;
  a.robot = b.robot = c.robot = "t1";
  a.name = "a";
  b.name = "b";
  c.name = "c";
  b.rate_hz = 10;
  c.enabled = false;
  return {a, b, c};
}

TEST(RenderSet, TheSceneAsDeclaredTheNamedOnesOnOrAllOff) {
  const auto all = RenderSet(Three(), {}, false);
  ASSERT_EQ(all.size(), 3u);
  EXPECT_TRUE(all[0].enabled);
  EXPECT_FALSE(all[2].enabled) << "declared off: in the set, off until switched on";
  const auto named = RenderSet(Three(), {"t1/c"}, false);
  ASSERT_EQ(named.size(), 1u);
  EXPECT_TRUE(named[0].enabled);
  for (const CameraSpec& c : RenderSet(Three(), {}, true)) EXPECT_FALSE(c.enabled) << c.name;
  EXPECT_THROW(RenderSet(Three(), {"t1/x"}, false), std::invalid_argument);
}

TEST(CameraSwitch, SwitchesItsOwnCamerasOnAndOffAtARate) {
  CameraSwitch s(Three());
  EXPECT_EQ(s.enabled_count(), 2u);
  std::string why;
  EXPECT_EQ(s.Apply({"t1", "c", true, 0, "test"}, &why), CameraSwitch::Outcome::kChanged);
  EXPECT_TRUE(s.enabled(2));
  EXPECT_DOUBLE_EQ(s.rate_hz(2), 30) << "0: the declared rate";
  EXPECT_EQ(s.Apply({"t1", "c", true, 0, "test"}, &why), CameraSwitch::Outcome::kUnchanged);
  EXPECT_EQ(s.Apply({"t1", "c", true, 62.5, "test"}, &why), CameraSwitch::Outcome::kChanged);
  EXPECT_DOUBLE_EQ(s.rate_hz(2), 62.5);
  EXPECT_EQ(s.Apply({"t1", "b", false, 0, "test"}, &why), CameraSwitch::Outcome::kChanged);
  EXPECT_FALSE(s.enabled(1));
  EXPECT_EQ(s.Apply({"t1", "b", false, 5, "test"}, &why), CameraSwitch::Outcome::kUnchanged) << "off is off";
  EXPECT_EQ(s.Apply({"t2", "a", true, 0, "test"}, &why), CameraSwitch::Outcome::kNotMine);
  EXPECT_EQ(s.enabled_count(), 2u);
}

TEST(CameraSwitch, ABadRateIsRefusedAndChangesNothing) {
  CameraSwitch s(Three());
  for (double bad : {std::nan(""), -1.0, double{INFINITY}, kMaxCameraRateHz + 1, 1e-10, kMinCameraRateHz / 2}) {
    std::string why;
    EXPECT_EQ(s.Apply({"t1", "c", true, bad, "test"}, &why), CameraSwitch::Outcome::kRefused) << bad;
    EXPECT_NE(why.find("rate_hz"), std::string::npos);
    EXPECT_FALSE(s.enabled(2));
  }
}

TEST(CameraSwitch, ParsesCommandLineSwitches) {
  std::string why;
  auto on = ParseCameraSwitch("red_1/camera=on", &why);
  ASSERT_TRUE(on.has_value()) << why;
  EXPECT_EQ(on->robot, "red_1");
  EXPECT_EQ(on->camera, "camera");
  EXPECT_TRUE(on->enabled);
  EXPECT_DOUBLE_EQ(on->rate_hz, 0);
  auto fast = ParseCameraSwitch("nao_1/top=on@62.5", &why);
  ASSERT_TRUE(fast.has_value()) << why;
  EXPECT_DOUBLE_EQ(fast->rate_hz, 62.5);
  auto off = ParseCameraSwitch("nao_1/top=off", &why);
  ASSERT_TRUE(off.has_value()) << why;
  EXPECT_FALSE(off->enabled);
  for (const char* bad : {"nao_1/top", "nao_1=on", "/top=on", "nao_1/=on", "nao_1/top=yes", "nao_1/top=on@",
                          "nao_1/top=on@0", "nao_1/top=on@-3", "nao_1/top=on@nan", "nao_1/top=on@5000",
                          "nao_1/top=on@5x", "nao_1/top=onn", "nao_1/top=on@1e-10"}) {
    why.clear();
    EXPECT_FALSE(ParseCameraSwitch(bad, &why).has_value()) << bad;
    EXPECT_FALSE(why.empty()) << bad;
  }
}

}  // namespace
}  // namespace turf
