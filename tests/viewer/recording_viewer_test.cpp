// turf-viewer --recording: a recording written here with turf's MCAP writer (what turf-record writes: each
// sample's CDR with its encapsulation header, publish_time = sim time) is served by the real turf-viewer
// process; the world state it returns for a slider time is the recorded sample at or before that time.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <turf/idl/ClockPubSubTypes.h>
#include <turf/idl/JointsPubSubTypes.h>
#include <turf/idl/SslVisionPubSubTypes.h>
#include <turf/idl/WorldStatePubSubTypes.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <thread>

#include "codecs/mcap/reader.h"
#include "codecs/mcap/writer.h"
#include "participants/viewer/recording.h"
#include "tests/support/cdr.h"
#include "tests/support/process.h"
#include "tests/viewer/web_client.h"
#include "tests/viewer/webdriver.h"

namespace turf {
namespace {

using nlohmann::json;
using test::Cdr;
using SteadyClock = std::chrono::steady_clock;

constexpr int kStates = 200;  // world states, every 10 ms of sim time from 10 ms
constexpr int64_t kStepNs = 10'000'000;

idl::SslField Field() {
  idl::SslField f;
  f.division(1);
  f.field_length(12.0);
  f.field_width(9.0);
  f.boundary_width(0.3);
  f.boundary_width_goal_line(0.3);
  f.goal_width(1.8);
  f.goal_depth(0.18);
  f.penalty_area_depth(1.8);
  f.penalty_area_width(3.6);
  f.center_circle_radius(0.5);
  f.line_thickness(0.01);
  f.ball_radius(0.0215);
  f.max_robot_radius(0.09);
  f.robot_height(0.15);
  f.robots_per_team(11);
  return f;
}

// State i (1..kStates): sim time i*10 ms, frame i, the ball at x = i mm, one blue robot at y = -i mm.
idl::WorldState State(int i) {
  idl::WorldState s;
  s.sim_time_ns(i * kStepNs);
  s.frame(static_cast<uint64_t>(i));
  s.ball().position().x(i * 1e-3);
  idl::RobotState r;
  r.team(idl::TEAM_BLUE);
  r.id(3);
  r.on_field(true);
  r.position().y(-i * 1e-3);
  r.orientation().w(1.0);
  s.robots().push_back(r);
  return s;
}

// What turf-record writes for these topics, in small chunks so a cut leaves whole chunks before it.
std::string Recording() {
  mcap::StringSink sink;
  mcap::WriterOptions options;
  options.chunk_size = 4096;
  mcap::Writer writer(&sink, options);
  const uint16_t state_schema = writer.AddSchema("turf::idl::WorldState", "omgidl", "");
  const uint16_t clock_schema = writer.AddSchema("turf::idl::Clock", "omgidl", "");
  const uint16_t field_schema = writer.AddSchema("turf::idl::SslField", "omgidl", "");
  const uint16_t state = writer.AddChannel(state_schema, "turf/world_state", "cdr");
  const uint16_t clock = writer.AddChannel(clock_schema, "turf/clock", "cdr");
  const uint16_t field = writer.AddChannel(field_schema, "turf/ssl/field", "cdr");
  const uint16_t other = writer.AddChannel(state_schema, "turf/ssl/command/blue", "cdr");  // not shown
  writer.Write(field, 0, 1, 0, Cdr<idl::SslFieldPubSubType>(Field()));
  for (int i = 1; i <= kStates; ++i) {
    const uint64_t log_time = 1'000'000'000'000 + static_cast<uint64_t>(i) * 1000;
    const uint64_t t = static_cast<uint64_t>(i * kStepNs);
    writer.Write(state, static_cast<uint32_t>(i), log_time, t, Cdr<idl::WorldStatePubSubType>(State(i)));
    idl::Clock c;
    c.sim_time_ns(i * kStepNs);
    c.speed(1.0);
    writer.Write(clock, static_cast<uint32_t>(i), log_time, t, Cdr<idl::ClockPubSubType>(c));
    writer.Write(other, static_cast<uint32_t>(i), log_time, t, "not shown");
  }
  writer.Close();
  return sink.bytes();
}

std::string WriteFile(const std::string& name, const std::string& bytes) {
  const std::string path = test::LogDir() + "/" + name;
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
  return path;
}

// The viewer's answer to `target` once it serves (it reads the file first), or a failed result at the deadline.
test::HttpResult GetWhenUp(int port, const std::string& target) {
  const auto deadline = SteadyClock::now() + std::chrono::seconds(20);
  test::HttpResult r;
  while (SteadyClock::now() < deadline) {
    r = test::HttpGet(port, target);
    if (r.status != 0) return r;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));  // retry pacing: the port is not open yet
  }
  return r;
}

