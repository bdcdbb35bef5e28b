// The grSim command codec: golden bytes, boundaries, every named error.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include "codecs/grsim/grsim_codec.h"
#include "codecs/proto/grsim.pb.h"
#include "tests/codecs/grsim/grsim_messages.h"

namespace turf::grsim {
namespace {

namespace wire = turf::wire::grsim;
using test::GrsimCommands;
using test::GrsimRobot;

// Blue commands for two robots. Tags are (field << 3) | wire type: VARINT 0,
// I64 1, LEN 2, I32 5. Floats and doubles are little-endian IEEE 754.
const std::vector<uint8_t> kCommandsPacket = {
    0x0A, 0x61,                                            // grSim_Packet.commands (1, LEN), 97 bytes
    0x09, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x29, 0x40,  //   timestamp (1, I64) = 12.5
    0x10, 0x00,                                            //   isteamyellow (2, VARINT) = false
    0x1A, 0x1F,                                            //   robot_commands (3, LEN), 31 bytes
    0x08, 0x03,                                            //     id (1, VARINT) = 3
    0x15, 0x00, 0x00, 0x80, 0x40,                          //     kickspeedx (2, I32) = 4.0
    0x1D, 0x00, 0x00, 0x00, 0x00,                          //     kickspeedz (3, I32) = 0.0
    0x25, 0x00, 0x00, 0x80, 0x3F,                          //     veltangent (4, I32) = 1.0
    0x2D, 0x00, 0x00, 0x00, 0xBF,                          //     velnormal (5, I32) = -0.5
    0x35, 0x00, 0x00, 0x00, 0x40,                          //     velangular (6, I32) = 2.0
    0x38, 0x01,                                            //     spinner (7, VARINT) = true
    0x40, 0x00,                                            //     wheelsspeed (8, VARINT) = false
    0x1A, 0x33,                                            //   robot_commands (3, LEN), 51 bytes
    0x08, 0x05,                                            //     id = 5
    0x15, 0x00, 0x00, 0x00, 0x00,                          //     kickspeedx = 0.0
    0x1D, 0x00, 0x00, 0x00, 0x00,                          //     kickspeedz = 0.0
    0x25, 0x00, 0x00, 0x00, 0x00,                          //     veltangent = 0.0
    0x2D, 0x00, 0x00, 0x00, 0x00,                          //     velnormal = 0.0
    0x35, 0x00, 0x00, 0x00, 0x00,                          //     velangular = 0.0
    0x38, 0x00,                                            //     spinner = false
    0x40, 0x01,                                            //     wheelsspeed = true
    0x4D, 0x00, 0x00, 0x80, 0x3F,                          //     wheel1 (9, I32) = 1.0 rad/s
    0x55, 0x00, 0x00, 0x00, 0x40,                          //     wheel2 (10, I32) = 2.0
    0x5D, 0x00, 0x00, 0x40, 0x40,                          //     wheel3 (11, I32) = 3.0
    0x65, 0x00, 0x00, 0x80, 0x40,                          //     wheel4 (12, I32) = 4.0
};

// A replacement: one yellow robot taken off the field, and the ball.
const std::vector<uint8_t> kReplacementPacket = {
    0x12, 0x49,                                            // grSim_Packet.replacement (2, LEN), 73 bytes
    0x0A, 0x24,                                            //   ball (1, LEN), 36 bytes
    0x09, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xF0, 0x3F,  //     x (1, I64) = 1.0
    0x11, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xC0,  //     y (2, I64) = -2.0
    0x19, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xE0, 0x3F,  //     vx (3, I64) = 0.5
    0x21, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,  //     vy (4, I64) = 0.0
    0x12, 0x21,                                            //   robots (2, LEN), 33 bytes
    0x09, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x08, 0xC0,  //     x (1, I64) = -3.0
    0x11, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xF8, 0x3F,  //     y (2, I64) = 1.5
    0x19, 0x00, 0x00, 0x00, 0x00, 0x00, 0x80, 0x56, 0x40,  //     dir (3, I64) = 90.0 degrees
    0x20, 0x02,                                            //     id (4, VARINT) = 2
    0x28, 0x01,                                            //     yellowteam (5, VARINT) = true
    0x30, 0x00,                                            //     turnon (6, VARINT) = false
};

GrsimDecodeResult DecodeBytes(const std::vector<uint8_t>& bytes, const GrsimCodecConfig& config = {}) {
  return Decode(bytes.data(), bytes.size(), config);
}

std::vector<uint8_t> Bytes(const google::protobuf::MessageLite& m) {
  const std::string s = m.SerializePartialAsString();
  return {s.begin(), s.end()};
}

GrsimDecodeResult DecodeRobot(const wire::grSim_Robot_Command& robot, const GrsimCodecConfig& config = {}) {
  return DecodeBytes(Bytes(GrsimCommands(false, {robot})), config);
}

wire::grSim_RobotReplacement Placed(uint32_t id, bool yellow, double x, double y, double dir) {
  wire::grSim_RobotReplacement r;
  r.set_id(id);
  r.set_yellowteam(yellow);
  r.set_x(x);
  r.set_y(y);
  r.set_dir(dir);
  return r;
}

void ExpectRefused(const GrsimDecodeResult& r, GrsimError error, const std::string& field = "") {
  EXPECT_EQ(GrsimErrorName(r.error), std::string(GrsimErrorName(error))) << r.detail;
  EXPECT_TRUE(r.requests.commands.empty());
  EXPECT_TRUE(r.requests.controls.empty());
  EXPECT_FALSE(r.requests.command_team.has_value());
  if (!field.empty()) {
    EXPECT_NE(r.detail.find(field), std::string::npos) << r.detail;
  }
}

TEST(GrsimCodec, GoldenCommandsDecode) {
  const GrsimDecodeResult r = DecodeBytes(kCommandsPacket);
  ASSERT_TRUE(r.ok()) << GrsimErrorName(r.error) << ": " << r.detail;
  ASSERT_EQ(r.requests.command_team, idl::TEAM_BLUE);
  ASSERT_EQ(r.requests.commands.size(), 2u);
  EXPECT_TRUE(r.requests.controls.empty());

  const idl::SslRobotCommand& a = r.requests.commands[0];
  EXPECT_EQ(a.team(), idl::TEAM_BLUE);
  EXPECT_EQ(a.id(), 3);
  EXPECT_EQ(a.move(), idl::MOVE_LOCAL_VELOCITY);
  EXPECT_DOUBLE_EQ(a.velocity().x(), 1.0);
  EXPECT_DOUBLE_EQ(a.velocity().y(), -0.5);
  EXPECT_DOUBLE_EQ(a.velocity().z(), 2.0);
  EXPECT_EQ(a.kick(), idl::KICK_FLAT);
  EXPECT_DOUBLE_EQ(a.kick_speed(), 4.0);
  EXPECT_DOUBLE_EQ(a.dribbler_speed(), 1000.0);

  const idl::SslRobotCommand& b = r.requests.commands[1];
  EXPECT_EQ(b.id(), 5);
  EXPECT_EQ(b.move(), idl::MOVE_WHEEL_VELOCITY);
  EXPECT_EQ(b.kick(), idl::KICK_NONE);
  EXPECT_DOUBLE_EQ(b.kick_speed(), 0.0);
  EXPECT_DOUBLE_EQ(b.dribbler_speed(), 0.0);
  // rad/s x 0.027 m, in turf's order front_right, back_right, back_left, front_left = wheel4, 3, 2, 1.
  EXPECT_DOUBLE_EQ(b.wheel_velocity()[0], 4.0 * 0.027);
  EXPECT_DOUBLE_EQ(b.wheel_velocity()[1], 3.0 * 0.027);
  EXPECT_DOUBLE_EQ(b.wheel_velocity()[2], 2.0 * 0.027);
  EXPECT_DOUBLE_EQ(b.wheel_velocity()[3], 1.0 * 0.027);
}

TEST(GrsimCodec, GoldenReplacementDecodes) {
  const GrsimDecodeResult r = DecodeBytes(kReplacementPacket);
  ASSERT_TRUE(r.ok()) << r.detail;
  EXPECT_FALSE(r.requests.command_team.has_value());
  ASSERT_EQ(r.requests.controls.size(), 2u);
  const idl::SimControl& robot = r.requests.controls[0];  // robots first, as grSim does
  EXPECT_EQ(robot.op(), idl::OP_TELEPORT_ROBOT);
  EXPECT_EQ(robot.robot().team(), idl::TEAM_YELLOW);
  EXPECT_EQ(robot.robot().id(), 2);
  EXPECT_FALSE(robot.robot().on_field());
  EXPECT_DOUBLE_EQ(robot.robot().position().x(), -3.0);
  EXPECT_DOUBLE_EQ(robot.robot().position().y(), 1.5);
  EXPECT_DOUBLE_EQ(robot.robot().orientation(), M_PI / 2);
  const idl::SimControl& ball = r.requests.controls[1];
  EXPECT_EQ(ball.op(), idl::OP_TELEPORT_BALL);
  EXPECT_DOUBLE_EQ(ball.ball().position().x(), 1.0);
  EXPECT_DOUBLE_EQ(ball.ball().position().y(), -2.0);
  EXPECT_DOUBLE_EQ(ball.ball().position().z(), 0.0);
  EXPECT_DOUBLE_EQ(ball.ball().velocity().x(), 0.5);
  EXPECT_DOUBLE_EQ(ball.ball().velocity().y(), 0.0);
}

// The annotations above are honest: protobuf writes the same bytes for the same values.
TEST(GrsimCodec, GoldenBytesAreWhatProtobufWrites) {
  wire::grSim_Robot_Command a = GrsimRobot(3);
  a.set_kickspeedx(4.0f);
  a.set_veltangent(1.0f);
  a.set_velnormal(-0.5f);
  a.set_velangular(2.0f);
  a.set_spinner(true);
  wire::grSim_Robot_Command b = GrsimRobot(5);
  b.set_wheelsspeed(true);
  b.set_wheel1(1.0f);
  b.set_wheel2(2.0f);
  b.set_wheel3(3.0f);
  b.set_wheel4(4.0f);
  wire::grSim_Packet commands = GrsimCommands(false, {a, b});
  commands.mutable_commands()->set_timestamp(12.5);
  EXPECT_EQ(Bytes(commands), kCommandsPacket);

  wire::grSim_Packet replacement;
  wire::grSim_BallReplacement* ball = replacement.mutable_replacement()->mutable_ball();
  ball->set_x(1.0);
  ball->set_y(-2.0);
  ball->set_vx(0.5);
  ball->set_vy(0.0);
  wire::grSim_RobotReplacement robot = Placed(2, true, -3.0, 1.5, 90.0);
  robot.set_turnon(false);
  *replacement.mutable_replacement()->add_robots() = robot;
  EXPECT_EQ(Bytes(replacement), kReplacementPacket);
}

// Each packet has one top-level field, so every proper prefix cuts it short.
TEST(GrsimCodec, EveryTruncationIsRefused) {
  for (const auto* packet : {&kCommandsPacket, &kReplacementPacket}) {
    ExpectRefused(Decode(packet->data(), 0, {}), GrsimError::kEmpty);
    for (size_t n = 1; n < packet->size(); ++n) {
      const GrsimDecodeResult r = Decode(packet->data(), n, {});
      EXPECT_TRUE(r.error == GrsimError::kMalformed || r.error == GrsimError::kMissingRequired)
          << n << " bytes: " << GrsimErrorName(r.error);
      EXPECT_TRUE(r.requests.commands.empty() && r.requests.controls.empty()) << n << " bytes";
    }
  }
}

TEST(GrsimCodec, EmptyOversizedAndGarbage) {
  ExpectRefused(DecodeBytes({}), GrsimError::kEmpty);
  GrsimCodecConfig small;
  small.max_datagram_size = 64;
  ExpectRefused(DecodeBytes(kCommandsPacket, small), GrsimError::kOversized);
  small.max_datagram_size = kCommandsPacket.size();
  EXPECT_TRUE(DecodeBytes(kCommandsPacket, small).ok());
  ExpectRefused(DecodeBytes({0xFF, 0xFF, 0xFF}), GrsimError::kMalformed);        // a tag that never ends
  ExpectRefused(DecodeBytes({0x0A, 0x05, 0x10, 0x00}), GrsimError::kMalformed);  // length past the end
  ExpectRefused(DecodeBytes({0x0F, 0x00}), GrsimError::kMalformed);              // wire type 7
  ExpectRefused(DecodeBytes({0x0A, 0x02, 0xFF, 0xFF}), GrsimError::kMalformed);  // garbage inside commands
  // Unknown fields are protobuf's business, not an error: nothing is asked.
  const GrsimDecodeResult unknown = DecodeBytes({0x78, 0x01});  // field 15, VARINT 1
  EXPECT_TRUE(unknown.ok());
  EXPECT_TRUE(unknown.requests.commands.empty() && unknown.requests.controls.empty());
}

TEST(GrsimCodec, MissingRequiredFieldsAreNamed) {
  wire::grSim_Robot_Command robot = GrsimRobot(1);
  robot.clear_kickspeedz();
  ExpectRefused(DecodeBytes(Bytes(GrsimCommands(false, {robot}))), GrsimError::kMissingRequired, "kickspeedz");

  wire::grSim_Packet no_team = GrsimCommands(false, {GrsimRobot(1)});
  no_team.mutable_commands()->clear_isteamyellow();
  ExpectRefused(DecodeBytes(Bytes(no_team)), GrsimError::kMissingRequired, "isteamyellow");

  wire::grSim_Packet no_id;
  wire::grSim_RobotReplacement placed = Placed(1, false, 0, 0, 0);
  placed.clear_id();
  *no_id.mutable_replacement()->add_robots() = placed;
  ExpectRefused(DecodeBytes(Bytes(no_id)), GrsimError::kMissingRequired, "id");

  wire::grSim_Robot_Command three_wheels = GrsimRobot(1);
  three_wheels.set_wheelsspeed(true);
  three_wheels.set_wheel1(1);
  three_wheels.set_wheel2(1);
  three_wheels.set_wheel4(1);
  ExpectRefused(DecodeRobot(three_wheels), GrsimError::kMissingRequired, "wheel3");
}

TEST(GrsimCodec, NonFiniteAnywhereRefusesTheDatagram) {
  using Setter = std::function<void(wire::grSim_Robot_Command*, float)>;
  const std::vector<std::pair<const char*, Setter>> fields = {
      {"kickspeedx", [](auto* c, float v) { c->set_kickspeedx(v); }},
      {"kickspeedz", [](auto* c, float v) { c->set_kickspeedz(v); }},
      {"veltangent", [](auto* c, float v) { c->set_veltangent(v); }},
      {"velnormal", [](auto* c, float v) { c->set_velnormal(v); }},
      {"velangular", [](auto* c, float v) { c->set_velangular(v); }},
      {"wheel1", [](auto* c, float v) { c->set_wheel1(v); }},
      {"wheel4", [](auto* c, float v) { c->set_wheel4(v); }},
  };
  for (const float bad : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                          -std::numeric_limits<float>::infinity()}) {
    for (const auto& [name, set] : fields) {
      wire::grSim_Robot_Command robot = GrsimRobot(1);
      set(&robot, bad);
      // A good robot before the bad one: the whole datagram goes, so it does not move either.
      ExpectRefused(DecodeBytes(Bytes(GrsimCommands(false, {GrsimRobot(0), robot}))), GrsimError::kNotFinite,
                    std::string("robot_commands[1].") + name);
    }
  }
  wire::grSim_Packet timestamp = GrsimCommands(true, {GrsimRobot(0)});
  timestamp.mutable_commands()->set_timestamp(std::numeric_limits<double>::infinity());
  ExpectRefused(DecodeBytes(Bytes(timestamp)), GrsimError::kNotFinite, "timestamp");

