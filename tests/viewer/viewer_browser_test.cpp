// The page itself, end to end: turf-sim and turf-viewer as real processes,
// the page in headless Chromium driven through chromedriver (W3C WebDriver),
// and a DDS client that knows the truth. Checks that robots are drawn where
// the world state (SSL) or robots/links (legged) says, that dragging the ball
// (and a legged robot) teleports it, that right-dragging the ball throws it,
// that two pages each see only the replies to their own requests, that Pause
// stops simulation time, and saves screenshots to <build>/tests/viewer/artifacts/.
// Skipped when chromium or chromedriver is not installed.
#include <gtest/gtest.h>
#include <turf/idl/JointsPubSubTypes.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "tests/sim/sim_harness.h"
#include "tests/support/process.h"
#include "tests/support/take.h"
#include "tests/viewer/web_client.h"
#include "tests/viewer/webdriver.h"

namespace turf::test {
namespace {

using nlohmann::json;

const std::string kArtifacts = TURF_BINARY_DIR "/tests/viewer/artifacts";

bool IsBlue(const json& c) { return c[2] > 180 && c[0] < 120; }
bool IsYellow(const json& c) { return c[0] > 180 && c[1] > 160 && c[2] < 100; }

bool SavePng(const std::optional<std::string>& png, const std::string& name) {
  if (!png || png->size() < 8 || png->compare(1, 3, "PNG") != 0) return false;
  std::filesystem::create_directories(kArtifacts);
  std::ofstream(kArtifacts + "/" + name, std::ios::binary) << *png;
  return true;
}

// Polls `done` for up to `ms`.
bool Within(int ms, const std::function<bool()>& done) {
  const auto end = Clock::now() + std::chrono::milliseconds(ms);
  while (Clock::now() < end) {
    if (done()) return true;
    std::this_thread::sleep_for(20ms);
  }
  return false;
}

// A legged scene's truth: every robot's newest body poses, the ball, the clock.
class LeggedClient {
 public:
  explicit LeggedClient(dds::ParticipantOptions o)
      : participant_((o.name = "client", o)),
        links_(participant_.MakeReader<idl::LinkStatePubSubType>(dds::Topic::kRobotLinks)),
        world_(participant_.MakeReader<idl::WorldStatePubSubType>(dds::Topic::kWorldState)),
        clock_(participant_.MakeReader<idl::ClockPubSubType>(dds::Topic::kClock)),
        control_(participant_, "test") {}
  void Poll() {
    TakeNewestByRobot(*links_, &links);
    TakeNewest(*world_, &world);
    TakeNewest(*clock_, &clock);
  }
  bool WaitFor(const std::function<bool()>& done, int ms = 10000) {
    return Within(ms, [&] {
      Poll();
      return done();
    });
  }
  // Sends a control request through dds::ControlClient (turf-sim and its reply
  // within 15 s); nullopt if no reply came.
  std::optional<idl::SimControlReply> Control(idl::ControlOp op) {
    idl::SimControl req;
    req.op(op);
    return control_.Call(std::move(req), 15s).reply;
  }
  // The named body's world position, or nullopt.
  std::optional<idl::Vec3> Body(const std::string& robot, const std::string& body) const {
    const auto it = links.find(robot);
    if (it == links.end()) return std::nullopt;
    for (const idl::LinkPose& p : it->second.links())
      if (p.name() == body) return p.position();
    return std::nullopt;
  }
  std::map<std::string, idl::LinkState> links;
  std::optional<idl::WorldState> world;
  std::optional<idl::Clock> clock;

