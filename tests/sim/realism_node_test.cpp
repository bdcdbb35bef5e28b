// Sensor realism in turf-sim's node: run-time changes through the control topic, modelled delays visible in the
// frames and the statistics topic, command links, and reproducible sensor streams. On a MemoryBus; the delays also
// over DDS, and the cameras' DDS deadline over DDS alone.
#include <cmath>

#include "tests/sim/sim_harness.h"

namespace turf::test {
namespace {

idl::RealismValue Value(idl::RealismParameter parameter, double value) {
  idl::RealismValue v;
  v.parameter(parameter);
  v.value(value);
  return v;
}

// OP_SET_REALISM: typed values, applied after the preset if one is named.
idl::SimControl Realism(std::vector<idl::RealismValue> values, const std::string& preset = "") {
  idl::SimControl c = Op(idl::OP_SET_REALISM);
  c.realism_preset(preset);
  c.realism_values(std::move(values));
  return c;
}

idl::SimControl Preset(const std::string& name) { return Realism({}, name); }

class RealismNode : public ::testing::TestWithParam<Transport> {};
INSTANTIATE_TEST_SUITE_P(On, RealismNode, ::testing::Values(Transport::kMemory), TransportName);
class RealismNodeAnyTransport : public RealismNode {};
INSTANTIATE_TEST_SUITE_P(On, RealismNodeAnyTransport, ::testing::Values(Transport::kMemory, Transport::kDds),
                         TransportName);

const idl::StreamStats* Stream(const idl::SensorStats& s, const std::string& name) {
  for (const auto& st : s.streams())
    if (st.name() == name) return &st;
  return nullptr;
}

TEST_P(RealismNodeAnyTransport, DelaysShowInFramesAndStatistics) {
  const TestTransport dds(GetParam());
  SimUnderTest sim(test::OneRobot(), dds, TimeMode::kScaled, 4.0);
  Client client(dds);
  ASSERT_TRUE(client.WaitMatched());
  auto reply = client.Control(
      Realism({Value(idl::REALISM_CAMERA_PROCESSING_DELAY, 0.020), Value(idl::REALISM_CAMERA_LINK_LATENCY, 0.010)}));
  ASSERT_TRUE(reply.has_value());
  ASSERT_EQ(reply->result(), idl::RESULT_OK) << reply->reason();
  const int64_t changed_at = reply->sim_time_ns();
  // Two full statistics windows after the change.
  ASSERT_TRUE(client.WaitState(
      [&](const idl::WorldState& s) {
        return client.stats() && client.stats()->sim_time_ns() > changed_at + 2'100'000'000 && s.frame() > 0;
      },
      15s));
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

// Steps lockstep in chunks of `steps` until a reply says `until_ns`, each
// chunk's camera frames received before the next chunk is asked for. turf-sim's
// one reliable camera writer delivers in the order it wrote, so once a frame of
// chunk k is in, all of chunk k-1's are, and the topic's history (16 frames a
// camera) never overflows.
::testing::AssertionResult StepReceivingEveryFrame(Client& client, uint32_t steps, int64_t until_ns) {
  int64_t chunk_start = -1;
  while (chunk_start < until_ns) {
    idl::SimControl step = Op(idl::OP_STEP);
    step.step_count(steps);
    const auto reply = client.Control(step);
    if (!Ok(reply)) return Ok(reply);
    const bool in = client.WaitFor([&] {
      for (auto it = client.frame_log().rbegin(); it != client.frame_log().rend(); ++it)
        if (it->capture_time_ns() > chunk_start) return true;
      return false;
    });
    if (!in) return ::testing::AssertionFailure() << "no camera frame captured after t=" << chunk_start << " ns";
    chunk_start = reply->sim_time_ns();
  }
  return ::testing::AssertionSuccess();
}

TEST_P(RealismNode, CameraLossAndNoiseFollowTheSettings) {
  const TestTransport dds(GetParam());
  // Lockstep, so that no frame is lost on the way to this client (a free-running
  // sim outruns the camera topic's history when the client is slow).
  SimUnderTest sim(test::OneRobot(), dds, TimeMode::kLockstep);
  Client client(dds);
  ASSERT_TRUE(client.WaitMatched(Client::kNoState));  // lockstep: no state before the first step
  const auto reply = client.Control(
      Realism({Value(idl::REALISM_CAMERA_ROBOT_POSITION_STDDEV, 0.01), Value(idl::REALISM_CAMERA_LINK_LOSS, 0.25)}));
  ASSERT_TRUE(Ok(reply));
  const int64_t t0 = reply->sim_time_ns();
  // 60 s in 100 ms chunks (six frames a camera), one more so every frame up to 60 s is in.
  ASSERT_TRUE(StepReceivingEveryFrame(client, 50, t0 + 60'100'000'000));
  // The robot stands still at the origin, seen by all four cameras.
  std::vector<double> xs;
  uint64_t frames = 0;
  for (const auto& f : client.frame_log()) {
    if (f.capture_time_ns() <= t0 + 1'000'000'000 || f.capture_time_ns() > t0 + 60'000'000'000) continue;
    ++frames;
    for (const auto& r : f.robots()) xs.push_back(r.position().x());
  }
  // 59 s x 60 Hz x 4 cameras, a quarter lost.
  const double expected = 59.0 * 60 * 4 * 0.75;
  EXPECT_NEAR(static_cast<double>(frames), expected, 0.03 * expected);
  double mean = 0, ss = 0;
  for (double x : xs) mean += x / xs.size();
  for (double x : xs) ss += (x - mean) * (x - mean);
  EXPECT_NEAR(std::sqrt(ss / (xs.size() - 1)), 0.01, 0.05 * 0.01);
}

TEST_P(RealismNode, CommandLinkDelaysTheRobot) {
  const TestTransport dds(GetParam());
  SimUnderTest sim(test::OneRobot(), dds, TimeMode::kLockstep);
  Client client(dds);
  ASSERT_TRUE(client.WaitMatched(Client::kNoState));  // lockstep: no state before the first step
  ASSERT_TRUE(Ok(client.Control(Realism({Value(idl::REALISM_COMMAND_LATENCY, 0.100)}))));
  // One STEP with a command, then step on: nothing moves for 100 ms.
  idl::SimControl step = Op(idl::OP_STEP);
  step.step_count(45);  // 90 ms
  step.commands().push_back(LocalVelocity(idl::TEAM_BLUE, 0, 1.0, 0.0, 0.0));
  ASSERT_TRUE(Ok(client.Control(step)));
  ASSERT_TRUE(client.WaitState([](const idl::WorldState& s) { return s.frame() == 45; }));
  const idl::RobotState* r = FindRobot(client.state(), idl::TEAM_BLUE, 0);
  ASSERT_NE(r, nullptr);
  EXPECT_EQ(r->linear_velocity().x(), 0.0);
  idl::SimControl more = Op(idl::OP_STEP);
  more.step_count(55);  // to 200 ms
  ASSERT_TRUE(Ok(client.Control(more)));
  ASSERT_TRUE(client.WaitState([](const idl::WorldState& s) { return s.frame() == 100; }));
  // Accelerating at 3 m/s^2 since t = 100 ms.
  r = FindRobot(client.state(), idl::TEAM_BLUE, 0);
  ASSERT_NE(r, nullptr);
  EXPECT_NEAR(r->linear_velocity().x(), 0.3, 0.02);
}

TEST_P(RealismNode, BadRealismRequestsAreRefused) {
  const TestTransport dds(GetParam());
  SimUnderTest sim(test::OneRobot(), dds, TimeMode::kScaled, 2.0);
  Client client(dds);
  ASSERT_TRUE(client.WaitMatched());
  struct Bad {
    idl::SimControl request;
    idl::ControlError error;
    const char* reason;  // part of the reply's reason
  };
  const Bad bad[] = {
      {Preset("/etc/passwd"), idl::CONTROL_UNKNOWN_PRESET, "/etc/passwd"},
      {Preset("nosuchpreset"), idl::CONTROL_UNKNOWN_PRESET, "nosuchpreset"},
      {Preset("camera: {robot_vanish: 1}"), idl::CONTROL_UNKNOWN_PRESET, "camera"},
      {Realism({Value(idl::REALISM_CAMERA_ROBOT_VANISH, 2.0)}), idl::CONTROL_OUT_OF_RANGE, "camera.robot_vanish"},
      {Realism({Value(idl::REALISM_COMMAND_LOSS, 0.1), Value(idl::REALISM_CAMERA_LINK_LATENCY, NAN)}),
       idl::CONTROL_NOT_FINITE, "camera.link.latency"},
      {Realism({Value(static_cast<idl::RealismParameter>(999), 0.0)}), idl::CONTROL_UNKNOWN_ENUM, "999"},
      {Realism({Value(idl::REALISM_COMMAND_JITTER_KIND, 7)}), idl::CONTROL_UNKNOWN_ENUM, "command.jitter_kind"},
      {Realism({Value(idl::REALISM_COMMAND_BURST_P_BAD_TO_GOOD, 0.0), Value(idl::REALISM_COMMAND_BURST_ENABLED, 1)}),
       idl::CONTROL_INVALID_REALISM, "p_bad_to_good"},
  };
  for (const Bad& b : bad) {
    auto reply = client.Control(b.request);
    ASSERT_TRUE(reply.has_value());
    EXPECT_EQ(reply->result(), idl::RESULT_REJECTED) << b.reason;
    EXPECT_EQ(reply->error(), b.error) << reply->reason();
    EXPECT_NE(reply->reason().find(b.reason), std::string::npos) << reply->reason();
  }
  EXPECT_TRUE(Ok(client.Control(Preset("harsh"))));
  EXPECT_TRUE(Ok(client.Control(Realism({Value(idl::REALISM_CAMERA_LINK_LOSS, 0.0)}, "realistic"))));
}

TEST(RealismNodeDds, DeadlineFlagsAStalledCamera) {
  const auto dds = UniqueDds("sim");
  SimUnderTest sim(test::OneRobot(), dds, TimeMode::kRealtime);
  Client client(dds);
  ASSERT_TRUE(client.WaitMatched());
  // Running: frames from every camera (each camera's deadline is armed).
  std::map<uint32_t, int> per_camera;
  ASSERT_TRUE(client.WaitFor([&] {
    per_camera.clear();
    for (const auto& f : client.frame_log()) ++per_camera[f.camera_id()];
    if (per_camera.size() != 4) return false;
    for (const auto& [id, n] : per_camera)
      if (n < 3) return false;
    return true;
  }));
  const int running_misses = client.CameraDeadlinesMissed();
  const auto pause = client.Control(Op(idl::OP_PAUSE));
  ASSERT_TRUE(Ok(pause));
  // Paused: the stalled cameras are reported, four deadline periods' worth...
  EXPECT_TRUE(client.WaitFor([&] { return client.CameraDeadlinesMissed() - running_misses >= 4; }));
  // ...and no frame captured after the pause arrived meanwhile.
  for (const auto& f : client.frame_log()) EXPECT_LE(f.capture_time_ns(), pause->sim_time_ns());
}

// Same seed and lockstep commands: identical camera streams; reset replays.
std::vector<idl::CameraFrame> LockstepFrames(Transport transport, const Scene& scene, const char* name) {
  const TestTransport dds(transport, name);
  SimUnderTest sim(scene, dds, TimeMode::kLockstep);
  Client client(dds);
  EXPECT_TRUE(client.WaitMatched(Client::kNoState));
  EXPECT_TRUE(Ok(client.Control(Preset("realistic"))));
  for (int i = 0; i < 20; ++i) {
    idl::SimControl step = Op(idl::OP_STEP);
    step.step_count(25);
    step.commands().push_back(LocalVelocity(idl::TEAM_BLUE, 0, 0.5, 0.2, 1.0));
    EXPECT_TRUE(Ok(client.Control(step)));
  }
  // The frames captured in that first second: all are in once one captured
  // 0.4 s later (far beyond the preset's ~12 ms of delay) is, as each
  // camera's frames arrive in the order they were sent.
  constexpr int64_t kCutoff = 1'000'000'000;
  EXPECT_TRUE(StepReceivingEveryFrame(client, 25, kCutoff + 400'000'000));
  std::vector<idl::CameraFrame> frames;
  for (const auto& f : client.frame_log())
    if (f.capture_time_ns() <= kCutoff) frames.push_back(f);
  return frames;
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

TEST_P(RealismNode, SameSeedSameSensorStreamOtherSeedAnother) {
  Scene scene = test::OneRobot();
  const auto a = LockstepFrames(GetParam(), scene, "a");
  const auto b = LockstepFrames(GetParam(), scene, "b");
  scene.seed = 2;
  const auto c = LockstepFrames(GetParam(), scene, "c");
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
