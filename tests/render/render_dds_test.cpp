// turf-sim and turf-render as real processes on a private domain and prefix, with a ROS 2-style subscriber
// (dds::VendorParticipant, exact topic names and ROS 2's types): the images of the declared size and encoding
// arrive with camera_info; --cameras selects; a renderer that cannot keep up drops frames while turf-sim runs on.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <turf/idl/CameraControlPubSubTypes.h>
#include <turf/idl/JointsPubSubTypes.h>
#include <turf/idl/RosImagePubSubTypes.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <functional>
#include <mutex>
#include <regex>
#include <vector>

#include "codecs/image/image_codec.h"
#include "dds/camera_topics.h"
#include "dds/participant.h"
#include "dds/topics.h"
#include "dds/vendor_participant.h"
#include "participants/common/wakeup.h"
#include "participants/render/render_node.h"
#include "tests/support/process.h"
#include "tests/support/wake_wait.h"
#include "tests/test_domain.h"

namespace turf {
namespace {

namespace ros = sensor_msgs::msg::dds_;
using std::chrono::seconds;
using Clock = std::chrono::steady_clock;

const std::string kSource = TURF_SOURCE_DIR;

// A T1 standing scene with the cameras `cameras_yaml` (indented list items under `cameras:`).
std::string WriteScene(const std::string& name, const std::string& cameras_yaml) {
  const std::string path = test::LogDir() + "/" + name + "_" + std::to_string(getpid()) + ".yaml";
  std::ofstream out(path);
  out << "kind: legged\nname: render-test\nphysics: {step: 0.005}\nrates: {joint_state_hz: 200}\n"
         "robots:\n  - name: t1\n    model: "
      << kSource << "/configs/robots/t1.xml\n    z: 0.665\n    cameras:\n"
      << cameras_yaml;
  return path;
}

template <class Sample>
struct Received {
  std::mutex mutex;
  std::vector<Sample> samples;
  void Add(const Sample& s) {
    std::lock_guard<std::mutex> lock(mutex);
    samples.push_back(s);
  }
  size_t Count() {
    std::lock_guard<std::mutex> lock(mutex);
    return samples.size();
  }
  std::vector<Sample> Copy() {
    std::lock_guard<std::mutex> lock(mutex);
    return samples;
  }
};

// A reader of `topic` that keeps every sample in `into` and wakes `wait`.
template <class PubSub, class Sample>
auto Collect(dds::VendorParticipant& participant, const std::string& topic, Received<Sample>* into,
             test::WakeWait* wait) {
  return participant.MakeReader<PubSub>(topic, [into, wait](const Sample& s, int64_t) {
    into->Add(s);
    wait->Wake();
  });
}

int64_t Stamp(const std_msgs::msg::dds_::Header_& h) {
  return static_cast<int64_t>(h.stamp().sec()) * 1'000'000'000 + h.stamp().nanosec();
}

// A ROS 2-style subscriber of the images of t1's head `camera` and `chest` camera.
struct HeadAndChestImages {
  HeadAndChestImages(int domain, const std::string& head_topic, const std::string& chest_topic)
      : dds(dds::VendorOptions{domain, "render-test", "", true}),
        head_reader(Collect<ros::Image_PubSubType>(dds, head_topic, &head, &wait)),
        chest_reader(Collect<ros::Image_PubSubType>(dds, chest_topic, &chest, &wait)) {}
  dds::VendorParticipant dds;
  test::WakeWait wait;
  Received<ros::Image_> head, chest;
  std::unique_ptr<dds::VendorParticipant::RawReader> head_reader, chest_reader;
};

class RenderDds : public ::testing::Test {
 protected:
  int domain_ = test::TestDomain(16);
  std::string prefix_ = "render" + std::to_string(getpid());