 private:
  dds::Participant participant_;
  std::unique_ptr<dds::Reader<idl::LinkStatePubSubType>> links_;
  std::unique_ptr<dds::Reader<idl::WorldStatePubSubType>> world_;
  std::unique_ptr<dds::Reader<idl::ClockPubSubType>> clock_;
  dds::ControlClient control_;
};

class ViewerBrowser : public ::testing::Test {
 protected:
  void SetUp() override {
    chromium_ = FindExecutable({"chromium", "chromium-browser", "google-chrome"});
    chromedriver_ = FindExecutable({"chromedriver"});
    if (chromium_.empty() || chromedriver_.empty())
      GTEST_SKIP() << "headless Chromium not installed (Debian packages chromium and chromium-driver; "
                      "scripts/setup.sh installs them)";
  }
  // turf-sim with `scene` (under configs/scenes/), turf-viewer and chromedriver.
  void Launch(const std::string& scene) {
    dds_ = UniqueDds("viewer-browser");
    dds_.domain = TestDomain(7);
    dds_.prefix = "browser" + std::to_string(getpid()) + "_" + std::to_string(++launches_);
    viewer_port_ = FreeTcpPort();
    const std::string domain = std::to_string(dds_.domain);
    sim_ = std::make_unique<Process>(
        "viewer_sim", std::vector<std::string>{Built("participants/sim/turf-sim"), "--scene",
                                               TURF_SOURCE_DIR "/configs/scenes/" + scene, "--domain", domain,
                                               "--prefix", dds_.prefix, "--qos", dds_.qos_file});
    viewer_ =
        std::make_unique<Process>("viewer", std::vector<std::string>{Built("participants/viewer/turf-viewer"), "--port",
                                                                     std::to_string(viewer_port_), "--domain", domain,
                                                                     "--prefix", dds_.prefix, "--qos", dds_.qos_file});
    const int driver_port = FreeTcpPort();
    driver_process_ = std::make_unique<Process>(
        "chromedriver", std::vector<std::string>{chromedriver_, "--port=" + std::to_string(driver_port)});
    profile_ = TURF_BINARY_DIR "/tests/viewer/chrome_profile_" + std::to_string(getpid());
    std::filesystem::remove_all(profile_);
    std::filesystem::create_directories(profile_);
    driver_ = std::make_unique<WebDriver>(driver_port);
  }
  void TearDown() override {
    driver_.reset();  // closes the session and Chromium
    driver_process_.reset();
    if (!profile_.empty()) std::filesystem::remove_all(profile_);
  }

  // Opens the page and waits until it shows the field and a world state;
  // `sim_up` waits for turf-sim.
  void OpenPage(const std::function<bool()>& sim_up) {
    ASSERT_TRUE(sim_up()) << "turf-sim did not come up: " << sim_->Log();
    ASSERT_TRUE(driver_->WaitReady(10000)) << "chromedriver did not come up: " << driver_process_->Log();
    ASSERT_TRUE(driver_->NewSession(chromium_, profile_, 1280, 800)) << driver_->error();
    ASSERT_TRUE(driver_->Navigate("http://127.0.0.1:" + std::to_string(viewer_port_) + "/")) << driver_->error();
    ASSERT_TRUE(Within(10000,
                       [&] {
                         const auto ready =
                             driver_->Execute("return !!(window.turfViewer && window.turfViewer.ready());");
                         return ready && *ready == true;
                       }))
        << "the page never got the field and a state; viewer log:\n"
        << viewer_->Log();
  }

  json ColorAt(double x, double y) {
    return driver_->Execute("return window.turfViewer.colorAt(arguments[0], arguments[1]);", {x, y}).value_or(json());
  }
  std::pair<int, int> ClientPoint(double x, double y) {
    const json p = driver_->Execute("return window.turfViewer.fieldToClient(arguments[0], arguments[1]);", {x, y})
                       .value_or(json{{"x", 0}, {"y", 0}});
    return {static_cast<int>(std::lround(p["x"].get<double>())), static_cast<int>(std::lround(p["y"].get<double>()))};
  }
  // The page's newest state: its frame and simulation time (-1: none yet).
  int64_t PageFrame() {
    const auto f = driver_->Execute("const s = window.turfViewer.state(); return s ? s.frame : -1;");
    return f && f->is_number() ? f->get<int64_t>() : -1;
  }
  double PageTime() {
    const auto t = driver_->Execute("const s = window.turfViewer.state(); return s ? s.t : -1;");
    return t && t->is_number() ? t->get<double>() : -1.0;
  }
  bool PagePaused() {
    const auto p = driver_->Execute("const s = window.turfViewer.state(); return !!(s && s.clock && s.clock.paused);");
    return p && *p == true;
  }
  // How many messages of `type` the page has received.
  int PageReceived(const std::string& type) {
    const auto n = driver_->Execute("return window.turfViewer.received()[arguments[0]] || 0;", {type});
    return n && n->is_number() ? n->get<int>() : -1;
  }
  std::string SimTimeText() {
    const auto element = driver_->Find("#simtime");
    return element ? driver_->Text(*element).value_or("") : "";
  }

