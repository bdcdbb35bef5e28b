// The page itself, end to end: turf-sim and turf-viewer as real processes,
// the page in headless Chromium driven through chromedriver (W3C WebDriver),
// and a DDS client that knows the truth. Checks that robots are drawn where
// the world state says, that dragging the ball teleports it, that Pause stops
// simulation time, and saves screenshots to <build>/tests/viewer/artifacts/.
// Skipped when chromium or chromedriver is not installed.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "tests/e2e/child_process.h"
#include "tests/sim/sim_harness.h"
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

class ViewerBrowser : public ::testing::Test {
 protected:
  void SetUp() override {
    chromium_ = FindExecutable({"chromium", "chromium-browser", "google-chrome"});
    chromedriver_ = FindExecutable({"chromedriver"});
    if (chromium_.empty() || chromedriver_.empty())
      GTEST_SKIP() << "headless Chromium not installed (Debian packages chromium and chromium-driver; "
                      "scripts/setup.sh installs them)";
    dds_ = UniqueDds("viewer-browser");
    dds_.domain = TestDomain(7);
    dds_.prefix = "browser" + std::to_string(getpid());
    viewer_port_ = FreeTcpPort();
    const std::string domain = std::to_string(dds_.domain);
    sim_ = std::make_unique<ChildProcess>(
        "viewer_sim", std::vector<std::string>{BuiltBinary("participants/sim/turf-sim"), "--scene",
                                               TURF_SOURCE_DIR "/configs/scenes/ssl_div_b.yaml", "--domain", domain,
                                               "--prefix", dds_.prefix, "--qos", dds_.qos_file});
    viewer_ = std::make_unique<ChildProcess>(
        "viewer",
        std::vector<std::string>{BuiltBinary("participants/viewer/turf-viewer"), "--port", std::to_string(viewer_port_),
                                 "--domain", domain, "--prefix", dds_.prefix, "--qos", dds_.qos_file});
    const int driver_port = FreeTcpPort();
    driver_process_ = std::make_unique<ChildProcess>(
        "chromedriver", std::vector<std::string>{chromedriver_, "--port=" + std::to_string(driver_port)});
    client_ = std::make_unique<Client>(dds_);
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

  // Opens the page and waits until it shows the field and a world state.
  void OpenPage() {
    ASSERT_TRUE(client_->WaitMatched(10s)) << "turf-sim did not come up: " << sim_->Log();
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
  std::string SimTimeText() {
    const auto element = driver_->Find("#simtime");
    return element ? driver_->Text(*element).value_or("") : "";
  }

  std::string chromium_, chromedriver_, profile_;
  dds::ParticipantOptions dds_;
  int viewer_port_ = 0;
  std::unique_ptr<ChildProcess> sim_, viewer_, driver_process_;
  std::unique_ptr<Client> client_;
  std::unique_ptr<WebDriver> driver_;
};

TEST_F(ViewerBrowser, DrawsTheWorldDragsTheBallPausesAndSavesScreenshots) {
  OpenPage();
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

  // 3. Pause: simulation time stops, in turf-sim and on the page.
  const std::string running = SimTimeText();
  ASSERT_TRUE(Within(2000, [&] { return SimTimeText() != running; })) << "time does not advance before pausing";
  const auto pause = driver_->Find("#pause");
  ASSERT_TRUE(pause);
  ASSERT_TRUE(driver_->Click(*pause)) << driver_->error();
  EXPECT_TRUE(Within(3000, [&] {
    client_->Poll();
    return client_->clock().paused();
  }));
  std::this_thread::sleep_for(200ms);  // the last state on its way
  const std::string paused_at = SimTimeText();
  const int64_t sim_paused_at = client_->clock().sim_time_ns();
  std::this_thread::sleep_for(700ms);
  client_->Poll();
  EXPECT_EQ(SimTimeText(), paused_at);
  EXPECT_EQ(client_->clock().sim_time_ns(), sim_paused_at);
  const auto badge = driver_->Execute("return !document.getElementById('paused-badge').classList.contains('hidden');");
  EXPECT_TRUE(badge && *badge == true);

  // 4. Screenshots: ground truth, then truth and camera detections together.
  EXPECT_TRUE(SavePng(driver_->Screenshot(), "viewer_truth.png")) << driver_->error();
  const auto both = driver_->Find("button[data-view=both]");
  ASSERT_TRUE(both && driver_->Click(*both));
  std::this_thread::sleep_for(100ms);
  EXPECT_TRUE(SavePng(driver_->Screenshot(), "viewer_both.png")) << driver_->error();

  // 5. The sensor model at work: harsh realism, camera view, running again.
  const auto harsh = driver_->Find("#realism option[value=harsh]");
  ASSERT_TRUE(harsh && driver_->Click(*harsh)) << driver_->error();
  const auto cameras = driver_->Find("button[data-view=cameras]");
  const auto resume = driver_->Find("#resume");
  ASSERT_TRUE(cameras && driver_->Click(*cameras) && resume && driver_->Click(*resume));
  EXPECT_TRUE(Within(3000, [&] {
    const auto seen = driver_->Execute(
        "const s = window.turfViewer.state(); return !!s && !s.clock.paused && s.detections.length > 0;");
    return seen && *seen == true;
  })) << "no camera detections on the page";
  const auto message = driver_->Find("#message");
  EXPECT_TRUE(Within(2000, [&] { return message && driver_->Text(*message).value_or("").rfind("resume", 0) == 0; }));
  std::this_thread::sleep_for(500ms);
  EXPECT_TRUE(SavePng(driver_->Screenshot(), "viewer_cameras.png")) << driver_->error();
  client_->Poll();
  EXPECT_FALSE(client_->clock().paused());

  EXPECT_EQ(viewer_->Stop(), 0) << viewer_->Log();  // SIGTERM: a clean exit
  EXPECT_NE(viewer_->Log().find("stopped cleanly"), std::string::npos);
}

}  // namespace
}  // namespace turf::test
