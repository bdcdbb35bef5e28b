// turf-hlvs-bridge with turf-sim's legged node (configs/scenes/hlvs.yaml: K1 robots red_1 and blue_1) on an
// in-memory bus, as fast as possible, and scripted HLVS clients over real TCP: the greeting, sensors at their
// requested time steps in simulated time, a commanded joint moving, refused clients, and bad input dropping only
// its client without moving the robot. No sleeps: every wait is for a message or a condition, with a deadline.
#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <thread>

#include "codecs/hlvs/camera_source.h"
#include "participants/hlvs_bridge/hlvs_bridge.h"
#include "tests/hlvs/hlvs_client.h"
#include "tests/hlvs/hlvs_requests.h"
#include "tests/support/front_end_on_bus.h"
#include "tests/support/legged_scene.h"

namespace turf {
namespace {

using namespace std::chrono_literals;
using test::HlvsClient;
namespace pb = hlvs::pb;

const std::string kWelcome("Welcome\0", 8);
const std::string kRefused("Refused\0", 8);

// turf-sim's legged node (the HLVS scene) and the bridge: red players 1 and 2 and blue player 1 on ports the kernel
// picks, from this machine.
class Match : public test::FrontEndOnBus<HlvsBridge> {
 public:
  // `max_speed` > 0: every robot's motors.max_speed instead of the scene's.
  // `cameras`: an image source, and real time (images of 230 KB would otherwise outrun a client on a loaded machine).
  explicit Match(double max_speed = 0, hlvs::CameraSource* cameras = nullptr)
      : FrontEndOnBus("hlvs", Scene(max_speed), [cameras](dds::Bus& bus) { return Bridge(cameras, bus); }) {}

