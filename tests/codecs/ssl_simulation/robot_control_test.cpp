// Team ports: RobotControl bytes -> turf robot commands, RobotControlResponse
// bytes. Golden bytes are annotated field by field (proto2 wire format).
#include <gtest/gtest.h>

#include <functional>

#include <cmath>
#include <limits>

#include "codecs/ssl_simulation/robot_control.h"
#include "tests/codecs/ssl_simulation/test_util.h"

namespace turf::simproto {
namespace {

// RobotControl { robot_commands { id: 3, move_command { local_velocity { forward: 1, left: 0.5,
// angular: -2 } }, kick_speed: 4 } }
const std::vector<uint8_t> kLocalVelocityAndKick = {
    0x0A, 0x1A,                    // robot_commands (1, LEN), 26 bytes
    0x08, 0x03,                    //   id (1, varint) = 3
    0x12, 0x11,                    //   move_command (2, LEN), 17 bytes
    0x12, 0x0F,                    //     local_velocity (2, LEN), 15 bytes
    0x0D, 0x00, 0x00, 0x80, 0x3F,  //       forward (1, fixed32) = 1.0f
    0x15, 0x00, 0x00, 0x00, 0x3F,  //       left (2, fixed32) = 0.5f
    0x1D, 0x00, 0x00, 0x00, 0xC0,  //       angular (3, fixed32) = -2.0f
    0x1D, 0x00, 0x00, 0x80, 0x40,  //   kick_speed (3, fixed32) = 4.0f
};

RobotControlDecode Decode(const std::vector<uint8_t>& bytes, Port port = Port::kBlue, int per_team = 6) {
  return DecodeRobotControl(bytes.data(), bytes.size(), port, per_team);
}

void ExpectRefused(const RobotControlDecode& d, DecodeError error) {
  EXPECT_EQ(d.error, error) << DecodeErrorName(d.error);
  EXPECT_TRUE(d.commands.empty());
  EXPECT_TRUE(d.wire_ids.empty());
  ASSERT_FALSE(d.errors.empty());
  EXPECT_EQ(d.errors.front().code, DecodeErrorCode(error));
}

TEST(RobotControlCodec, GoldenLocalVelocityAndFlatKick) {
  const RobotControlDecode d = Decode(kLocalVelocityAndKick, Port::kYellow);
  ASSERT_EQ(d.error, DecodeError::kOk);
  EXPECT_TRUE(d.errors.empty());
  ASSERT_EQ(d.commands.size(), 1u);
  const idl::SslRobotCommand& c = d.commands[0];
  EXPECT_EQ(c.team(), idl::TEAM_YELLOW);  // the port decides the team
  EXPECT_EQ(c.id(), 3);
  EXPECT_EQ(c.move(), idl::MOVE_LOCAL_VELOCITY);
  EXPECT_EQ(c.velocity().x(), 1.0);
  EXPECT_EQ(c.velocity().y(), 0.5);
  EXPECT_EQ(c.velocity().z(), -2.0);
  EXPECT_EQ(c.kick(), idl::KICK_FLAT);
  EXPECT_EQ(c.kick_speed(), 4.0);
  EXPECT_EQ(c.chip_angle(), 0.0);
  EXPECT_EQ(c.dribbler_speed(), 0.0);
  EXPECT_EQ(d.wire_ids, std::vector<uint32_t>{3});

  // The annotation is what protobuf itself writes.
  ws::RobotControl rc;
  ws::RobotCommand* rcmd = AddLocal(&rc, 3, 1.0f);
  rcmd->mutable_move_command()->mutable_local_velocity()->set_left(0.5f);
  rcmd->mutable_move_command()->mutable_local_velocity()->set_angular(-2.0f);
  rcmd->set_kick_speed(4.0f);
  EXPECT_EQ(Serialize(rc), kLocalVelocityAndKick);
}

TEST(RobotControlCodec, GoldenResponseCarriesContactForEveryCommandedRobot) {
  const RobotControlDecode d = Decode(kLocalVelocityAndKick, Port::kBlue);
  ContactMap contacts;
  contacts[{idl::TEAM_BLUE, 3}] = true;
  contacts[{idl::TEAM_YELLOW, 3}] = false;
  const std::vector<uint8_t> expected = {
      0x12, 0x04,  // feedback (2, LEN), 4 bytes
      0x08, 0x03,  //   id (1, varint) = 3
      0x10, 0x01,  //   dribbler_ball_contact (2, varint) = true
  };
  EXPECT_EQ(EncodeRobotControlResponse(d, contacts), expected);

  // Without a feedback sample a robot has no contact, and is still answered.
  const std::vector<uint8_t> no_contact = {0x12, 0x04, 0x08, 0x03, 0x10, 0x00};
  EXPECT_EQ(EncodeRobotControlResponse(d, {}), no_contact);

  ws::RobotControl rc;
  for (uint32_t id : {0u, 4u, 5u}) AddLocal(&rc, id, 0.5f);
  const RobotControlDecode three = ConvertRobotControl(rc, Port::kBlue, 6);
  ws::RobotControlResponse response;
  ASSERT_TRUE(response.ParseFromString(std::string(
      reinterpret_cast<const char*>(EncodeRobotControlResponse(three, {{{idl::TEAM_BLUE, 4}, true}}).data()),
      EncodeRobotControlResponse(three, {{{idl::TEAM_BLUE, 4}, true}}).size())));
  ASSERT_EQ(response.feedback_size(), 3);
  EXPECT_EQ(response.feedback(0).id(), 0u);
  EXPECT_FALSE(response.feedback(0).dribbler_ball_contact());
  EXPECT_EQ(response.feedback(1).id(), 4u);
  EXPECT_TRUE(response.feedback(1).dribbler_ball_contact());
  EXPECT_EQ(response.errors_size(), 0);
}

TEST(RobotControlCodec, GoldenResponseWithError) {
  const RobotControlDecode d = Decode({0xFF, 0xFF, 0xFF});
  const std::vector<uint8_t> bytes = EncodeRobotControlResponse(d, {});
  ws::RobotControlResponse response;
  ASSERT_TRUE(response.ParseFromArray(bytes.data(), static_cast<int>(bytes.size())));
  EXPECT_EQ(response.feedback_size(), 0);
  ASSERT_EQ(response.errors_size(), 1);
  EXPECT_EQ(response.errors(0).code(), "TURF_MALFORMED");
}

TEST(RobotControlCodec, EveryTruncationIsANamedErrorWithNoCommand) {
  for (size_t n = 0; n < kLocalVelocityAndKick.size(); ++n) {
    SCOPED_TRACE(n);
    const RobotControlDecode d = DecodeRobotControl(kLocalVelocityAndKick.data(), n, Port::kBlue, 6);
    ExpectRefused(d, n == 0 ? DecodeError::kEmpty : DecodeError::kMalformed);
  }
}

TEST(RobotControlCodec, MissingRequiredFields) {
  // robot_commands { kick_speed: 4 }: no id.
  ExpectRefused(Decode({0x0A, 0x05, 0x1D, 0x00, 0x00, 0x80, 0x40}), DecodeError::kMissingRequired);
  // local_velocity without angular.
  ws::RobotControl rc;
  AddLocal(&rc, 1, 1.0f)->mutable_move_command()->mutable_local_velocity()->clear_angular();
  ExpectRefused(Decode(Serialize(rc)), DecodeError::kMissingRequired);
}

TEST(RobotControlCodec, GarbageAndOversized) {
  ExpectRefused(Decode({0xFF, 0xFF, 0xFF, 0xFF}), DecodeError::kMalformed);
  ExpectRefused(Decode({0x0A}), DecodeError::kMalformed);
  ExpectRefused(Decode(std::vector<uint8_t>(kMaxDatagramBytes + 1, 0)), DecodeError::kOversized);
}

TEST(RobotControlCodec, NonFiniteOrOutOfRangeAnywhereRefusesTheWholeDatagram) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  struct Case {
    const char* what;
    void (*spoil)(ws::RobotCommand*, float, float);
    DecodeError error;
  };
  const Case cases[] = {
      {"forward nan",
       [](ws::RobotCommand* c, float n, float) { c->mutable_move_command()->mutable_local_velocity()->set_forward(n); },
       DecodeError::kNotFinite},
      {"kick inf", [](ws::RobotCommand* c, float, float i) { c->set_kick_speed(i); }, DecodeError::kNotFinite},
      {"dribbler nan", [](ws::RobotCommand* c, float n, float) { c->set_dribbler_speed(n); }, DecodeError::kNotFinite},
      {"speed 25",
       [](ws::RobotCommand* c, float, float) {
         c->mutable_move_command()->mutable_local_velocity()->set_forward(25.0f);
       },
       DecodeError::kOutOfRange},
      {"hypot 15+15",
       [](ws::RobotCommand* c, float, float) {
         c->mutable_move_command()->mutable_local_velocity()->set_forward(15.0f);
         c->mutable_move_command()->mutable_local_velocity()->set_left(15.0f);
       },
       DecodeError::kOutOfRange},
      {"kick -1", [](ws::RobotCommand* c, float, float) { c->set_kick_speed(-1.0f); }, DecodeError::kOutOfRange},
      {"kick 31", [](ws::RobotCommand* c, float, float) { c->set_kick_speed(31.0f); }, DecodeError::kOutOfRange},
      {"angle 90",
       [](ws::RobotCommand* c, float, float) {
         c->set_kick_speed(3.0f);
         c->set_kick_angle(90.0f);
       },
       DecodeError::kOutOfRange},
      {"angle -5", [](ws::RobotCommand* c, float, float) { c->set_kick_angle(-5.0f); }, DecodeError::kOutOfRange},
      {"dribbler -100", [](ws::RobotCommand* c, float, float) { c->set_dribbler_speed(-100.0f); },
       DecodeError::kOutOfRange},
      {"wheel inf",
       [](ws::RobotCommand* c, float, float i) {
         auto* w = c->mutable_move_command()->mutable_wheel_velocity();
         w->set_front_right(1.0f);
         w->set_back_right(1.0f);
         w->set_back_left(i);
         w->set_front_left(1.0f);
       },
       DecodeError::kNotFinite},
  };
  for (const Case& k : cases) {
    SCOPED_TRACE(k.what);
    ws::RobotControl rc;
    AddLocal(&rc, 0, 1.0f);  // a good command first: it must not go out either
    k.spoil(AddLocal(&rc, 1, 1.0f), nan, inf);
    ExpectRefused(Decode(Serialize(rc)), k.error);
  }
}

TEST(RobotControlCodec, UnknownRobotsAndDuplicates) {
  ws::RobotControl rc;
  AddLocal(&rc, 0, 1.0f);
  AddLocal(&rc, 16, 1.0f);
  ExpectRefused(Decode(Serialize(rc), Port::kBlue, 16), DecodeError::kUnknownRobot);  // id 16 never exists
  ws::RobotControl six;
  AddLocal(&six, 6, 1.0f);
  ExpectRefused(Decode(Serialize(six), Port::kBlue, 6), DecodeError::kUnknownRobot);  // ids 0..5
  EXPECT_EQ(Decode(Serialize(six), Port::kBlue, 7).error, DecodeError::kOk);
  ws::RobotControl twice;
  AddLocal(&twice, 2, 1.0f);
  AddLocal(&twice, 2, -1.0f);
  ExpectRefused(Decode(Serialize(twice)), DecodeError::kDuplicateRobot);
}

TEST(RobotControlCodec, WheelGlobalChipDribblerAndStop) {
  ws::RobotControl rc;
  ws::RobotCommand* wheels = rc.add_robot_commands();
  wheels->set_id(0);
  auto* w = wheels->mutable_move_command()->mutable_wheel_velocity();
  w->set_front_right(1.0f);
  w->set_back_right(2.0f);
  w->set_back_left(3.0f);
  w->set_front_left(4.0f);
  ws::RobotCommand* global = rc.add_robot_commands();
  global->set_id(1);
  auto* g = global->mutable_move_command()->mutable_global_velocity();
  g->set_x(-1.0f);
  g->set_y(2.0f);
  g->set_angular(3.0f);
  global->set_kick_speed(5.0f);
  global->set_kick_angle(45.0f);
  global->set_dribbler_speed(1000.0f);
  ws::RobotCommand* stop = rc.add_robot_commands();
  stop->set_id(2);
  stop->set_kick_angle(30.0f);  // an angle without a speed is no kick
  const RobotControlDecode d = Decode(Serialize(rc));
  ASSERT_EQ(d.error, DecodeError::kOk);
  ASSERT_EQ(d.commands.size(), 3u);
  EXPECT_EQ(d.commands[0].move(), idl::MOVE_WHEEL_VELOCITY);
  EXPECT_EQ(d.commands[0].wheel_velocity(), (std::array<double, 4>{1.0, 2.0, 3.0, 4.0}));
  EXPECT_EQ(d.commands[0].kick(), idl::KICK_NONE);
  EXPECT_EQ(d.commands[1].move(), idl::MOVE_GLOBAL_VELOCITY);
  EXPECT_EQ(d.commands[1].velocity().x(), -1.0);
  EXPECT_EQ(d.commands[1].velocity().y(), 2.0);
  EXPECT_EQ(d.commands[1].velocity().z(), 3.0);
  EXPECT_EQ(d.commands[1].kick(), idl::KICK_CHIP);
  EXPECT_DOUBLE_EQ(d.commands[1].chip_angle(), M_PI / 4);
  EXPECT_EQ(d.commands[1].kick_speed(), 5.0);
  EXPECT_EQ(d.commands[1].dribbler_speed(), 1000.0);
  EXPECT_EQ(d.commands[2].move(), idl::MOVE_NONE);
  EXPECT_EQ(d.commands[2].kick(), idl::KICK_NONE);
}

TEST(RobotControlCodec, SyncPortMapsIdsSixteenUpToYellow) {
  ws::RobotControl rc;
  AddLocal(&rc, 3, 1.0f);
  AddLocal(&rc, 19, 1.0f);
  const RobotControlDecode d = Decode(Serialize(rc), Port::kSync);
  ASSERT_EQ(d.error, DecodeError::kOk);
  ASSERT_EQ(d.commands.size(), 2u);
  EXPECT_EQ(d.commands[0].team(), idl::TEAM_BLUE);
  EXPECT_EQ(d.commands[0].id(), 3);
  EXPECT_EQ(d.commands[1].team(), idl::TEAM_YELLOW);
  EXPECT_EQ(d.commands[1].id(), 3);
  EXPECT_EQ(d.wire_ids, (std::vector<uint32_t>{3, 19}));
  ws::RobotControl too_high;
  AddLocal(&too_high, 32, 1.0f);
  ExpectRefused(Decode(Serialize(too_high), Port::kSync, 16), DecodeError::kUnknownRobot);
  ws::RobotControl yellow_missing;
  AddLocal(&yellow_missing, 22, 1.0f);  // yellow 6 of a 6-a-side scene
  ExpectRefused(Decode(Serialize(yellow_missing), Port::kSync, 6), DecodeError::kUnknownRobot);
}

// Robot 1 driving forward at 0.5 m/s.
ws::RobotControl OneLocalCommand() {
  ws::RobotControl rc;
  ws::RobotCommand* c = rc.add_robot_commands();
  c->set_id(1);
  c->mutable_move_command()->mutable_local_velocity()->set_forward(0.5f);
  c->mutable_move_command()->mutable_local_velocity()->set_left(0.0f);
  c->mutable_move_command()->mutable_local_velocity()->set_angular(0.0f);
  return rc;
}

TEST(RobotControlCodec, UnknownFieldsAreAppliedButNamed) {
  std::vector<uint8_t> bytes = kLocalVelocityAndKick;
  bytes[1] += 2;
  bytes.insert(bytes.end(), {0x48, 0x01});  // robot command field 9 (varint) = 1: not in the protocol
  const RobotControlDecode d = Decode(bytes);
  ASSERT_EQ(d.error, DecodeError::kOk);
  EXPECT_EQ(d.commands.size(), 1u);
  ASSERT_EQ(d.errors.size(), 1u);
  EXPECT_EQ(d.errors[0].code, kUnknownField);
  EXPECT_NE(d.errors[0].message.find("robot_commands[0].#9"), std::string::npos) << d.errors[0].message;
}

// A response stays small whatever the request: 1800 unknown fields in a 3.6 KB datagram were answered with 65 KB
// (an 18x reflector), and 1500 duplicates were refused with an answer too big to send.
TEST(RobotControlCodec, AResponseListsBoundedErrors) {
  ws::RobotControl rc = OneLocalCommand();
  ws::RobotCommand* c = rc.mutable_robot_commands(0);
  for (int i = 0; i < 1800; ++i) c->mutable_move_command()->mutable_unknown_fields()->AddVarint(15, 0);
  const std::vector<uint8_t> request = Serialize(rc);
  const RobotControlDecode d = Decode(request);
  const std::vector<uint8_t> response = EncodeRobotControlResponse(d, {}, {});
  EXPECT_LT(response.size(), 1024u) << "for a request of " << request.size() << " bytes";

  ws::RobotControl dups;
  for (int i = 0; i < 1500; ++i) dups.add_robot_commands()->set_id(0);
  const RobotControlDecode refused = ConvertRobotControl(dups, Port::kBlue, 11);
  ASSERT_NE(refused.error, DecodeError::kOk);
  ws::RobotControlResponse out;
  FillRobotControlResponse(refused, {}, {}, &out);
  ASSERT_EQ(out.errors_size(), static_cast<int>(kMaxListedErrors) + 1);
  EXPECT_EQ(out.errors(static_cast<int>(kMaxListedErrors)).code(), kMoreErrors);
  EXPECT_LT(out.ByteSizeLong(), size_t{16} * 1024);
}

// At every depth of a command (the top message, a command, its move, its velocity) an unknown field is named.
TEST(RobotControlCodec, UnknownFieldsAreNamedAtEveryDepth) {
  auto with_unknown = [](const std::function<google::protobuf::UnknownFieldSet*(ws::RobotControl*)>& where) {
    ws::RobotControl rc = OneLocalCommand();
    where(&rc)->AddVarint(99, 1);
    return ConvertRobotControl(rc, Port::kBlue, 11);
  };
  const std::pair<const char*, std::function<google::protobuf::UnknownFieldSet*(ws::RobotControl*)>> cases[] = {
      {"#99", [](ws::RobotControl* rc) { return rc->mutable_unknown_fields(); }},
      {"robot_commands[0].#99",
       [](ws::RobotControl* rc) { return rc->mutable_robot_commands(0)->mutable_unknown_fields(); }},
      {"robot_commands[0].move_command.#99",
       [](ws::RobotControl* rc) {
         return rc->mutable_robot_commands(0)->mutable_move_command()->mutable_unknown_fields();
       }},
      {"robot_commands[0].move_command.local_velocity.#99",
       [](ws::RobotControl* rc) {
         return rc->mutable_robot_commands(0)
             ->mutable_move_command()
             ->mutable_local_velocity()
             ->mutable_unknown_fields();
       }},
  };
  for (const auto& [path, where] : cases) {
    const RobotControlDecode d = with_unknown(where);
    EXPECT_EQ(d.commands.size(), 1u) << path;
    ASSERT_EQ(d.errors.size(), 1u) << path;
    EXPECT_EQ(d.errors[0].code, kUnknownField) << path;
    EXPECT_NE(d.errors[0].message.find(path), std::string::npos) << d.errors[0].message;
  }
}

TEST(RobotControlCodec, EmptyRobotControlIsNoCommand) {
  // A zero-length datagram is refused; an explicit empty message cannot be sent (it has no bytes).
  ws::RobotControl rc;
  EXPECT_TRUE(Serialize(rc).empty());
  ExpectRefused(Decode(Serialize(rc)), DecodeError::kEmpty);
}

}  // namespace
}  // namespace turf::simproto
