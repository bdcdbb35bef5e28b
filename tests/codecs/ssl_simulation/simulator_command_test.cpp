// Control port: SimulatorCommand bytes -> turf control requests, and
// SimulatorResponse bytes.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "codecs/ssl_simulation/simulator_command.h"
#include "core/realism_fields.h"
#include "kernel/time_control.h"
#include "tests/codecs/ssl_simulation/test_util.h"

namespace turf::simproto {
namespace {

// SimulatorCommand { control { teleport_ball { x: 1.5, y: -1, z: 0, vx: 2, roll: true } } }
const std::vector<uint8_t> kTeleportBall = {
    0x0A, 0x18,                    // control (1, LEN), 24 bytes
    0x0A, 0x16,                    //   teleport_ball (1, LEN), 22 bytes
    0x0D, 0x00, 0x00, 0xC0, 0x3F,  //     x (1, fixed32) = 1.5f
    0x15, 0x00, 0x00, 0x80, 0xBF,  //     y (2, fixed32) = -1.0f
    0x1D, 0x00, 0x00, 0x00, 0x00,  //     z (3, fixed32) = 0.0f
    0x25, 0x00, 0x00, 0x00, 0x40,  //     vx (4, fixed32) = 2.0f
    0x40, 0x01,                    //     roll (8, varint) = true
};

void SetFieldSize(wire::vision::SSL_GeometryFieldSize* f) {
  f->set_field_length(9000);
  f->set_field_width(6000);
  f->set_goal_width(1000);
  f->set_goal_depth(180);
  f->set_boundary_width(300);
}

class SimulatorCommandCodec : public ::testing::Test {
 protected:
  SimulatorCommandDecode Decode(const std::vector<uint8_t>& bytes) {
    return DecodeSimulatorCommand(bytes.data(), bytes.size(), context_);
  }
  SimulatorCommandDecode Convert(const ws::SimulatorCommand& command) {
    return ConvertSimulatorCommand(command, context_);
  }
  static ws::TeleportRobot* Robot(ws::SimulatorCommand* c, ws::Team team, uint32_t id) {
    ws::TeleportRobot* t = c->mutable_control()->add_teleport_robot();
    t->mutable_id()->set_id(id);
    t->mutable_id()->set_team(team);
    return t;
  }
  void ExpectRefused(const SimulatorCommandDecode& d, DecodeError error) {
    EXPECT_EQ(d.error, error) << DecodeErrorName(d.error);
    EXPECT_TRUE(d.requests.empty());
    ASSERT_FALSE(d.errors.empty());
    EXPECT_EQ(d.errors.front().code, DecodeErrorCode(error));
  }