class RecordingViewerProcess {
 public:
  explicit RecordingViewerProcess(const std::string& file)
      : port_(test::FreeTcpPort()),
        process_("viewer_recording", {test::Built("participants/viewer/turf-viewer"), "--recording", file, "--port",
                                      std::to_string(port_)}) {}
  int port() const { return port_; }
  test::Process& process() { return process_; }

 private:
  int port_;
  test::Process process_;
};

json StateAt(int port, const std::string& seconds) {
  const test::HttpResult r = test::HttpGet(port, "/recording/state?t=" + seconds);
  EXPECT_EQ(r.status, 200) << seconds << ": " << r.body << r.error;
  EXPECT_EQ(r.content_type, "application/json");
  return r.status == 200 ? json::parse(r.body) : json::object();
}

TEST(RecordingViewer, ShowsTheRecordedWorldStateAtOrBeforeTheSliderTime) {
  const std::string file = WriteFile("viewer_recording.mcap", Recording());
  RecordingViewerProcess viewer(file);
  const test::HttpResult info = GetWhenUp(viewer.port(), "/recording/info");
  ASSERT_EQ(info.status, 200) << info.error << viewer.process().Log();
  const json i = json::parse(info.body);
  EXPECT_EQ(i["type"], "recording");
  EXPECT_NEAR(i["start"].get<double>(), 0.01, 1e-9);
  EXPECT_NEAR(i["end"].get<double>(), 2.0, 1e-9);
  EXPECT_EQ(i["states"], kStates);
  EXPECT_EQ(i["damage"], "");

  // 0.505 s lies between the states of 0.50 and 0.51 s: the one at 0.50 s is shown.
  const json a = StateAt(viewer.port(), "0.505");
  EXPECT_EQ(a["type"], "state");
  EXPECT_DOUBLE_EQ(a["t"].get<double>(), 0.5);
  EXPECT_EQ(a["frame"], 50);
  EXPECT_NEAR(a["ball"]["p"][0].get<double>(), 0.050, 1e-6);
  ASSERT_EQ(a["robots"].size(), 1u);
  EXPECT_NEAR(a["robots"][0]["p"][1].get<double>(), -0.050, 1e-6);
  EXPECT_DOUBLE_EQ(a["clock"]["speed"].get<double>(), 1.0);
  // Exactly at a sample's time: that sample; and back in time again.
  const json b = StateAt(viewer.port(), "1.73");
  EXPECT_DOUBLE_EQ(b["t"].get<double>(), 1.73);
  EXPECT_EQ(b["frame"], 173);
  EXPECT_NEAR(b["ball"]["p"][0].get<double>(), 0.173, 1e-6);
  EXPECT_EQ(StateAt(viewer.port(), "0.2")["frame"], 20);
  // After the end: the last state; before the first, or a time that is no number: nothing.
  EXPECT_EQ(StateAt(viewer.port(), "99")["frame"], kStates);
  EXPECT_EQ(test::HttpGet(viewer.port(), "/recording/state?t=0.001").status, 404);
  EXPECT_EQ(test::HttpGet(viewer.port(), "/recording/state?t=nan").status, 404);
  EXPECT_EQ(test::HttpGet(viewer.port(), "/recording/state?t=1e400").status, 404);
  EXPECT_EQ(test::HttpGet(viewer.port(), "/recording/state").status, 404);
  // The page itself is served as live, with the recording's script.
  EXPECT_NE(test::HttpGet(viewer.port(), "/").body.find("recording.js"), std::string::npos);

  // The WebSocket gives the recorded field; a page's action is refused, nothing else happens.
  test::WsClient ws;
  std::string error;
  ASSERT_TRUE(ws.Connect(viewer.port(), "", &error)) << error;
  EXPECT_TRUE(ws.ReadUntil([](const std::string& m) { return json::parse(m)["type"] == "field"; }));
  ASSERT_TRUE(ws.Send(R"({"op":"pause"})"));
  EXPECT_TRUE(ws.ReadUntil([](const std::string& m) {
    const json j = json::parse(m);
    return j["type"] == "refused" && j["kind"] == "recording";
  }));
  const int status = viewer.process().Stop();
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << viewer.process().Log();
}

