// Tracked data (TrackerWrapperPacket) from a world state: contents and units.
#include <gtest/gtest.h>

#include <cmath>

#include "codecs/proto/ssl_vision.pb.h"
#include "codecs/ssl_vision/tracked.h"
#include "tests/support/idl_values.h"

namespace turf::vision {
namespace {

using test::V3;

idl::RobotState Robot(idl::Team team, int id, bool on_field, double x, double y, double yaw) {
  idl::RobotState r;
  r.team(team);
  r.id(static_cast<uint8_t>(id));
  r.on_field(on_field);
  r.position(V3(x, y, 0.0));
  r.yaw(yaw);
  r.linear_velocity(V3(0.5, -0.25, 0.0));
  r.angular_velocity(V3(0.0, 0.0, 2.0));
  return r;
}

idl::WorldState State() {
  idl::WorldState s;
  s.sim_time_ns(3'000'000'000);
  s.frame(1500);
  s.ball().position(V3(1.0, -2.0, 0.3));
  s.ball().velocity(V3(3.0, 0.5, 1.25));
  s.robots().push_back(Robot(idl::TEAM_BLUE, 2, true, -1.5, 0.75, 1.0));
  s.robots().push_back(Robot(idl::TEAM_YELLOW, 15, true, 2.0, 1.0, -3.0));
  s.robots().push_back(Robot(idl::TEAM_YELLOW, 4, false, 0.0, 0.0, 0.0));  // parked: not sent
  return s;
}

TEST(SslVisionTracked, PacketContents) {
  std::vector<uint8_t> bytes;
  ASSERT_EQ(EncodeTracked(State(), {"0b5e-uuid", "turf"}, 1'700'000'000.5, &bytes), VisionError::kOk);
  wire::vision::TrackerWrapperPacket packet;
  ASSERT_TRUE(packet.ParseFromArray(bytes.data(), static_cast<int>(bytes.size())));
  ASSERT_TRUE(packet.IsInitialized());
  EXPECT_EQ(packet.uuid(), "0b5e-uuid");
  EXPECT_EQ(packet.source_name(), "turf");
  const wire::vision::TrackedFrame& f = packet.tracked_frame();
  EXPECT_EQ(f.frame_number(), 1500u);
  EXPECT_DOUBLE_EQ(f.timestamp(), 1'700'000'000.5);
  ASSERT_EQ(f.balls_size(), 1);
  EXPECT_FLOAT_EQ(f.balls(0).pos().x(), 1.0f);  // metres
  EXPECT_FLOAT_EQ(f.balls(0).pos().y(), -2.0f);
  EXPECT_FLOAT_EQ(f.balls(0).pos().z(), 0.3f);
  EXPECT_FLOAT_EQ(f.balls(0).vel().x(), 3.0f);
  EXPECT_FLOAT_EQ(f.balls(0).vel().z(), 1.25f);
  ASSERT_EQ(f.robots_size(), 2);
  const auto& blue = f.robots(0);
  EXPECT_EQ(blue.robot_id().id(), 2u);
  EXPECT_EQ(blue.robot_id().team_color(), wire::vision::TEAM_COLOR_BLUE);
  EXPECT_FLOAT_EQ(blue.pos().x(), -1.5f);
  EXPECT_FLOAT_EQ(blue.pos().y(), 0.75f);
  EXPECT_FLOAT_EQ(blue.orientation(), 1.0f);
  EXPECT_FLOAT_EQ(blue.vel().x(), 0.5f);
  EXPECT_FLOAT_EQ(blue.vel().y(), -0.25f);
  EXPECT_FLOAT_EQ(blue.vel_angular(), 2.0f);
  const auto& yellow = f.robots(1);
  EXPECT_EQ(yellow.robot_id().id(), 15u);
  EXPECT_EQ(yellow.robot_id().team_color(), wire::vision::TEAM_COLOR_YELLOW);
  EXPECT_FLOAT_EQ(yellow.orientation(), -3.0f);
  ASSERT_EQ(f.capabilities_size(), 1);
  EXPECT_EQ(f.capabilities(0), wire::vision::CAPABILITY_DETECT_FLYING_BALLS);
  EXPECT_FALSE(f.has_kicked_ball());
}

TEST(SslVisionTracked, RefusesBadStatesAndTimes) {
  auto with = [](auto change, double timestamp = 1.0) {
    idl::WorldState s = State();
    change(s);
    std::vector<uint8_t> bytes{1};
    const VisionError e = EncodeTracked(s, {"u", "turf"}, timestamp, &bytes);
    if (e != VisionError::kOk) {
      EXPECT_TRUE(bytes.empty());
    }
    return e;
  };
  EXPECT_EQ(with([](idl::WorldState&) {}), VisionError::kOk);
  EXPECT_EQ(with([](idl::WorldState& s) { s.ball().position().x(NAN); }), VisionError::kNotFinite);
  EXPECT_EQ(with([](idl::WorldState& s) { s.ball().velocity().z(1e9); }), VisionError::kOutOfRange);
  EXPECT_EQ(with([](idl::WorldState& s) { s.robots()[0].yaw(INFINITY); }), VisionError::kNotFinite);
  EXPECT_EQ(with([](idl::WorldState& s) { s.robots()[1].id(16); }), VisionError::kBadRobotId);
  EXPECT_EQ(with([](idl::WorldState& s) { s.robots()[0].team(static_cast<idl::Team>(3)); }), VisionError::kUnknownTeam);
  // A parked robot's garbage pose is never sent, so it does not matter.
  EXPECT_EQ(with([](idl::WorldState& s) { s.robots()[2].position().x(NAN); }), VisionError::kOk);
  EXPECT_EQ(with([](idl::WorldState&) {}, 0.0), VisionError::kTimeNotPositive);
  EXPECT_EQ(with([](idl::WorldState&) {}, NAN), VisionError::kNotFinite);
}

}  // namespace
}  // namespace turf::vision