  wire::grSim_Packet ball;
  ball.mutable_replacement()->mutable_ball()->set_vy(NAN);
  ExpectRefused(DecodeBytes(Bytes(ball)), GrsimError::kNotFinite, "replacement.ball.vy");
  wire::grSim_Packet robot;
  *robot.mutable_replacement()->add_robots() = Placed(1, false, 0, 0, NAN);
  ExpectRefused(DecodeBytes(Bytes(robot)), GrsimError::kNotFinite, "replacement.robots[0].dir");
}

// A robot taken off the field (turnon = false) still carries a pose, and absurd values refuse the whole
// datagram: x = 1e308 once took 20 of 22 robots off a match (issue: hardening a running match).
TEST(GrsimCodec, AbsurdReplacementsAreRefusedWhateverTurnonSays) {
  for (const bool turnon : {false, true}) {
    const struct {
      double x, y, dir;
      const char* field;
    } kBad[] = {{1e308, 0, 0, "x"}, {0, -2000, 0, "y"}, {0, 0, 1e300, "dir"}, {-1e4, 0, 0, "x"}};
    for (const auto& b : kBad) {
      wire::grSim_Packet packet;
      wire::grSim_RobotReplacement good = Placed(0, false, 1.0, 1.0, 0.0);
      wire::grSim_RobotReplacement bad = Placed(1, false, b.x, b.y, b.dir);
      bad.set_turnon(turnon);
      *packet.mutable_replacement()->add_robots() = good;
      *packet.mutable_replacement()->add_robots() = bad;
      ExpectRefused(DecodeBytes(Bytes(packet)), GrsimError::kOutOfRange,
                    std::string("replacement.robots[1].") + b.field);
    }
  }
  // Far but not absurd (some teams park removed robots well outside the field): taken off, as asked.
  wire::grSim_Packet parked;
  wire::grSim_RobotReplacement far = Placed(2, true, 500.0, -500.0, 720.0);
  far.set_turnon(false);
  *parked.mutable_replacement()->add_robots() = far;
  const GrsimDecodeResult r = DecodeBytes(Bytes(parked));
  ASSERT_TRUE(r.ok()) << GrsimErrorName(r.error) << " " << r.detail;
  ASSERT_EQ(r.requests.controls.size(), 1u);
  EXPECT_FALSE(r.requests.controls[0].robot().on_field());
}

// A packet turf-sim would refuse in part is refused whole: a robot twice (490 a packet were 490 world states), or,
// once the walls are known, a ball or robot beyond them (the robots before a ball at x = 50 were placed).
TEST(GrsimCodec, AReplacementIsWholeOrRefused) {
  wire::grSim_Packet twice;
  *twice.mutable_replacement()->add_robots() = Placed(3, false, 1.0, 1.0, 0.0);
  *twice.mutable_replacement()->add_robots() = Placed(3, true, 1.0, -1.0, 0.0);  // the other team's 3: fine
  *twice.mutable_replacement()->add_robots() = Placed(3, false, 2.0, 1.0, 0.0);
  ExpectRefused(DecodeBytes(Bytes(twice)), GrsimError::kDuplicateRobot, "replacement.robots[2].id");

  GrsimCodecConfig walls;  // division A: 12 x 9 m, 0.3 m to the walls
  walls.wall_x = 6.3;
  walls.wall_y = 4.8;
  walls.ball_radius = 0.0215;
  walls.robot_radius = 0.09;
  wire::grSim_Packet far_ball;
  *far_ball.mutable_replacement()->add_robots() = Placed(3, false, 1.0, 1.0, 0.0);
  far_ball.mutable_replacement()->mutable_ball()->set_x(50.0);
  far_ball.mutable_replacement()->mutable_ball()->set_y(0.0);
  ExpectRefused(DecodeBytes(Bytes(far_ball), walls), GrsimError::kOutsideField, "replacement.ball.x");
  EXPECT_TRUE(DecodeBytes(Bytes(far_ball)).ok()) << "walls unknown: turf-sim checks";
  far_ball.mutable_replacement()->mutable_ball()->set_x(6.27);
  EXPECT_TRUE(DecodeBytes(Bytes(far_ball), walls).ok());

  wire::grSim_Packet far_robot;
  *far_robot.mutable_replacement()->add_robots() = Placed(3, false, 0.0, 4.75, 0.0);
  ExpectRefused(DecodeBytes(Bytes(far_robot), walls), GrsimError::kOutsideField, "replacement.robots[0].x");
  far_robot.mutable_replacement()->mutable_robots(0)->set_turnon(false);  // taken off: anywhere
  EXPECT_TRUE(DecodeBytes(Bytes(far_robot), walls).ok());
}

TEST(GrsimCodec, UnknownRobotsAreRefused) {
  ExpectRefused(DecodeRobot(GrsimRobot(16)), GrsimError::kUnknownRobot, "id");
  ExpectRefused(DecodeRobot(GrsimRobot(4000000000u)), GrsimError::kUnknownRobot, "id");
  GrsimCodecConfig six;
  six.robots_per_team = 6;
  EXPECT_TRUE(DecodeRobot(GrsimRobot(5), six).ok());
  ExpectRefused(DecodeRobot(GrsimRobot(6), six), GrsimError::kUnknownRobot, "id");
  EXPECT_TRUE(DecodeRobot(GrsimRobot(15)).ok());
  wire::grSim_Packet placed;
  *placed.mutable_replacement()->add_robots() = Placed(16, true, 0, 0, 0);
  ExpectRefused(DecodeBytes(Bytes(placed)), GrsimError::kUnknownRobot, "replacement.robots[0].id");
}

TEST(GrsimCodec, PastTheSanityLimitsIsOutOfRange) {
  std::vector<std::pair<const char*, wire::grSim_Robot_Command>> cases;
  auto add = [&](const char* field, const std::function<void(wire::grSim_Robot_Command*)>& set) {
    wire::grSim_Robot_Command c = GrsimRobot(2);
    set(&c);
    cases.emplace_back(field, c);
  };
  add("kickspeedx", [](auto* c) { c->set_kickspeedx(-1.0f); });
  add("kickspeedz", [](auto* c) { c->set_kickspeedz(-0.5f); });
  add("kickspeedx", [](auto* c) { c->set_kickspeedx(31.0f); });
  add("kickspeedz", [](auto* c) {
    c->set_kickspeedx(25.0f);
    c->set_kickspeedz(25.0f);  // 35 m/s along the launch
  });
  add("veltangent", [](auto* c) { c->set_veltangent(21.0f); });
  add("veltangent", [](auto* c) {
    c->set_veltangent(15.0f);
    c->set_velnormal(-15.0f);
  });
  add("velangular", [](auto* c) { c->set_velangular(-101.0f); });
  add("wheel2", [](auto* c) {
    c->set_wheelsspeed(true);
    c->set_wheel1(0);
    c->set_wheel2(800.0f);  // 21.6 m/s at the rim
    c->set_wheel3(0);
    c->set_wheel4(0);
  });
  for (const auto& [field, robot] : cases) ExpectRefused(DecodeRobot(robot), GrsimError::kOutOfRange, field);

  wire::grSim_Packet ball;
  ball.mutable_replacement()->mutable_ball()->set_vx(40.0);
  ExpectRefused(DecodeBytes(Bytes(ball)), GrsimError::kOutOfRange, "replacement.ball");
}

TEST(GrsimCodec, WheelSpeedsBecomeRimSpeedsInTurfOrder) {
  wire::grSim_Robot_Command c = GrsimRobot(0);
  c.set_wheelsspeed(true);
  c.set_wheel1(10.0f);
  c.set_wheel2(-20.0f);
  c.set_wheel3(30.0f);
  c.set_wheel4(-40.0f);
  GrsimCodecConfig config;
  config.wheel_radius = 0.025;
  GrsimDecodeResult r = DecodeRobot(c, config);
  ASSERT_TRUE(r.ok()) << r.detail;
  const auto& w = r.requests.commands[0].wheel_velocity();
  EXPECT_DOUBLE_EQ(w[0], -40.0 * 0.025);  // front_right = wheel4 (300 degrees)
  EXPECT_DOUBLE_EQ(w[1], 30.0 * 0.025);   // back_right = wheel3 (225)
  EXPECT_DOUBLE_EQ(w[2], -20.0 * 0.025);  // back_left = wheel2 (135)
  EXPECT_DOUBLE_EQ(w[3], 10.0 * 0.025);   // front_left = wheel1 (60)

  config.wheel_source = {0, 1, 2, 3};  // a robot numbered the other way round
  r = DecodeRobot(c, config);
  ASSERT_TRUE(r.ok());
  EXPECT_DOUBLE_EQ(r.requests.commands[0].wheel_velocity()[0], 10.0 * 0.025);
  EXPECT_DOUBLE_EQ(r.requests.commands[0].wheel_velocity()[3], -40.0 * 0.025);
}

TEST(GrsimCodec, KicksFlatAndChipped) {
  wire::grSim_Robot_Command c = GrsimRobot(0);
  c.set_kickspeedx(3.0f);
  c.set_kickspeedz(4.0f);
  GrsimDecodeResult r = DecodeRobot(c);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.requests.commands[0].kick(), idl::KICK_CHIP);
  EXPECT_DOUBLE_EQ(r.requests.commands[0].kick_speed(), 5.0);
  EXPECT_DOUBLE_EQ(r.requests.commands[0].chip_angle(), std::atan2(4.0, 3.0));

