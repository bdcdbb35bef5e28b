// turf-viewer's node in-process with turf-sim's node and a DDS client, on a
// test domain and prefix: the page's files over HTTP, its WebSocket stream,
// controls reaching turf-sim, and hostile input refused without effect.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <atomic>
#include <boost/asio.hpp>
#include <cmath>
#include <istream>
#include <memory>
#include <thread>

#include "participants/viewer/viewer_node.h"
#include "participants/viewer/web_server.h"
#include "tests/sim/sim_harness.h"
#include "tests/support/in_process.h"
#include "tests/viewer/viewer_under_test.h"
#include "tests/viewer/web_client.h"

namespace turf::test {
namespace {

using nlohmann::json;
namespace http = boost::beast::http;

// Connects a page's WebSocket to the viewer, as a browser on its page would.
::testing::AssertionResult Connected(WsClient& ws, ViewerUnderTest& viewer) {
  std::string error;
  if (ws.Connect(viewer.port(), viewer.origin(), &error)) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << error;
}

// Reads until a message of `type` satisfying `also` arrives; returns it.
std::optional<json> ReadType(
    WsClient& ws, const std::string& type,
    const std::function<bool(const json&)>& also = [](const json&) { return true; },
    std::chrono::milliseconds timeout = 5s) {
  std::optional<json> found;
  ws.ReadUntil(
      [&](const std::string& text) {
        json m = json::parse(text, nullptr, false);
        if (m.is_discarded() || m["type"] != type || !also(m)) return false;
        found = std::move(m);
        return true;
      },
      timeout);
  return found;
}

// Polls `done` until it holds or the timeout passes (counters are updated on
// the viewer's threads, a moment after the client sees the effect).
bool Eventually(const std::function<bool()>& done, std::chrono::milliseconds timeout = 30s) {
  const auto end = Clock::now() + timeout;
  while (!done()) {
    if (Clock::now() > end) return false;
    std::this_thread::sleep_for(5ms);
  }
  return true;
}

struct Rig {
  dds::ParticipantOptions dds = UniqueDds("viewer");
  SimUnderTest sim{Teams(3), dds, TimeMode::kRealtime};
  ViewerUnderTest viewer{dds};
  Client client{dds};

