// turf-vision-bridge in-process: turf-sim's node and the bridge on threads of
// their own, each test on its own DDS domain and topic prefix, sending unicast
// to a UDP port the test picked free. Assertions are on the decoded packets.
#include <gtest/gtest.h>
#include <turf/idl/SimControlPubSubTypes.h>
#include <turf/idl/SslVisionPubSubTypes.h>
#include <unistd.h>
#include "tests/test_domain.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <thread>

#include "bridges/proto/ssl_vision.pb.h"
#include "dds/participant.h"
#include "participants/common/udp.h"
#include "participants/sim/sim_node.h"
#include "participants/vision_bridge/vision_bridge.h"
#include "tests/core/test_scenes.h"

namespace turf {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

int g_test_counter = 0;

dds::ParticipantOptions UniqueDds() {
  ++g_test_counter;
  dds::ParticipantOptions o;
  o.domain = turf::test::TestDomain();
  o.prefix = "vision" + std::to_string(getpid()) + "_" + std::to_string(g_test_counter);
  o.name = "test";
  o.qos_file = TURF_SOURCE_DIR "/configs/qos/turf_qos.xml";
  return o;
}

// Runs `node.Run(stop)` on a thread until destroyed.
template <class Node>
class OnThread {
 public:
  explicit OnThread(std::unique_ptr<Node> node) : node_(std::move(node)) {
    thread_ = std::thread([this] { node_->Run([this] { return stop_.load(); }); });
  }
  ~OnThread() {
    stop_ = true;
    thread_.join();
  }
  Node& node() { return *node_; }

 private:
  std::unique_ptr<Node> node_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

std::unique_ptr<SimNode> MakeSim(const dds::ParticipantOptions& dds, Scene scene) {
  SimNodeOptions o;
  o.domain = dds.domain;
  o.prefix = dds.prefix;
  o.qos_file = dds.qos_file;
  o.mode = TimeMode::kRealtime;
  return std::make_unique<SimNode>(std::move(scene), o);
}

VisionBridgeOptions BridgeOptions(const dds::ParticipantOptions& dds, uint16_t port) {
  VisionBridgeOptions o;
  o.domain = dds.domain;
  o.prefix = dds.prefix;
  o.qos_file = dds.qos_file;
  o.address = "127.0.0.1";
  o.port = port;
  return o;
}

// A UDP port on loopback, picked free by the kernel.
class Receiver {
 public:
  Receiver() {
    std::string error;
    auto s = UdpSocket::Bind("127.0.0.1", 0, false, &error);
    EXPECT_TRUE(s.has_value()) << error;
    socket_ = std::move(*s);
  }
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

// Receives wrappers until `done` holds or the timeout; false on timeout.
bool ReceiveUntil(Receiver& rx, const std::function<bool(const wire::vision::SSL_WrapperPacket&)>& done,
                  std::chrono::milliseconds timeout = 5s) {
  const auto end = Clock::now() + timeout;
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
  c.client("vision-test");
  c.request_id(1);
  c.robot().team(team);
  c.robot().id(static_cast<uint8_t>(id));
  c.robot().on_field(true);
  c.robot().position().x(x);
  c.robot().position().y(y);
  c.robot().orientation(orientation);
  return c;
}

TEST(VisionBridge, DivisionACamerasGeometryAndATeleportedRobot) {
  const auto dds = UniqueDds();
  Receiver rx;
  VisionBridgeOptions o = BridgeOptions(dds, rx.port());
  o.geometry_every = 30;  // twice a second at 60 Hz
  OnThread<VisionBridge> bridge(std::make_unique<VisionBridge>(o));
  OnThread<SimNode> sim(MakeSim(dds, test::OneRobot()));

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
  auto control = client.MakeWriter<idl::SimControlPubSubType>(dds::Topic::kControl);
  auto replies = client.MakeReader<idl::SimControlReplyPubSubType>(dds::Topic::kControlReply);
  const auto matched_by = Clock::now() + 5s;
  while ((control->Matched() == 0 || replies->Matched() == 0) && Clock::now() < matched_by)
    std::this_thread::sleep_for(5ms);
  ASSERT_GT(control->Matched(), 0);
  ASSERT_TRUE(control->Write(Teleport(idl::TEAM_BLUE, 0, 3.0, 2.0, 1.0)));
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
  std::vector<idl::SimControlReply> got;
  replies->Take(&got);
  ASSERT_FALSE(got.empty());
  EXPECT_EQ(got.back().result(), idl::RESULT_OK);
  EXPECT_EQ(bridge.node().Stats().rejected, 0u);
  EXPECT_EQ(bridge.node().Stats().send_errors, 0u);
}

TEST(VisionBridge, SimClockAndTrackedPackets) {
  const auto dds = UniqueDds();
  Receiver rx, tracked_rx;
  VisionBridgeOptions o = BridgeOptions(dds, rx.port());
  o.clock = vision::ClockMode::kSim;
  o.tracked = true;
  o.tracked_address = "127.0.0.1";
  o.tracked_port = tracked_rx.port();
  OnThread<VisionBridge> bridge(std::make_unique<VisionBridge>(o));
  OnThread<SimNode> sim(MakeSim(dds, test::OneRobot(-2.0, -1.0, 0.5)));

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

  const auto end = Clock::now() + 5s;
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

TEST(VisionBridge, BadSamplesAreDroppedAndCounted) {
  const auto dds = UniqueDds();
  Receiver rx;
  OnThread<VisionBridge> bridge(std::make_unique<VisionBridge>(BridgeOptions(dds, rx.port())));
  // A rogue participant in turf-sim's place.
  dds::Participant rogue(dds);
  auto cameras = rogue.MakeWriter<idl::CameraFramePubSubType>(dds::Topic::kSslCamera);
  auto fields = rogue.MakeWriter<idl::SslFieldPubSubType>(dds::Topic::kSslField);
  const auto matched_by = Clock::now() + 5s;
  while ((cameras->Matched() == 0 || fields->Matched() == 0) && Clock::now() < matched_by)
    std::this_thread::sleep_for(5ms);
  ASSERT_GT(cameras->Matched(), 0);

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
  ASSERT_TRUE(rx.Next(&p, 5000ms));
  ASSERT_TRUE(p.has_detection());  // no geometry: the field was refused
  EXPECT_EQ(p.detection().camera_id(), 1u);
  ASSERT_EQ(p.detection().robots_yellow_size(), 1);
  EXPECT_EQ(p.detection().robots_yellow(0).pixel_x(), 0.0f);  // no camera model without a field
  const auto end = Clock::now() + 2s;
  while ((bridge.node().Stats().rejected < 4 || bridge.node().Stats().detections_sent < 1) && Clock::now() < end)
    std::this_thread::sleep_for(5ms);
  EXPECT_EQ(bridge.node().Rejected("camera.not_finite"), 1u);
  EXPECT_EQ(bridge.node().Rejected("camera.bad_robot_id"), 1u);
  EXPECT_EQ(bridge.node().Rejected("camera.time_not_positive"), 1u);
  EXPECT_EQ(bridge.node().Rejected("field.non_positive_size"), 1u);
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