  c.set_kickspeedx(0.0f);  // straight up: turf-sim refuses 90 degrees, so the steepest chip it takes
  r = DecodeRobot(c);
  ASSERT_TRUE(r.ok());
  EXPECT_DOUBLE_EQ(r.requests.commands[0].kick_speed(), 4.0);
  EXPECT_NEAR(r.requests.commands[0].chip_angle(), 89.0 * M_PI / 180.0, 1e-12);
  EXPECT_LT(r.requests.commands[0].chip_angle(), M_PI / 2);

  // Not clamped unless the field's limits are known; then clamped along the launch.
  c.set_kickspeedx(8.0f);
  c.set_kickspeedz(0.0f);
  r = DecodeRobot(c);
  EXPECT_EQ(r.requests.commands[0].kick(), idl::KICK_FLAT);
  EXPECT_DOUBLE_EQ(r.requests.commands[0].kick_speed(), 8.0);
  GrsimCodecConfig limited;
  limited.max_flat_kick_speed = 6.5;
  limited.max_chip_kick_speed = 5.0;
  EXPECT_DOUBLE_EQ(DecodeRobot(c, limited).requests.commands[0].kick_speed(), 6.5);
  c.set_kickspeedx(6.0f);
  c.set_kickspeedz(8.0f);
  r = DecodeRobot(c, limited);
  EXPECT_DOUBLE_EQ(r.requests.commands[0].kick_speed(), 5.0);
  EXPECT_DOUBLE_EQ(r.requests.commands[0].chip_angle(), std::atan2(8.0, 6.0));
}

