// HLVS camera images end to end: turf-sim with configs/scenes/hlvs.yaml (its K1 head cameras declared off),
// turf-render with that scene and turf-hlvs-bridge as real processes, and a scripted HLVS client. The client
// enables "Camera" every 16 ms: the bridge switches the camera on in turf-render (cameras/control), and the client
// gets CameraMeasurements of 320 x 240, raw (quality -1), B G R bytes, at times 16 ms apart, each a different frame
// (the client turns the head all the time); red_1 looks at the field (green in the G byte). Then the client sets 0 and
// no camera comes any more. Skipped where turf-render can make no EGL context.
#include <gtest/gtest.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <optional>
#include <set>
#include <string>
#include <thread>

#include "tests/hlvs/hlvs_client.h"
#include "tests/hlvs/hlvs_requests.h"
#include "tests/support/process.h"
#include "tests/test_domain.h"

namespace turf::test {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

const std::string kScene = std::string(TURF_SOURCE_DIR) + "/configs/scenes/hlvs.yaml";

// Pixels whose G byte (the middle of B, G, R) stands clearly above the other two: the field.
int GreenPixels(const std::string& bgr) {
  int n = 0;
  for (size_t i = 0; i + 2 < bgr.size(); i += 3) {
    const int b = static_cast<uint8_t>(bgr[i]), g = static_cast<uint8_t>(bgr[i + 1]),
              r = static_cast<uint8_t>(bgr[i + 2]);
    n += g > b + 20 && g > r + 20;
  }
  return n;
}

TEST(HlvsCamera, AClientGetsRenderedImagesAtItsStepAndNoneOnceOff) {
  const int red = FreePort(SOCK_STREAM), blue = FreePort(SOCK_STREAM);
  const std::string domain = std::to_string(TestDomain(37)), prefix = "hlvscam" + std::to_string(getpid());
  Process render("hlvs_cam_render", {Built("participants/render/turf-render"), "--scene", kScene, "--status-every", "1",
                                     "--domain", domain, "--prefix", prefix});
  Process sim("hlvs_cam_sim",
              {Built("participants/sim/turf-sim"), "--scene", kScene, "--domain", domain, "--prefix", prefix});
  // Real time: the renderer keeps up with one camera at 62.5 Hz of simulated time.
  Process bridge("hlvs_cam_bridge", {Built("participants/hlvs_bridge/turf-hlvs-bridge"), "--listen", "127.0.0.1",
                                     "--red-ports", std::to_string(red), "--blue-ports", std::to_string(blue),
                                     "--realtime-factor", "1", "--domain", domain, "--prefix", prefix});
  HlvsClient client;
  std::string greeting;
  const auto end = Clock::now() + 60s;
  while (greeting != std::string("Welcome\0", 8) && Clock::now() < end) {
    if (!render.Running() && render.Log().find("EGL") != std::string::npos)
      GTEST_SKIP() << "turf-render has no EGL display here:\n" << render.Log();
    if (client.Connect(static_cast<uint16_t>(red))) greeting = client.Greeting(5s);
    if (greeting != std::string("Welcome\0", 8)) std::this_thread::sleep_for(200ms);
  }
  ASSERT_EQ(greeting, std::string("Welcome\0", 8)) << bridge.Log() << sim.Log();
  auto first = client.Receive(20s);
  ASSERT_TRUE(first.has_value()) << bridge.Log();
  ASSERT_TRUE(client.Send(TimeSteps({{"Camera", 16}})));

  // Images until 5 have come (the renderer may start late, and a frame not rendered in time is left out).
  std::optional<uint32_t> phase;  // the first camera message's time modulo 16
  std::set<std::string> distinct;
  int images = 0;
  const auto deadline = Clock::now() + 90s;
  while (images < 5 && Clock::now() < deadline) {
    auto m = client.Receive(20s);
    ASSERT_TRUE(m.has_value()) << bridge.Log();
    ASSERT_TRUE(client.Send(Position("Neck", 0.5 * std::sin(m->time() * 1e-3 * M_PI))));  // the head keeps turning
    for (const auto& w : m->messages()) ADD_FAILURE() << "a message: " << w.text();
    for (const auto& c : m->cameras()) {
      ++images;
      EXPECT_EQ(c.name(), "Camera");
      EXPECT_EQ(c.width(), 320u);
      EXPECT_EQ(c.height(), 240u);
      EXPECT_EQ(c.quality(), -1);
      ASSERT_EQ(c.image().size(), 320u * 240u * 3u);
      EXPECT_GT(GreenPixels(c.image()), 320 * 240 / 10) << "the field, green in the middle byte (B, G, R)";
      distinct.insert(c.image());
    }
    if (!m->cameras().empty()) {
      // Cameras only on their period: 16 ms apart (times are multiples of 8), a step that missed its frame aside.
      if (!phase) phase = m->time() % 16;
      EXPECT_EQ(m->time() % 16, *phase) << "time " << m->time();
    }
  }
  ASSERT_GE(images, 5) << render.Log() << bridge.Log();
  EXPECT_EQ(distinct.size(), static_cast<size_t>(images)) << "never one frame twice (the head turns all the time)";
  EXPECT_NE(render.Log().find("camera red_1/camera on at 62.5 Hz of sim time (asked by 'turf-hlvs-bridge')"),
            std::string::npos)
      << render.Log();

  // Off: the bridge switches it off in turf-render, and after the step that took the request no camera comes.
  ASSERT_TRUE(client.Send(TimeSteps({{"Camera", 0}})));
  const auto off_deadline = Clock::now() + 30s;
  while (render.Log().find("camera red_1/camera off") == std::string::npos && Clock::now() < off_deadline)
    std::this_thread::sleep_for(100ms);
  EXPECT_NE(render.Log().find("camera red_1/camera off (asked by 'turf-hlvs-bridge')"), std::string::npos)
      << render.Log();
  // The messages the bridge sent before it took the request may still carry a camera (it reads requests once a
  // step: one or two steps); then none.
  int last_camera = -1;
  for (int i = 0; i < 40; ++i) {
    auto m = client.Receive(20s);
    ASSERT_TRUE(m.has_value());
    if (m->cameras_size() > 0) last_camera = i;
  }
  EXPECT_LT(last_camera, 10) << "cameras after the request to switch off was taken";
  client.Close();
  const int bridge_status = bridge.Stop();
  EXPECT_TRUE(WIFEXITED(bridge_status) && WEXITSTATUS(bridge_status) == 0) << bridge.Log();
  EXPECT_NE(bridge.Log().find("camera images: "), std::string::npos) << bridge.Log();
  const int render_status = render.Stop();
  EXPECT_TRUE(WIFEXITED(render_status) && WEXITSTATUS(render_status) == 0) << render.Log();
  sim.Stop();
}

}  // namespace
}  // namespace turf::test
