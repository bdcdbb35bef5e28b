// grSim robot status: golden bytes and the change semantics of StatusTracker.
#include <gtest/gtest.h>

#include <vector>

#include "codecs/grsim/robot_status.h"
#include "codecs/proto/grsim.pb.h"

namespace turf::grsim {
namespace {

using Packets = std::vector<std::vector<RobotStatus>>;

idl::SslRobotFeedback Feedback(idl::Team team, int id, int64_t t_ms, bool contact, uint32_t kicks,
                               idl::KickKind last = idl::KICK_NONE) {
  idl::SslRobotFeedback f;
  f.team(team);
  f.id(static_cast<uint8_t>(id));
  f.sim_time_ns(t_ms * 1'000'000);
  f.ball_contact(contact);
  f.kick_count(kicks);
  f.last_kick(last);
  return f;
}

RobotStatus Status(int id, bool infrared, bool flat = false, bool chip = false) {
  RobotStatus s;
  s.robot_id = id;
  s.infrared = infrared;
  s.flat_kick = flat;
  s.chip_kick = chip;
  return s;
}

TEST(GrsimStatus, GoldenBytes) {
  const std::vector<uint8_t> expected = {
      0x0A, 0x08,  // Robots_Status.robots_status (1, LEN), 8 bytes
      0x08, 0x02,  //   robot_id (1, VARINT) = 2
      0x10, 0x01,  //   infrared (2, VARINT) = true
      0x18, 0x00,  //   flat_kick (3, VARINT) = false
      0x20, 0x00,  //   chip_kick (4, VARINT) = false
      0x0A, 0x08,  // robots_status, 8 bytes
      0x08, 0x0F,  //   robot_id = 15
      0x10, 0x00,  //   infrared = false
      0x18, 0x00,  //   flat_kick = false
      0x20, 0x01,  //   chip_kick = true
  };
  EXPECT_EQ(EncodeStatus({Status(2, true), Status(15, false, false, true)}), expected);
  EXPECT_TRUE(EncodeStatus({}).empty());
  // And a grSim client reads it back.
  turf::wire::grsim::Robots_Status parsed;
  ASSERT_TRUE(parsed.ParseFromArray(expected.data(), static_cast<int>(expected.size())));
  ASSERT_EQ(parsed.robots_status_size(), 2);
  EXPECT_TRUE(parsed.robots_status(1).chip_kick());
}

TEST(GrsimStatus, OnlyChangesAreReported) {
  StatusTracker tracker;
  tracker.Feed(Feedback(idl::TEAM_BLUE, 3, 10, false, 0));  // as grSim starts: all false, nothing to say
  EXPECT_TRUE(tracker.TakePackets(idl::TEAM_BLUE).empty());
  tracker.Feed(Feedback(idl::TEAM_BLUE, 3, 20, true, 0));
  EXPECT_EQ(tracker.TakePackets(idl::TEAM_BLUE), Packets({{Status(3, true)}}));
  tracker.Feed(Feedback(idl::TEAM_BLUE, 3, 30, true, 0));  // same booleans
  EXPECT_TRUE(tracker.TakePackets(idl::TEAM_BLUE).empty());
  EXPECT_TRUE(tracker.TakePackets(idl::TEAM_YELLOW).empty());
}

TEST(GrsimStatus, AKickIsTrueOnceThenFalseAtTheNextChange) {
  StatusTracker tracker;
  tracker.Feed(Feedback(idl::TEAM_YELLOW, 1, 10, true, 0));
  tracker.TakePackets(idl::TEAM_YELLOW);
  tracker.Feed(Feedback(idl::TEAM_YELLOW, 1, 20, false, 1, idl::KICK_FLAT));  // kicked: the ball leaves
  EXPECT_EQ(tracker.TakePackets(idl::TEAM_YELLOW), Packets({{Status(1, false, true)}}));
  tracker.Feed(Feedback(idl::TEAM_YELLOW, 1, 500, true, 1, idl::KICK_FLAT));  // touches again, no new kick
  EXPECT_EQ(tracker.TakePackets(idl::TEAM_YELLOW), Packets({{Status(1, true, false)}}));
  tracker.Feed(Feedback(idl::TEAM_YELLOW, 1, 600, false, 2, idl::KICK_CHIP));
  EXPECT_EQ(tracker.TakePackets(idl::TEAM_YELLOW), Packets({{Status(1, false, false, true)}}));
  tracker.Feed(Feedback(idl::TEAM_YELLOW, 1, 700, true, 2, idl::KICK_CHIP));
  EXPECT_EQ(tracker.TakePackets(idl::TEAM_YELLOW), Packets({{Status(1, true)}}));
}

TEST(GrsimStatus, ChangesBetweenTakesAreAllKept) {
  StatusTracker tracker;
  tracker.Feed(Feedback(idl::TEAM_BLUE, 0, 10, true, 0));
  tracker.Feed(Feedback(idl::TEAM_BLUE, 4, 10, true, 0));
  tracker.Feed(Feedback(idl::TEAM_BLUE, 0, 12, false, 1, idl::KICK_FLAT));  // robot 0 again: a second packet
  tracker.Feed(Feedback(idl::TEAM_YELLOW, 0, 12, true, 0));
  EXPECT_EQ(tracker.TakePackets(idl::TEAM_BLUE),
            Packets({{Status(0, true), Status(4, true)}, {Status(0, false, true)}}));
  EXPECT_EQ(tracker.TakePackets(idl::TEAM_YELLOW), Packets({{Status(0, true)}}));
  EXPECT_TRUE(tracker.TakePackets(idl::TEAM_BLUE).empty());
}

TEST(GrsimStatus, KicksBeforeTheBridgeListenedAreNotReported) {
  StatusTracker tracker;
  tracker.Feed(Feedback(idl::TEAM_BLUE, 2, 9000, false, 7, idl::KICK_CHIP));  // a late joiner's first sample
  EXPECT_TRUE(tracker.TakePackets(idl::TEAM_BLUE).empty());
  tracker.Feed(Feedback(idl::TEAM_BLUE, 2, 9100, false, 8, idl::KICK_FLAT));
  EXPECT_EQ(tracker.TakePackets(idl::TEAM_BLUE), Packets({{Status(2, false, true)}}));
}

TEST(GrsimStatus, AResetRestartsKickCounts) {
  StatusTracker tracker;
  tracker.Feed(Feedback(idl::TEAM_BLUE, 0, 1000, true, 0));
  tracker.Feed(Feedback(idl::TEAM_BLUE, 0, 1010, false, 1, idl::KICK_FLAT));
  tracker.Feed(Feedback(idl::TEAM_BLUE, 0, 2000, true, 1, idl::KICK_FLAT));
  tracker.TakePackets(idl::TEAM_BLUE);
  // Reset: time restarts; the first kick after it brings the count back to 1.
  tracker.Feed(Feedback(idl::TEAM_BLUE, 0, 50, false, 1, idl::KICK_FLAT));
  EXPECT_EQ(tracker.TakePackets(idl::TEAM_BLUE), Packets({{Status(0, false, true)}}));
}

TEST(GrsimStatus, StrangeSamplesAreIgnored) {
  StatusTracker tracker;
  tracker.Feed(Feedback(idl::TEAM_BLUE, 16, 10, true, 0));
  tracker.Feed(Feedback(static_cast<idl::Team>(7), 0, 10, true, 0));
  EXPECT_TRUE(tracker.TakePackets(idl::TEAM_BLUE).empty());
  EXPECT_TRUE(tracker.TakePackets(idl::TEAM_YELLOW).empty());
  EXPECT_TRUE(tracker.TakePackets(static_cast<idl::Team>(7)).empty());
}

}  // namespace
}  // namespace turf::grsim
