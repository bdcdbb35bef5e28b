// turf-vision-bridge in-process: turf-sim's node and the bridge on threads of
// their own, each test on its own DDS domain and topic prefix, sending unicast
// to a UDP port the test picked free. Assertions are on the decoded packets.
// Waits count packets and frames (simulation time), under a deadline that only
// catches a hang (kPatience): a machine with every core busy is slow, not wrong.
#include <gtest/gtest.h>
#include <turf/idl/ClockPubSubTypes.h>
#include <turf/idl/SimControlPubSubTypes.h>
#include <turf/idl/SslVisionPubSubTypes.h>
#include <unistd.h>
#include "tests/test_domain.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <thread>
#include <tuple>

#include "codecs/proto/ssl_vision.pb.h"
#include "dds/control_client.h"
#include "dds/participant.h"
#include "participants/common/udp.h"
#include "participants/sim/sim_node.h"
#include "participants/vision_bridge/vision_bridge.h"
#include "tests/core/test_scenes.h"
#include "tests/support/in_process.h"

namespace turf {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

constexpr auto kPatience = 15s;  // the longest any one wait may take

// Polls `done` until it holds or kPatience has passed.
bool WaitFor(const std::function<bool()>& done) {
  const auto end = Clock::now() + kPatience;
  while (!done()) {
    if (Clock::now() >= end) return false;
    std::this_thread::sleep_for(2ms);
  }
  return true;
}

using test::OnThread;

VisionBridgeOptions BridgeOptions(const dds::ParticipantOptions& dds, uint16_t port) {
  auto o = test::OnDds<VisionBridgeOptions>(dds);
  o.address = "127.0.0.1";
  o.port = port;
  return o;
}

// A UDP port on loopback, picked free by the kernel.
class Receiver {
 public:
  Receiver() : socket_(test::BindLoopback()) {}
  uint16_t port() const { return socket_.LocalPort(); }
  template <class Packet>
  bool Next(Packet* out, std::chrono::milliseconds timeout = 1000ms) {
    auto d = socket_.Receive(65536, timeout);
    if (!d) return false;
    EXPECT_FALSE(d->truncated);
    const bool ok = out->ParseFromArray(d->bytes.data(), static_cast<int>(d->bytes.size()));
    EXPECT_TRUE(ok && out->IsInitialized());
    return ok;
  }

