// Legged scenes in the viewer: LeggedSceneInfo and LinkState in, the page's
// "legged" and state JSON out (parsed back and checked value by value), bad
// samples refused by name, and legged teleports from the page checked against
// the scene. No sockets, no DDS.
#include "participants/viewer/legged_json.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>

#include "participants/viewer/viewer_json.h"
#include "participants/viewer/viewer_model.h"
#include "tests/viewer/viewer_samples.h"

namespace turf::viewer {
namespace {

using nlohmann::json;

TEST(LeggedJson, SceneHasTheFieldAndEveryRobotsShapesOnce) {
  ViewerModel model("v", "turf");
  ASSERT_EQ(model.OnLeggedScene(test::LeggedScene()), SampleError::kOk);
  EXPECT_TRUE(model.is_legged());
  EXPECT_FALSE(model.has_state());
  const json s = json::parse(model.Field());
  EXPECT_EQ(s["type"], "legged");
  EXPECT_EQ(s["name"], "simspark-3d");
  EXPECT_DOUBLE_EQ(s["field"]["length"], 30.0);
  EXPECT_DOUBLE_EQ(s["field"]["width"], 20.0);
  EXPECT_DOUBLE_EQ(s["field"]["goal_width"], 2.1);
  EXPECT_DOUBLE_EQ(s["field"]["goal_depth"], 0.6);
  EXPECT_DOUBLE_EQ(s["field"]["ball_radius"], 0.042);
  ASSERT_EQ(s["robots"].size(), 2u);
  const json& r = s["robots"][0];
  EXPECT_EQ(r["name"], "nao_1");
  EXPECT_EQ(r["id"], 1);
  EXPECT_EQ(r["bodies"], json({"torso", "head"}));  // each once, in order of first use
  ASSERT_EQ(r["geoms"].size(), 3u);
  EXPECT_EQ(r["geoms"][0]["shape"], "box");
  EXPECT_EQ(r["geoms"][0]["b"], 0);
  EXPECT_EQ(r["geoms"][0]["size"], json({0.05, 0.05, 0.09}));
  EXPECT_EQ(r["geoms"][0]["q"], json({1.0, 0.0, 0.0, 0.0}));
  EXPECT_EQ(r["geoms"][1]["shape"], "capsule");
  EXPECT_EQ(r["geoms"][1]["b"], 0);
  EXPECT_EQ(r["geoms"][1]["p"], json({0.0, 0.0, 0.09}));
  EXPECT_EQ(r["geoms"][2]["shape"], "sphere");
  EXPECT_EQ(r["geoms"][2]["b"], 1);

  idl::LeggedSceneInfo bare = test::LeggedScene();
  bare.has_field(false);
  ASSERT_EQ(model.OnLeggedScene(bare), SampleError::kOk);
  EXPECT_TRUE(json::parse(model.Field())["field"].is_null());
}

TEST(LeggedJson, StateHasEachRobotsBodyPosesInTheScenesBodyOrder) {
  ViewerModel model("v", "turf");
  ASSERT_EQ(model.OnLeggedScene(test::LeggedScene()), SampleError::kOk);
  ASSERT_EQ(model.OnLinks(test::Links("nao_1", -14.2, 0.0)), SampleError::kOk);
  EXPECT_TRUE(model.has_state());
  json s = json::parse(model.State());
  EXPECT_EQ(s["type"], "state");
  EXPECT_DOUBLE_EQ(s["t"], 2.0);
  EXPECT_EQ(s["frame"], 1000);
  EXPECT_TRUE(s["robots"].empty());
  EXPECT_FALSE(s.contains("ball"));  // no world state yet
  ASSERT_TRUE(s["links"].contains("nao_1"));
  EXPECT_FALSE(s["links"].contains("nao_2"));  // no poses yet
  // torso then head, as "bodies"; positions to 1 mm, quaternions to 1e-4.
  EXPECT_EQ(s["links"]["nao_1"], json({-14.2, 0.0, 0.386, 0.7071, 0.0, 0.0, -0.7071,  //
                                       -14.2, 0.0, 0.512, 0.7071, 0.0, 0.0, -0.7071}));

  idl::WorldState ball;
  ball.sim_time_ns(2'000'000'000);
  ball.ball().position().x(1.0);
  ball.ball().position().z(0.042);
  ASSERT_EQ(model.OnWorldState(ball), SampleError::kOk);
  ASSERT_EQ(model.OnClock(test::SampleClock(true)), SampleError::kOk);
  ASSERT_EQ(model.OnLinks(test::Links("nao_2", -5.0, 1.5)), SampleError::kOk);
  model.SetControlMatched(true);
  s = json::parse(model.State());
  EXPECT_DOUBLE_EQ(s["ball"]["p"][0], 1.0);
  EXPECT_DOUBLE_EQ(s["links"]["nao_2"][1], 1.5);
  EXPECT_EQ(s["clock"]["paused"], true);
  EXPECT_EQ(s["viewer"]["control"], true);

  // A LinkState missing one of the drawn bodies: that robot is left out.
  idl::LinkState partial = test::Links("nao_2");
  partial.links().erase(partial.links().begin());  // no head
  ASSERT_EQ(model.OnLinks(partial), SampleError::kOk);
  EXPECT_FALSE(json::parse(model.State())["links"].contains("nao_2"));
}

TEST(LeggedJson, TheNewestSceneKindWins) {
  ViewerModel model("v", "turf");
  ASSERT_EQ(model.OnField(test::DivBField()), SampleError::kOk);
  ASSERT_EQ(model.OnWorldState(test::SampleState()), SampleError::kOk);
  ASSERT_EQ(model.OnLeggedScene(test::LeggedScene()), SampleError::kOk);
  EXPECT_FALSE(model.has_field());
  EXPECT_FALSE(model.has_state());  // the SSL state's robots are not in this scene
  ASSERT_EQ(model.OnLinks(test::Links()), SampleError::kOk);
  ASSERT_EQ(model.OnField(test::DivBField()), SampleError::kOk);
  EXPECT_FALSE(model.is_legged());
  EXPECT_EQ(json::parse(model.Field())["type"], "field");
}

TEST(LeggedJson, BadSamplesAreRefusedByName) {
  ViewerModel model("v", "turf");
  idl::LeggedSceneInfo s = test::LeggedScene();
  s.robots()[0].geoms()[0].size().x(test::kNaN);
  EXPECT_EQ(model.OnLeggedScene(s), SampleError::kNotFinite);
  s = test::LeggedScene();
  s.robots()[1].geoms()[2].orientation().w(INFINITY);
  EXPECT_EQ(model.OnLeggedScene(s), SampleError::kNotFinite);
  s = test::LeggedScene();
  s.robots()[0].geoms()[0].shape(static_cast<idl::GeomShape>(42));
  EXPECT_EQ(model.OnLeggedScene(s), SampleError::kUnknownEnum);
  s = test::LeggedScene();
  s.robots()[0].geoms()[0].size().y(-0.1);
  EXPECT_EQ(model.OnLeggedScene(s), SampleError::kBadSize);
  s = test::LeggedScene();
  s.field_length(0.0);
  EXPECT_EQ(model.OnLeggedScene(s), SampleError::kBadSize);
  s = test::LeggedScene();
  s.robots()[1].robot("nao_1");
  EXPECT_EQ(model.OnLeggedScene(s), SampleError::kDuplicate);
  s = test::LeggedScene();
  s.robots().resize(kMaxLeggedRobots + 1);
  EXPECT_EQ(model.OnLeggedScene(s), SampleError::kTooMany);
  s = test::LeggedScene();
  s.robots()[0].geoms().resize(kMaxBodies + 1);
  EXPECT_EQ(model.OnLeggedScene(s), SampleError::kTooMany);
  s = test::LeggedScene();
  s.robots()[0].robot(std::string(kMaxNameLength + 1, 'x'));
  EXPECT_EQ(model.OnLeggedScene(s), SampleError::kBadSize);
  EXPECT_FALSE(model.is_legged());

  ASSERT_EQ(model.OnLeggedScene(test::LeggedScene()), SampleError::kOk);
  idl::LinkState l = test::Links();
  l.links()[1].position().y(test::kNaN);
  EXPECT_EQ(model.OnLinks(l), SampleError::kNotFinite);
  l = test::Links();
  l.links()[0].orientation().x(-INFINITY);
  EXPECT_EQ(model.OnLinks(l), SampleError::kNotFinite);
  l = test::Links();
  l.links().resize(kMaxBodies + 1);
  EXPECT_EQ(model.OnLinks(l), SampleError::kTooMany);
  l = test::Links("");
  EXPECT_EQ(model.OnLinks(l), SampleError::kBadSize);
  EXPECT_FALSE(model.has_state());
  for (size_t i = 0; i < kMaxLeggedRobots; ++i)
    ASSERT_EQ(model.OnLinks(test::Links("r" + std::to_string(i))), SampleError::kOk);
  EXPECT_EQ(model.OnLinks(test::Links("one_too_many")), SampleError::kTooMany);
}

TEST(LeggedJson, TheMatchSceneStaysCompact) {
  // 22 robots of 23 shapes on 23 bodies (the Nao), every pose at full digits.
  idl::LeggedSceneInfo scene;
  scene.name("simspark-match");
  std::map<std::string, idl::LinkState> links;
  for (int i = 0; i < 22; ++i) {
    idl::RobotDescription r;
    r.robot("nao_" + std::to_string(i + 1));
    idl::LinkState l;
    l.robot(r.robot());
    for (int b = 0; b < 23; ++b) {
      const std::string body = "body" + std::to_string(b);
      r.geoms().push_back(test::Geom(body.c_str(), idl::GEOM_BOX, 0.05, 0.05, 0.05));
      l.links().push_back(test::Link(body.c_str(), -13.123456789 + i, -12.000123456, 0.3456789, 0.7071067, -0.7071067));
    }
    scene.robots().push_back(r);
    links[r.robot()] = l;
  }
  const std::string state = LeggedStateJson(nullptr, scene, links, std::nullopt, {});
  EXPECT_LT(state.size(), 22u * 23 * 7 * 8) << "about 8 bytes a number at most";
  EXPECT_EQ(json::parse(state)["links"]["nao_22"].size(), 23u * 7);
  RecordProperty("state_bytes", static_cast<int>(state.size()));
}

// The page's legged teleports, checked against the scene turf-sim runs.
class LeggedPage : public ::testing::Test {
 protected:
  PageRequest Parse(const std::string& text) { return ParsePageRequest(text, PageScene{nullptr, &scene_}); }
  idl::LeggedSceneInfo scene_ = test::LeggedScene();
};

TEST_F(LeggedPage, BallAnywhereOnTheFieldOrBesideIt) {
  PageRequest r = Parse(R"({"op":"teleport_ball","x":3,"y":-11})");
  ASSERT_EQ(r.error, PageError::kOk) << r.detail;
  EXPECT_EQ(r.control.op(), idl::OP_TELEPORT_BALL);
  EXPECT_DOUBLE_EQ(r.control.ball().position().x(), 3.0);
  EXPECT_DOUBLE_EQ(r.control.ball().position().y(), -11.0);
  EXPECT_DOUBLE_EQ(r.control.ball().position().z(), 0.042);  // resting on the ground
  EXPECT_TRUE(r.control.ball().roll());
  EXPECT_EQ(Parse(R"({"op":"teleport_ball","x":20.1,"y":0})").error, PageError::kOutsideField);
  EXPECT_EQ(Parse(R"({"op":"teleport_ball","x":0,"y":0,"z":11})").error, PageError::kOutsideField);
  EXPECT_EQ(Parse(R"({"op":"teleport_ball","x":0,"y":0,"vx":40})").error, PageError::kOutOfRange);
  EXPECT_EQ(Parse(R"({"op":"teleport_ball","x":"0","y":0})").error, PageError::kWrongType);
  scene_.has_field(false);
  EXPECT_EQ(Parse(R"({"op":"teleport_ball","x":0,"y":0})").error, PageError::kNoField);  // no field: no ball
}

TEST_F(LeggedPage, ThrowTheBall) {
  PageRequest r = Parse(R"({"op":"throw_ball","x":3,"y":-11,"vx":-2,"vy":5})");
  ASSERT_EQ(r.error, PageError::kOk) << r.detail;
  EXPECT_EQ(r.control.op(), idl::OP_TELEPORT_BALL);
  EXPECT_DOUBLE_EQ(r.control.ball().position().x(), 3.0);
  EXPECT_DOUBLE_EQ(r.control.ball().position().z(), 0.042);
  EXPECT_DOUBLE_EQ(r.control.ball().velocity().x(), -2.0);
  EXPECT_DOUBLE_EQ(r.control.ball().velocity().y(), 5.0);
  EXPECT_DOUBLE_EQ(r.control.ball().velocity().z(), 0.0);
  EXPECT_EQ(Parse(R"({"op":"throw_ball","x":20.1,"y":0,"vx":1,"vy":0})").error, PageError::kOutsideField);
  EXPECT_EQ(Parse(R"({"op":"throw_ball","x":0,"y":0,"vx":7,"vy":7})").error, PageError::kOutOfRange);
  scene_.has_field(false);
  EXPECT_EQ(Parse(R"({"op":"throw_ball","x":0,"y":0,"vx":1,"vy":0})").error, PageError::kNoField);
}

TEST_F(LeggedPage, RobotKeepsItsOrientationNormalised) {
  const PageRequest r =
      Parse(R"({"op":"teleport_robot","robot":"nao_2","x":-4,"y":2,"z":0.385,"qw":0.7,"qx":0,"qy":0,"qz":-0.7})");
  ASSERT_EQ(r.error, PageError::kOk) << r.detail;
  EXPECT_EQ(r.control.op(), idl::OP_TELEPORT_ROBOT);
  const idl::LeggedTeleport& t = r.control.legged();
  EXPECT_EQ(t.robot(), "nao_2");
  EXPECT_DOUBLE_EQ(t.position().x(), -4.0);
  EXPECT_DOUBLE_EQ(t.position().y(), 2.0);
  EXPECT_DOUBLE_EQ(t.position().z(), 0.385);
  EXPECT_NEAR(t.orientation().w(), std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(t.orientation().z(), -std::sqrt(0.5), 1e-12);
  EXPECT_FALSE(t.reset_joints());
}

TEST_F(LeggedPage, BadRobotTeleportsAreRefusedByName) {
  const std::string pose = R"("x":0,"y":0,"z":0.4,"qw":1,"qx":0,"qy":0,"qz":0)";
  EXPECT_EQ(Parse(R"({"op":"teleport_robot","robot":"nao_9",)" + pose + "}").error, PageError::kUnknownRobot);
  EXPECT_EQ(Parse(R"({"op":"teleport_robot","robot":"nao_1","reset_joints":true,)" + pose + "}").error,
            PageError::kUnknownKey);
  EXPECT_EQ(Parse(R"({"op":"teleport_robot","robot":"nao_1","x":0,"y":0,"z":0.4})").error, PageError::kMissingField);
  EXPECT_EQ(
      Parse(R"({"op":"teleport_robot","robot":"nao_1","x":0,"y":-25.1,"z":0.4,"qw":1,"qx":0,"qy":0,"qz":0})").error,
      PageError::kOutsideField);
  EXPECT_EQ(Parse(R"({"op":"teleport_robot","robot":"nao_1","x":0,"y":0,"z":-1,"qw":1,"qx":0,"qy":0,"qz":0})").error,
            PageError::kOutOfRange);
  EXPECT_EQ(Parse(R"({"op":"teleport_robot","robot":"nao_1","x":0,"y":0,"z":0.4,"qw":0,"qx":0,"qy":0,"qz":0})").error,
            PageError::kOutOfRange);  // not a rotation
  EXPECT_EQ(
      Parse(R"({"op":"teleport_robot","robot":"nao_1","x":0,"y":0,"z":0.4,"qw":1e999,"qx":0,"qy":0,"qz":0})").error,
      PageError::kNotJson);
  EXPECT_EQ(Parse(R"({"op":"teleport_robot","robot":7,)" + pose + "}").error, PageError::kWrongType);
  // The SSL form means nothing in a legged scene.
  EXPECT_EQ(Parse(R"({"op":"teleport_robot","team":"blue","id":0,"on_field":true,"x":0,"y":0,"yaw":0})").error,
            PageError::kUnknownKey);
  // And the legged form nothing in an SSL one.
  const std::optional<idl::SslField> ssl = test::DivBField();
  EXPECT_NE(ParsePageRequest(R"({"op":"teleport_robot","robot":"nao_1",)" + pose + "}", ssl).error, PageError::kOk);
}

TEST_F(LeggedPage, ModelChecksTeleportsAgainstTheLeggedScene) {
  ViewerModel model("v", "turf");
  EXPECT_EQ(model.OnPageMessage(R"({"op":"teleport_ball","x":12,"y":0})").error, PageError::kNoField);
  ASSERT_EQ(model.OnLeggedScene(scene_), SampleError::kOk);
  const PageRequest r = model.OnPageMessage(R"({"op":"teleport_ball","x":12,"y":0})");
  ASSERT_EQ(r.error, PageError::kOk) << r.detail;
  EXPECT_EQ(r.control.client(), "v");
  EXPECT_EQ(model.OnPageMessage(R"({"op":"pause"})").error, PageError::kOk);
}

}  // namespace
}  // namespace turf::viewer