 private:
  static LeggedScene Scene(double max_speed) {
    LeggedScene scene = test::LoadScene("hlvs.yaml");
    for (auto& robot : scene.robots)
      if (max_speed > 0) robot.motors.max_speed = max_speed;
    return scene;
  }
  static std::unique_ptr<HlvsBridge> Bridge(hlvs::CameraSource* cameras, dds::Bus& bus) {
    HlvsBridgeOptions o;
    o.listen = "127.0.0.1";
    o.red_ports = {0, 0};
    o.blue_ports = {0};
    o.red_allow = {"127.0.0.1"};
    o.blue_allow = {"127.0.0.0/8"};
    o.realtime_factor = cameras != nullptr ? 1.0 : 0.0;
    auto bridge = std::make_unique<HlvsBridge>(o, bus);
    bridge->SetCameraSource(cameras);
    return bridge;
  }
};

using test::Position;
using test::TimeSteps;

std::optional<double> Sensor(const pb::SensorMeasurements& m, const std::string& name) {
  for (const pb::PositionSensorMeasurement& p : m.position_sensors())
    if (p.name() == name) return p.value();
  return std::nullopt;
}

// Connects to `port` and waits for Welcome (the bridge may still be attaching to turf-sim).
void Welcome(HlvsClient* c, uint16_t port) {
  ASSERT_TRUE(c->Connect(port));
  ASSERT_EQ(c->Greeting(), kWelcome);
}

// The NeckS value of the first message that has it (the client enabled NeckS before).
double ReadNeck(HlvsClient* c) {
  for (int i = 0; i < 100; ++i) {
    auto m = c->Receive();
    if (!m) break;
    if (auto v = Sensor(*m, "NeckS")) return *v;
  }
  ADD_FAILURE() << "no NeckS";
  return std::nan("");
}

TEST(HlvsBridge, SensorsAtTheirStepsAndACommandedJointMoves) {
  Match match;
  HlvsClient c;
  Welcome(&c, match.bridge().port("red", 1));
  auto first = c.Receive();
  ASSERT_TRUE(first);
  EXPECT_EQ(first->time() % 8, 0u);
  EXPECT_GT(first->real_time(), 1600000000000u);  // Unix ms
  EXPECT_EQ(first->position_sensors_size(), 0);   // nothing before the client enables sensors
  ASSERT_TRUE(c.Send(TimeSteps({{"NeckS", 8}, {"Gyro", 16}, {"Accelerometer", 32}, {"lf", 8}, {"Camera", 16}})));
  // Find the first message with NeckS: from there on every 8 ms step has it, the gyro every 16, the accelerometer 32.
  std::optional<pb::SensorMeasurements> m;
  for (int i = 0; i < 200 && !(m && Sensor(*m, "NeckS")); ++i) m = c.Receive();
  ASSERT_TRUE(m && Sensor(*m, "NeckS"));
  const uint32_t t0 = m->time();
  int gyros = 0, accs = 0;
  uint32_t last = t0;
  for (int i = 1; i <= 32; ++i) {
    m = c.Receive();
    ASSERT_TRUE(m);
    EXPECT_EQ(m->time(), last + 8) << "one message per 8 ms step";
    last = m->time();
    EXPECT_TRUE(Sensor(*m, "NeckS"));
    ASSERT_EQ(m->forces_size(), 1);  // lf, standing: about half the K1's weight
    EXPECT_GT(m->forces(0).value(), 20.0);
    gyros += m->gyros_size();
    accs += m->accelerometers_size();
    EXPECT_EQ(m->cameras_size(), 0);  // no renderer: no images
    if (m->accelerometers_size() == 1) {
      EXPECT_NEAR(m->accelerometers(0).value().z(), 9.81, 1.0);  // standing: +g up
    }
  }
  EXPECT_EQ(gyros, 16);
  EXPECT_EQ(accs, 8);
  // Neck (the K1's head yaw) to 0.5 rad: Webots' P 10 gives a time constant of 0.1 s; within 0.02 rad after
  // ln(25) / 10 = 0.32 s. Allow 1 s of simulated time; then it holds.
  ASSERT_TRUE(Sensor(*m, "NeckS"));
  const double start = *Sensor(*m, "NeckS");
  EXPECT_NEAR(start, 0.0, 0.01);
  ASSERT_TRUE(c.Send(Position("Neck", 0.5)));
  const uint32_t sent = m->time();
  uint32_t reached = 0;
  while (m && m->time() < sent + 1000 && reached == 0) {
    m = c.Receive();
    ASSERT_TRUE(m);
    ASSERT_TRUE(Sensor(*m, "NeckS"));
    if (std::abs(*Sensor(*m, "NeckS") - 0.5) < 0.02) reached = m->time();
  }
  ASSERT_NE(reached, 0u) << "Neck did not reach 0.5 rad within 1 s of simulated time";
  EXPECT_GE(reached - sent, 200u) << "faster than Webots' P controller allows";
  RecordProperty("neck_settle_ms", static_cast<int>(reached - sent));
  for (int i = 0; i < 50; ++i) m = c.Receive();
  ASSERT_TRUE(m);
  ASSERT_TRUE(Sensor(*m, "NeckS"));
  EXPECT_NEAR(*Sensor(*m, "NeckS"), 0.5, 0.02);
}

TEST(HlvsBridge, RefusesClientsOutsideTheAllowlistAndOnABusyPort) {
  Match match;
  const uint16_t port = match.bridge().port("red", 1);
  HlvsClient stranger;
  ASSERT_TRUE(stranger.Connect(port, "127.0.0.2"));
  EXPECT_EQ(stranger.Greeting(), kRefused);
  EXPECT_TRUE(stranger.WaitClosed());
  HlvsClient first, second;
  Welcome(&first, port);
  ASSERT_TRUE(second.Connect(port));
  EXPECT_EQ(second.Greeting(), kRefused);
  EXPECT_TRUE(second.WaitClosed());
  EXPECT_TRUE(first.Receive());  // the first client is still served
  // A client that leaves and comes straight back is welcome again (as the reference's next accept).
  first.Close();
  HlvsClient back;
  Welcome(&back, port);
  EXPECT_TRUE(back.Receive());
  // Blue's allowlist is 127.0.0.0/8: the same stranger is welcome there.
  HlvsClient blue;
  ASSERT_TRUE(blue.Connect(match.bridge().port("blue", 1), "127.0.0.2"));
  EXPECT_EQ(blue.Greeting(), kWelcome);
  const HlvsBridgeStats stats =
      match.bridge().WaitForStats([](const HlvsBridgeStats& s) { return s.welcomed >= 3; }, 20s);
  EXPECT_EQ(stats.refused_clients, 2u);
  EXPECT_EQ(stats.refused_by_kind.at("client_not_allowed"), 1u);
  EXPECT_EQ(stats.refused_by_kind.at("port_busy"), 1u);
}

// A bad frame right behind a good command, in one write: the client is dropped, the command is not applied.
void ExpectDroppedWithoutMoving(Match* match, const std::string& bad, const char* kind) {
  const uint16_t port = match->bridge().port("red", 1);
  HlvsClient c;
  Welcome(&c, port);
  ASSERT_TRUE(c.SendRaw(HlvsClient::Framed(Position("Neck", 1.0).SerializeAsString()) + bad));
  EXPECT_TRUE(c.WaitClosed()) << kind;
  const HlvsBridgeStats stats =
      match->bridge().WaitForStats([kind](const HlvsBridgeStats& s) { return s.refused_by_kind.count(kind) > 0; }, 20s);
  EXPECT_EQ(stats.refused_by_kind.count(kind), 1u) << kind;
  HlvsClient again;
  Welcome(&again, port);
  ASSERT_TRUE(again.Send(TimeSteps({{"NeckS", 8}})));
  double neck = 0;
  for (int i = 0; i < 25; ++i) neck = ReadNeck(&again);  // 25 steps after: a moving head would be 0.8 rad on
  EXPECT_NEAR(neck, 0.0, 0.01) << kind << ": the robot moved";
  // Leave, and wait until the bridge has seen it (a client on a busy port is refused).
  const uint64_t dropped = match->bridge().Stats().dropped_clients;
  again.Close();
  match->bridge().WaitForStats([dropped](const HlvsBridgeStats& s) { return s.dropped_clients > dropped; }, 20s);
}

TEST(HlvsBridge, BadInputDropsOnlyThatClientAndDoesNotMoveTheRobot) {
  Match match;
  HlvsClient blue;
  Welcome(&blue, match.bridge().port("blue", 1));
  ExpectDroppedWithoutMoving(&match, HlvsClient::Framed("\xff\xff\xff\xff garbage"), "request.malformed");
  ExpectDroppedWithoutMoving(&match, HlvsClient::Framed(Position("Head", std::nan("")).SerializeAsString()),
                             "request.not_finite");
  ExpectDroppedWithoutMoving(&match, std::string("\x00\x10\x00\x00", 4), "frame_too_large");  // 1 MiB announced
  // The blue client was served throughout and still is.
  for (int i = 0; i < 10; ++i) ASSERT_TRUE(blue.Receive()) << "blue was dropped";
  EXPECT_FALSE(blue.bad());
}

// A scene whose motors are slower than the HLVS table's 20 rad/s: turf-sim refuses the fast velocity target; the
// bridge counts it and steps on without the commands instead of stopping the match.
TEST(HlvsBridge, ARefusedStepIsCountedAndTheMatchGoesOn) {
  Match match(/*max_speed=*/1.0);
  HlvsClient c;
  Welcome(&c, match.bridge().port("red", 1));
  ASSERT_TRUE(c.Send(Position("Neck", 0.5)));  // P 10 x 0.5 rad = 5 rad/s > 1
  const HlvsBridgeStats stats = match.bridge().WaitForStats(
      [](const HlvsBridgeStats& s) { return s.refused_by_kind.count("step_refused") > 0; }, 20s);
  EXPECT_GT(stats.refused_by_kind.count("step_refused"), 0u);
  auto m = c.Receive();
  ASSERT_TRUE(m);
  for (int i = 0; i < 5; ++i) {
    auto next = c.Receive();
    ASSERT_TRUE(next) << "the bridge stopped";
    EXPECT_EQ(next->time(), m->time() + 8);
    m = next;
  }
}

// A stand-in renderer: every request answered with an image whose first byte is the request's time step count.
class StandInCamera : public hlvs::CameraSource {
 public:
  std::optional<hlvs::CameraImage> Take(const hlvs::CameraRequest& r) override {
    hlvs::CameraImage image;
    image.width = r.width;
    image.height = r.height;
    image.image.assign(size_t{r.width} * r.height * 3, '\x40');
    image.image[0] = static_cast<char>((r.sim_time_ms / 8) & 0xff);
    if (r.robot != "red_1" || r.camera != "camera") image.image.clear();  // the K1's MJCF camera of red_1 only
    return image;
  }
};

// With an image source, a client gets camera images of the table's size at its requested step (the issue's
// "scripted HLVS client receives images of the requested size and step"; the images are the stand-in's).
TEST(HlvsBridge, CameraImagesComeAtTheirStepWhenThereIsASource) {
  StandInCamera camera;
  Match match(0, &camera);
  HlvsClient c;
  Welcome(&c, match.bridge().port("red", 1));
  ASSERT_TRUE(c.Send(TimeSteps({{"Camera", 32}})));
  std::vector<uint32_t> times;
  for (int i = 0; i < 100 && times.size() < 4; ++i) {
    auto m = c.Receive();
    ASSERT_TRUE(m);
    if (m->cameras_size() == 0) continue;
    ASSERT_EQ(m->cameras_size(), 1);
    const pb::CameraMeasurement& image = m->cameras(0);
    EXPECT_EQ(image.name(), "Camera");
    EXPECT_EQ(image.width(), 320u);
    EXPECT_EQ(image.height(), 240u);
    EXPECT_EQ(image.quality(), -1);
    ASSERT_EQ(image.image().size(), 320u * 240u * 3u);
    EXPECT_EQ(static_cast<uint8_t>(image.image()[0]), (m->time() / 8) & 0xff) << "the image of this step";
    times.push_back(m->time());
  }
  ASSERT_EQ(times.size(), 4u);
  for (size_t i = 1; i < times.size(); ++i) EXPECT_EQ(times[i] - times[i - 1], 32u);
}

}  // namespace
}  // namespace turf