  // turf-sim, the client and the viewer's control writer all matched.
  bool Ready() {
    return client.WaitMatched() && Eventually([this] { return viewer.node().Stats().control_matched; });
  }
  // Ready(), and a page's WebSocket connected to the viewer.
  ::testing::AssertionResult ReadyAndConnected(WsClient& ws) {
    if (!Ready()) return ::testing::AssertionFailure() << "turf-sim, the client and the viewer did not all match";
    return Connected(ws, viewer);
  }
};

TEST(ViewerServer, ServesThePageFilesAndNothingElse) {
  Rig rig;
  const int port = rig.viewer.port();
  const HttpResult index = HttpGet(port, "/");
  ASSERT_EQ(index.status, 200) << index.error;
  EXPECT_EQ(index.content_type, "text/html; charset=utf-8");
  EXPECT_NE(index.body.find("<canvas id=\"field\""), std::string::npos);
  const HttpResult app = HttpGet(port, "/app.js");
  EXPECT_EQ(app.status, 200);
  EXPECT_EQ(app.content_type, "text/javascript; charset=utf-8");
  EXPECT_EQ(HttpGet(port, "/style.css").status, 200);
  EXPECT_EQ(HttpGet(port, "/missing.js").status, 404);
  EXPECT_EQ(HttpGet(port, "/../CMakeLists.txt").status, 404);
  EXPECT_EQ(HttpGet(port, "/%2e%2e/CMakeLists.txt").status, 404);
  EXPECT_EQ(HttpRequest(http::verb::post, port, "/", "{}").status, 405);
  const HttpResult huge = HttpGet(port, "/", {{"X-Filler", std::string(16 * 1024, 'a')}});
  EXPECT_NE(huge.status, 200);                  // headers over the limit: refused, connection closed
  EXPECT_EQ(HttpGet(port, "/ws").status, 404);  // not an upgrade
  EXPECT_GE(rig.viewer.node().Rejected("http.bad_target"), 2u);
  EXPECT_EQ(rig.viewer.node().Rejected("http.method"), 1u);
  EXPECT_EQ(rig.viewer.node().Rejected("http.malformed"), 1u);
}

TEST(ViewerServer, StreamsTheWorldAndTeleportsTheBall) {
  Rig rig;
  WsClient ws;
  ASSERT_TRUE(rig.ReadyAndConnected(ws));
  ASSERT_TRUE(ReadType(ws, "hello"));
  const auto field = ReadType(ws, "field");
  ASSERT_TRUE(field);
  EXPECT_EQ((*field)["division"], "A");
  EXPECT_DOUBLE_EQ((*field)["length"], 12.0);
  const auto state = ReadType(ws, "state", [](const json& m) { return m["robots"].size() == 6; });
  ASSERT_TRUE(state);
  // The robots stand still, so the page's state and the DDS client's agree.
  rig.client.Poll();
  for (const json& r : (*state)["robots"]) {
    const idl::RobotState* truth =
        FindRobot(rig.client.state(), r["team"] == "blue" ? idl::TEAM_BLUE : idl::TEAM_YELLOW, r["id"]);
    ASSERT_NE(truth, nullptr);
    EXPECT_NEAR(r["p"][0].get<double>(), truth->position().x(), 2e-3);
    EXPECT_NEAR(r["p"][1].get<double>(), truth->position().y(), 2e-3);
    EXPECT_NEAR(r["yaw"].get<double>(), truth->yaw(), 2e-3);
  }

  ASSERT_TRUE(ws.Send(R"({"op":"teleport_ball","x":1.25,"y":-0.75})"));
  EXPECT_TRUE(rig.client.WaitState([](const idl::WorldState& s) {
    return std::hypot(s.ball().position().x() - 1.25, s.ball().position().y() + 0.75) < 0.01;
  }));
  const auto reply = ReadType(ws, "reply", [](const json& m) { return m["op"] == "teleport_ball"; });
  ASSERT_TRUE(reply);
  EXPECT_EQ((*reply)["ok"], true);
  EXPECT_TRUE(ReadType(ws, "state", [](const json& m) {
    return std::hypot(m["ball"]["p"][0].get<double>() - 1.25, m["ball"]["p"][1].get<double>() + 0.75) < 0.01;
  }));
  EXPECT_EQ(rig.viewer.node().Stats().controls_sent, 1u);
}

TEST(ViewerServer, PauseStepAndResumeFromThePage) {
  Rig rig;
  WsClient ws;
  ASSERT_TRUE(rig.ReadyAndConnected(ws));
  ASSERT_TRUE(ws.Send(R"({"op":"pause"})"));
  // The reply gives the simulation time at which it paused; the state of that
  // time follows, and then nothing later.
  const auto reply = ReadType(ws, "reply", [](const json& m) { return m["op"] == "pause"; });
  ASSERT_TRUE(reply);
  EXPECT_EQ((*reply)["ok"], true);
  const double t_paused = (*reply)["t"];
  ASSERT_TRUE(ReadType(ws, "state", [&](const json& m) {
    return m["clock"]["paused"] == true && std::abs(m["t"].get<double>() - t_paused) < 1e-9;
  }));
  // Nothing later: a second pause (each request is a turn of turf-sim's loop,
  // which would step if it could) is answered at the same time, and the state
  // turf-sim publishes after it, like every state before it, is of that time.
  ASSERT_TRUE(ws.Send(R"({"op":"pause"})"));
  std::optional<double> t_probe;
  int states = 0;
  ASSERT_TRUE(ws.ReadUntil([&](const std::string& text) {
    const json m = json::parse(text, nullptr, false);
    if (m.is_discarded()) return false;
    if (m["type"] == "reply") t_probe = m["t"].get<double>();
    if (m["type"] == "state") {
      ++states;
      EXPECT_NEAR(m["t"].get<double>(), t_paused, 1e-9);
      EXPECT_EQ(m["clock"]["paused"], true);
    }
    return t_probe && states > 0;
  })) << "no reply to the second pause, or no state after it";
  EXPECT_NEAR(*t_probe, t_paused, 1e-9);
  ASSERT_TRUE(ws.Send(R"({"op":"step","count":50})"));
  EXPECT_TRUE(
      ReadType(ws, "state", [&](const json& m) { return std::abs(m["t"].get<double>() - t_paused - 0.1) < 1e-6; }));
  ASSERT_TRUE(ws.Send(R"({"op":"resume"})"));
  EXPECT_TRUE(ReadType(ws, "state", [&](const json& m) { return m["t"].get<double>() > t_paused + 0.3; }));
}

TEST(ViewerServer, EachPageSeesOnlyTheRepliesToItsOwnRequests) {
  Rig rig;
  ASSERT_TRUE(rig.Ready());
  WsClient a, b;
  ASSERT_TRUE(Connected(a, rig.viewer));
  ASSERT_TRUE(Connected(b, rig.viewer));
  ASSERT_TRUE(ReadType(a, "state"));
  ASSERT_TRUE(ReadType(b, "state"));
  // Page A steps a running simulation: turf-sim refuses, and A is told why.
  ASSERT_TRUE(a.Send(R"({"op":"step","count":5})"));
  const auto refused = ReadType(a, "reply");
  ASSERT_TRUE(refused);
  EXPECT_EQ((*refused)["op"], "step");
  EXPECT_EQ((*refused)["ok"], false);
  EXPECT_EQ((*refused)["error"], "not_allowed");
  // Page B's first reply is the answer to its own request (A's refusal came
  // before it, so had it been sent to B it would be read first).
  ASSERT_TRUE(b.Send(R"({"op":"pause"})"));
  const auto b_reply = ReadType(b, "reply");
  ASSERT_TRUE(b_reply);
  EXPECT_EQ((*b_reply)["op"], "pause");
  EXPECT_EQ((*b_reply)["ok"], true);
  // And A does not see B's: its next reply is to its own resume. State
  // updates still reach both pages.
  ASSERT_TRUE(a.Send(R"({"op":"resume"})"));
  const auto a_reply = ReadType(a, "reply");
  ASSERT_TRUE(a_reply);
  EXPECT_EQ((*a_reply)["op"], "resume");
  const double t_resumed = (*a_reply)["t"];
  for (WsClient* page : {&a, &b})
    EXPECT_TRUE(ReadType(*page, "state", [&](const json& m) { return m["t"].get<double>() > t_resumed; }));
  EXPECT_TRUE(Eventually([&] { return rig.viewer.node().Stats().replies == 3; }));
}

TEST(ViewerServer, ThrowsTheBall) {
  Rig rig;
  WsClient ws;
  ASSERT_TRUE(rig.ReadyAndConnected(ws));
  ASSERT_TRUE(ReadType(ws, "field"));
  ASSERT_TRUE(ws.Send(R"({"op":"throw_ball","x":-1,"y":0.5,"vx":3,"vy":-1})"));
  // It rolls off in the thrown direction, slowing on the carpet.
  EXPECT_TRUE(rig.client.WaitState([](const idl::WorldState& s) {
    const idl::Vec3& p = s.ball().position();
    const idl::Vec3& v = s.ball().velocity();
    return p.x() > -0.9 && p.y() < 0.5 && v.x() > 0.5 && std::abs(v.y() + v.x() / 3) < 0.2;
  })) << "ball at ("
      << rig.client.state().ball().position().x() << ", " << rig.client.state().ball().position().y() << ")";
  ASSERT_TRUE(ws.Send(R"({"op":"throw_ball","x":-1,"y":0.5,"vx":8,"vy":8})"));  // 11.3 m/s
  const auto refused = ReadType(ws, "refused");
  ASSERT_TRUE(refused);
  EXPECT_EQ((*refused)["kind"], "out_of_range");
  EXPECT_EQ(rig.viewer.node().Stats().controls_sent, 1u);
}

TEST(ViewerServer, RefusesHostileMessagesAndMovesNothing) {
  Rig rig;
  WsClient ws;
  ASSERT_TRUE(rig.ReadyAndConnected(ws));
  ASSERT_TRUE(ReadType(ws, "field"));
  rig.client.Poll();
  const idl::WorldState before = rig.client.state();

  const std::vector<std::string> hostile = {
      "not json at all",
      "{\"op\":\"teleport_ball\",\"x\":NaN,\"y\":0}",
      R"({"op":"teleport_ball","x":1e999,"y":0})",
      R"({"op":"teleport_ball","x":99,"y":0})",
      R"({"op":"teleport_robot","team":"blue","id":200,"on_field":true,"x":0,"y":0,"yaw":0})",
      R"({"op":"teleport_robot","team":"green","id":0,"on_field":false})",
      R"({"op":"step","count":4294967296})",
      R"({"op":"realism","preset":"../../etc/passwd"})",
      R"({"op":"shutdown"})",
      R"([{"op":"pause"}])",
      std::string(5000, 'x'),
  };
  for (const std::string& m : hostile) ASSERT_TRUE(ws.Send(m));
  ASSERT_TRUE(ws.SendBinary(std::string("\x00\x01\x02", 3)));
  int refused = 0;
  ws.ReadUntil([&](const std::string& text) {
    const json m = json::parse(text);
    if (m["type"] == "refused") ++refused;
    return refused == static_cast<int>(hostile.size()) + 1;
  });
  EXPECT_EQ(refused, static_cast<int>(hostile.size()) + 1);
  ViewerNode& v = rig.viewer.node();
  EXPECT_EQ(v.Stats().controls_sent, 0u);
  EXPECT_EQ(v.Rejected("page.not_json"), 3u);
  EXPECT_EQ(v.Rejected("page.outside_field"), 1u);
  EXPECT_EQ(v.Rejected("page.unknown_robot"), 1u);
  EXPECT_EQ(v.Rejected("page.unknown_team"), 1u);
  EXPECT_EQ(v.Rejected("page.out_of_range"), 1u);
  EXPECT_EQ(v.Rejected("page.unknown_preset"), 1u);
  EXPECT_EQ(v.Rejected("page.unknown_op"), 1u);
  EXPECT_EQ(v.Rejected("page.not_object"), 1u);
  EXPECT_EQ(v.Rejected("page.too_large"), 1u);
  EXPECT_EQ(v.Rejected("page.binary"), 1u);

  // A message past the frame limit closes that connection; others go on.
  // (The viewer may close before the client has written it all: the send can fail.)
  ws.Send(std::string(100 * 1024, ' '));
  EXPECT_FALSE(ws.ReadUntil([](const std::string&) { return false; }, 60s));
  EXPECT_TRUE(ws.closed()) << "the connection stayed open for 60 s";
  EXPECT_TRUE(Eventually([&] { return v.Rejected("page.too_large") == 2; }));
  WsClient again;
  ASSERT_TRUE(Connected(again, rig.viewer));
  EXPECT_TRUE(ReadType(again, "state"));

  // Nothing moved: the ball and every robot are where they were.
  rig.client.Poll();
  const idl::WorldState& after = rig.client.state();
  EXPECT_NEAR(after.ball().position().x(), before.ball().position().x(), 1e-6);
  EXPECT_NEAR(after.ball().position().y(), before.ball().position().y(), 1e-6);
  for (const idl::RobotState& r : before.robots()) {
    const idl::RobotState* now = FindRobot(after, r.team(), r.id());
    ASSERT_NE(now, nullptr);
    EXPECT_NEAR(now->position().x(), r.position().x(), 1e-3);
    EXPECT_EQ(now->on_field(), r.on_field());
  }
  EXPECT_EQ(rig.sim.node().Stats().rejected, 0u);  // turf-sim never saw a bad request
}

TEST(ViewerServer, WithoutTurfSimActionsAreRefusedNotLost) {
  const dds::ParticipantOptions dds = UniqueDds("viewer-alone");
  ViewerUnderTest viewer(dds);
  WsClient ws;
  ASSERT_TRUE(Connected(ws, viewer));
  ASSERT_TRUE(ReadType(ws, "hello"));
  ASSERT_TRUE(ws.Send(R"({"op":"pause"})"));
  const auto refused = ReadType(ws, "refused");
  ASSERT_TRUE(refused);
  EXPECT_EQ((*refused)["kind"], "no_simulator");
  EXPECT_EQ(viewer.node().Rejected("page.no_simulator"), 1u);
  EXPECT_EQ(viewer.node().Stats().controls_sent, 0u);
  EXPECT_FALSE(viewer.node().Stats().control_matched);
}

// Connections that send part of a request and wait (a slowloris client) hold at most max_clients_per_address
// slots: the next one from that address is closed and counted, and a page from another address is served.
TEST(ViewerServer, OneAddressCannotTakeEveryConnection) {
  namespace asio = boost::asio;
  using tcp = asio::ip::tcp;
  const dds::ParticipantOptions dds = UniqueDds("viewer-slots");
  ViewerUnderTest viewer(dds);
  const tcp::endpoint server(asio::ip::make_address("127.0.0.1"), static_cast<uint16_t>(viewer.port()));
  asio::io_context io;
  std::vector<tcp::socket> idle;
  const std::string partial = "GET / HTTP/1.1\r\nHost: 127.0.0.1\r\n";
  for (size_t i = 0; i < viewer::WebServerOptions{}.max_clients_per_address; ++i) {
    idle.emplace_back(io);
    idle.back().connect(server);
    asio::write(idle.back(), asio::buffer(partial));
  }
  tcp::socket extra(io);
  extra.connect(server);
  EXPECT_TRUE(Eventually([&] { return viewer.node().Rejected("http.too_many_from_address") == 1; }));

  tcp::socket other(io);
  other.open(tcp::v4());
  other.bind(tcp::endpoint(asio::ip::make_address("127.0.0.2"), 0));
  other.connect(server);
  const std::string get =
      "GET / HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(viewer.port()) + "\r\nConnection: close\r\n\r\n";
  asio::write(other, asio::buffer(get));
  asio::streambuf reply;
  boost::system::error_code ec;
  asio::read_until(other, reply, "\r\n", ec);
  ASSERT_FALSE(ec) << ec.message();
  std::string status_line;
  std::getline(std::istream(&reply), status_line);
  EXPECT_EQ(status_line.rfind("HTTP/1.1 200", 0), 0u) << status_line;
  EXPECT_EQ(viewer.node().Rejected("http.too_many_clients"), 0u);
}

// turf-sim stops: the page is told that what it shows is turf-sim's last word, and since when.
TEST(ViewerServer, WhenTurfSimStopsThePageIsToldSinceWhen) {
  const dds::ParticipantOptions dds = UniqueDds("viewer-gone");
  auto sim = std::make_unique<SimUnderTest>(Teams(1), dds, TimeMode::kRealtime);
  ViewerUnderTest viewer(dds);
  ASSERT_TRUE(Eventually([&] { return viewer.node().Stats().control_matched; }, 20s));
  WsClient ws;
  ASSERT_TRUE(Connected(ws, viewer));
  ASSERT_TRUE(ReadType(
      ws, "state", [](const json& m) { return m["viewer"]["control"] == true; }, 10s));
  const int64_t before =
      std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::system_clock::now().time_since_epoch())
          .count();
  sim.reset();  // turf-sim stops; its participant leaves the domain
  const auto gone = ReadType(
      ws, "state", [](const json& m) { return m["viewer"].contains("gone_since"); }, 30s);
  ASSERT_TRUE(gone) << "no state told the page that turf-sim is gone";
  EXPECT_EQ((*gone)["viewer"]["control"], false);
  const int64_t since = (*gone)["viewer"]["gone_since"];
  EXPECT_GE(since, before);
  EXPECT_LE(since,
            std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::system_clock::now().time_since_epoch())
                .count());
  // A page that connects later is told too (the newest state is kept for it).
  WsClient late;
  ASSERT_TRUE(Connected(late, viewer));
  const auto told = ReadType(late, "state", [](const json& m) { return m["viewer"].contains("gone_since"); });
  ASSERT_TRUE(told);
  EXPECT_EQ((*told)["viewer"]["gone_since"], since);
}

TEST(ViewerServer, RefusesWebSocketsFromOtherSitesAndFloods) {
  Rig rig;
  WsClient evil;
  std::string error;
  EXPECT_FALSE(evil.Connect(rig.viewer.port(), "http://evil.example", &error));
  EXPECT_EQ(rig.viewer.node().Rejected("http.origin"), 1u);

  WsClient ws;
  ASSERT_TRUE(ws.Connect(rig.viewer.port(), "", &error)) << error;  // no Origin: not a browser
  for (int i = 0; i < 300; ++i) ASSERT_TRUE(ws.Send("{}"));
  // Every message is refused; the answers to a flood are not all sent (a
  // page's queue is bounded), but every refusal is counted.
  ViewerNode& v = rig.viewer.node();
  EXPECT_TRUE(Eventually([&] { return v.Rejected("page.rate_limited") + v.Rejected("page.unknown_op") == 300; }));
  EXPECT_TRUE(ReadType(ws, "refused"));
  const uint64_t limited = v.Rejected("page.rate_limited");
  EXPECT_GE(limited, 100u);
  EXPECT_EQ(v.Stats().controls_sent, 0u);
}

}  // namespace
}  // namespace turf::test