  // Presses the mouse on field point (x0, y0) and releases it on (x1, y1).
  bool DragField(double x0, double y0, double x1, double y1) {
    const auto [cx0, cy0] = ClientPoint(x0, y0);
    const auto [cx1, cy1] = ClientPoint(x1, y1);
    return driver_->Drag(cx0, cy0, cx1, cy1, 400);
  }

  int launches_ = 0;
  std::string chromium_, chromedriver_, profile_;
  dds::ParticipantOptions dds_;
  int viewer_port_ = 0;
  std::unique_ptr<Process> sim_, viewer_, driver_process_;
  std::unique_ptr<Client> client_;
  std::unique_ptr<WebDriver> driver_;
};

TEST_F(ViewerBrowser, DrawsTheWorldDragsTheBallPausesAndSavesScreenshots) {
  Launch("ssl_div_b.yaml");
  client_ = std::make_unique<Client>(dds_);
  OpenPage([&] { return client_->WaitMatched(true, 10s); });
  if (HasFatalFailure()) return;

  // 1. Every robot on the field is drawn in its team's colour where the world
  // state puts it (sampled behind its centre, away from the id and the heading
  // mark), and the carpet beside it is not.
  client_->Poll();
  const idl::WorldState state = client_->state();
  const double r = 0.09;
  int checked = 0;
  for (const idl::RobotState& robot : state.robots()) {
    if (!robot.on_field()) continue;
    const double x = robot.position().x(), y = robot.position().y();
    const json inside = ColorAt(x - 0.6 * r * std::cos(robot.yaw()), y - 0.6 * r * std::sin(robot.yaw()));
    const json beside = ColorAt(x, y + 2.5 * r);
    const bool blue = robot.team() == idl::TEAM_BLUE;
    EXPECT_TRUE(blue ? IsBlue(inside) : IsYellow(inside))
        << (blue ? "blue " : "yellow ") << int(robot.id()) << " at (" << x << ", " << y << "): " << inside;
    EXPECT_FALSE(IsBlue(beside) || IsYellow(beside)) << beside;
    ++checked;
  }
  EXPECT_GE(checked, 6);

  // 2. Dragging the ball with the mouse teleports it.
  const double bx = state.ball().position().x(), by = state.ball().position().y();
  const auto [x0, y0] = ClientPoint(bx, by);
  const auto [x1, y1] = ClientPoint(1.5, 1.0);
  ASSERT_TRUE(driver_->Drag(x0, y0, x1, y1, 400)) << driver_->error();
  EXPECT_TRUE(client_->WaitState([](const idl::WorldState& s) {
    return std::hypot(s.ball().position().x() - 1.5, s.ball().position().y() - 1.0) < 0.03;
  })) << "ball at ("
      << client_->state().ball().position().x() << ", " << client_->state().ball().position().y() << ")";

  // 2b. Right-dragging the ball throws it: the arrow from the ball to the
  // release point, 2 (m/s)/m, is its velocity; world_state shows it rolling
  // that way (towards open field, before it meets anything).
  {
    const auto [tx0, ty0] = ClientPoint(1.5, 1.0);
    const auto [tx1, ty1] = ClientPoint(0.5, 1.5);  // v = (-2, 1) m/s
    ASSERT_TRUE(driver_->Drag(tx0, ty0, tx1, ty1, 300, /*button=*/2)) << driver_->error();
    EXPECT_TRUE(client_->WaitState([](const idl::WorldState& s) {
      const idl::Vec3& p = s.ball().position();
      const idl::Vec3& v = s.ball().velocity();
      const double speed = std::hypot(v.x(), v.y());
      // Moving along (-2, 1)/|.| at about its speed, and already moved that way.
      return speed > 1.0 && speed < 2.4 && (-2 * v.x() + v.y()) / (std::sqrt(5.0) * speed) > 0.97 && p.x() < 1.45 &&
             p.y() > 1.02;
    })) << "ball at ("
        << client_->state().ball().position().x() << ", " << client_->state().ball().position().y() << ") moving ("
        << client_->state().ball().velocity().x() << ", " << client_->state().ball().velocity().y() << ")";
  }

  // 3. Pause: simulation time stops, in turf-sim and on the page.
  const std::string running = SimTimeText();
  ASSERT_TRUE(Within(30000, [&] { return SimTimeText() != running; })) << "time does not advance before pausing";
  const auto pause = driver_->Find("#pause");
  ASSERT_TRUE(pause);
  ASSERT_TRUE(driver_->Click(*pause)) << driver_->error();
  // turf-sim's clock says paused (published at the pause's frame), and so does the page.
  ASSERT_TRUE(client_->WaitClock([](const idl::Clock& c) { return c.paused(); }));
  const auto paused_frame = static_cast<int64_t>(client_->clock().frame());
  const int64_t sim_paused_at = client_->clock().sim_time_ns();
  ASSERT_TRUE(Within(30000, [&] { return PagePaused() && PageFrame() == paused_frame; }))
      << "page at frame " << PageFrame() << ", turf-sim paused at " << paused_frame;
  const std::string paused_at = SimTimeText();
  // Time stands still: later requests, each a turn of turf-sim's loop that
  // would step if it could, are answered at the same frame; the states turf-sim
  // publishes after them reach the page, still of that frame.
  const int states_before = PageReceived("state");
  for (int i = 0; i < 5; ++i) {
    const auto probe = client_->Control(Op(idl::OP_PAUSE));
    ASSERT_TRUE(Ok(probe));
    EXPECT_EQ(static_cast<int64_t>(probe->frame()), paused_frame);
  }
  ASSERT_TRUE(Within(30000, [&] { return PageReceived("state") > states_before; }));
  EXPECT_EQ(PageFrame(), paused_frame);
  EXPECT_EQ(SimTimeText(), paused_at);
  client_->Poll();
  EXPECT_EQ(client_->clock().sim_time_ns(), sim_paused_at);
  const auto badge = driver_->Execute("return !document.getElementById('paused-badge').classList.contains('hidden');");
  EXPECT_TRUE(badge && *badge == true);

  // 4. Screenshots: ground truth, then truth and camera detections together.
  EXPECT_TRUE(SavePng(driver_->Screenshot(), "viewer_truth.png")) << driver_->error();
  const auto both = driver_->Find("button[data-view=both]");
  ASSERT_TRUE(both && driver_->Click(*both));
  EXPECT_TRUE(Within(30000, [&] {
    const auto active =
        driver_->Execute("return document.querySelector('button[data-view=both]').classList.contains('active');");
    return active && *active == true;
  }));
  EXPECT_TRUE(SavePng(driver_->Screenshot(), "viewer_both.png")) << driver_->error();

  // 5. The sensor model at work: harsh realism, camera view, running again.
  const auto harsh = driver_->Find("#realism option[value=harsh]");
  ASSERT_TRUE(harsh && driver_->Click(*harsh)) << driver_->error();
  const auto cameras = driver_->Find("button[data-view=cameras]");
  const auto resume = driver_->Find("#resume");
  ASSERT_TRUE(cameras && driver_->Click(*cameras) && resume && driver_->Click(*resume));
  EXPECT_TRUE(Within(30000, [&] {
    const auto seen = driver_->Execute(
        "const s = window.turfViewer.state(); return !!s && !s.clock.paused && s.detections.length > 0;");
    return seen && *seen == true;
  })) << "no camera detections on the page";
  const auto message = driver_->Find("#message");
  EXPECT_TRUE(Within(30000, [&] { return message && driver_->Text(*message).value_or("").rfind("resume", 0) == 0; }));
  // Half a second of simulation with detections on the page before the screenshot.
  const double detections_from = PageTime();
  EXPECT_TRUE(Within(30000, [&] { return PageTime() > detections_from + 0.5; }));
  EXPECT_TRUE(SavePng(driver_->Screenshot(), "viewer_cameras.png")) << driver_->error();
  EXPECT_TRUE(client_->WaitClock([](const idl::Clock& c) { return !c.paused(); }));

  // 6. Two pages: each sees the answers to its own requests only, and both
  // see the match. Page A steps the running simulation (turf-sim refuses);
  // page B pauses it (accepted).
  const std::optional<std::string> page_a = driver_->CurrentWindow();
  const std::optional<std::string> page_b = driver_->NewWindow();
  ASSERT_TRUE(page_a && page_b) << driver_->error();
  ASSERT_TRUE(driver_->SwitchTo(*page_b) && driver_->Navigate("http://127.0.0.1:" + std::to_string(viewer_port_) + "/"))
      << driver_->error();
  auto script_true = [&](const std::string& script) {
    const auto v = driver_->Execute(script);
    return v && *v == true;
  };
  auto message_text = [&] {
    const auto m = driver_->Find("#message");
    return m ? driver_->Text(*m).value_or("") : std::string();
  };
  ASSERT_TRUE(Within(10000, [&] { return script_true("return !!(window.turfViewer && window.turfViewer.ready());"); }));
  auto replies = [&] {
    return driver_->Execute("return window.turfViewer.received().reply || 0;").value_or(json(-1)).get<int>();
  };
  ASSERT_TRUE(driver_->SwitchTo(*page_a));
  const int a_replies = replies();  // to its drags, pause, realism and resume so far
  const auto step = driver_->Find("#step");
  ASSERT_TRUE(step && driver_->Click(*step)) << driver_->error();
  EXPECT_TRUE(Within(30000, [&] { return message_text().rfind("turf-sim refused step (not_allowed): ", 0) == 0; }))
      << message_text();
  ASSERT_TRUE(driver_->SwitchTo(*page_b));
  const auto b_pause = driver_->Find("#pause");
  ASSERT_TRUE(b_pause && driver_->Click(*b_pause)) << driver_->error();
  EXPECT_TRUE(Within(30000, [&] { return message_text().rfind("pause: ok", 0) == 0; })) << message_text();
  EXPECT_EQ(replies(), 1);  // its pause's, not A's step's
  EXPECT_TRUE(Within(30000, [&] { return script_true("return window.turfViewer.state().clock.paused;"); }));
  // Page A steps again, now accepted. Its reply comes after B's pause's (turf-sim
  // wrote that first), so A has had both of its replies and, were B's sent to
  // it too, that one as well.
  ASSERT_TRUE(driver_->SwitchTo(*page_a));
  const auto a_step = driver_->Find("#step");
  ASSERT_TRUE(a_step && driver_->Click(*a_step)) << driver_->error();
  EXPECT_TRUE(Within(30000, [&] { return message_text().rfind("step: ok", 0) == 0; })) << message_text();
  EXPECT_EQ(replies(), a_replies + 2);  // its two steps', not B's pause's
  EXPECT_TRUE(Within(30000, [&] { return script_true("return window.turfViewer.state().clock.paused;"); }));

  EXPECT_EQ(viewer_->Stop(), 0) << viewer_->Log();  // SIGTERM: a clean exit
  EXPECT_NE(viewer_->Log().find("stopped cleanly"), std::string::npos);
}

}  // namespace
}  // namespace turf::test