TEST(GrsimCodec, TeamsAndDribbler) {
  wire::grSim_Robot_Command c = GrsimRobot(4);
  c.set_spinner(true);
  GrsimCodecConfig config;
  config.dribbler_rpm = 1500;
  GrsimDecodeResult r = DecodeBytes(Bytes(GrsimCommands(true, {c})), config);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.requests.command_team, idl::TEAM_YELLOW);
  EXPECT_EQ(r.requests.commands[0].team(), idl::TEAM_YELLOW);
  EXPECT_DOUBLE_EQ(r.requests.commands[0].dribbler_speed(), 1500.0);
  // Commands with no robot still name the team (robot status goes to its sender).
  r = DecodeBytes(Bytes(GrsimCommands(true, {})));
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.requests.command_team, idl::TEAM_YELLOW);
  EXPECT_TRUE(r.requests.commands.empty());
}

TEST(GrsimCodec, ReplacementDegreesBecomeRadians) {
  wire::grSim_Packet p;
  *p.mutable_replacement()->add_robots() = Placed(0, false, 1.0, 2.0, 270.0);
  *p.mutable_replacement()->add_robots() = Placed(1, false, 0, 0, -45.0);
  *p.mutable_replacement()->add_robots() = Placed(2, true, 0, 0, 720.0 + 30.0);
  p.mutable_replacement()->mutable_ball()->set_x(0.5);  // y, vx, vy absent: 0
  const GrsimDecodeResult r = DecodeBytes(Bytes(p));
  ASSERT_TRUE(r.ok()) << r.detail;
  ASSERT_EQ(r.requests.controls.size(), 4u);
  EXPECT_NEAR(r.requests.controls[0].robot().orientation(), -M_PI / 2, 1e-12);
  EXPECT_NEAR(r.requests.controls[1].robot().orientation(), -M_PI / 4, 1e-12);
  EXPECT_NEAR(r.requests.controls[2].robot().orientation(), M_PI / 6, 1e-12);
  EXPECT_TRUE(r.requests.controls[0].robot().on_field());  // turnon absent: on
  EXPECT_EQ(r.requests.controls[2].robot().team(), idl::TEAM_YELLOW);
  const idl::SimControl& ball = r.requests.controls[3];
  EXPECT_EQ(ball.op(), idl::OP_TELEPORT_BALL);
  EXPECT_DOUBLE_EQ(ball.ball().position().x(), 0.5);
  EXPECT_DOUBLE_EQ(ball.ball().position().y(), 0.0);
  EXPECT_DOUBLE_EQ(ball.ball().velocity().x(), 0.0);
}

