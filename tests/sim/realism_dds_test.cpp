// Sensor realism in turf-sim over DDS: run-time changes through the control
// topic, modelled delays visible in the frames and the statistics topic,
// command links, and reproducible sensor streams.
#include "tests/sim/sim_harness.h"

namespace turf::test {
namespace {

idl::SimControl Realism(const std::string& spec) {
  idl::SimControl c = Op(idl::OP_SET_REALISM);
  c.realism(spec);
  return c;
}

const idl::StreamStats* Stream(const idl::SensorStats& s, const std::string& name) {
  for (const auto& st : s.streams())
    if (st.name() == name) return &st;
  return nullptr;
}

TEST(RealismDds, DelaysShowInFramesAndStatistics) {
  const auto dds = UniqueDds("sim");
  SimUnderTest sim(test::OneRobot(), dds, TimeMode::kScaled, 4.0);
  Client client(dds);
  ASSERT_TRUE(client.WaitMatched());
  auto reply = client.Control(Realism("camera: {processing_delay: 0.020, link: {latency: 0.010}}"));
  ASSERT_TRUE(reply.has_value());
  ASSERT_EQ(reply->result(), idl::RESULT_OK) << reply->reason();
  const int64_t changed_at = reply->sim_time_ns();
  // Two full statistics windows after the change.
  ASSERT_TRUE(client.WaitState([&](const idl::WorldState& s) {
    client.Poll();
    return client.stats() && client.stats()->sim_time_ns() > changed_at + 2'100'000'000 && s.frame() > 0;
  }));
  const idl::StreamStats* cam = Stream(*client.stats(), "ssl/camera/0");
  ASSERT_NE(cam, nullptr);
  // Released at the first 2 ms step after capture + 30 ms.
  EXPECT_NEAR(cam->latency_mean(), 0.031, 0.0015);
  EXPECT_NEAR(cam->rate_hz(), 60.0, 1.5);
  EXPECT_EQ(cam->lost(), 0u);
  int checked = 0;
  for (const auto& f : client.frame_log()) {
    if (f.capture_time_ns() <= changed_at) continue;
    EXPECT_EQ(f.sent_time_ns() - f.capture_time_ns(), 20'000'000);
    ++checked;
  }
  EXPECT_GT(checked, 50);
}

TEST(RealismDds, CameraLossAndNoiseFollowTheSettings) {
  const auto dds = UniqueDds("sim");
  SimUnderTest sim(test::OneRobot(), dds, TimeMode::kFreeRunning);
  Client client(dds);
  ASSERT_TRUE(client.WaitMatched());
  const auto reply = client.Control(Realism("camera: {robot_position_stddev: 0.01, link: {loss: 0.25}}"));
  ASSERT_TRUE(reply);
  ASSERT_EQ(reply->result(), idl::RESULT_OK);
  // When the change took effect (the client's newest state may lag behind a
  // free-running sim on a busy machine).
  const int64_t t0 = reply->sim_time_ns();
  ASSERT_TRUE(client.WaitState([&](const idl::WorldState& s) { return s.sim_time_ns() > t0 + 60'000'000'000; }, 60s));
  client.Poll();
  // The robot stands still at the origin, seen by all four cameras.
  std::vector<double> xs;
  uint64_t frames = 0;
  for (const auto& f : client.frame_log()) {
    if (f.capture_time_ns() <= t0 + 1'000'000'000) continue;
    ++frames;
    for (const auto& r : f.robots()) xs.push_back(r.position().x());
  }
  // ~59 s x 60 Hz x 4 cameras, a quarter lost.
  const double expected = 59.0 * 60 * 4 * 0.75;
  EXPECT_NEAR(static_cast<double>(frames), expected, 0.03 * expected);
  double mean = 0, ss = 0;
  for (double x : xs) mean += x / xs.size();
  for (double x : xs) ss += (x - mean) * (x - mean);
  EXPECT_NEAR(std::sqrt(ss / (xs.size() - 1)), 0.01, 0.05 * 0.01);
}

TEST(RealismDds, CommandLinkDelaysTheRobot) {
  const auto dds = UniqueDds("sim");
  SimUnderTest sim(test::OneRobot(), dds, TimeMode::kLockstep);
  Client client(dds);
  ASSERT_TRUE(client.WaitMatched());
  ASSERT_EQ(client.Control(Realism("command: {latency: 0.100}"))->result(), idl::RESULT_OK);
  // One STEP with a command, then step on: nothing moves for 100 ms.
  idl::SimControl step = Op(idl::OP_STEP);
  step.step_count(45);  // 90 ms
  step.commands().push_back(LocalVelocity(idl::TEAM_BLUE, 0, 1.0, 0.0, 0.0));
  ASSERT_EQ(client.Control(step)->result(), idl::RESULT_OK);
  ASSERT_TRUE(client.WaitState([](const idl::WorldState& s) { return s.frame() == 45; }));
  EXPECT_EQ(FindRobot(client.state(), idl::TEAM_BLUE, 0)->linear_velocity().x(), 0.0);
  idl::SimControl more = Op(idl::OP_STEP);
  more.step_count(55);  // to 200 ms
  ASSERT_EQ(client.Control(more)->result(), idl::RESULT_OK);
  ASSERT_TRUE(client.WaitState([](const idl::WorldState& s) { return s.frame() == 100; }));
  // Accelerating at 3 m/s^2 since t = 100 ms.
  EXPECT_NEAR(FindRobot(client.state(), idl::TEAM_BLUE, 0)->linear_velocity().x(), 0.3, 0.02);
}

TEST(RealismDds, BadRealismRequestsAreRefused) {
  const auto dds = UniqueDds("sim");
  SimUnderTest sim(test::OneRobot(), dds, TimeMode::kScaled, 2.0);
  Client client(dds);
  ASSERT_TRUE(client.WaitMatched());
  for (const char* spec : {"/etc/passwd", "nosuchpreset", "camera: {robot_vanish: 2}", "camera: {bogus: 1}"}) {
    auto reply = client.Control(Realism(spec));
    ASSERT_TRUE(reply.has_value());
    EXPECT_EQ(reply->result(), idl::RESULT_REJECTED) << spec;
    EXPECT_FALSE(reply->reason().empty());
  }
  EXPECT_EQ(client.Control(Realism("harsh"))->result(), idl::RESULT_OK);
}

TEST(RealismDds, DeadlineFlagsAStalledCamera) {
  const auto dds = UniqueDds("sim");
  SimUnderTest sim(test::OneRobot(), dds, TimeMode::kRealtime);
  Client client(dds);
  ASSERT_TRUE(client.WaitMatched());
  std::this_thread::sleep_for(500ms);  // running: frames every 17 ms
  const int running_misses = client.CameraDeadlinesMissed();
  ASSERT_EQ(client.Control(Op(idl::OP_PAUSE))->result(), idl::RESULT_OK);
  std::this_thread::sleep_for(400ms);  // paused: no frames for four deadline periods
  EXPECT_GE(client.CameraDeadlinesMissed() - running_misses, 4);
}

// Same seed and lockstep commands: identical camera streams; reset replays.
std::vector<idl::CameraFrame> LockstepFrames(const Scene& scene, const char* name) {
  const auto dds = UniqueDds(name);
  SimUnderTest sim(scene, dds, TimeMode::kLockstep);
  Client client(dds);
  EXPECT_TRUE(client.WaitMatched());
  EXPECT_EQ(client.Control(Realism("realistic"))->result(), idl::RESULT_OK);
  for (int i = 0; i < 20; ++i) {
    idl::SimControl step = Op(idl::OP_STEP);
    step.step_count(25);
    step.commands().push_back(LocalVelocity(idl::TEAM_BLUE, 0, 0.5, 0.2, 1.0));
    EXPECT_EQ(client.Control(step)->result(), idl::RESULT_OK);
  }
  std::this_thread::sleep_for(300ms);
  client.Poll();
  return client.frame_log();
}

bool SameFrames(const std::vector<idl::CameraFrame>& a, const std::vector<idl::CameraFrame>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    if (a[i].camera_id() != b[i].camera_id() || a[i].capture_time_ns() != b[i].capture_time_ns() ||
        a[i].robots().size() != b[i].robots().size() || a[i].balls().size() != b[i].balls().size())
      return false;
    for (size_t j = 0; j < a[i].robots().size(); ++j)
      if (a[i].robots()[j].position().x() != b[i].robots()[j].position().x()) return false;
  }
  return true;
}

TEST(RealismDds, SameSeedSameSensorStreamOtherSeedAnother) {
  Scene scene = test::OneRobot();
  const auto a = LockstepFrames(scene, "a");
  const auto b = LockstepFrames(scene, "b");
  scene.seed = 2;
  const auto c = LockstepFrames(scene, "c");
  ASSERT_GT(a.size(), 100u);
  // Frames of different cameras may arrive interleaved differently; compare per camera.
  auto by_camera = [](std::vector<idl::CameraFrame> v) {
    std::stable_sort(v.begin(), v.end(), [](const auto& x, const auto& y) { return x.camera_id() < y.camera_id(); });
    return v;
  };
  EXPECT_TRUE(SameFrames(by_camera(a), by_camera(b)));
  EXPECT_FALSE(SameFrames(by_camera(a), by_camera(c)));
}

}  // namespace
}  // namespace turf::test