 private:
  UdpSocket socket_;
};

// Receives wrappers until `done` holds or kPatience has passed; false then.
bool ReceiveUntil(Receiver& rx, const std::function<bool(const wire::vision::SSL_WrapperPacket&)>& done) {
  const auto end = Clock::now() + kPatience;
  while (Clock::now() < end) {
    wire::vision::SSL_WrapperPacket p;
    if (rx.Next(&p, 100ms) && done(p)) return true;
  }
  return false;
}

const wire::vision::SSL_DetectionRobot* FindBlue(const wire::vision::SSL_DetectionFrame& d, uint32_t id) {
  for (const auto& r : d.robots_blue())
    if (r.robot_id() == id) return &r;
  return nullptr;
}

idl::SimControl Teleport(idl::Team team, int id, double x, double y, double orientation) {
  idl::SimControl c;
  c.op(idl::OP_TELEPORT_ROBOT);
  c.robot().team(team);
  c.robot().id(static_cast<uint8_t>(id));
  c.robot().on_field(true);
  c.robot().position().x(x);
  c.robot().position().y(y);
  c.robot().orientation(orientation);
  return c;
}

TEST(VisionBridge, DivisionACamerasGeometryAndATeleportedRobot) {
  const auto dds = test::UniqueDds("test");
  Receiver rx;
  VisionBridgeOptions o = BridgeOptions(dds, rx.port());
  o.geometry_every = 30;  // twice a second at 60 Hz
  OnThread<VisionBridge> bridge(std::make_unique<VisionBridge>(o));
  test::SimUnderTest sim(test::OneRobot(), dds, TimeMode::kRealtime);

  std::set<uint32_t> cameras;
  std::map<uint32_t, uint32_t> last_frame;
  std::map<uint32_t, double> round_time;
  int geometry = 0;
  const double now = std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
  ASSERT_TRUE(ReceiveUntil(rx,
                           [&](const wire::vision::SSL_WrapperPacket& p) {
                             EXPECT_EQ(p.source(), wire::vision::SSL_SOURCE_OTHER);
                             EXPECT_NE(p.has_detection(), p.has_geometry());  // geometry goes in packets of its own
                             if (p.has_geometry()) {
                               ++geometry;
                               EXPECT_EQ(p.geometry().field().field_length(), 12000);
                               EXPECT_EQ(p.geometry().field().field_width(), 9000);
                               EXPECT_EQ(p.geometry().calib_size(), 4);
                               EXPECT_EQ(p.geometry().field().field_lines_size(), 12);
                             }
                             if (p.has_detection()) {
                               const auto& d = p.detection();
                               cameras.insert(d.camera_id());
                               EXPECT_GE(d.t_sent(), d.t_capture());
                               EXPECT_GT(d.t_capture(), now - 60.0);  // Unix time, not sim time
                               EXPECT_LT(d.t_sent(), now + 60.0);
                               if (last_frame.count(d.camera_id())) {
                                 EXPECT_GT(d.frame_number(), last_frame[d.camera_id()]);
                               }
                               last_frame[d.camera_id()] = d.frame_number();
                               // The cameras of one capture round share its time stamp.
                               auto [it, first] = round_time.emplace(d.frame_number(), d.t_capture());
                               if (!first) {
                                 EXPECT_EQ(it->second, d.t_capture());
                               }
                             }
                             return cameras.size() == 4 && geometry >= 2;
                           }))
      << cameras.size() << " cameras, " << geometry << " geometry packets";
  EXPECT_EQ(cameras, (std::set<uint32_t>{0, 1, 2, 3}));

  // Teleport blue 0 into camera 0's quadrant (+x, +y) through the control topic.
  dds::Participant client(dds);
  dds::ControlClient control(client, "vision-test");
  const dds::ControlOutcome teleported = control.Call(Teleport(idl::TEAM_BLUE, 0, 3.0, 2.0, 1.0), kPatience);
  ASSERT_TRUE(teleported.ok()) << teleported.Describe();  // turf-sim answered RESULT_OK
  std::set<uint32_t> seen_by;
  ASSERT_TRUE(ReceiveUntil(rx, [&](const wire::vision::SSL_WrapperPacket& p) {
    if (!p.has_detection()) return false;
    const auto* r = FindBlue(p.detection(), 0);
    if (r == nullptr || std::abs(r->x() - 3000.0f) > 1.0f) return false;
    seen_by.insert(p.detection().camera_id());
    EXPECT_NEAR(r->y(), 2000.0f, 1.0f);
    EXPECT_NEAR(r->orientation(), 1.0f, 1e-4);
    EXPECT_NEAR(r->height(), 150.0f, 1e-3);
    // Camera 0 hangs at (3.3, 2.4, 4) m: the robot is left of and below its image centre.
    EXPECT_LT(r->pixel_x(), 390.0f);
    EXPECT_GT(r->pixel_y(), 290.0f);
    EXPECT_GT(r->pixel_x(), 0.0f);
    EXPECT_LT(r->pixel_y(), 580.0f);
    return seen_by.size() >= 1 && p.detection().frame_number() > last_frame[0] + 10;
  }));
  EXPECT_EQ(seen_by, std::set<uint32_t>{0});  // and by no other camera
  EXPECT_EQ(bridge.node().Stats().rejected, 0u);
  EXPECT_EQ(bridge.node().Stats().send_errors, 0u);
}

TEST(VisionBridge, SimClockAndTrackedPackets) {
  const auto dds = test::UniqueDds("test");
  Receiver rx, tracked_rx;
  VisionBridgeOptions o = BridgeOptions(dds, rx.port());
  o.clock = vision::ClockMode::kSim;
  o.tracked = true;
  o.tracked_address = "127.0.0.1";
  o.tracked_port = tracked_rx.port();
  OnThread<VisionBridge> bridge(std::make_unique<VisionBridge>(o));
  test::SimUnderTest sim(test::OneRobot(-2.0, -1.0, 0.5), dds, TimeMode::kRealtime);

  int detections = 0;
  int geometry_after = -1;  // detections before the first geometry packet
  ASSERT_TRUE(ReceiveUntil(rx, [&](const wire::vision::SSL_WrapperPacket& p) {
    if (p.has_geometry() && geometry_after < 0) geometry_after = detections;
    if (!p.has_detection()) return false;
    const auto& d = p.detection();
    EXPECT_GT(d.t_capture(), 0.0);
    EXPECT_LT(d.t_capture(), 30.0);  // simulation seconds since the start
    EXPECT_EQ(d.t_sent(), d.t_capture());
    // Captures fall on the 60 Hz grid (to the 2 ms physics step).
    EXPECT_NEAR(std::remainder(d.t_capture(), 1.0 / 60), 0.0, 0.0021);
    return ++detections >= 8 && geometry_after >= 0;
  }));
  // Geometry goes out as soon as the field is known, not after 120 rounds.
  EXPECT_LT(geometry_after, 4 * 60);

  const auto end = Clock::now() + kPatience;
  double last_timestamp = 0.0;
  int tracked = 0;
  while (tracked < 5 && Clock::now() < end) {
    wire::vision::TrackerWrapperPacket t;
    if (!tracked_rx.Next(&t, 100ms)) continue;
    ++tracked;
    EXPECT_FALSE(t.uuid().empty());
    EXPECT_EQ(t.source_name(), "turf");
    const auto& f = t.tracked_frame();
    EXPECT_GT(f.timestamp(), last_timestamp);
    last_timestamp = f.timestamp();
    ASSERT_EQ(f.balls_size(), 1);
    ASSERT_EQ(f.robots_size(), 1);
    EXPECT_EQ(f.robots(0).robot_id().team_color(), wire::vision::TEAM_COLOR_BLUE);
    EXPECT_NEAR(f.robots(0).pos().x(), -2.0f, 1e-3);  // metres
    EXPECT_NEAR(f.robots(0).pos().y(), -1.0f, 1e-3);
    EXPECT_NEAR(f.robots(0).orientation(), 0.5f, 1e-3);
  }
  EXPECT_EQ(tracked, 5);
  EXPECT_GT(bridge.node().Stats().tracked_sent, 0u);
}

// One bridge's detections by (timeline, camera, frame number). Frame numbers
// restart with a reset, which starts the camera's next timeline; `went_back`
// counts t_capture values below that camera's previous one.
struct Detections {
  struct Times {
    double t_capture;
    double t_sent;
  };
  std::map<std::tuple<int, uint32_t, uint32_t>, Times> frames;
  std::map<uint32_t, uint32_t> last_frame;
  std::map<uint32_t, double> last_capture;
  std::map<uint32_t, int> timeline;
  int went_back = 0;
  int sent_before_captured = 0;