  idl::SslField field_ = test::DivAField();
  idl::WorldState world_ = test::World();
  ControlContext context_{&field_, &world_, false};
};

TEST_F(SimulatorCommandCodec, GoldenTeleportBall) {
  const SimulatorCommandDecode d = Decode(kTeleportBall);
  ASSERT_EQ(d.error, DecodeError::kOk);
  EXPECT_TRUE(d.errors.empty());
  ASSERT_EQ(d.requests.size(), 1u);
  const idl::SimControl& r = d.requests[0];
  EXPECT_EQ(r.op(), idl::OP_TELEPORT_BALL);
  EXPECT_EQ(r.ball().position().x(), 1.5);
  EXPECT_EQ(r.ball().position().y(), -1.0);
  // z is the ball's height above the carpet, as ER-Force's simulator reads it: the centre is a radius higher.
  EXPECT_EQ(r.ball().position().z(), field_.ball_radius());
  EXPECT_EQ(r.ball().velocity().x(), 2.0);
  EXPECT_EQ(r.ball().velocity().y(), 0.0);  // absent velocities are 0
  EXPECT_EQ(r.ball().velocity().z(), 0.0);
  EXPECT_TRUE(r.ball().roll());

  ws::SimulatorCommand c;
  auto* b = c.mutable_control()->mutable_teleport_ball();
  b->set_x(1.5f);
  b->set_y(-1.0f);
  b->set_z(0.0f);
  b->set_vx(2.0f);
  b->set_roll(true);
  EXPECT_EQ(Serialize(c), kTeleportBall);
}

TEST_F(SimulatorCommandCodec, GoldenResponses) {
  EXPECT_TRUE(EncodeSimulatorResponse({}).empty());  // nothing went wrong: an empty message
  const std::vector<uint8_t> expected = {
      0x0A, 0x14,                                          // errors (1, LEN), 20 bytes
      0x0A, 0x0F, 'T', 'U', 'R', 'F', '_', 'N', 'O', 'T',  //   code (1, LEN), 15 bytes
      '_',  'F',  'I', 'N', 'I', 'T', 'E',                 //
      0x12, 0x01, 'x',                                     //   message (2, LEN), 1 byte
  };
  EXPECT_EQ(EncodeSimulatorResponse({{"TURF_NOT_FINITE", "x"}}), expected);
}

TEST_F(SimulatorCommandCodec, EveryTruncationIsANamedErrorWithNoRequest) {
  for (size_t n = 0; n < kTeleportBall.size(); ++n) {
    SCOPED_TRACE(n);
    const SimulatorCommandDecode d = DecodeSimulatorCommand(kTeleportBall.data(), n, context_);
    ExpectRefused(d, n == 0 ? DecodeError::kEmpty : DecodeError::kMalformed);
  }
}

TEST_F(SimulatorCommandCodec, GarbageOversizedAndMissingRequired) {
  ExpectRefused(Decode({0x0A, 0x05, 0xFF, 0xFF}), DecodeError::kMalformed);
  ExpectRefused(Decode(std::vector<uint8_t>(kMaxDatagramBytes + 1, 0x0A)), DecodeError::kOversized);
  // teleport_robot without its required id.
  ExpectRefused(Decode({0x0A, 0x07, 0x12, 0x05, 0x15, 0x00, 0x00, 0x80, 0x3F}), DecodeError::kMissingRequired);
}

TEST_F(SimulatorCommandCodec, AbsentPositionKeepsTheCurrentOne) {
  ws::SimulatorCommand c;
  c.mutable_control()->mutable_teleport_ball()->set_x(2.0f);
  ws::TeleportRobot* turn = Robot(&c, ws::BLUE, 0);
  turn->set_orientation(1.0f);  // only turn blue 0 where it stands
  const SimulatorCommandDecode d = Convert(c);
  ASSERT_EQ(d.error, DecodeError::kOk);
  ASSERT_EQ(d.requests.size(), 2u);
  EXPECT_EQ(d.requests[0].ball().position().x(), 2.0);
  EXPECT_EQ(d.requests[0].ball().position().y(), -0.5);    // kept
  EXPECT_EQ(d.requests[0].ball().position().z(), 0.0215);  // kept
  const idl::RobotTeleport& r = d.requests[1].robot();
  EXPECT_EQ(d.requests[1].op(), idl::OP_TELEPORT_ROBOT);
  EXPECT_EQ(r.team(), idl::TEAM_BLUE);
  EXPECT_EQ(r.id(), 0);
  EXPECT_TRUE(r.on_field());  // present absent: stays on
  EXPECT_EQ(r.position().x(), 1.0);
  EXPECT_EQ(r.position().y(), 1.0);
  EXPECT_EQ(r.orientation(), 1.0);

  // Without a world state there is nothing to keep.
  context_.world = nullptr;
  ExpectRefused(Convert(c), DecodeError::kMissingRequired);
}

TEST_F(SimulatorCommandCodec, RobotsOnAndOffTheField) {
  ws::SimulatorCommand c;
  Robot(&c, ws::YELLOW, 2)->set_present(false);
  ws::TeleportRobot* on = Robot(&c, ws::BLUE, 1);  // off the field now
  on->set_present(true);
  on->set_x(-1.0f);
  on->set_y(2.0f);
  on->set_v_x(0.5f);
  on->set_v_angular(-1.0f);
  const SimulatorCommandDecode d = Convert(c);
  ASSERT_EQ(d.error, DecodeError::kOk);
  ASSERT_EQ(d.requests.size(), 2u);
  EXPECT_EQ(d.requests[0].robot().team(), idl::TEAM_YELLOW);
  EXPECT_EQ(d.requests[0].robot().id(), 2);
  EXPECT_FALSE(d.requests[0].robot().on_field());
  const idl::RobotTeleport& r = d.requests[1].robot();
  EXPECT_TRUE(r.on_field());
  EXPECT_EQ(r.position().x(), -1.0);
  EXPECT_EQ(r.position().y(), 2.0);
  EXPECT_EQ(r.orientation(), 0.0);  // an off-field robot has no orientation to keep
  EXPECT_EQ(r.velocity().x(), 0.5);
  EXPECT_EQ(r.velocity().z(), -1.0);

  // Bringing a robot on needs a position.
  ws::SimulatorCommand no_pos;
  Robot(&no_pos, ws::BLUE, 1)->set_present(true);
  ExpectRefused(Convert(no_pos), DecodeError::kMissingRequired);
}

TEST_F(SimulatorCommandCodec, BadValuesAnywhereRefuseEverything) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  auto with_good_ball = [] {
    ws::SimulatorCommand c;
    c.mutable_control()->mutable_teleport_ball()->set_x(0.0f);
    c.mutable_control()->mutable_teleport_ball()->set_y(0.0f);
    return c;
  };
  ws::SimulatorCommand c = with_good_ball();
  Robot(&c, ws::BLUE, 0)->set_x(nan);
  ExpectRefused(Convert(c), DecodeError::kNotFinite);