TEST(RecordingViewer, ShowsADamagedFileUpToTheDamageAndSaysWhere) {
  const std::string bytes = Recording();
  const std::string file = WriteFile("viewer_recording_cut.mcap", bytes.substr(0, bytes.size() / 2));
  RecordingViewerProcess viewer(file);
  const test::HttpResult info = GetWhenUp(viewer.port(), "/recording/info");
  ASSERT_EQ(info.status, 200) << info.error << viewer.process().Log();
  const json i = json::parse(info.body);
  const std::string damage = i["damage"];
  EXPECT_NE(damage.find("at offset"), std::string::npos) << damage;
  // Some whole chunks came before the cut, not all of them.
  ASSERT_TRUE(i.contains("end")) << info.body;
  const double end = i["end"];
  EXPECT_GT(end, 0.1);
  EXPECT_LT(end, 2.0);
  const json last = StateAt(viewer.port(), "2.0");
  EXPECT_NEAR(last["t"].get<double>(), end, 1e-6);
  EXPECT_TRUE(viewer.process().Running());
  const int status = viewer.process().Stop();
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  const std::string log = viewer.process().Log();
  EXPECT_NE(log.find("read up to the damage"), std::string::npos) << log;
  EXPECT_NE(log.find("at offset"), std::string::npos) << log;
}

TEST(RecordingViewer, RefusesAFileThatIsNoMcapWithExitStatus2) {
  const std::string file = WriteFile("viewer_recording_not_mcap.mcap", "this is no MCAP file at all");
  RecordingViewerProcess viewer(file);
  const std::optional<int> status = viewer.process().Wait(std::chrono::seconds(20));
  ASSERT_TRUE(status.has_value());
  EXPECT_TRUE(WIFEXITED(*status) && WEXITSTATUS(*status) == 2) << viewer.process().Log();
  EXPECT_NE(viewer.process().Log().find("bad_magic"), std::string::npos) << viewer.process().Log();
}