namespace turf::test {
namespace {

// Light grey robot shapes (legged.js shades them 150..245 by height) on green grass.
bool IsRobotGrey(const json& c) { return c.is_array() && c.size() >= 3 && c[0] > 140 && c[1] > 140 && c[2] > 140; }
std::string Where(const std::optional<idl::Vec3>& p) {
  if (!p) return "(nowhere)";
  return "(" + std::to_string(p->x()) + ", " + std::to_string(p->y()) + ", " + std::to_string(p->z()) + ")";
}
bool IsGrass(const json& c) {
  if (!c.is_array() || c.size() < 3) return false;
  const int r = c[0], g = c[1], b = c[2];
  return g > r + 40 && g > b + 40;
}

TEST_F(ViewerBrowser, LeggedSceneDrawsRobotsWhereTheirLinksAreAndDragsBallAndRobot) {
  Launch("simspark_3d.yaml");
  LeggedClient truth(dds_);
  OpenPage([&] {
    return truth.WaitFor([&] { return truth.links.count("nao_1") && truth.links.count("nao_2") && truth.world; });
  });
  if (HasFatalFailure()) return;

  // 1. Both Naos are drawn, each torso where robots/links puts it (and where
  // the scene starts them), in robot grey with grass beside.
  const auto legged = driver_->Execute("return window.turfViewer.legged();");
  ASSERT_TRUE(legged && legged->is_object()) << "no legged scene on the page";
  EXPECT_DOUBLE_EQ((*legged)["field"]["length"].get<double>(), 30.0);
  ASSERT_TRUE(Within(30000, [&] {
    const auto n = driver_->Execute("return window.turfViewer.leggedDrawn().length;");
    return n && *n == 2;
  }));
  const json drawn = driver_->Execute("return window.turfViewer.leggedDrawn();").value_or(json::array());
  truth.Poll();
  const std::map<std::string, std::pair<double, double>> start = {{"nao_1", {-14.2, 0.0}}, {"nao_2", {-5.0, 1.5}}};
  for (const json& r : drawn) {
    const std::string name = r["name"];
    ASSERT_TRUE(start.count(name)) << name;
    const std::optional<idl::Vec3> torso = truth.Body(name, "torso");
    ASSERT_TRUE(torso) << name;
    const double x = r["first"][0], y = r["first"][1];  // the torso box's drawn centre
    EXPECT_NEAR(x, torso->x(), 0.02) << name;
    EXPECT_NEAR(y, torso->y(), 0.02) << name;
    EXPECT_NEAR(x, start.at(name).first, 0.05) << name;
    EXPECT_NEAR(y, start.at(name).second, 0.05) << name;
    size_t geoms = 0;  // every shape of the robot's is drawn
    for (const json& d : (*legged)["robots"])
      if (d["name"] == name) geoms = d["geoms"].size();
    EXPECT_GE(geoms, 10u) << name;
    EXPECT_EQ(r["shapes"], geoms) << name;
    // Robot grey over the torso. At this zoom the torso is about 3 pixels wide
    // and the head's and neck's dark outlines cross it, so sample a 3 x 3 grid
    // over the torso box (+-0.04 m) rather than one pixel: a robot drawn
    // anywhere else leaves only grass there.
    int grey = 0;
    json seen = json::array();
    for (double dx : {-0.04, 0.0, 0.04}) {
      for (double dy : {-0.04, 0.0, 0.04}) {
        const json c = ColorAt(torso->x() + dx, torso->y() + dy);
        grey += IsRobotGrey(c);
        seen.push_back(c);
      }
    }
    const json beside = ColorAt(torso->x(), torso->y() - 0.6);
    EXPECT_GE(grey, 2) << name << ": " << seen;
    EXPECT_TRUE(IsGrass(beside)) << name << ": " << beside;
  }

  // 2. Dragging the ball teleports it; world_state says so.
  const double bx = truth.world->ball().position().x(), by = truth.world->ball().position().y();
  ASSERT_TRUE(DragField(bx, by, 2.0, -3.0)) << driver_->error();
  EXPECT_TRUE(truth.WaitFor(
      [&] {
        return std::hypot(truth.world->ball().position().x() - 2.0, truth.world->ball().position().y() + 3.0) < 0.1;
      },
      5000))
      << "ball at (" << truth.world->ball().position().x() << ", " << truth.world->ball().position().y() << ")";

  // 2b. Right-dragging it throws it: v = (2, 0) m/s along the grass.
  {
    const auto [tx0, ty0] = ClientPoint(2.0, -3.0);
    const auto [tx1, ty1] = ClientPoint(3.0, -3.0);
    ASSERT_TRUE(driver_->Drag(tx0, ty0, tx1, ty1, 300, /*button=*/2)) << driver_->error();
    EXPECT_TRUE(truth.WaitFor(
        [&] {
          const idl::Vec3& p = truth.world->ball().position();
          const idl::Vec3& v = truth.world->ball().velocity();
          return v.x() > 0.8 && v.x() < 2.2 && std::abs(v.y()) < 0.2 && p.x() > 2.05 && std::abs(p.y() + 3.0) < 0.1;
        },
        5000))
        << "ball at (" << truth.world->ball().position().x() << ", " << truth.world->ball().position().y()
        << ") moving (" << truth.world->ball().velocity().x() << ", " << truth.world->ball().velocity().y() << ")";
  }

  // 3. Dragging a robot teleports it upright, at its height and orientation.
  ASSERT_TRUE(DragField(-5.0, 1.5, -3.0, 3.0)) << driver_->error();
  EXPECT_TRUE(truth.WaitFor(
      [&] {
        const std::optional<idl::Vec3> t = truth.Body("nao_2", "torso");
        return t && std::hypot(t->x() + 3.0, t->y() - 3.0) < 0.1;
      },
      5000))
      << "nao_2's torso at " << Where(truth.Body("nao_2", "torso"));
  // Half a second of simulation to settle; a fallen Nao's torso is below 0.15 m.
  const int64_t moved_at = truth.links["nao_2"].sim_time_ns();
  ASSERT_TRUE(truth.WaitFor([&] { return truth.links["nao_2"].sim_time_ns() > moved_at + 500'000'000; }, 5000));
  const std::optional<idl::Vec3> settled = truth.Body("nao_2", "torso");
  ASSERT_TRUE(settled);
  EXPECT_GT(settled->z(), 0.3) << "nao_2 fell after the teleport";

  // 4. Pause stops time for legged scenes too.
  const auto pause = driver_->Find("#pause");
  ASSERT_TRUE(pause && driver_->Click(*pause)) << driver_->error();
  ASSERT_TRUE(truth.WaitFor([&] { return truth.clock && truth.clock->paused(); }, 3000));
  const auto paused_frame = static_cast<int64_t>(truth.clock->frame());
  ASSERT_TRUE(Within(30000, [&] { return PagePaused() && PageFrame() == paused_frame; }))
      << "page at frame " << PageFrame() << ", turf-sim paused at " << paused_frame;
  const std::string paused_at = SimTimeText();
  // Later requests are answered at the same frame; the states after them reach
  // the page, still of that frame.
  const int states_before = PageReceived("state");
  for (int i = 0; i < 5; ++i) {
    const auto probe = truth.Control(idl::OP_PAUSE);
    ASSERT_TRUE(probe);
    EXPECT_EQ(static_cast<int64_t>(probe->frame()), paused_frame);
  }
  ASSERT_TRUE(Within(30000, [&] { return PageReceived("state") > states_before; }));
  EXPECT_EQ(PageFrame(), paused_frame);
  EXPECT_EQ(SimTimeText(), paused_at);
  const auto badge = driver_->Execute("return !document.getElementById('paused-badge').classList.contains('hidden');");
  EXPECT_TRUE(badge && *badge == true);

  EXPECT_TRUE(SavePng(driver_->Screenshot(), "legged.png")) << driver_->error();
  EXPECT_EQ(viewer_->Stop(), 0) << viewer_->Log();
}

// The camera panel: turf-render draws red_1's head camera of the HLVS scene (declared off there, on by --cameras);
// the page opened at ?camera=red_1/camera shows its newest images (polled from the viewer,
// /camera/red_1/camera.jpg) in the legged scene's side panel.
TEST_F(ViewerBrowser, TheCameraPanelShowsARobotsCameraLive) {
  Launch("hlvs.yaml");
  Process render("viewer_render", {Built("participants/render/turf-render"), "--scene",
                                   TURF_SOURCE_DIR "/configs/scenes/hlvs.yaml", "--cameras", "red_1/camera", "--domain",
                                   std::to_string(dds_.domain), "--prefix", dds_.prefix, "--qos", dds_.qos_file});
  LeggedClient truth(dds_);
  OpenPage([&] { return truth.WaitFor([&] { return truth.links.count("red_1") && truth.world; }); });
  if (HasFatalFailure()) return;
  ASSERT_TRUE(driver_->Navigate("http://127.0.0.1:" + std::to_string(viewer_port_) + "/?camera=red_1/camera"))
      << driver_->error();
  const char* kShown =
      "const p = document.getElementById('camera-panel');"
      "const i = [...document.querySelectorAll('.camera-view img')].find(x => !x.classList.contains('hidden'));"
      "return {panel: !p.classList.contains('hidden'), width: i ? i.naturalWidth : 0, height: i ? i.naturalHeight : 0,"
      " status: document.getElementById('camera-status').textContent,"
      " frames: parseInt((document.getElementById('camera-status').textContent.match(/: (\\d+) frames$/) || [0, "
      "'0'])[1])};";
  json shown;
  const bool ok = Within(60000, [&] {
    shown = driver_->Execute(kShown).value_or(json());
    // At least 3 images shown (the count keeps growing: polled on a loaded machine, it is seldom exactly 3).
    return shown.is_object() && shown["width"] == 320 && shown["frames"].is_number() && shown["frames"] >= 3;
  });
  ASSERT_TRUE(ok) << shown.dump() << "\n" << render.Log() << viewer_->Log();
  EXPECT_TRUE(shown["panel"].get<bool>()) << "the legged scene shows the panel";
  EXPECT_EQ(shown["height"], 240);
  EXPECT_TRUE(SavePng(driver_->Screenshot(), "camera_panel.png")) << driver_->error();
}

}  // namespace
}  // namespace turf::test
