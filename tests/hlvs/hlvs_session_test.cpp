// The HLVS session: sensor time steps (periods, first report, the reference's warnings), the robot table, Webots
// motor semantics as turf joint commands, the rendering and network quotas, and cameras without an image source.
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "codecs/hlvs/session.h"

namespace turf::hlvs {
namespace {

class HlvsSessionTest : public ::testing::Test {
 protected:
  HlvsSessionTest() {
    options_.robot = "red_1";
    options_.model = FindModel("K1");
    reading_.position.assign(options_.model->motors.size(), 0.0);
    reading_.touch.resize(options_.model->touch.size());
    reading_.touch[0].force = 42;
  }
  static ActuatorRequests Steps(std::vector<NamedStep> steps) {
    ActuatorRequests r;
    r.sensor_time_steps = std::move(steps);
    return r;
  }

  SessionOptions options_;
  RobotReading reading_;
};

TEST(HlvsRobots, EveryMotorNameIsUniqueAndTheSampleNamesExist) {
  for (const RobotModel& m : Models()) {
    std::set<std::string> names, joints;
    for (const MotorEntry& e : m.motors) {
      EXPECT_TRUE(names.insert(e.motor).second) << m.name << " " << e.motor;
      EXPECT_TRUE(joints.insert(e.joint).second) << m.name << " " << e.joint;
    }
    for (const char* sample : {"Neck", "Head", "ShoulderR", "LegLowerL", "FootR"})
      EXPECT_TRUE(names.count(sample)) << m.name << " " << sample;
  }
  EXPECT_EQ(FindModel("K1")->motors.size(), 22u);
  EXPECT_EQ(FindModel("T1")->motors.size(), 23u);
  EXPECT_EQ(FindModel("NAO"), nullptr);
}

std::string ReadFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Every joint, touch sensor and camera the tables name is in the robot file.
TEST(HlvsRobots, EveryDeviceExistsInTheRobotFile) {
  for (const RobotModel& m : Models()) {
    std::string lower = m.name;
    for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    const std::string xml = ReadFile(std::string(TURF_SOURCE_DIR) + "/configs/robots/" + lower + ".xml");
    ASSERT_FALSE(xml.empty()) << lower;
    for (const MotorEntry& e : m.motors)
      EXPECT_NE(xml.find("<joint name=\"" + std::string(e.joint) + "\""), std::string::npos)
          << m.name << " " << e.joint;
    for (const TouchEntry& t : m.touch)
      EXPECT_NE(xml.find("<touch name=\"" + std::string(t.sensor) + "\""), std::string::npos)
          << m.name << " " << t.sensor;
    for (const CameraEntry& c : m.cameras)
      EXPECT_NE(xml.find("<camera name=\"" + std::string(c.mjcf) + "\""), std::string::npos) << m.name << " " << c.mjcf;
  }
}

// The README's motor table is this table: one row per motor, K1 and T1 joints side by side.
TEST(HlvsRobots, TheReadmeTableIsTheCodeTable) {
  const std::string readme = ReadFile(TURF_SOURCE_DIR "/README.md");
  const RobotModel& k1 = *FindModel("K1");
  const RobotModel& t1 = *FindModel("T1");
  for (const MotorEntry& t : t1.motors) {
    std::string k1_joint = "—";
    for (const MotorEntry& k : k1.motors)
      if (std::string(k.motor) == t.motor) k1_joint = "`" + std::string(k.joint) + "`";
    const std::string row = "| `" + std::string(t.motor) + "` | " + k1_joint + " | `" + t.joint + "` |";
    EXPECT_NE(readme.find(row), std::string::npos) << "README lacks: " << row;
  }
  for (const MotorEntry& k : k1.motors) {
    bool in_t1 = false;
    for (const MotorEntry& t : t1.motors) in_t1 = in_t1 || std::string(k.motor) == t.motor;
    EXPECT_TRUE(in_t1) << k.motor << ": the README table lists the T1's motors";
  }
}

TEST_F(HlvsSessionTest, SensorsComeOnlyAtTheirPeriodFirstOnePeriodAfterEnabling) {
  Session s(options_);
  EXPECT_TRUE(s.Measure(reading_, 8, 1).position_sensors.empty());  // nothing before the client enables
  s.Apply(Steps({{"NeckS", 8}, {"Gyro", 24}, {"lf", 16}}), 16);
  std::vector<uint32_t> neck, gyro, force;
  for (uint32_t t = 16; t <= 80; t += kBasicStepMs) {
    const SensorMeasurements m = s.Measure(reading_, t, 1);
    if (!m.position_sensors.empty()) neck.push_back(t);
    if (!m.gyros.empty()) gyro.push_back(t);
    if (!m.forces.empty()) {
      force.push_back(t);
      EXPECT_EQ(m.forces[0].value, 42);
    }
  }
  EXPECT_EQ(neck, (std::vector<uint32_t>{24, 32, 40, 48, 56, 64, 72, 80}));
  EXPECT_EQ(gyro, (std::vector<uint32_t>{40, 64}));
  EXPECT_EQ(force, (std::vector<uint32_t>{32, 48, 64, 80}));
  s.Apply(Steps({{"Gyro", 0}}), 80);
  EXPECT_EQ(s.SensorPeriods().count("Gyro"), 0u);
}

TEST_F(HlvsSessionTest, AnswersWithTheReferenceWarnings) {
  Session s(options_);
  ActuatorRequests r = Steps({{"Nose", 8}, {"Neck", 8}, {"Camera", 10}, {"NeckS", 20}});
  r.positions.push_back({"Tail", 1});
  r.camera_qualities.push_back({"Camera", 50});
  s.Apply(r, 8);
  const SensorMeasurements m = s.Measure(reading_, 8, 1);
  std::vector<std::string> texts;
  for (const TextMessage& t : m.messages) texts.push_back(t.text);
  EXPECT_EQ(texts, (std::vector<std::string>{
                       "Motor \"Tail\" not found, position command ignored.",
                       "CameraQuality is not yet implemented, ignored.",
                       "Device \"Nose\" not found, time step command, ignored.",
                       "Device \"Neck\" is not supported, time step command, ignored.",
                       "Time step for \"Camera\" should be greater or equal to 16, ignoring 10 value.",
                       "Time step for \"NeckS\" should be a multiple of 8, ignoring 20 value.",
                   }));
  EXPECT_TRUE(s.Measure(reading_, 16, 1).messages.empty());  // sent once
}

TEST_F(HlvsSessionTest, RenderingQuotaRefusesTooMuch) {
  options_.team_players = 4;
  Session s(options_);
  s.Apply(Steps({{"Camera", 16}}), 8);  // 320 x 240 at 16 ms: 13.7 MB/s, within 87.5
  EXPECT_EQ(s.SensorPeriods().at("Camera"), 16u);
  options_.team_players = 40;  // 8.75 MB/s each
  Session tight(options_);
  tight.Apply(Steps({{"Camera", 16}}), 8);
  const SensorMeasurements m = tight.Measure(reading_, 8, 1);
  ASSERT_EQ(m.messages.size(), 1u);
  EXPECT_EQ(m.messages[0].text, "requested rendering bandwidth is above the limit (14MB/s > 9MB/s)");
  EXPECT_EQ(tight.SensorPeriods().count("Camera"), 0u);
}

class FixedCamera : public CameraSource {
 public:
  std::optional<CameraImage> Take(const CameraRequest& r) override {
    last = r;
    CameraImage i;
    i.width = r.width;
    i.height = r.height;
    i.image.assign(size_t{r.width} * r.height * 3, 'x');
    return i;
  }
  void Enable(const std::string& robot, const std::string& camera, uint32_t period_ms) override {
    enables.push_back(robot + "/" + camera + "@" + std::to_string(period_ms));
  }
  CameraRequest last;
  std::vector<std::string> enables;
};

TEST_F(HlvsSessionTest, TheImageSourceHearsEachCameraPeriodChangeOnce) {
  FixedCamera source;
  options_.cameras = &source;
  Session s(options_);
  const std::vector<std::pair<uint32_t, uint32_t>> steps = {{16, 8},  {16, 16},  // the same again: nothing changes
                                                            {12, 24},  // refused (not a multiple of 8): nothing changes
                                                            {32, 32}, {0, 40},  {0, 48}};  // already off
  for (const auto& [period, t] : steps) {
    s.Apply(Steps({{"Camera", period}}), t);
    s.Measure(reading_, t, 1);
  }
  s.Apply(Steps({{"Gyro", 8}}), 56);  // not a camera
  s.Measure(reading_, 56, 1);
  EXPECT_EQ(source.enables, (std::vector<std::string>{"red_1/camera@16", "red_1/camera@32", "red_1/camera@0"}));
}

// A client switching a camera on and off in every entry of its requests: the source hears the step's final period
// once (it heard every switch: 196,622 log lines and as many DDS writes in 8 s, the match at a tenth of real time).
TEST_F(HlvsSessionTest, SwitchingACameraWithinAStepReachesTheSourceOnceAtMost) {
  FixedCamera source;
  options_.cameras = &source;
  Session s(options_);
  std::vector<NamedStep> toggles;
  for (int i = 0; i < 1024; ++i) toggles.push_back({"Camera", i % 2 == 0 ? 16u : 0u});
  for (int request = 0; request < 30; ++request) s.Apply(Steps(toggles), 8);  // ends off: as before
  s.Measure(reading_, 8, 1);
  EXPECT_TRUE(source.enables.empty());
  toggles.push_back({"Camera", 16});
  s.Apply(Steps(toggles), 16);  // ends on
  s.Measure(reading_, 16, 1);
  EXPECT_EQ(source.enables, (std::vector<std::string>{"red_1/camera@16"}));
}

// 30 requests of 1024 unknown motors made 30,000 warnings in one message (1.5 MB): past the connection's send
// limit, so the client was dropped, with a wrong reason.
TEST_F(HlvsSessionTest, AMessageListsAtMostKMaxWarnings) {
  Session s(options_);
  ActuatorRequests r;
  for (int i = 0; i < 1024; ++i) r.positions.push_back({"Tail" + std::to_string(i), 1});
  for (int request = 0; request < 30; ++request) s.Apply(r, 8);
  const SensorMeasurements m = s.Measure(reading_, 8, 1);
  ASSERT_EQ(m.messages.size(), kMaxWarnings + 1);
  EXPECT_EQ(m.messages[0].text, "Motor \"Tail0\" not found, position command ignored.");
  EXPECT_EQ(m.messages.back().text, fmt::format("{} more warnings, not listed.", 30 * 1024 - kMaxWarnings));
  EXPECT_TRUE(s.Measure(reading_, 16, 1).messages.empty());  // the count starts again
  EXPECT_LT(FrameSensorMeasurements(m).framed.size(), size_t{16} * 1024);
}

// A client that leaves takes its sensors with it: the next client got the first one's sensors (and its camera
// stayed on at turf-render until the bridge exited). Motor commands stay.
TEST_F(HlvsSessionTest, AClientLeavingSwitchesItsSensorsOffAndKeepsTheMotors) {
  FixedCamera source;
  options_.cameras = &source;
  Session s(options_);
  ActuatorRequests r = Steps({{"Camera", 16}, {"NeckS", 8}});
  r.positions.push_back({options_.model->motors[0].motor, 0.5});
  r.positions.push_back({"Tail", 1});  // a warning pending
  s.Apply(r, 8);
  s.Measure(reading_, 8, 1);
  ASSERT_EQ(s.SensorPeriods().size(), 2u);
  s.Apply(Steps({{"Nose", 8}}), 16);  // another warning, never sent
  s.ClientLeft();
  EXPECT_EQ(source.enables, (std::vector<std::string>{"red_1/camera@16", "red_1/camera@0"}));
  EXPECT_TRUE(s.SensorPeriods().empty());
  const SensorMeasurements next = s.Measure(reading_, 16, 1);
  EXPECT_TRUE(next.messages.empty());
  EXPECT_TRUE(next.position_sensors.empty());
  EXPECT_TRUE(next.cameras.empty());
  const std::vector<JointOutput> commands = s.Commands(reading_);
  ASSERT_EQ(commands.size(), 1u);
  EXPECT_EQ(commands[0].joint, options_.model->motors[0].joint);
  EXPECT_GT(commands[0].value, 0.0);  // still driving toward 0.5 rad
}

TEST_F(HlvsSessionTest, CamerasNeedAnImageSource) {
  Session none(options_);
  none.Apply(Steps({{"Camera", 16}}), 8);
  EXPECT_TRUE(none.Measure(reading_, 24, 1).cameras.empty());
  EXPECT_TRUE(none.camera_unavailable());
  FixedCamera source;
  options_.cameras = &source;
  Session s(options_);
  ActuatorRequests r = Steps({{"Camera", 16}});
  r.camera_exposures.push_back({"Camera", 2.5});
  s.Apply(r, 8);
  EXPECT_TRUE(s.Measure(reading_, 16, 1).cameras.empty());
  const SensorMeasurements m = s.Measure(reading_, 24, 1);
  ASSERT_EQ(m.cameras.size(), 1u);
  EXPECT_EQ(m.cameras[0].name, "Camera");
  EXPECT_EQ(m.cameras[0].width, 320u);
  EXPECT_EQ(m.cameras[0].quality, -1);
  EXPECT_EQ(source.last.camera, "camera");
  EXPECT_EQ(source.last.robot, "red_1");
  EXPECT_EQ(source.last.exposure, 2.5);
  EXPECT_EQ(source.last.sim_time_ms, 24u);
}

TEST_F(HlvsSessionTest, PositionControlIsWebotsPOnAVelocityMotor) {
  options_.limits.assign(options_.model->motors.size(), JointLimits{-1.0, 1.0, 6.0});
  Session s(options_);
  EXPECT_TRUE(s.Commands(reading_).empty());  // uncommanded motors keep the scene's mode
  ActuatorRequests r;
  r.positions.push_back({"Neck", 0.5});
  r.velocities.push_back({"Head", 2.0});
  r.positions.push_back({"Head", 5.0});  // beyond the range: clamped to 1
  s.Apply(r, 8);
  const auto out = s.Commands(reading_);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].joint, "AAHead_yaw");
  EXPECT_EQ(out[0].mode, JointOutput::Mode::kVelocity);
  EXPECT_DOUBLE_EQ(out[0].value, 10 * 0.5);  // P 10
  EXPECT_EQ(out[1].joint, "Head_pitch");
  EXPECT_DOUBLE_EQ(out[1].value, 2.0);  // limited by the velocity command
  ActuatorRequests t;
  t.torques.push_back({"Neck", -50});
  t.positions.push_back({"Head", std::numeric_limits<double>::infinity()});
  s.Apply(t, 16);
  const auto out2 = s.Commands(reading_);
  EXPECT_EQ(out2[0].mode, JointOutput::Mode::kTorque);
  EXPECT_DOUBLE_EQ(out2[0].value, -6.0);  // the effort limit
  EXPECT_DOUBLE_EQ(out2[1].value, 2.0);   // velocity control
}

