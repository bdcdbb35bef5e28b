// ViewerModel and viewer_json: DDS samples in, the page's JSON out (parsed back
// here and checked value by value), and bad samples refused by name.
#include "participants/viewer/viewer_model.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>

#include "core/errors.h"
#include "participants/viewer/http_rules.h"
#include "participants/viewer/viewer_json.h"
#include "tests/viewer/viewer_samples.h"

namespace turf::viewer {
namespace {

using nlohmann::json;

TEST(ViewerModel, NothingToShowBeforeSamples) {
  ViewerModel model("v", "turf");
  EXPECT_TRUE(model.Field().empty());
  EXPECT_TRUE(model.State().empty());
  EXPECT_TRUE(model.Stats().empty());
  const json hello = json::parse(model.Hello());
  EXPECT_EQ(hello["type"], "hello");
  EXPECT_EQ(hello["prefix"], "turf");
  EXPECT_EQ(hello["max_message"], kMaxPageMessage);
}

TEST(ViewerModel, FieldJsonHasTheGeometryToDrawToScale) {
  ViewerModel model("v", "turf");
  ASSERT_EQ(model.OnField(test::DivBField()), SampleError::kOk);
  const json f = json::parse(model.Field());
  EXPECT_EQ(f["type"], "field");
  EXPECT_EQ(f["division"], "B");
  EXPECT_DOUBLE_EQ(f["length"], 9.0);
  EXPECT_DOUBLE_EQ(f["width"], 6.0);
  EXPECT_DOUBLE_EQ(f["boundary"], 0.3);
  EXPECT_DOUBLE_EQ(f["goal_width"], 1.0);
  EXPECT_DOUBLE_EQ(f["goal_depth"], 0.18);
  EXPECT_DOUBLE_EQ(f["penalty_depth"], 1.0);
  EXPECT_DOUBLE_EQ(f["penalty_width"], 2.0);
  EXPECT_DOUBLE_EQ(f["center_radius"], 0.5);
  EXPECT_DOUBLE_EQ(f["ball_radius"], 0.0215);
  EXPECT_DOUBLE_EQ(f["robot_radius"], 0.09);
  EXPECT_EQ(f["robots_per_team"], 6);
  ASSERT_EQ(f["cameras"].size(), 1u);
  EXPECT_DOUBLE_EQ(f["cameras"][0]["min"][0], -4.8);
  EXPECT_DOUBLE_EQ(f["cameras"][0]["max"][1], 3.3);
}

TEST(ViewerModel, StateJsonHasBallRobotsClockAndRecentDetections) {
  ViewerModel model("v", "turf");
  ASSERT_EQ(model.OnWorldState(test::SampleState()), SampleError::kOk);
  ASSERT_EQ(model.OnClock(test::SampleClock(true)), SampleError::kOk);
  ASSERT_EQ(model.OnCamera(test::SampleFrame(0, 1'480'000'000)), SampleError::kOk);  // 20 ms old: shown
  ASSERT_EQ(model.OnCamera(test::SampleFrame(1, 1'000'000'000)), SampleError::kOk);  // 500 ms old: not
  ASSERT_EQ(model.OnCamera(test::SampleFrame(2, 1'600'000'000)), SampleError::kOk);  // future (reset): not
  const json s = json::parse(model.State());
  EXPECT_EQ(s["type"], "state");
  EXPECT_DOUBLE_EQ(s["t"], 1.5);
  EXPECT_EQ(s["frame"], 750);
  EXPECT_DOUBLE_EQ(s["ball"]["p"][0], 1.0);
  EXPECT_DOUBLE_EQ(s["ball"]["p"][2], 0.3);
  EXPECT_DOUBLE_EQ(s["ball"]["v"][0], 2.0);
  ASSERT_EQ(s["robots"].size(), 3u);
  const json& blue = s["robots"][0];
  EXPECT_EQ(blue["team"], "blue");
  EXPECT_EQ(blue["id"], 0);
  EXPECT_EQ(blue["on"], true);
  EXPECT_DOUBLE_EQ(blue["p"][0], -1.25);
  EXPECT_DOUBLE_EQ(blue["yaw"], 0.7854);  // rounded to 1e-4 rad
  EXPECT_EQ(s["robots"][1]["team"], "yellow");
  EXPECT_EQ(s["robots"][2]["on"], false);
  EXPECT_EQ(s["clock"]["paused"], true);
  EXPECT_EQ(s["clock"]["mode"], "scaled");
  EXPECT_DOUBLE_EQ(s["clock"]["speed"], 2.0);
  EXPECT_DOUBLE_EQ(s["clock"]["rtf"], 1.98);
  ASSERT_EQ(s["detections"].size(), 1u);
  const json& d = s["detections"][0];
  EXPECT_EQ(d["camera"], 0);
  EXPECT_DOUBLE_EQ(d["t"], 1.48);
  EXPECT_DOUBLE_EQ(d["balls"][0][0], 1.01);
  EXPECT_DOUBLE_EQ(d["balls"][0][3], 0.9);
  EXPECT_EQ(d["robots"][0]["team"], "blue");
  EXPECT_DOUBLE_EQ(d["robots"][0]["conf"], 0.95);
  EXPECT_EQ(s["viewer"]["refused"], 0);
  EXPECT_EQ(s["viewer"]["control"], false);
  model.SetControlMatched(true);
  EXPECT_EQ(json::parse(model.State())["viewer"]["control"], true);
  EXPECT_FALSE(json::parse(model.State())["viewer"].contains("gone_since"));  // present: nothing to say
  model.SetControlMatched(false);
  model.SetSimGoneSince(1764096727000);
  EXPECT_EQ(json::parse(model.State())["viewer"]["gone_since"], 1764096727000);
  model.SetSimGoneSince(0);
  EXPECT_FALSE(json::parse(model.State())["viewer"].contains("gone_since"));
}

TEST(ViewerModel, StatsJsonPerStream) {
  ViewerModel model("v", "turf");
  idl::SensorStats st;
  st.sim_time_ns(3'000'000'000);
  st.window_s(1.0);
  idl::StreamStats cam;
  cam.name("ssl/camera/0");
  cam.rate_hz(58.0);
  cam.sent(60);
  cam.lost(2);
  cam.loss_ratio(2.0 / 60.0);
  cam.latency_mean(0.0123456);
  cam.latency_stddev(0.002);
  st.streams().push_back(cam);
  ASSERT_EQ(model.OnStats(st), SampleError::kOk);
  const json s = json::parse(model.Stats());
  EXPECT_EQ(s["type"], "stats");
  EXPECT_DOUBLE_EQ(s["t"], 3.0);
  EXPECT_EQ(s["streams"][0]["name"], "ssl/camera/0");
  EXPECT_DOUBLE_EQ(s["streams"][0]["rate"], 58.0);
  EXPECT_EQ(s["streams"][0]["lost"], 2);
  EXPECT_DOUBLE_EQ(s["streams"][0]["loss"], 0.0333);
  EXPECT_DOUBLE_EQ(s["streams"][0]["latency"], 0.012346);
}

TEST(ViewerModel, BadSamplesAreRefusedAndKeepTheLastGoodOne) {
  ViewerModel model("v", "turf");
  ASSERT_EQ(model.OnWorldState(test::SampleState()), SampleError::kOk);
  const std::string good = model.State();

  idl::WorldState nan_ball = test::SampleState();
  nan_ball.ball().position().x(test::kNaN);
  EXPECT_EQ(model.OnWorldState(nan_ball), SampleError::kNotFinite);
  idl::WorldState inf_yaw = test::SampleState();
  inf_yaw.robots()[0].yaw(INFINITY);
  EXPECT_EQ(model.OnWorldState(inf_yaw), SampleError::kNotFinite);
  idl::WorldState bad_team = test::SampleState();
  bad_team.robots()[0].team(static_cast<idl::Team>(7));
  EXPECT_EQ(model.OnWorldState(bad_team), SampleError::kUnknownEnum);
  idl::WorldState crowd = test::SampleState();
  crowd.robots().resize(kMaxRobots + 1);
  EXPECT_EQ(model.OnWorldState(crowd), SampleError::kTooMany);
  EXPECT_EQ(model.State(), good);

  idl::SslField field = test::DivBField();
  field.field_length(-9.0);
  EXPECT_EQ(model.OnField(field), SampleError::kBadSize);
  field = test::DivBField();
  field.ball_radius(test::kNaN);
  EXPECT_EQ(model.OnField(field), SampleError::kNotFinite);
  EXPECT_FALSE(model.has_field());

  idl::CameraFrame frame = test::SampleFrame(0, 1'490'000'000);
  frame.robots()[0].confidence(std::numeric_limits<float>::quiet_NaN());
  EXPECT_EQ(model.OnCamera(frame), SampleError::kNotFinite);
  for (uint32_t c = 0; c < kMaxCameras; ++c) EXPECT_EQ(model.OnCamera(test::SampleFrame(c, 0)), SampleError::kOk);
  EXPECT_EQ(model.OnCamera(test::SampleFrame(1000, 0)), SampleError::kTooMany);

  idl::Clock clock = test::SampleClock(false);
  clock.real_time_factor(test::kNaN);
  EXPECT_EQ(model.OnClock(clock), SampleError::kNotFinite);
  clock = test::SampleClock(false);
  clock.mode(static_cast<idl::TimeMode>(9));
  EXPECT_EQ(model.OnClock(clock), SampleError::kUnknownEnum);

  idl::SensorStats stats;
  stats.streams().resize(kMaxStreams + 1);
  EXPECT_EQ(model.OnStats(stats), SampleError::kTooMany);
}

TEST(ViewerJson, InvalidUtf8FromOutsideDoesNotThrow) {
  idl::SimControlReply reply;
  reply.op(idl::OP_TELEPORT_BALL);
  reply.result(idl::RESULT_REJECTED);
  reply.reason("bad \xff\xfe bytes");
  const json r = json::parse(ReplyJson(reply));
  EXPECT_EQ(r["type"], "reply");
  EXPECT_EQ(r["op"], "teleport_ball");
  EXPECT_EQ(r["ok"], false);
  EXPECT_NE(r["reason"].get<std::string>().find("bad"), std::string::npos);
  EXPECT_EQ(json::parse(RefusedJson("not_json", "\xc3"))["kind"], "not_json");
  EXPECT_EQ(json::parse(HelloJson("pre\xff"))["type"], "hello");
}

TEST(ViewerJson, ReplyCarriesTheErrorCodeByItsTaxonomyName) {
  idl::SimControlReply reply;
  reply.op(idl::OP_STEP);
  reply.result(idl::RESULT_REJECTED);
  reply.error(idl::CONTROL_NOT_ALLOWED);
  reply.reason("step needs a paused simulation or lockstep mode");
  json r = json::parse(ReplyJson(reply));
  EXPECT_EQ(r["ok"], false);
  EXPECT_EQ(r["error"], "not_allowed");
  EXPECT_EQ(r["reason"], "step needs a paused simulation or lockstep mode");
  // Every code is sent by core/errors.h's name for the same value.
  for (int e = 0; e < static_cast<int>(Error::kCount); ++e) {
    reply.error(static_cast<idl::ControlError>(e));
    EXPECT_EQ(json::parse(ReplyJson(reply))["error"], ErrorName(static_cast<Error>(e))) << e;
  }
  reply.error(idl::CONTROL_NO_BALL);
  EXPECT_EQ(json::parse(ReplyJson(reply))["error"], "no_ball");
  reply.result(idl::RESULT_OK);
  reply.error(idl::CONTROL_OK);
  r = json::parse(ReplyJson(reply));
  EXPECT_EQ(r["ok"], true);
  EXPECT_EQ(r["error"], "ok");
}

TEST(HttpRules, StaticFilesStayInsideTheWebRoot) {
  EXPECT_EQ(StaticFile("/"), "index.html");
  EXPECT_EQ(StaticFile("/app.js"), "app.js");
  EXPECT_EQ(StaticFile("/style.css?v=2"), "style.css");
  EXPECT_EQ(StaticFile("/img/logo.svg"), "img/logo.svg");
  for (const char* bad : {"", "app.js", "/../etc/passwd", "/..", "/.git/config", "/a//b", "/a/", "/%2e%2e/x", "/a\\b",
                          "/a b", "/a/b/c/d/e", "http://x/app.js", "/\x01"})
    EXPECT_FALSE(StaticFile(bad)) << bad;
  EXPECT_FALSE(StaticFile("/" + std::string(300, 'a')));
  EXPECT_EQ(ContentType("index.html"), "text/html; charset=utf-8");
  EXPECT_EQ(ContentType("app.js"), "text/javascript; charset=utf-8");
  EXPECT_EQ(ContentType("x.bin"), "application/octet-stream");
}

TEST(HttpRules, WebSocketOnlyFromTheViewersOwnPage) {
  EXPECT_TRUE(UpgradeAllowed("127.0.0.1:8080", "http://127.0.0.1:8080", true));
  EXPECT_TRUE(UpgradeAllowed("localhost:8080", "http://localhost:8080", true));
  EXPECT_TRUE(UpgradeAllowed("127.0.0.1:8080", "", true));  // not a browser
  EXPECT_FALSE(UpgradeAllowed("127.0.0.1:8080", "http://evil.example", true));
  EXPECT_FALSE(UpgradeAllowed("127.0.0.1:8080", "http://127.0.0.1:9999", true));
  EXPECT_FALSE(UpgradeAllowed("127.0.0.1:8080", "null", true));
  EXPECT_FALSE(UpgradeAllowed("evil.example:8080", "http://evil.example:8080", true));  // DNS rebinding
  const std::vector<std::string> names = {"field-pc"};
  EXPECT_TRUE(UpgradeAllowed("field-pc:8080", "http://field-pc:8080", false, names));  // --listen 0.0.0.0
  EXPECT_TRUE(UpgradeAllowed("Field-PC:8080", "http://Field-PC:8080", false, names));  // names have no case
  EXPECT_FALSE(UpgradeAllowed("field-pc:8080", "http://evil.example", false, names));
  EXPECT_FALSE(UpgradeAllowed("", "", true));
  // On the network the Host is an address, localhost or a name the viewer knows: a rebinding site's page (its own
  // name resolved to this machine's address) has Origin == Host, which alone let it drive the simulator.
  EXPECT_FALSE(UpgradeAllowed("evil.example:8080", "http://evil.example:8080", false, names));
  EXPECT_TRUE(UpgradeAllowed("192.168.1.20:8080", "http://192.168.1.20:8080", false, names));
  EXPECT_TRUE(UpgradeAllowed("[fe80::1]:8080", "http://[fe80::1]:8080", false, names));
  EXPECT_TRUE(UpgradeAllowed("localhost:8080", "http://localhost:8080", false, names));
  const std::vector<std::string> defaults = PageHostNames({"robots.lab"});
  EXPECT_EQ(defaults.front(), "robots.lab");
  EXPECT_GE(defaults.size(), 3u) << "this machine's name and its .local";
  EXPECT_TRUE(UpgradeAllowed(defaults[1] + ":8080", "http://" + defaults[1] + ":8080", false, defaults));
}

TEST(HttpRules, RateLimitPerSecond) {
  RateLimit limit(3);
  const auto t0 = std::chrono::steady_clock::now();
  EXPECT_TRUE(limit.Allow(t0));
  EXPECT_TRUE(limit.Allow(t0));
  EXPECT_TRUE(limit.Allow(t0));
  EXPECT_FALSE(limit.Allow(t0 + std::chrono::milliseconds(500)));
  EXPECT_TRUE(limit.Allow(t0 + std::chrono::milliseconds(1001)));
}

}  // namespace
}  // namespace turf::viewer