  void Add(const wire::vision::SSL_DetectionFrame& d) {
    const uint32_t cam = d.camera_id();
    if (last_frame.count(cam) && d.frame_number() <= last_frame[cam]) ++timeline[cam];
    if (last_capture.count(cam) && d.t_capture() < last_capture[cam]) ++went_back;
    if (d.t_sent() < d.t_capture()) ++sent_before_captured;
    last_frame[cam] = d.frame_number();
    last_capture[cam] = d.t_capture();
    frames[{timeline[cam], cam, d.frame_number()}] = {d.t_capture(), d.t_sent()};
  }
  // Takes every datagram waiting at `rx` (at most `wait` for the first).
  void Pump(Receiver& rx, std::chrono::milliseconds wait) {
    wire::vision::SSL_WrapperPacket p;
    while (rx.Next(&p, wait)) {
      if (p.has_detection()) Add(p.detection());
      wait = 0ms;
    }
  }
};

// Tracked timestamps by world-state frame (before any reset).
void PumpTracked(Receiver& rx, std::map<uint32_t, double>* out) {
  wire::vision::TrackerWrapperPacket t;
  auto wait = 5ms;
  while (rx.Next(&t, wait)) {
    (*out)[t.tracked_frame().frame_number()] = t.tracked_frame().timestamp();
    wait = 0ms;
  }
}

// Frames of timeline `timeline` that both bridges sent.
std::vector<std::pair<Detections::Times, Detections::Times>> Matched(const Detections& a, const Detections& b,
                                                                     int timeline) {
  std::vector<std::pair<Detections::Times, Detections::Times>> out;
  for (const auto& [key, times] : a.frames) {
    if (std::get<0>(key) != timeline) continue;
    auto it = b.frames.find(key);
    if (it != b.frames.end()) out.emplace_back(times, it->second);
  }
  return out;
}

// The newest run epoch on turf-sim's clock topic.
class EpochWatch {
 public:
  explicit EpochWatch(dds::Participant& p) : reader_(p.MakeReader<idl::ClockPubSubType>(dds::Topic::kClock)) {}
  std::optional<int64_t> Poll() {
    if (reader_->Take(&inbox_)) {
      epoch_ = inbox_.back().run_epoch_unix_ns();
      sim_ns_ = inbox_.back().sim_time_ns();
    }
    return epoch_;
  }
  int64_t sim_ns() const { return sim_ns_; }