TEST(GrsimCodec, ConfigIsChecked) {
  EXPECT_EQ(CheckConfig({}), "");
  GrsimCodecConfig c;
  c.wheel_source = {0, 0, 1, 2};
  EXPECT_NE(CheckConfig(c), "");
  c = {};
  c.wheel_source = {0, 1, 2, 4};
  EXPECT_NE(CheckConfig(c), "");
  c = {};
  c.wheel_radius = 0;
  EXPECT_NE(CheckConfig(c), "");
  c = {};
  c.robots_per_team = 17;
  EXPECT_NE(CheckConfig(c), "");
  c = {};
  c.dribbler_rpm = NAN;
  EXPECT_NE(CheckConfig(c), "");
  c = {};
  c.max_datagram_size = 0;
  EXPECT_NE(CheckConfig(c), "");
  c = {};
  c.max_flat_kick_speed = -1;
  EXPECT_NE(CheckConfig(c), "");
}

// The fuzzer starts from valid packets.
TEST(GrsimCodec, FuzzSeedsAreValidPackets) {
  int seeds = 0;
  for (const auto& entry : std::filesystem::directory_iterator(TURF_SOURCE_DIR "/tests/fuzz/seeds/grsim")) {
    std::ifstream in(entry.path(), std::ios::binary);
    const std::vector<uint8_t> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    const GrsimDecodeResult r = DecodeBytes(bytes);
    EXPECT_TRUE(r.ok()) << entry.path() << ": " << GrsimErrorName(r.error) << " " << r.detail;
    ++seeds;
  }
  EXPECT_GE(seeds, 3);
}

TEST(GrsimCodec, ErrorsHaveNames) {
  for (int e = 0; e < static_cast<int>(GrsimError::kCount); ++e)
    EXPECT_STRNE(GrsimErrorName(static_cast<GrsimError>(e)), "unknown");
  EXPECT_STREQ(GrsimErrorName(GrsimError::kMissingRequired), "missing_required");
}

}  // namespace
}  // namespace turf::grsim
