// Sync port: SimulationSyncRequest -> requested step (ns), command, robot commands;
// capture times of a step; SimulationSyncResponse bytes.
#include <gtest/gtest.h>

#include <limits>

#include "codecs/ssl_simulation/sync.h"
#include "tests/codecs/ssl_simulation/test_util.h"

namespace turf::simproto {
namespace {

constexpr double kStep = 0.002;

class SyncCodec : public ::testing::Test {
 protected:
  SyncDecode Decode(const ws::SimulationSyncRequest& request) {
    const std::vector<uint8_t> bytes = Serialize(request);
    return DecodeSyncRequest(bytes.data(), bytes.size(), context_, kStep);
  }
  static ws::SimulationSyncRequest Request(float sim_step) {
    ws::SimulationSyncRequest r;
    r.set_sim_step(sim_step);
    return r;
  }
  static void AddLocal(ws::SimulationSyncRequest* r, uint32_t id, float forward) {
    ws::RobotCommand* c = r->mutable_robot_control()->add_robot_commands();
    c->set_id(id);
    auto* v = c->mutable_move_command()->mutable_local_velocity();
    v->set_forward(forward);
    v->set_left(0.0f);
    v->set_angular(0.0f);
  }
  void ExpectRefused(const SyncDecode& d, DecodeError error) {
    EXPECT_EQ(d.error, error) << DecodeErrorName(d.error);
    EXPECT_EQ(d.sim_step_ns, 0);
    EXPECT_TRUE(d.command.requests.empty());
    EXPECT_TRUE(d.robots.commands.empty());
    ASSERT_FALSE(d.errors.empty());
  }