 private:
  std::unique_ptr<dds::Reader<idl::ClockPubSubType>> reader_;
  std::vector<idl::Clock> inbox_;
  std::optional<int64_t> epoch_;
  int64_t sim_ns_ = 0;
};

// Unix seconds of epoch + t_s, for comparing with what the bridge sent.
double EpochPlus(int64_t epoch_ns, double t_s) { return static_cast<double>(epoch_ns) * 1e-9 + t_s; }

// The default clock over DDS: turf-sim at speed 2; a run-clock bridge, a
// sim-clock bridge and a run-clock bridge started later send the same frames.
// Each run stamp is exactly the clock topic's epoch + the sim stamp, the late
// bridge's are bit-identical to the first's, and a reset keeps them monotonic.
TEST(VisionBridge, RunClockIsTheRunEpochPlusSimTime) {
  const auto dds = test::UniqueDds("test");
  Receiver run_rx, sim_rx, late_rx, run_tracked_rx, sim_tracked_rx;
  VisionBridgeOptions run_o = BridgeOptions(dds, run_rx.port());
  ASSERT_EQ(run_o.clock, vision::ClockMode::kRun);  // the default
  VisionBridgeOptions sim_o = BridgeOptions(dds, sim_rx.port());
  sim_o.clock = vision::ClockMode::kSim;
  for (auto [o, rx] : {std::pair{&run_o, &run_tracked_rx}, std::pair{&sim_o, &sim_tracked_rx}}) {
    o->tracked = true;
    o->tracked_address = "127.0.0.1";
    o->tracked_port = rx->port();
  }
  OnThread<VisionBridge> run_bridge(std::make_unique<VisionBridge>(run_o));
  OnThread<VisionBridge> sim_bridge(std::make_unique<VisionBridge>(sim_o));
  test::SimUnderTest sim(test::OneRobot(), dds, TimeMode::kScaled, 2.0);
  dds::Participant client(dds);
  EpochWatch clock(client);

  Detections run, sim_times, late;
  std::map<uint32_t, double> run_tracked, sim_tracked;
  size_t tracked_matched = 0;
  ASSERT_TRUE(WaitFor([&] {
    run.Pump(run_rx, 5ms);
    sim_times.Pump(sim_rx, 5ms);
    PumpTracked(run_tracked_rx, &run_tracked);
    PumpTracked(sim_tracked_rx, &sim_tracked);
    tracked_matched = 0;
    for (const auto& [frame, t] : sim_tracked) tracked_matched += run_tracked.count(frame);
    return clock.Poll().has_value() && Matched(run, sim_times, 0).size() >= 40 && tracked_matched >= 20;
  })) << Matched(run, sim_times, 0).size()
      << " frames matched, " << tracked_matched << " tracked";
  const std::optional<int64_t> epoch0 = clock.Poll();
  ASSERT_TRUE(epoch0.has_value());
  const double now = std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
  EXPECT_LT(std::abs(*epoch0 * 1e-9 - now), 120.0);  // Unix-looking: this run started just now
  for (const auto& [r, s] : Matched(run, sim_times, 0)) {
    EXPECT_NEAR(r.t_capture, EpochPlus(*epoch0, s.t_capture), 1e-6);
    EXPECT_NEAR(r.t_sent, EpochPlus(*epoch0, s.t_sent), 1e-6);
  }
  for (const auto& [frame, t] : sim_tracked) {
    if (run_tracked.count(frame)) {
      EXPECT_NEAR(run_tracked[frame], EpochPlus(*epoch0, t), 1e-6) << frame;
    }
  }

  // A bridge started now (or restarted) stamps the same frames the same.
  VisionBridgeOptions late_o = BridgeOptions(dds, late_rx.port());
  OnThread<VisionBridge> late_bridge(std::make_unique<VisionBridge>(late_o));
  ASSERT_TRUE(WaitFor([&] {
    run.Pump(run_rx, 5ms);
    sim_times.Pump(sim_rx, 5ms);
    late.Pump(late_rx, 5ms);
    return Matched(late, run, 0).size() >= 20;
  })) << Matched(late, run, 0).size()
      << " frames matched";
  for (const auto& [l, r] : Matched(late, run, 0)) {
    EXPECT_EQ(l.t_capture, r.t_capture);
    EXPECT_EQ(l.t_sent, r.t_sent);
  }

  // Reset: sim time restarts at 0, the epoch advances by the sim time reached.
  dds::ControlClient control(client, "vision-test");
  ASSERT_TRUE(control.WaitForServer(Clock::now() + kPatience));
  idl::SimControl reset;
  reset.op(idl::OP_RESET);
  clock.Poll();
  const int64_t sim_before_reset_ns = clock.sim_ns();
  const dds::ControlOutcome reply = control.Call(reset, kPatience);
  ASSERT_TRUE(reply.reply.has_value()) << reply.Describe();
  EXPECT_EQ(reply.reply->result(), idl::RESULT_OK);
  std::optional<int64_t> epoch1;
  ASSERT_TRUE(WaitFor([&] {
    run.Pump(run_rx, 5ms);
    sim_times.Pump(sim_rx, 5ms);
    late.Pump(late_rx, 5ms);
    epoch1 = clock.Poll();
    return epoch1 != epoch0 && Matched(run, sim_times, 1).size() >= 20 && Matched(late, run, 1).size() >= 20;
  })) << Matched(run, sim_times, 1).size()
      << " frames matched after the reset";
  ASSERT_TRUE(epoch1.has_value());
  EXPECT_GE(*epoch1 - *epoch0, sim_before_reset_ns);  // advanced by at least the sim time seen before
  EXPECT_GE(sim_times.went_back, 1);                  // sim seconds restart...
  EXPECT_EQ(run.went_back, 0);                        // ...run seconds never go back
  EXPECT_EQ(late.went_back, 0);
  EXPECT_EQ(run.sent_before_captured, 0);
  for (const auto& [r, s] : Matched(run, sim_times, 1)) {
    EXPECT_NEAR(r.t_capture, EpochPlus(*epoch1, s.t_capture), 1e-6);
    EXPECT_NEAR(r.t_sent, EpochPlus(*epoch1, s.t_sent), 1e-6);
  }
  for (const auto& [l, r] : Matched(late, run, 1)) EXPECT_EQ(l.t_capture, r.t_capture);
  EXPECT_EQ(run_bridge.node().Stats().rejected, 0u);
  EXPECT_EQ(late_bridge.node().Stats().rejected, 0u);
}

idl::CameraFrame Frame(uint32_t camera, int64_t capture_ns) {
  idl::CameraFrame f;
  f.camera_id(camera);
  f.frame_number(1);
  f.capture_time_ns(capture_ns);
  f.sent_time_ns(capture_ns);
  idl::DetectedRobot r;
  r.team(idl::TEAM_YELLOW);
  r.id(4);
  r.position().x(1.0);
  r.confidence(1.0f);
  f.robots().push_back(r);
  return f;
}

idl::Clock ClockWithEpoch(int64_t run_epoch_unix_ns) {
  idl::Clock c;
  c.sim_time_ns(1'000'000);
  c.run_epoch_unix_ns(run_epoch_unix_ns);
  return c;
}

TEST(VisionBridge, BadSamplesAreDroppedAndCounted) {
  const auto dds = test::UniqueDds("test");
  Receiver rx;
  OnThread<VisionBridge> bridge(std::make_unique<VisionBridge>(BridgeOptions(dds, rx.port())));
  // A rogue participant in turf-sim's place.
  dds::Participant rogue(dds);
  auto cameras = rogue.MakeWriter<idl::CameraFramePubSubType>(dds::Topic::kSslCamera);
  auto fields = rogue.MakeWriter<idl::SslFieldPubSubType>(dds::Topic::kSslField);
  auto clocks = rogue.MakeWriter<idl::ClockPubSubType>(dds::Topic::kClock);
  ASSERT_TRUE(WaitFor([&] { return cameras->Matched() > 0 && fields->Matched() > 0 && clocks->Matched() > 0; }));

  // Before any run epoch: a good frame is not sent with a made-up time, but counted.
  ASSERT_TRUE(cameras->Write(Frame(2, 1'000'000)));
  ASSERT_TRUE(WaitFor([&] { return bridge.node().Stats().no_epoch >= 1; }));
  EXPECT_EQ(bridge.node().Rejected("camera.no_epoch"), 1u);
  // A good epoch, then garbage ones: each garbage one is counted and the good one stays.
  constexpr int64_t kEpoch = 1'700'000'000'000'000'000;
  ASSERT_TRUE(clocks->Write(ClockWithEpoch(kEpoch)));
  ASSERT_TRUE(clocks->Write(ClockWithEpoch(0)));
  ASSERT_TRUE(clocks->Write(ClockWithEpoch(-3)));
  ASSERT_TRUE(clocks->Write(ClockWithEpoch(std::numeric_limits<int64_t>::max())));
  ASSERT_TRUE(WaitFor([&] { return bridge.node().Rejected("clock.bad_epoch") >= 3; }));

  idl::CameraFrame nan = Frame(0, 1'000'000);
  nan.robots()[0].position().y(NAN);
  idl::CameraFrame bad_id = Frame(0, 1'000'000);
  bad_id.robots()[0].id(200);
  idl::CameraFrame time_zero = Frame(0, 0);
  idl::SslField field;  // all zero: no field size
  field.field_length(-12.0);
  ASSERT_TRUE(cameras->Write(nan));
  ASSERT_TRUE(cameras->Write(bad_id));
  ASSERT_TRUE(cameras->Write(time_zero));
  ASSERT_TRUE(fields->Write(field));
  ASSERT_TRUE(cameras->Write(Frame(1, 2'000'000)));  // a good one still goes out

  wire::vision::SSL_WrapperPacket p;
  ASSERT_TRUE(rx.Next(&p, std::chrono::duration_cast<std::chrono::milliseconds>(kPatience)));
  ASSERT_TRUE(p.has_detection());  // no geometry: the field was refused
  EXPECT_EQ(p.detection().camera_id(), 1u);
  ASSERT_EQ(p.detection().robots_yellow_size(), 1);
  EXPECT_EQ(p.detection().robots_yellow(0).pixel_x(), 0.0f);  // no camera model without a field
  // Stamped with the good epoch: 1.7e9 s + 2 ms.
  EXPECT_NEAR(p.detection().t_capture(), 1'700'000'000.002, 1e-6);
  EXPECT_EQ(p.detection().t_sent(), p.detection().t_capture());
  ASSERT_TRUE(
      WaitFor([&] { return bridge.node().Stats().rejected >= 7 && bridge.node().Stats().detections_sent >= 1; }));
  EXPECT_EQ(bridge.node().Rejected("camera.not_finite"), 1u);
  EXPECT_EQ(bridge.node().Rejected("camera.bad_robot_id"), 1u);
  EXPECT_EQ(bridge.node().Rejected("camera.time_not_positive"), 1u);
  EXPECT_EQ(bridge.node().Rejected("field.non_positive_size"), 1u);
  EXPECT_EQ(bridge.node().Rejected("clock.bad_epoch"), 3u);
  EXPECT_EQ(bridge.node().Stats().rejected, 7u);
  EXPECT_EQ(bridge.node().Stats().no_epoch, 1u);
  EXPECT_EQ(bridge.node().Stats().detections_sent, 1u);
  EXPECT_EQ(bridge.node().Stats().geometry_sent, 0u);
}

TEST(VisionBridge, BadAddressesAreRefusedUpFront) {
  VisionBridgeOptions o;
  o.address = "not-an-address";
  EXPECT_THROW(VisionBridge{o}, std::invalid_argument);
  o.address = "127.0.0.1";
  o.tracked_address = "224.5.23";
  EXPECT_THROW(VisionBridge{o}, std::invalid_argument);
}

}  // namespace
}  // namespace turf