  c = with_good_ball();
  Robot(&c, ws::BLUE, 1)->set_present(false);
  c.mutable_control()->mutable_teleport_robot(0)->set_v_y(nan);  // even for a robot going off
  ExpectRefused(Convert(c), DecodeError::kNotFinite);

  c = with_good_ball();
  Robot(&c, ws::BLUE, 1)->set_present(false);
  c.mutable_control()->mutable_teleport_robot(0)->set_orientation(1e30f);  // absurd, even for a robot going off
  ExpectRefused(Convert(c), DecodeError::kOutOfRange);

  c = with_good_ball();
  Robot(&c, ws::BLUE, 1)->set_present(false);
  c.mutable_control()->mutable_teleport_robot(0)->set_x(5000.0f);  // beyond any field, on or off it
  ExpectRefused(Convert(c), DecodeError::kOutOfRange);

  c = with_good_ball();
  c.mutable_control()->mutable_teleport_ball()->set_x(6.6f);  // wall at 6.6 - ball radius
  ExpectRefused(Convert(c), DecodeError::kOutsideField);

  c = with_good_ball();
  c.mutable_control()->mutable_teleport_ball()->set_z(-0.5f);
  ExpectRefused(Convert(c), DecodeError::kOutsideField);

  c = with_good_ball();
  c.mutable_control()->mutable_teleport_ball()->set_vx(25.0f);
  c.mutable_control()->mutable_teleport_ball()->set_vy(25.0f);
  ExpectRefused(Convert(c), DecodeError::kOutOfRange);

  c = with_good_ball();
  ws::TeleportRobot* r = Robot(&c, ws::YELLOW, 2);
  r->set_y(4.8f);
  ExpectRefused(Convert(c), DecodeError::kOutsideField);

  c = with_good_ball();
  Robot(&c, ws::UNKNOWN, 2)->set_x(0.0f);
  ExpectRefused(Convert(c), DecodeError::kUnknownRobot);

  c = with_good_ball();
  Robot(&c, ws::BLUE, 6)->set_x(0.0f);  // a 6-a-side scene: ids 0..5
  ExpectRefused(Convert(c), DecodeError::kUnknownRobot);