TEST_F(HlvsSessionTest, AVelocityAloneHoldsWhereTheJointIs) {
  options_.limits.assign(options_.model->motors.size(), JointLimits{-1.0, 1.0, 6.0});
  Session s(options_);
  ActuatorRequests r;
  r.velocities.push_back({"Neck", 3.0});
  s.Apply(r, 8);
  reading_.position[0] = 0.3;
  auto out = s.Commands(reading_);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].value, 0.0);
  reading_.position[0] = 0.2;  // pushed away: back towards 0.3, at most 3 rad/s
  out = s.Commands(reading_);
  EXPECT_NEAR(out[0].value, 1.0, 1e-12);
}

// A joint angle that is no number (a forged robots/state sample) gives a holding command, never a NaN one: turf-sim
// refuses a step's commands whole, so a NaN would have cost every robot its commands.
TEST_F(HlvsSessionTest, AReadingThatIsNoNumberHoldsTheJoint) {
  Session s(options_);
  ActuatorRequests r;
  r.positions.push_back({"Neck", 0.5});
  s.Apply(r, 8);
  reading_.position[0] = std::numeric_limits<double>::quiet_NaN();
  auto out = s.Commands(reading_);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].value, 0.0);
  reading_.position[0] = 0.0;  // numbers again: P 10 toward 0.5, no integral or derivative of the NaN left
  out = s.Commands(reading_);
  EXPECT_NEAR(out[0].value, 5.0, 1e-12);
}

TEST(HlvsQuota, KeepsTheLastSecondWithinTheQuota) {
  NetworkQuota q(4);  // 87.5 MiB/s
  const size_t mib = 1024 * 1024;
  EXPECT_TRUE(q.Admit(80 * mib, 0));
  EXPECT_FALSE(q.Admit(8 * mib, 500));
  EXPECT_TRUE(q.Admit(7 * mib, 500));
  EXPECT_TRUE(q.Admit(80 * mib, 1000));  // the first left the window
  EXPECT_EQ(q.ExceededText(), "87.500000 MB/s quota exceeded.");
}

}  // namespace
}  // namespace turf::hlvs