  std::vector<std::string> Common() { return {"--domain", std::to_string(domain_), "--prefix", prefix_}; }
  std::string Topic(const std::string& camera, dds::CameraTopic kind) {
    return dds::CameraTopicName(prefix_, "t1", camera, kind);
  }
  test::Process Sim(const std::string& scene, std::vector<std::string> extra = {}) {
    std::vector<std::string> argv = {test::Built("participants/sim/turf-sim"), "--scene", scene};
    for (auto& a : Common()) argv.push_back(a);
    for (auto& a : extra) argv.push_back(a);
    return test::Process("render_sim", argv);
  }
  test::Process Render(const std::string& scene, std::vector<std::string> extra = {},
                       const std::string& status_every = "1") {
    std::vector<std::string> argv = {test::Built("participants/render/turf-render"), "--scene", scene, "--status-every",
                                     status_every};
    for (auto& a : Common()) argv.push_back(a);
    for (auto& a : extra) argv.push_back(a);
    return test::Process("render_render", argv);
  }
  // A scene with a head camera and a chest camera (64 x 48 at 20 Hz), and a subscriber of both.
  std::string HeadAndChestScene(const std::string& name) {
    return WriteScene(name,
                      "      - {name: camera, width: 64, height: 48, rate_hz: 20}\n"
                      "      - {name: chest, body: torso, width: 64, height: 48, rate_hz: 20}\n");
  }
  std::unique_ptr<HeadAndChestImages> SubscribeHeadAndChest() {
    return std::make_unique<HeadAndChestImages>(domain_, Topic("camera", dds::CameraTopic::kImage),
                                                Topic("chest", dds::CameraTopic::kImage));
  }
};

TEST_F(RenderDds, ImagesOfTheDeclaredSizeAndEncodingArriveWithCameraInfo) {
  const std::string scene =
      WriteScene("render_sizes",
                 "      - {name: camera, width: 160, height: 120, rate_hz: 20}\n"
                 "      - {name: chest, body: torso, pos: [0.1, 0, 0], xyaxes: [0, -1, 0, 0, 0, 1], width: 64, "
                 "height: 48, hfov_deg: 90, rate_hz: 10, encoding: yuv422}\n"
                 "      - {name: back, body: torso, pos: [-0.1, 0, 0], xyaxes: [0, 1, 0, 0, 0, 1], width: 64, "
                 "height: 48, rate_hz: 10, encoding: jpeg}\n");
  dds::VendorParticipant dds(dds::VendorOptions{domain_, "render-test", "", true});
  test::WakeWait wait;
  Received<ros::Image_> head, chest;
  Received<ros::CompressedImage_> back;
  Received<ros::CameraInfo_> info;
  auto r1 = Collect<ros::Image_PubSubType>(dds, Topic("camera", dds::CameraTopic::kImage), &head, &wait);
  auto r2 = Collect<ros::Image_PubSubType>(dds, Topic("chest", dds::CameraTopic::kImage), &chest, &wait);
  auto r3 = Collect<ros::CompressedImage_PubSubType>(dds, Topic("back", dds::CameraTopic::kCompressed), &back, &wait);
  auto r4 = Collect<ros::CameraInfo_PubSubType>(dds, Topic("camera", dds::CameraTopic::kCameraInfo), &info, &wait);
  test::Process render = Render(scene);
  test::Process sim = Sim(scene);
  ASSERT_TRUE(
      wait.Until(Clock::now() + seconds(60),
                 [&] { return head.Count() >= 3 && chest.Count() >= 2 && back.Count() >= 2 && info.Count() >= 3; }))
      << "head " << head.Count() << ", chest " << chest.Count() << ", back " << back.Count() << "\n"
      << render.Log();
  for (const ros::Image_& img : head.Copy()) {
    EXPECT_EQ(img.width(), 160u);
    EXPECT_EQ(img.height(), 120u);
    EXPECT_EQ(img.encoding(), "rgb8");
    EXPECT_EQ(img.step(), 480u);
    EXPECT_EQ(img.data().size(), 160u * 120u * 3u);
    EXPECT_EQ(img.header().frame_id(), "t1/camera");
    EXPECT_EQ(Stamp(img.header()) % 5'000'000, 0) << "a state's time: a multiple of the 5 ms step";
  }
  const auto heads = head.Copy();
  for (size_t i = 1; i < heads.size(); ++i) EXPECT_GT(Stamp(heads[i].header()), Stamp(heads[i - 1].header()));
  for (const ros::Image_& img : chest.Copy()) {
    EXPECT_EQ(img.encoding(), "yuv422_yuy2");
    EXPECT_EQ(img.step(), 128u);
    EXPECT_EQ(img.data().size(), 64u * 48u * 2u);
  }
  for (const ros::CompressedImage_& img : back.Copy()) {
    EXPECT_EQ(img.format(), "jpeg");
    int w = 0, h = 0;
    EXPECT_EQ(image::DecodeJpeg(img.data(), 64 * 48, &w, &h).error, Error::kOk);
    EXPECT_EQ(w, 64);
    EXPECT_EQ(h, 48);
  }
  const ros::CameraInfo_ k = info.Copy().front();
  EXPECT_EQ(k.width(), 160u);
  EXPECT_EQ(k.distortion_model(), "plumb_bob");
  EXPECT_DOUBLE_EQ(k.k()[2], 79.5);
  EXPECT_DOUBLE_EQ(k.k()[0], k.k()[4]);
  EXPECT_DOUBLE_EQ(k.k()[8], 1.0);
  EXPECT_EQ(sim.Stop(), 0);
  EXPECT_EQ(render.Stop(), 0);
}

TEST_F(RenderDds, CamerasSelectsWhichOnesThisRendererDraws) {
  const std::string scene = HeadAndChestScene("render_select");
  const auto cams = SubscribeHeadAndChest();
  test::Process render = Render(scene, {"--cameras", "t1/chest"});
  test::Process sim = Sim(scene);
  ASSERT_TRUE(cams->wait.Until(Clock::now() + seconds(60), [&] { return cams->chest.Count() >= 5; })) << render.Log();
  EXPECT_EQ(cams->head.Count(), 0u);
  EXPECT_EQ(sim.Stop(), 0);
  EXPECT_EQ(render.Stop(), 0);
  // An unknown camera is a configuration error that names the scene's cameras.
  test::Process bad = Render(scene, {"--cameras", "t1/eye"});
  const auto status = bad.Wait(std::chrono::milliseconds(30000));
  ASSERT_TRUE(status);
  EXPECT_EQ(WEXITSTATUS(*status), 2);
  EXPECT_NE(bad.Log().find("t1/camera, t1/chest"), std::string::npos) << bad.Log();
}

// A camera far beyond what the renderer can draw (640x480 at 1000 Hz of sim time) while turf-sim runs as fast as
// it can for 200 s of sim time: turf-sim reaches its duration and exits by itself; the images that arrive are a
// sparse subset of the due frames (stamps further apart than the camera's period), so frames were dropped, not
// waited for. (No wall-clock assertion: the speed comparison is in bench/.) 200 s, not less: one T1 steps 20 s of
// sim time in a few tenths of a second, in which a renderer on a loaded machine drew fewer than the two images
// the span needs (a full run of the suite found it).
TEST_F(RenderDds, ARendererThatFallsBehindDropsFramesAndNeverHoldsThePhysics) {
  const std::string scene =
      WriteScene("render_behind", "      - {name: camera, width: 640, height: 480, rate_hz: 1000}\n");
  dds::VendorParticipant dds(dds::VendorOptions{domain_, "render-test", "", true});
  test::WakeWait wait;
  Received<ros::Image_> head;
  auto r1 = Collect<ros::Image_PubSubType>(dds, Topic("camera", dds::CameraTopic::kImage), &head, &wait);
  test::Process render = Render(scene);
  // The renderer is up (its image writer matched this reader) before turf-sim starts. Discovery wakes nothing
  // here: look every 100 ms until the deadline.
  const auto ready_by = Clock::now() + seconds(30);
  while (r1->Matched() < 1 && Clock::now() < ready_by) {
    Wakeup idle;
    idle.WaitFor(std::chrono::milliseconds(100));
  }
  ASSERT_GE(r1->Matched(), 1) << render.Log();
  test::Process sim = Sim(scene, {"--speed", "max", "--duration", "200"});
  const auto status = sim.Wait(std::chrono::milliseconds(300000));
  ASSERT_TRUE(status) << "turf-sim did not reach 200 s of sim time";
  EXPECT_TRUE(WIFEXITED(*status) && WEXITSTATUS(*status) == 0);
  ASSERT_TRUE(wait.Until(Clock::now() + seconds(20), [&] { return head.Count() >= 2; })) << render.Log();
  const auto images = head.Copy();
  const int64_t span = Stamp(images.back().header()) - Stamp(images.front().header());
  const int64_t due = span / 1'000'000;  // frames due at 1000 Hz over that span
  EXPECT_LT(static_cast<int64_t>(images.size()) * 4, due) << images.size() << " images over " << span << " ns";
  EXPECT_EQ(render.Stop(), 0);
  // Its last status line counts more frames dropped than rendered.
  const std::string log = render.Log();
  const std::regex status_line(R"(status: (\d+) frames rendered, (\d+) dropped)");
  std::string last;
  for (auto it = std::sregex_iterator(log.begin(), log.end(), status_line); it != std::sregex_iterator(); ++it)
    last = it->str();
  std::smatch m;
  ASSERT_TRUE(std::regex_search(last, m, status_line)) << log;
  EXPECT_GT(std::stoull(m[2]), std::stoull(m[1])) << last;
}

// Untrusted input: a robots/state sample with a NaN pose is refused whole (nothing drawn from it, counted), and the
// renderer goes on with the next good state. The states come from this test, not from turf-sim.
TEST_F(RenderDds, AStateWithANanPoseIsRefusedAndTheNextOneRendered) {
  const std::string scene = WriteScene("render_nan", "      - {name: camera, width: 64, height: 48, rate_hz: 10}\n");
  dds::VendorParticipant images(dds::VendorOptions{domain_, "render-test", "", true});
  test::WakeWait wait;
  Received<ros::Image_> head;
  auto r1 = Collect<ros::Image_PubSubType>(images, Topic("camera", dds::CameraTopic::kImage), &head, &wait);
  dds::ParticipantOptions o;
  o.domain = domain_;
  o.prefix = prefix_;
  o.name = "render-test-states";
  o.qos_file = dds::DefaultQosFile();
  dds::Participant turf(o);
  auto states = turf.MakeWriter(dds::Topic::kRobotsState);
  test::Process render = Render(scene, {}, "0.1");
  const auto ready_by = Clock::now() + seconds(30);
  while ((states->Matched() < 1 || r1->Matched() < 1) && Clock::now() < ready_by) {
    Wakeup idle;
    idle.WaitFor(std::chrono::milliseconds(100));
  }
  ASSERT_GE(states->Matched(), 1) << render.Log();
  auto state = [](int64_t t_ns, double x) {
    idl::LeggedState s;
    s.sim_time_ns(t_ns);
    idl::LinkState robot;
    robot.robot("t1");
    idl::LinkPose head;
    head.name("H2");
    head.position().x(x);
    head.position().z(1.0);
    head.orientation().w(1.0);
    robot.links().push_back(head);
    s.links().push_back(robot);
    return s;
  };
  // robots/state and the images are best effort and the renderer's writer may match this reader after its first
  // image, so each step writes its state again (one frame period of sim time later) until its outcome shows: an
  // image, or the refusal in the status line (every 0.1 s; nothing else tells).
  const int64_t period = 100'000'000;
  int64_t t = 0;
  auto write_until = [&](double x, const std::function<bool()>& done) {
    const auto by = Clock::now() + seconds(30);
    while (!done() && Clock::now() < by) {
      if (!states->Write(state(t, x))) return false;
      t += period;
      wait.Until(Clock::now() + std::chrono::milliseconds(300), done);
    }
    return done();
  };
  ASSERT_TRUE(write_until(0.0, [&] { return head.Count() >= 1; })) << render.Log();
  const int64_t nan_from = t;
  const std::regex refused(R"(superseded, [1-9]\d* refused)");
  ASSERT_TRUE(write_until(std::nan(""), [&] { return std::regex_search(render.Log(), refused); })) << render.Log();
  const int64_t good_from = t;
  const size_t before = head.Count();
  ASSERT_TRUE(write_until(0.5, [&] { return head.Count() > before; })) << render.Log();
  for (const auto& image : head.Copy()) {
    const int64_t stamp = Stamp(image.header());
    EXPECT_TRUE(stamp < nan_from || stamp >= good_from) << "an image from a NaN state at " << stamp << " ns";
    EXPECT_EQ(stamp % period, 0) << stamp;
  }
  EXPECT_EQ(render.Stop(), 0);
}

// --cameras off: the renderer takes states and draws nothing (its status line: states taken, 0 frames, 0 cameras
// on) until a control sample on cameras/control switches a camera on at a rate (here from `turf-render --switch`);
// then that camera's images come at that rate of sim time. A control sample with a NaN rate (from this test's own
// writer) is refused (logged, counted), and off stops it again.
TEST_F(RenderDds, CamerasOffUntilAControlSampleSwitchesOneOn) {
  const std::string scene = HeadAndChestScene("render_switch");
  const auto cams = SubscribeHeadAndChest();
  auto control = cams->dds.MakeWriter<idl::CameraControlPubSubType>(dds::CameraControlTopicName(prefix_));
  test::Process render = Render(scene, {"--cameras", "off"}, "0.2");
  test::Process sim = Sim(scene);
  // Looks every 100 ms (a log line or a refusal wakes nothing) until `check` or 30 s.
  auto poll = [](const std::function<bool()>& check) {
    const auto by = Clock::now() + seconds(30);
    while (!check() && Clock::now() < by) {
      Wakeup idle;
      idle.WaitFor(std::chrono::milliseconds(100));
    }
    return check();
  };
  auto log_has = [&](const std::string& text) {
    return poll([&] { return render.Log().find(text) != std::string::npos; });
  };
  // States are taken and discarded: a status line with states and no frame.
  const std::regex idle_line(
      R"(status: 0 frames rendered, 0 dropped \(.*\), [1-9]\d* states taken .* 0 camera\(s\) on)");
  ASSERT_TRUE(poll([&] { return std::regex_search(render.Log(), idle_line); })) << render.Log();
  EXPECT_EQ(cams->head.Count() + cams->chest.Count(), 0u);
  auto send = [&control](bool on, double rate) {
    idl::CameraControl c;
    c.robot("t1");
    c.camera("chest");
    c.enabled(on);
    c.rate_hz(rate);
    c.source("render-test");
    return control->Write(c);
  };
  // Best effort and discovery: sent until it took effect, as the bridge re-sends.
  ASSERT_TRUE(poll([&] {
    send(true, std::nan(""));
    return render.Log().find("refused (1 so far)") != std::string::npos;
  })) << render.Log();
  // The command line's switch (turf-render --switch) writes the same samples.
  auto cli_switch = [&](const std::string& state) {
    std::vector<std::string> argv = {test::Built("participants/render/turf-render"), "--switch", "t1/chest=" + state};
    for (auto& a : Common()) argv.push_back(a);
    test::Process p("render_switch", argv);
    const auto status = p.Wait(std::chrono::milliseconds(30000));
    return status && WIFEXITED(*status) && WEXITSTATUS(*status) == 0;
  };
  // Its samples are best effort, sent once its writer has matched the renderer's reader, which may not have matched
  // the writer yet (discovery is not symmetric in time): run it again until the renderer says it took effect.
  auto switched = [&](const std::string& state, const std::string& line) {
    for (int attempt = 0; attempt < 5; ++attempt) {
      if (!cli_switch(state)) return false;
      if (log_has(line)) return true;
    }
    return false;
  };
  ASSERT_TRUE(switched("on@5", "camera t1/chest on at 5 Hz of sim time (asked by 'turf-render --switch')"))
      << render.Log();
  ASSERT_TRUE(cams->wait.Until(Clock::now() + seconds(60), [&] { return cams->chest.Count() >= 3; })) << render.Log();
  EXPECT_EQ(cams->head.Count(), 0u);
  const auto images = cams->chest.Copy();
  for (size_t i = 1; i < images.size(); ++i)
    EXPECT_GT(Stamp(images[i].header()) - Stamp(images[i - 1].header()), 150'000'000) << "5 Hz of sim time, not 20";
  EXPECT_TRUE(switched("off", "camera t1/chest off (asked by 'turf-render --switch')")) << render.Log();
  EXPECT_EQ(sim.Stop(), 0);
  EXPECT_EQ(render.Stop(), 0);
}

TEST(SelectCameras, AllEnabledByDefaultOrTheNamedOnes) {
  CameraSpec a, b, c;
  a.robot = b.robot = c.robot = "t1";
  a.name = "a";
  b.name = "b";
  c.name = "c";
  c.enabled = false;
  EXPECT_EQ(SelectCameras({a, b, c}, {}).size(), 2u);
  const auto only = SelectCameras({a, b, c}, {"t1/c"});
  ASSERT_EQ(only.size(), 1u);
  EXPECT_EQ(only[0].name, "c");
  EXPECT_THROW(SelectCameras({a, b, c}, {"t1/x"}), std::invalid_argument);
}

}  // namespace
}  // namespace turf