  c = with_good_ball();
  c.mutable_control()->set_simulation_speed(nan);
  ExpectRefused(Convert(c), DecodeError::kNotFinite);
}

// Each robot once: 2040 teleports of one robot in a datagram were 2040 world states (and lost replies).
TEST_F(SimulatorCommandCodec, ARobotTeleportedTwiceRefusesTheCommand) {
  ws::SimulatorCommand c;
  auto place = [&](ws::Team team, float x) {
    ws::TeleportRobot* t = Robot(&c, team, 1);
    t->set_x(x);
    t->set_y(0.5f);
    t->set_present(true);
  };
  place(ws::BLUE, 0.5f);
  place(ws::YELLOW, -0.5f);  // the other team's 1: fine
  const SimulatorCommandDecode ok = Convert(c);
  ASSERT_EQ(ok.error, DecodeError::kOk) << (ok.errors.empty() ? "" : ok.errors[0].message);
  EXPECT_EQ(ok.requests.size(), 2u);
  place(ws::BLUE, 1.0f);
  ExpectRefused(Convert(c), DecodeError::kDuplicateRobot);
}

TEST_F(SimulatorCommandCodec, SimulationSpeed) {
  auto speed = [&](float s) {
    ws::SimulatorCommand c;
    c.mutable_control()->set_simulation_speed(s);
    return Convert(c);
  };
  SimulatorCommandDecode d = speed(0.0f);
  ASSERT_EQ(d.requests.size(), 1u);
  EXPECT_EQ(d.requests[0].op(), idl::OP_PAUSE);

  d = speed(1.0f);
  ASSERT_EQ(d.requests.size(), 2u);
  EXPECT_EQ(d.requests[0].op(), idl::OP_SET_TIME_MODE);
  EXPECT_EQ(d.requests[0].time_mode(), idl::TIME_REALTIME);
  EXPECT_EQ(d.requests[1].op(), idl::OP_RESUME);

  d = speed(2.0f);
  ASSERT_EQ(d.requests.size(), 2u);
  EXPECT_EQ(d.requests[0].time_mode(), idl::TIME_SCALED);
  EXPECT_EQ(d.requests[0].speed(), 2.0);
  EXPECT_EQ(d.requests[1].op(), idl::OP_RESUME);

  ExpectRefused(speed(-1.0f), DecodeError::kOutOfRange);
  ExpectRefused(speed(5000.0f), DecodeError::kOutOfRange);
  // turf-sim's own range: a speed it refuses is refused here, before the command's teleports are applied (0.005 was
  // passed on: turf-sim refused it after moving the ball, and resumed a paused match).
  static_assert(kMinSimulationSpeed == kMinTimeSpeed && kMaxSimulationSpeed == kMaxTimeSpeed);
  ExpectRefused(speed(0.005f), DecodeError::kOutOfRange);
  ExpectRefused(speed(std::nextafter(static_cast<float>(kMinSimulationSpeed), 0.0f)), DecodeError::kOutOfRange);
  EXPECT_EQ(speed(0.0101f).error, DecodeError::kOk);

  context_.sync = true;  // sync mode owns time
  d = speed(2.0f);
  EXPECT_EQ(d.error, DecodeError::kOk);
  EXPECT_TRUE(d.requests.empty());
  ASSERT_EQ(d.errors.size(), 1u);
  EXPECT_EQ(d.errors[0].code, kUnsupportedSyncSpeed);
}

TEST_F(SimulatorCommandCodec, ErForceRealismKnobsBecomeARealismRequest) {
  ws::SimulatorCommand c;
  ws::RealismConfigErForce e;
  e.set_stddev_robot_p(0.002f);
  e.set_stddev_ball_p(0.003f);
  e.set_missing_ball_detections(0.05f);
  e.set_vision_delay(35'000'000);  // ns
  e.set_vision_processing_time(10'000'000);
  e.set_robot_command_loss(0.1f);
  e.set_enable_invisible_ball(true);
  e.set_camera_overlap(0.3f);  // not modelled: named
  auto* any = c.mutable_config()->mutable_realism_config()->add_custom();
  any->set_type_url("type.googleapis.com/sslsim.RealismConfigErForce");  // ER-Force's package, not ours
  any->set_value(e.SerializeAsString());
  const SimulatorCommandDecode d = Convert(c);
  ASSERT_EQ(d.error, DecodeError::kOk);
  ASSERT_EQ(d.requests.size(), 1u);
  EXPECT_EQ(d.requests[0].op(), idl::OP_SET_REALISM);
  // One typed value per knob, in the codec's table order, in turf's SI units;
  // no preset (only the named settings change).
  EXPECT_EQ(d.requests[0].realism_preset(), "");
  const std::vector<std::pair<idl::RealismParameter, double>> expected = {
      {idl::REALISM_CAMERA_BALL_POSITION_STDDEV, 0.003f},   // stddev_ball_p
      {idl::REALISM_CAMERA_ROBOT_POSITION_STDDEV, 0.002f},  // stddev_robot_p
      {idl::REALISM_CAMERA_BALL_VANISH, 0.05f},             // missing_ball_detections
      {idl::REALISM_CAMERA_PROCESSING_DELAY, 0.010},        // vision_processing_time, 10 ms in ns
      {idl::REALISM_CAMERA_LINK_LATENCY, 0.035},            // vision_delay, 35 ms in ns
      {idl::REALISM_COMMAND_LOSS, 0.1f},                    // robot_command_loss
      {idl::REALISM_CAMERA_BALL_OCCLUSION, 1.0}};           // enable_invisible_ball
  const auto& values = d.requests[0].realism_values();
  ASSERT_EQ(values.size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(values[i].parameter(), expected[i].first) << i;
    EXPECT_DOUBLE_EQ(values[i].value(), expected[i].second) << i;
  }
  ASSERT_EQ(d.errors.size(), 1u);
  EXPECT_EQ(d.errors[0].code, kUnsupportedRealism);
  EXPECT_NE(d.errors[0].message.find("camera_overlap"), std::string::npos);
  // A NaN knob refuses the whole command.
  e.set_stddev_robot_p(NAN);
  any->set_value(e.SerializeAsString());
  EXPECT_EQ(Convert(c).error, DecodeError::kNotFinite);
}

// Each knob at turf-sim's bound (core/realism_fields.h) is passed on, and the float just above it is refused here:
// a float 3.1416 for stddev_robot_phi (above pi) was passed on and refused by turf-sim after the command's teleport.
TEST_F(SimulatorCommandCodec, ErForceKnobsAreCheckedAgainstTurfSimsRanges) {
  auto knob = [&](void (*set)(ws::RealismConfigErForce*, float), float value) {
    ws::SimulatorCommand c;
    c.mutable_control()->mutable_teleport_ball()->set_x(1.0f);
    ws::RealismConfigErForce e;
    set(&e, value);
    auto* any = c.mutable_config()->mutable_realism_config()->add_custom();
    any->set_type_url("type.googleapis.com/RealismConfigErForce");
    any->set_value(e.SerializeAsString());
    return Convert(c);
  };
  auto phi = [](ws::RealismConfigErForce* e, float v) { e->set_stddev_robot_phi(v); };
  auto ball_p = [](ws::RealismConfigErForce* e, float v) { e->set_stddev_ball_p(v); };
  auto loss = [](ws::RealismConfigErForce* e, float v) { e->set_robot_command_loss(v); };
  const double pi_max = Info(RealismField::kCameraRobotOrientationStddev).max;
  const float below_pi = std::nextafter(static_cast<float>(pi_max), 0.0f);
  ASSERT_LT(below_pi, pi_max);
  EXPECT_EQ(knob(phi, below_pi).error, DecodeError::kOk);
  const SimulatorCommandDecode over = knob(phi, 3.1416f);
  ExpectRefused(over, DecodeError::kOutOfRange);
  EXPECT_TRUE(over.requests.empty()) << "the teleport is not applied either";
  EXPECT_EQ(knob(ball_p, 1.0f).error, DecodeError::kOk);
  ExpectRefused(knob(ball_p, std::nextafter(1.0f, 2.0f)), DecodeError::kOutOfRange);
  ExpectRefused(knob(loss, std::nextafter(1.0f, 2.0f)), DecodeError::kOutOfRange);
}

// Each knob alone: its one parameter and value (the mapping table row by row).
TEST_F(SimulatorCommandCodec, EachErForceKnobMapsToItsParameter) {
  struct Case {
    const char* knob;
    void (*set)(ws::RealismConfigErForce*);
    idl::RealismParameter parameter;
    double value;
  };
  const Case cases[] = {
      {"stddev_ball_p", [](ws::RealismConfigErForce* e) { e->set_stddev_ball_p(0.5f); },
       idl::REALISM_CAMERA_BALL_POSITION_STDDEV, 0.5},
      {"stddev_robot_p", [](ws::RealismConfigErForce* e) { e->set_stddev_robot_p(0.25f); },
       idl::REALISM_CAMERA_ROBOT_POSITION_STDDEV, 0.25},
      {"stddev_robot_phi", [](ws::RealismConfigErForce* e) { e->set_stddev_robot_phi(0.125f); },
       idl::REALISM_CAMERA_ROBOT_ORIENTATION_STDDEV, 0.125},
      {"enable_invisible_ball", [](ws::RealismConfigErForce* e) { e->set_enable_invisible_ball(false); },
       idl::REALISM_CAMERA_BALL_OCCLUSION, 0.0},
      {"missing_ball_detections", [](ws::RealismConfigErForce* e) { e->set_missing_ball_detections(0.75f); },
       idl::REALISM_CAMERA_BALL_VANISH, 0.75},
      {"vision_delay", [](ws::RealismConfigErForce* e) { e->set_vision_delay(2'000'000'000); },
       idl::REALISM_CAMERA_LINK_LATENCY, 2.0},
      {"vision_processing_time", [](ws::RealismConfigErForce* e) { e->set_vision_processing_time(5'000'000); },
       idl::REALISM_CAMERA_PROCESSING_DELAY, 0.005},
      {"robot_command_loss", [](ws::RealismConfigErForce* e) { e->set_robot_command_loss(0.5f); },
       idl::REALISM_COMMAND_LOSS, 0.5},
  };
  for (const Case& k : cases) {
    ws::SimulatorCommand c;
    ws::RealismConfigErForce e;
    k.set(&e);
    auto* any = c.mutable_config()->mutable_realism_config()->add_custom();
    any->set_type_url("type.googleapis.com/RealismConfigErForce");
    any->set_value(e.SerializeAsString());
    const SimulatorCommandDecode d = Convert(c);
    ASSERT_EQ(d.error, DecodeError::kOk) << k.knob;
    ASSERT_EQ(d.requests.size(), 1u) << k.knob;
    ASSERT_EQ(d.requests[0].realism_values().size(), 1u) << k.knob;
    EXPECT_EQ(d.requests[0].realism_values()[0].parameter(), k.parameter) << k.knob;
    EXPECT_DOUBLE_EQ(d.requests[0].realism_values()[0].value(), k.value) << k.knob;
    EXPECT_TRUE(d.errors.empty()) << k.knob;
  }
}

TEST_F(SimulatorCommandCodec, UnsupportedConfigIsNamedAndTheRestApplies) {
  ws::SimulatorCommand c;
  c.mutable_control()->mutable_teleport_ball()->set_x(1.0f);
  ws::SimulatorConfig* config = c.mutable_config();
  SetFieldSize(config->mutable_geometry()->mutable_field());
  ws::RobotSpecs* spec = config->add_robot_specs();
  spec->mutable_id()->set_id(0);
  spec->set_radius(0.08f);
  config->mutable_realism_config()->add_custom()->set_type_url("type.googleapis.com/other.RealismConfigOther");
  config->set_vision_port(10006);
  const SimulatorCommandDecode d = Convert(c);
  EXPECT_EQ(d.error, DecodeError::kOk);
  ASSERT_EQ(d.requests.size(), 1u);
  EXPECT_EQ(d.requests[0].op(), idl::OP_TELEPORT_BALL);
  std::vector<std::string> codes;
  for (const SimError& e : d.errors) codes.push_back(e.code);
  EXPECT_EQ(codes, (std::vector<std::string>{kUnsupportedGeometry, kUnsupportedRobotSpecs, kUnsupportedRealism,
                                             kUnsupportedVisionPort}));
  // Only geometry: no request at all, one named error.
  ws::SimulatorCommand only;
  SetFieldSize(only.mutable_config()->mutable_geometry()->mutable_field());
  const SimulatorCommandDecode g = Decode(Serialize(only));
  EXPECT_EQ(g.error, DecodeError::kOk);
  EXPECT_TRUE(g.requests.empty());
  ASSERT_EQ(g.errors.size(), 1u);
  EXPECT_EQ(g.errors[0].code, "TURF_UNSUPPORTED_CONFIG_GEOMETRY");
}

TEST_F(SimulatorCommandCodec, ByForceIsNamedAndNotDone) {
  ws::SimulatorCommand c;
  c.mutable_control()->mutable_teleport_ball()->set_x(1.0f);
  c.mutable_control()->mutable_teleport_ball()->set_by_force(true);
  ws::TeleportRobot* pushed = Robot(&c, ws::BLUE, 0);
  pushed->set_x(0.0f);
  pushed->set_by_force(true);
  Robot(&c, ws::YELLOW, 2)->set_x(-3.0f);
  const SimulatorCommandDecode d = Convert(c);
  EXPECT_EQ(d.error, DecodeError::kOk);
  ASSERT_EQ(d.requests.size(), 1u);  // only yellow 2
  EXPECT_EQ(d.requests[0].robot().team(), idl::TEAM_YELLOW);
  ASSERT_EQ(d.errors.size(), 2u);
  EXPECT_EQ(d.errors[0].code, kUnsupportedByForce);
  EXPECT_EQ(d.errors[1].code, kUnsupportedByForce);
}

// ER-Force's simulator adds the ball's radius to a teleport's z (a ball 0.5 m above the carpet); an absent z keeps
// the ball's centre at its height now.
TEST_F(SimulatorCommandCodec, TeleportBallZIsTheHeightAboveTheCarpet) {
  ws::SimulatorCommand c;
  auto* b = c.mutable_control()->mutable_teleport_ball();
  b->set_x(1.0f);
  b->set_y(1.0f);
  b->set_z(0.5f);
  SimulatorCommandDecode d = Convert(c);
  ASSERT_EQ(d.error, DecodeError::kOk);
  ASSERT_EQ(d.requests.size(), 1u);
  EXPECT_NEAR(d.requests[0].ball().position().z(), 0.5 + field_.ball_radius(), 1e-7);
  b->clear_z();
  d = Convert(c);
  ASSERT_EQ(d.error, DecodeError::kOk);
  ASSERT_EQ(d.requests.size(), 1u);
  EXPECT_EQ(d.requests[0].ball().position().z(), world_.ball().position().z());
}

TEST_F(SimulatorCommandCodec, TeleportSafelyPushesRobotsOutOfTheBallsWay) {
  ws::SimulatorCommand c;
  auto* b = c.mutable_control()->mutable_teleport_ball();
  b->set_x(1.05f);  // 5 cm from blue 0 at (1, 1)
  b->set_y(1.0f);
  b->set_z(0.0f);
  b->set_teleport_safely(true);
  const SimulatorCommandDecode d = Convert(c);
  ASSERT_EQ(d.error, DecodeError::kOk);
  ASSERT_EQ(d.requests.size(), 2u);
  EXPECT_EQ(d.requests[0].op(), idl::OP_TELEPORT_BALL);
  const idl::RobotTeleport& r = d.requests[1].robot();
  EXPECT_EQ(r.team(), idl::TEAM_BLUE);
  EXPECT_EQ(r.id(), 0);
  const double clear = 0.09 + 0.0215 + kSafeTeleportMargin;
  EXPECT_NEAR(r.position().x(), 1.05f - clear, 1e-6);  // straight away from the ball
  EXPECT_NEAR(r.position().y(), 1.0, 1e-6);
  EXPECT_EQ(r.velocity().x(), 0.0);
  EXPECT_NEAR(r.orientation(), 0.25, 1e-9);

  // A robot teleported in the same command is left where the client puts it.
  Robot(&c, ws::BLUE, 0)->set_x(-4.0f);
  const SimulatorCommandDecode e = Convert(c);
  ASSERT_EQ(e.requests.size(), 2u);
  EXPECT_EQ(e.requests[1].robot().position().x(), -4.0);
}

TEST_F(SimulatorCommandCodec, RejectedBySimNamesTheOpAndReason) {
  idl::SimControlReply reply;
  reply.op(idl::OP_TELEPORT_ROBOT);
  reply.result(idl::RESULT_REJECTED);
  reply.reason("robot teleport refused: outside_field");
  const SimError e = RejectedBySim(reply);
  EXPECT_EQ(e.code, kRejectedBySim);
  EXPECT_EQ(e.message, "turf-sim refused teleport_robot: robot teleport refused: outside_field");
}

}  // namespace
}  // namespace turf::simproto
