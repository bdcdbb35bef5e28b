// Page messages -> SimControl: what is accepted becomes exactly the request
// turf-sim expects; everything else is refused with its named error and yields
// no request. No sockets, no DDS.
#include "participants/viewer/page_request.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "participants/viewer/viewer_model.h"
#include "tests/viewer/viewer_samples.h"

namespace turf::viewer {
namespace {

const std::optional<idl::SslField> kField = test::DivBField();

PageRequest Parse(const std::string& text) { return ParsePageRequest(text, kField); }

TEST(PageRequest, TeleportBallOnTheGroundRolls) {
  const PageRequest r = Parse(R"({"op":"teleport_ball","x":1.5,"y":-2})");
  ASSERT_EQ(r.error, PageError::kOk) << r.detail;
  EXPECT_EQ(r.control.op(), idl::OP_TELEPORT_BALL);
  EXPECT_DOUBLE_EQ(r.control.ball().position().x(), 1.5);
  EXPECT_DOUBLE_EQ(r.control.ball().position().y(), -2.0);
  EXPECT_DOUBLE_EQ(r.control.ball().position().z(), 0.0215);  // resting on the carpet
  EXPECT_DOUBLE_EQ(r.control.ball().velocity().x(), 0.0);
  EXPECT_TRUE(r.control.ball().roll());
}

TEST(PageRequest, TeleportBallWithHeightAndVelocity) {
  const PageRequest r = Parse(R"({"op":"teleport_ball","x":0,"y":0,"z":0.5,"vx":1,"vy":-2,"vz":3})");
  ASSERT_EQ(r.error, PageError::kOk) << r.detail;
  EXPECT_DOUBLE_EQ(r.control.ball().position().z(), 0.5);
  EXPECT_DOUBLE_EQ(r.control.ball().velocity().y(), -2.0);
  EXPECT_DOUBLE_EQ(r.control.ball().velocity().z(), 3.0);
  EXPECT_FALSE(r.control.ball().roll());
}

TEST(PageRequest, ThrowBallRollsFromWhereItLies) {
  const PageRequest r = Parse(R"({"op":"throw_ball","x":-1,"y":0.5,"vx":4.8,"vy":-6.4})");  // 8 m/s
  ASSERT_EQ(r.error, PageError::kOk) << r.detail;
  EXPECT_EQ(r.control.op(), idl::OP_TELEPORT_BALL);
  EXPECT_DOUBLE_EQ(r.control.ball().position().x(), -1.0);
  EXPECT_DOUBLE_EQ(r.control.ball().position().y(), 0.5);
  EXPECT_DOUBLE_EQ(r.control.ball().position().z(), 0.0215);  // on the carpet
  EXPECT_DOUBLE_EQ(r.control.ball().velocity().x(), 4.8);
  EXPECT_DOUBLE_EQ(r.control.ball().velocity().y(), -6.4);
  EXPECT_DOUBLE_EQ(r.control.ball().velocity().z(), 0.0);
  EXPECT_TRUE(r.control.ball().roll());
}

TEST(PageRequest, TeleportRobotPlacesAndNormalisesYaw) {
  const PageRequest r = Parse(R"({"op":"teleport_robot","team":"yellow","id":5,"on_field":true,"x":-4,"y":3,"yaw":7})");
  ASSERT_EQ(r.error, PageError::kOk) << r.detail;
  const idl::RobotTeleport& t = r.control.robot();
  EXPECT_EQ(r.control.op(), idl::OP_TELEPORT_ROBOT);
  EXPECT_EQ(t.team(), idl::TEAM_YELLOW);
  EXPECT_EQ(t.id(), 5);
  EXPECT_TRUE(t.on_field());
  EXPECT_DOUBLE_EQ(t.position().x(), -4.0);
  EXPECT_DOUBLE_EQ(t.position().y(), 3.0);
  EXPECT_NEAR(t.orientation(), 7.0 - 2 * M_PI, 1e-12);
  EXPECT_DOUBLE_EQ(t.velocity().x(), 0.0);
}

TEST(PageRequest, TakeRobotOffTheField) {
  const PageRequest r = Parse(R"({"op":"teleport_robot","team":"blue","id":0,"on_field":false})");
  ASSERT_EQ(r.error, PageError::kOk) << r.detail;
  EXPECT_FALSE(r.control.robot().on_field());
  EXPECT_EQ(r.control.robot().team(), idl::TEAM_BLUE);
}

TEST(PageRequest, SimulationOps) {
  EXPECT_EQ(Parse(R"({"op":"pause"})").control.op(), idl::OP_PAUSE);
  EXPECT_EQ(Parse(R"({"op":"resume"})").control.op(), idl::OP_RESUME);
  EXPECT_EQ(Parse(R"({"op":"reset"})").control.op(), idl::OP_RESET);
  const PageRequest step = Parse(R"({"op":"step","count":25})");
  EXPECT_EQ(step.control.op(), idl::OP_STEP);
  EXPECT_EQ(step.control.step_count(), 25u);
  EXPECT_EQ(Parse(R"({"op":"step"})").control.step_count(), 1u);
  const PageRequest scaled = Parse(R"({"op":"time_mode","mode":"scaled","speed":0.5})");
  EXPECT_EQ(scaled.control.op(), idl::OP_SET_TIME_MODE);
  EXPECT_EQ(scaled.control.time_mode(), idl::TIME_SCALED);
  EXPECT_DOUBLE_EQ(scaled.control.speed(), 0.5);
  EXPECT_EQ(Parse(R"({"op":"time_mode","mode":"free"})").control.time_mode(), idl::TIME_FREE_RUNNING);
  EXPECT_EQ(Parse(R"({"op":"time_mode","mode":"realtime"})").control.time_mode(), idl::TIME_REALTIME);
  const PageRequest realism = Parse(R"({"op":"realism","preset":"harsh"})");
  EXPECT_EQ(realism.control.op(), idl::OP_SET_REALISM);
  EXPECT_EQ(realism.control.realism_preset(), "harsh");
  EXPECT_TRUE(realism.control.realism_values().empty());
}

TEST(PageRequest, TeleportsNeedTheField) {
  const PageRequest r = ParsePageRequest(R"({"op":"teleport_ball","x":0,"y":0})", std::nullopt);
  EXPECT_EQ(r.error, PageError::kNoField);
  EXPECT_EQ(ParsePageRequest(R"({"op":"throw_ball","x":0,"y":0,"vx":1,"vy":0})", std::nullopt).error,
            PageError::kNoField);
  EXPECT_EQ(ParsePageRequest(R"({"op":"pause"})", std::nullopt).error, PageError::kOk);
}

struct Bad {
  std::string text;
  PageError error;
};

class PageRequestRefuses : public ::testing::TestWithParam<Bad> {};

TEST_P(PageRequestRefuses, WithItsNamedError) {
  const PageRequest r = Parse(GetParam().text);
  EXPECT_EQ(r.error, GetParam().error) << PageErrorName(r.error) << ": " << r.detail;
  EXPECT_FALSE(r.detail.empty());
}

INSTANTIATE_TEST_SUITE_P(
    Malicious, PageRequestRefuses,
    ::testing::Values(
        Bad{std::string(kMaxPageMessage + 1, ' '), PageError::kTooLarge}, Bad{"", PageError::kNotJson},
        Bad{"{", PageError::kNotJson}, Bad{"{\"op\":\"pause\"", PageError::kNotJson},
        Bad{R"({"op":"teleport_ball","x":NaN,"y":0})", PageError::kNotJson},
        Bad{R"({"op":"teleport_ball","x":Infinity,"y":0})", PageError::kNotJson},
        Bad{R"({"op":"teleport_ball","x":1e999,"y":0})", PageError::kNotJson},  // JSON cannot hold it
        Bad{"\xff\xfe{}", PageError::kNotJson}, Bad{std::string("{\"op\":\"pa\0se\"}", 14), PageError::kNotJson},
        Bad{std::string(2000, '[') + std::string(2000, ']'), PageError::kNotObject}, Bad{"[]", PageError::kNotObject},
        Bad{"42", PageError::kNotObject}, Bad{"\"pause\"", PageError::kNotObject}, Bad{"null", PageError::kNotObject},
        Bad{"{}", PageError::kUnknownOp}, Bad{R"({"op":7})", PageError::kUnknownOp},
        Bad{R"({"op":"explode"})", PageError::kUnknownOp}, Bad{R"({"op":"PAUSE"})", PageError::kUnknownOp},
        Bad{R"({"op":"pause","now":true})", PageError::kUnknownKey},
        Bad{R"({"op":"teleport_ball","x":0,"y":0,"__proto__":{}})", PageError::kUnknownKey},
        Bad{R"({"op":"teleport_ball","x":0})", PageError::kMissingField},
        Bad{R"({"op":"teleport_ball","x":"0","y":0})", PageError::kWrongType},
        Bad{R"({"op":"teleport_ball","x":null,"y":0})", PageError::kWrongType},
        Bad{R"({"op":"teleport_ball","x":[1],"y":0})", PageError::kWrongType},
        Bad{R"({"op":"teleport_ball","x":5,"y":0})", PageError::kOutsideField},    // past the goal-line wall
        Bad{R"({"op":"teleport_ball","x":0,"y":3.3})", PageError::kOutsideField},  // the wall itself
        Bad{R"({"op":"teleport_ball","x":0,"y":0,"z":-0.1})", PageError::kOutsideField},
        Bad{R"({"op":"teleport_ball","x":0,"y":0,"z":11})", PageError::kOutsideField},
        Bad{R"({"op":"teleport_ball","x":1e300,"y":0})", PageError::kOutOfRange},
        Bad{R"({"op":"teleport_ball","x":0,"y":0,"vx":31})", PageError::kOutOfRange},
        Bad{R"({"op":"teleport_ball","x":0,"y":0,"vx":25,"vy":25})", PageError::kOutOfRange},
        Bad{"{\"op\":\"throw_ball\",\"x\":0,\"y\":0,\"vx\":NaN,\"vy\":0}", PageError::kNotJson},
        Bad{R"({"op":"throw_ball","x":0,"y":0,"vx":null,"vy":0})", PageError::kWrongType},  // JSON.stringify(NaN)
        Bad{R"({"op":"throw_ball","x":0,"y":0,"vx":1e999,"vy":0})", PageError::kNotJson},
        Bad{R"({"op":"throw_ball","x":0,"y":0,"vx":8.01,"vy":0})", PageError::kOutOfRange},
        Bad{R"({"op":"throw_ball","x":0,"y":0,"vx":6,"vy":-6})", PageError::kOutOfRange},  // 8.5 m/s
        Bad{R"({"op":"throw_ball","x":0,"y":0,"vx":-30,"vy":0})", PageError::kOutOfRange},
        Bad{R"({"op":"throw_ball","x":4.8,"y":0,"vx":1,"vy":0})", PageError::kOutsideField},
        Bad{R"({"op":"throw_ball","x":0,"y":-3.3,"vx":1,"vy":0})", PageError::kOutsideField},
        Bad{R"({"op":"throw_ball","x":1e300,"y":0,"vx":1,"vy":0})", PageError::kOutOfRange},
        Bad{R"({"op":"throw_ball","x":0,"y":0,"vx":1})", PageError::kMissingField},
        Bad{R"({"op":"throw_ball","x":0,"y":0,"z":1,"vx":1,"vy":0})", PageError::kUnknownKey},
        Bad{R"({"op":"throw_ball","x":0,"y":0,"vx":1,"vy":0,"vz":5})", PageError::kUnknownKey},
        Bad{R"({"op":"throw_ball","x":0,"y":0,"vx":"1","vy":0})", PageError::kWrongType},
        Bad{R"({"op":"teleport_robot","team":"red","id":0,"on_field":false})", PageError::kUnknownTeam},
        Bad{R"({"op":"teleport_robot","team":"blue","id":6,"on_field":false})", PageError::kUnknownRobot},
        Bad{R"({"op":"teleport_robot","team":"blue","id":256,"on_field":false})", PageError::kOutOfRange},
        Bad{R"({"op":"teleport_robot","team":"blue","id":-1,"on_field":false})", PageError::kOutOfRange},
        Bad{R"({"op":"teleport_robot","team":"blue","id":18446744073709551615,"on_field":false})",
            PageError::kOutOfRange},
        Bad{R"({"op":"teleport_robot","team":"blue","id":1.5,"on_field":false})", PageError::kWrongType},
        Bad{R"({"op":"teleport_robot","team":"blue","id":0,"on_field":"yes"})", PageError::kWrongType},
        Bad{R"({"op":"teleport_robot","team":"blue","id":0,"on_field":true,"x":0,"y":0})", PageError::kMissingField},
        Bad{R"({"op":"teleport_robot","team":"blue","id":0,"on_field":false,"x":0})", PageError::kUnknownKey},
        Bad{R"({"op":"teleport_robot","team":"blue","id":0,"on_field":true,"x":4.75,"y":0,"yaw":0})",
            PageError::kOutsideField},
        Bad{R"({"op":"teleport_robot","team":"blue","id":0,"on_field":true,"x":0,"y":0,"yaw":1e9})",
            PageError::kOutOfRange},
        Bad{R"({"op":"step","count":0})", PageError::kOutOfRange},
        Bad{R"({"op":"step","count":1001})", PageError::kOutOfRange},
        Bad{R"({"op":"step","count":-5})", PageError::kOutOfRange},
        Bad{R"({"op":"time_mode","mode":"warp"})", PageError::kUnknownMode},
        Bad{R"({"op":"time_mode","mode":"scaled"})", PageError::kMissingField},
        Bad{R"({"op":"time_mode","mode":"scaled","speed":0})", PageError::kOutOfRange},
        Bad{R"({"op":"time_mode","mode":"scaled","speed":-1})", PageError::kOutOfRange},
        Bad{R"({"op":"time_mode","mode":"scaled","speed":1e6})", PageError::kOutOfRange},
        Bad{R"({"op":"time_mode","mode":"scaled","speed":1e-6})", PageError::kOutOfRange},
        Bad{R"({"op":"time_mode","mode":"free","speed":2})", PageError::kUnknownKey},
        Bad{R"({"op":"realism","preset":"/etc/passwd"})", PageError::kUnknownPreset},
        Bad{R"({"op":"realism","preset":"camera: {robot_vanish: 1}"})", PageError::kUnknownPreset}));

// Client name and request ids: dds::ControlClient's (tests/sim/control_client_test.cpp).
TEST(ViewerModelPages, RequestsAreReadyToSend) {
  ViewerModel model("turf-viewer-1", "turf");
  ASSERT_EQ(model.OnField(test::DivBField()), SampleError::kOk);
  const PageRequest a = model.OnPageMessage(R"({"op":"pause"})");
  ASSERT_EQ(a.error, PageError::kOk);
  EXPECT_EQ(a.control.op(), idl::OP_PAUSE);
  const PageRequest b = model.OnPageMessage(R"({"op":"teleport_ball","x":0.5,"y":-1})");
  ASSERT_EQ(b.error, PageError::kOk);
  EXPECT_EQ(b.control.op(), idl::OP_TELEPORT_BALL);
  EXPECT_EQ(b.control.ball().position().x(), 0.5);
}

TEST(ViewerModelPages, RefusalsAreCountedAndShownToThePage) {
  ViewerModel model("v", "turf");
  EXPECT_EQ(model.OnPageMessage("garbage").error, PageError::kNotJson);
  EXPECT_EQ(model.OnPageMessage(R"({"op":"teleport_ball","x":0,"y":0})").error, PageError::kNoField);
  model.CountRefusedPage();
  EXPECT_EQ(model.refused_pages(), 3u);
  ASSERT_EQ(model.OnWorldState(test::SampleState()), SampleError::kOk);
  EXPECT_NE(model.State().find("\"refused\":3"), std::string::npos);
}

}  // namespace
}  // namespace turf::viewer