// Polls `done` for up to `ms` (a page's state changes only when it fetches one). The deadlines below are generous:
// this test failed once in the full suite after 15 s (2026-11-28; not reproduced alone, under load or next to the
// other browser tests), as if one 10 s wait had run out.
bool Within(int ms, const std::function<bool()>& done) {
  const auto end = SteadyClock::now() + std::chrono::milliseconds(ms);
  while (SteadyClock::now() < end) {
    if (done()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

// The page in headless Chromium: the slider bar appears, the live controls hide, a seek shows the recorded
// state of that time, Play moves time on. Skipped without Chromium.
TEST(RecordingViewerBrowser, TheSliderSeeksAndPlayMovesTheRecordedWorld) {
  const std::string chromium = test::FindExecutable({"chromium", "chromium-browser", "google-chrome"});
  const std::string chromedriver = test::FindExecutable({"chromedriver"});
  if (chromium.empty() || chromedriver.empty()) GTEST_SKIP() << "headless Chromium not installed";
  const std::string file = WriteFile("viewer_recording_browser.mcap", Recording());
  RecordingViewerProcess viewer(file);
  ASSERT_EQ(GetWhenUp(viewer.port(), "/recording/info").status, 200) << viewer.process().Log();
  const int driver_port = test::FreeTcpPort();
  test::Process driver_process("chromedriver_recording", {chromedriver, "--port=" + std::to_string(driver_port)});
  const std::string profile = TURF_BINARY_DIR "/tests/viewer/chrome_profile_rec_" + std::to_string(getpid());
  std::filesystem::remove_all(profile);
  std::filesystem::create_directories(profile);
  {
    test::WebDriver driver(driver_port);
    ASSERT_TRUE(driver.WaitReady(30000)) << driver_process.Log();
    ASSERT_TRUE(driver.NewSession(chromium, profile, 1280, 800)) << driver.error();
    ASSERT_TRUE(driver.Navigate("http://127.0.0.1:" + std::to_string(viewer.port()) + "/")) << driver.error();
    auto page_time = [&] {
      const auto t = driver.Execute("const s = window.turfViewer.state(); return s ? s.t : -1;");
      return t && t->is_number() ? t->get<double>() : -1.0;
    };
    // At start the page shows the first state, with the slider bar and without the simulation controls.
    ASSERT_TRUE(Within(30000, [&] { return std::abs(page_time() - 0.01) < 1e-9; })) << viewer.process().Log();
    const auto shown = driver.Execute(
        "return [!document.getElementById('recording-bar').classList.contains('hidden'),"
        " document.getElementById('pause').offsetParent === null,"
        " document.getElementById('realism').offsetParent === null,"
        " document.getElementById('connection').textContent];");
    ASSERT_TRUE(shown.has_value());
    EXPECT_EQ(*shown, json({true, true, true, "recording"}));
    // A seek (what the slider's input does) shows the state at or before that time.
    ASSERT_TRUE(driver.Execute("window.turfRecording.seek(1.234); return true;"));
    EXPECT_TRUE(Within(30000, [&] { return std::abs(page_time() - 1.23) < 1e-9; })) << page_time();
    const auto ball = driver.Execute("return window.turfViewer.state().ball.p[0];");
    EXPECT_TRUE(ball && std::abs(ball->get<double>() - 0.123) < 1e-6);
    // Play at 0.25x (3 s to the end), then Pause: the page shows the state at or before the time it paused at
    // (the request's time has six decimals; states are 10 ms apart), not the last one fetched while playing.
    const auto slow = driver.Find("#rec-speed option[value='0.25']");
    ASSERT_TRUE(slow && driver.Click(*slow)) << driver.error();
    const auto play = driver.Find("#rec-play");
    ASSERT_TRUE(play && driver.Click(*play)) << driver.error();
    ASSERT_TRUE(Within(30000, [&] { return page_time() > 1.25; })) << page_time();
    ASSERT_TRUE(driver.Click(*play)) << driver.error();
    const auto paused_at = driver.Execute(
        "const t = Number(window.turfRecording.time().toFixed(6)); return Math.floor(t * 100 + 1e-6) / 100;");
    ASSERT_TRUE(paused_at && paused_at->is_number());
    EXPECT_TRUE(Within(30000, [&] { return std::abs(page_time() - paused_at->get<double>()) < 1e-9; }))
        << page_time() << " shown, paused at " << *paused_at;
    // Play at 10x: time moves on and stops at the end, showing the last state.
    const auto speed = driver.Find("#rec-speed option[value='10']");
    ASSERT_TRUE(speed && driver.Click(*speed)) << driver.error();
    ASSERT_TRUE(driver.Click(*play)) << driver.error();
    EXPECT_TRUE(Within(30000, [&] { return std::abs(page_time() - 2.0) < 1e-9; })) << page_time();
    const auto playing = driver.Execute("return window.turfRecording.playing();");
    EXPECT_TRUE(playing && *playing == false);
    const auto png = driver.Screenshot();
    if (png) {
      std::filesystem::create_directories(TURF_BINARY_DIR "/tests/viewer/artifacts");
      std::ofstream(TURF_BINARY_DIR "/tests/viewer/artifacts/recording.png", std::ios::binary) << *png;
    }
  }
  std::filesystem::remove_all(profile);
}

// In process: the index over a string, and the query parser.
TEST(RecordingIndex, KeepsOnlyTheShownTopicsAndSkipsTheRest) {
  const std::string bytes = Recording();
  const viewer::Recording r{std::make_unique<mcap::StringSource>(bytes)};
  EXPECT_TRUE(r.damage().ok());
  EXPECT_EQ(r.count(viewer::Recording::kState), static_cast<size_t>(kStates));
  EXPECT_EQ(r.count(viewer::Recording::kClock), static_cast<size_t>(kStates));
  EXPECT_EQ(r.count(viewer::Recording::kField), 1u);
  EXPECT_EQ(r.skipped(), static_cast<uint64_t>(kStates));  // the command channel
  EXPECT_FALSE(r.FieldJson().empty());
  EXPECT_TRUE(r.StatsJsonAt(1'000'000'000).empty());  // no stats recorded
}

// Shown from chunks read again on demand, through a cache of 8 KiB (one or two of these 4 KiB chunks): every state
// at its time, in any order, and the cache stays within its budget; with a large cache a second pass reads nothing.
TEST(RecordingIndex, ReadsSamplesFromTheirChunksWithinTheCacheBudget) {
  const std::string bytes = Recording();
  const viewer::Recording small{std::make_unique<mcap::StringSource>(bytes), 8192};
  const viewer::Recording large{std::make_unique<mcap::StringSource>(bytes), 1u << 30};
  ASSERT_TRUE(small.damage().ok()) << small.damage().Describe();
  EXPECT_EQ(small.chunk_reads(), 0u);  // nothing read again before something is shown
  const auto pass = [](const viewer::Recording& r) {
    for (int i : {1, 200, 2, 199, 100, 57, 143, 3, 198}) {
      const json at = json::parse(r.StateJsonAt(i * kStepNs));
      EXPECT_NEAR(at["t"].get<double>(), i * 0.01, 1e-6) << i;
      EXPECT_NEAR(at["ball"]["p"][0].get<double>(), i * 1e-3, 1e-6) << i;
    }
  };
  for (int round = 0; round < 2; ++round) {
    pass(small);
    EXPECT_LE(small.cached_bytes(), 8192u);
    pass(large);
  }
  const uint64_t large_reads = large.chunk_reads();
  EXPECT_GT(large_reads, 2u);                   // the states span several chunks
  EXPECT_GT(small.chunk_reads(), large_reads);  // evicted chunks were read again
  pass(large);
  EXPECT_EQ(large.chunk_reads(), large_reads);  // all cached: nothing read again
  EXPECT_EQ(small.reread_failures(), 0u);
}

// A legged scene: robots "a" (links every 10 ms to 100 ms, at x = 1 m per 10 ms) and "b" (links at 50 ms only).
std::string LeggedRecording() {
  mcap::StringSink sink;
  mcap::Writer writer(&sink, {});
  const uint16_t scene_schema = writer.AddSchema("turf::idl::LeggedSceneInfo", "omgidl", "");
  const uint16_t links_schema = writer.AddSchema("turf::idl::LinkState", "omgidl", "");
  const uint16_t scene = writer.AddChannel(scene_schema, "turf/legged/scene", "cdr");
  const uint16_t links = writer.AddChannel(links_schema, "turf/robots/links", "cdr");
  idl::LeggedSceneInfo info;
  info.name("two");
  for (const char* name : {"a", "b"}) {
    idl::RobotDescription r;
    r.robot(name);
    idl::RobotGeom g;
    g.body("torso");
    g.shape(idl::GEOM_SPHERE);
    g.size().x(0.1);
    g.orientation().w(1.0);
    r.geoms().push_back(g);
    info.robots().push_back(r);
  }
  writer.Write(scene, 0, 1, 0, Cdr<idl::LeggedSceneInfoPubSubType>(info));
  auto pose = [&](const char* robot, int i) {
    idl::LinkState l;
    l.robot(robot);
    l.sim_time_ns(i * kStepNs);
    l.frame(static_cast<uint64_t>(i));
    idl::LinkPose p;
    p.name("torso");
    p.position().x(i);
    p.orientation().w(1.0);
    l.links().push_back(p);
    writer.Write(links, static_cast<uint32_t>(i), 2, static_cast<uint64_t>(i * kStepNs),
                 Cdr<idl::LinkStatePubSubType>(l));
  };
  for (int i = 1; i <= 10; ++i) {
    pose("a", i);
    if (i == 5) pose("b", i);
  }
  writer.Close();
  return sink.bytes();
}

TEST(RecordingIndex, ALeggedSceneShowsEachRobotsNewestLinksAtOrBeforeT) {
  const std::string bytes = LeggedRecording();
  const viewer::Recording r{std::make_unique<mcap::StringSource>(bytes)};
  ASSERT_TRUE(r.damage().ok()) << r.damage().Describe();
  EXPECT_EQ(json::parse(r.FieldJson())["type"], "legged");
  const json at = json::parse(r.StateJsonAt(75'000'000));
  EXPECT_DOUBLE_EQ(at["t"].get<double>(), 0.07);
  EXPECT_DOUBLE_EQ(at["links"]["a"][0].get<double>(), 7.0);
  EXPECT_DOUBLE_EQ(at["links"]["b"][0].get<double>(), 5.0);
  // 0.3 s: a's newest (0.1 s) is within the 0.2 s window, b's (0.05 s) no longer.
  const json late = json::parse(r.StateJsonAt(300'000'000));
  EXPECT_DOUBLE_EQ(late["links"]["a"][0].get<double>(), 10.0);
  EXPECT_FALSE(late["links"].contains("b"));
  EXPECT_TRUE(r.StateJsonAt(5'000'000).empty());  // before the first
}

TEST(RecordingIndex, ReadsTheTimeOfAQuery) {
  EXPECT_EQ(viewer::QueryTime("/recording/state?t=1.5"), 1'500'000'000);
  EXPECT_EQ(viewer::QueryTime("/recording/state?x=1&t=0.01"), 10'000'000);
  EXPECT_EQ(viewer::QueryTime("/recording/state?t=-2"), -2'000'000'000);
  EXPECT_FALSE(viewer::QueryTime("/recording/state"));
  EXPECT_FALSE(viewer::QueryTime("/recording/state?t="));
  EXPECT_FALSE(viewer::QueryTime("/recording/state?t=1.5x"));
  EXPECT_FALSE(viewer::QueryTime("/recording/state?t=inf"));
  EXPECT_FALSE(viewer::QueryTime("/recording/state?t=1e300"));
}

}  // namespace
}  // namespace turf