  idl::SslField field_ = test::DivAField();
  idl::WorldState world_ = test::World();
  ControlContext context_{&field_, &world_, false};
};

TEST_F(SyncCodec, StepCommandAndRobots) {
  // SimulationSyncRequest { sim_step: 0.016 } as bytes: field 1 (fixed32) = 0.016f.
  const std::vector<uint8_t> golden = {0x0D, 0x6F, 0x12, 0x83, 0x3C};
  const SyncDecode bare = DecodeSyncRequest(golden.data(), golden.size(), context_, kStep);
  ASSERT_EQ(bare.error, DecodeError::kOk);
  EXPECT_EQ(bare.sim_step_ns, 16'000'000);
  EXPECT_EQ(Serialize(Request(0.016f)), golden);

  ws::SimulationSyncRequest r = Request(0.016f);
  r.mutable_simulator_command()->mutable_control()->mutable_teleport_ball()->set_x(1.0f);
  AddLocal(&r, 0, 1.0f);
  AddLocal(&r, 18, -1.0f);  // yellow 2
  const SyncDecode d = Decode(r);
  ASSERT_EQ(d.error, DecodeError::kOk);
  EXPECT_TRUE(d.errors.empty());
  EXPECT_EQ(d.sim_step_ns, 16'000'000);
  ASSERT_EQ(d.command.requests.size(), 1u);
  EXPECT_EQ(d.command.requests[0].op(), idl::OP_TELEPORT_BALL);
  ASSERT_EQ(d.robots.commands.size(), 2u);
  EXPECT_EQ(d.robots.commands[1].team(), idl::TEAM_YELLOW);
  EXPECT_EQ(d.robots.commands[1].id(), 2);
}

TEST_F(SyncCodec, AnyPositiveFiniteSimStepUpToOneSecondIsAccepted) {
  // What every 60 Hz loop sends: 8.33 physics steps. The planner, not the
  // codec, decides how many steps each request runs.
  const SyncDecode sixtieth = Decode(Request(1.0f / 60.0f));
  ASSERT_EQ(sixtieth.error, DecodeError::kOk) << (sixtieth.errors.empty() ? "" : sixtieth.errors[0].message);
  EXPECT_TRUE(sixtieth.errors.empty());
  EXPECT_EQ(sixtieth.sim_step_ns, 16'666'668);  // 0.016666668 as the float reads
  EXPECT_EQ(Decode(Request(0.015f)).sim_step_ns, 15'000'000);
  EXPECT_EQ(Decode(Request(0.002f)).sim_step_ns, 2'000'000);
  EXPECT_EQ(Decode(Request(1.0f)).sim_step_ns, 1'000'000'000);
  EXPECT_EQ(Decode(Request(1e-9f)).sim_step_ns, 1);
  const SyncDecode tiny = Decode(Request(1e-12f));  // positive: accepted, rounds to 0 ns (zero steps)
  EXPECT_EQ(tiny.error, DecodeError::kOk);
  EXPECT_EQ(tiny.sim_step_ns, 0);
}

TEST_F(SyncCodec, ZeroNegativeNonFiniteOversizedOrAbsentSimStepIsRefused) {
  ExpectRefused(Decode(Request(0.0f)), DecodeError::kOutOfRange);
  ExpectRefused(Decode(Request(-0.0f)), DecodeError::kOutOfRange);
  ExpectRefused(Decode(Request(-1.0f)), DecodeError::kOutOfRange);
  ExpectRefused(Decode(Request(-0.016f)), DecodeError::kOutOfRange);
  ExpectRefused(Decode(Request(1.002f)), DecodeError::kOutOfRange);
  ExpectRefused(Decode(Request(std::numeric_limits<float>::max())), DecodeError::kOutOfRange);
  ExpectRefused(Decode(Request(std::numeric_limits<float>::quiet_NaN())), DecodeError::kNotFinite);
  ExpectRefused(Decode(Request(std::numeric_limits<float>::infinity())), DecodeError::kNotFinite);
  ExpectRefused(Decode(Request(-std::numeric_limits<float>::infinity())), DecodeError::kNotFinite);
  ws::SimulationSyncRequest none;
  AddLocal(&none, 0, 1.0f);
  ExpectRefused(Decode(none), DecodeError::kMissingRequired);
  const std::vector<uint8_t> bytes = Serialize(Request(0.016f));
  ExpectRefused(DecodeSyncRequest(bytes.data(), bytes.size(), context_, 0.0), DecodeError::kMissingRequired);
}

TEST_F(SyncCodec, AnyFatalPartRefusesTheWholeRequest) {
  ws::SimulationSyncRequest r = Request(0.016f);
  r.mutable_simulator_command()->mutable_control()->mutable_teleport_ball()->set_x(1.0f);
  AddLocal(&r, 0, 1.0f);
  AddLocal(&r, 1, std::numeric_limits<float>::infinity());
  ExpectRefused(Decode(r), DecodeError::kNotFinite);

  ws::SimulationSyncRequest bad_ball = Request(0.016f);
  bad_ball.mutable_simulator_command()->mutable_control()->mutable_teleport_ball()->set_x(100.0f);
  AddLocal(&bad_ball, 0, 1.0f);
  ExpectRefused(Decode(bad_ball), DecodeError::kOutsideField);

  // Cut inside the robot control (the last field): refused, nothing steps.
  const std::vector<uint8_t> bytes = Serialize(r);
  for (size_t n = bytes.size() - 10; n < bytes.size(); ++n) {
    const SyncDecode t = DecodeSyncRequest(bytes.data(), n, context_, kStep);
    EXPECT_EQ(t.error, DecodeError::kMalformed) << n;
    EXPECT_EQ(t.sim_step_ns, 0);
    EXPECT_TRUE(t.robots.commands.empty());
  }
}

TEST_F(SyncCodec, SpeedInSyncModeIsNamedNotApplied) {
  ws::SimulationSyncRequest r = Request(0.016f);
  r.mutable_simulator_command()->mutable_control()->set_simulation_speed(3.0f);
  const SyncDecode d = Decode(r);
  ASSERT_EQ(d.error, DecodeError::kOk);
  EXPECT_EQ(d.sim_step_ns, 16'000'000);
  EXPECT_TRUE(d.command.requests.empty());
  ASSERT_EQ(d.errors.size(), 1u);
  EXPECT_EQ(d.errors[0].code, kUnsupportedSyncSpeed);
}

TEST(SyncResponse, DetectionsInCaptureOrderAndFeedback) {
  const idl::SslField field = test::DivAField();
  std::vector<idl::CameraFrame> frames;
  for (int64_t t : {34'000'000, 18'000'000}) {
    for (uint32_t cam : {1u, 0u}) {
      idl::CameraFrame f;
      f.camera_id(cam);
      f.frame_number(t == 18'000'000 ? 1 : 2);
      f.capture_time_ns(t);
      f.sent_time_ns(t);
      if (cam == 0) {
        idl::DetectedBall b;
        b.position().x(1.0);
        b.position().y(2.0);
        b.position().z(0.0215);
        b.confidence(1.0f);
        f.balls().push_back(b);
      }
      frames.push_back(f);
    }
  }
  ws::SimulationSyncRequest r;
  r.set_sim_step(0.032f);
  ws::RobotCommand* c = r.mutable_robot_control()->add_robot_commands();
  c->set_id(17);
  idl::SslField f = field;
  idl::WorldState w = test::World();
  const std::vector<uint8_t> req = Serialize(r);
  const SyncDecode decoded = DecodeSyncRequest(req.data(), req.size(), {&f, &w, false}, kStep);
  ASSERT_EQ(decoded.error, DecodeError::kOk);
  const std::vector<uint8_t> bytes =
      EncodeSyncResponse(frames, field, decoded, {{{idl::TEAM_YELLOW, 1}, true}}, {{"TURF_X", "extra"}});
  ws::SimulationSyncResponse response;
  ASSERT_TRUE(response.ParseFromArray(bytes.data(), static_cast<int>(bytes.size())));
  ASSERT_EQ(response.detection_size(), 4);
  EXPECT_EQ(response.detection(0).camera_id(), 0u);
  EXPECT_DOUBLE_EQ(response.detection(0).t_capture(), 0.018);
  EXPECT_EQ(response.detection(1).camera_id(), 1u);
  EXPECT_DOUBLE_EQ(response.detection(2).t_capture(), 0.034);
  ASSERT_EQ(response.detection(0).balls_size(), 1);
  EXPECT_FLOAT_EQ(response.detection(0).balls(0).x(), 1000.0f);  // millimetres on the wire
  ASSERT_EQ(response.robot_control_response().feedback_size(), 1);
  EXPECT_EQ(response.robot_control_response().feedback(0).id(), 17u);
  EXPECT_TRUE(response.robot_control_response().feedback(0).dribbler_ball_contact());
  ASSERT_EQ(response.robot_control_response().errors_size(), 1);
  EXPECT_EQ(response.robot_control_response().errors(0).code(), "TURF_X");

  // The same inputs give the same bytes, whatever order the frames came in.
  std::vector<idl::CameraFrame> reversed(frames.rbegin(), frames.rend());
  EXPECT_EQ(EncodeSyncResponse(reversed, field, decoded, {{{idl::TEAM_YELLOW, 1}, true}}, {{"TURF_X", "extra"}}),
            bytes);
}

TEST(SyncResponse, TooManyDetectionsLeaveOutTheOldestToFitOneDatagram) {
  const idl::SslField field = test::DivAField();
  std::vector<idl::CameraFrame> frames;
  for (int i = 1; i <= 400; ++i) {
    idl::CameraFrame f;
    f.camera_id(static_cast<uint32_t>(i % 4));
    f.frame_number(static_cast<uint64_t>(i));
    f.capture_time_ns(i * 1'000'000LL);
    f.sent_time_ns(i * 1'000'000LL);
    for (int id = 0; id < 8; ++id) {
      idl::DetectedRobot r;
      r.id(static_cast<uint8_t>(id));
      r.position().x(0.5 * id);
      r.confidence(1.0f);
      f.robots().push_back(r);
    }
    frames.push_back(f);
  }
  const std::vector<uint8_t> bytes = EncodeSyncResponse(frames, field, SyncDecode{}, {}, {});
  EXPECT_LE(bytes.size(), kMaxResponseBytes);
  ws::SimulationSyncResponse response;
  ASSERT_TRUE(response.ParseFromArray(bytes.data(), static_cast<int>(bytes.size())));
  EXPECT_GT(response.detection_size(), 50);
  EXPECT_LT(response.detection_size(), 400);
  EXPECT_EQ(response.detection(response.detection_size() - 1).frame_number(), 400u);  // the newest stay
  ASSERT_EQ(response.robot_control_response().errors_size(), 1);
  EXPECT_EQ(response.robot_control_response().errors(0).code(), kSyncResponseTooLarge);
}

TEST(SyncResponse, RefusedRequestAnswersWithItsErrors) {
  const idl::SslField field = test::DivAField();
  const std::vector<uint8_t> garbage = {0xFF, 0x01};
  const SyncDecode d = DecodeSyncRequest(garbage.data(), garbage.size(), {&field, nullptr, false}, kStep);
  EXPECT_EQ(d.error, DecodeError::kMalformed);
  const std::vector<uint8_t> bytes = EncodeSyncResponse({}, field, d, {}, {});
  ws::SimulationSyncResponse response;
  ASSERT_TRUE(response.ParseFromArray(bytes.data(), static_cast<int>(bytes.size())));
  EXPECT_EQ(response.detection_size(), 0);
  ASSERT_EQ(response.robot_control_response().errors_size(), 1);
  EXPECT_EQ(response.robot_control_response().errors(0).code(), "TURF_MALFORMED");
}

}  // namespace
}  // namespace turf::simproto
