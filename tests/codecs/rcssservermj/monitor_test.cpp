// Monitor-port commands (shared/protocols/rcssservermj.md, "Monitor port 60001").
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "codecs/rcssservermj/monitor.h"
#include "tests/support/issues.h"

namespace turf::rcssservermj {
namespace {

TEST(MjMonitor, TheFactsCommands) {
  const MonitorMessage m = ParseMonitorMessage(
      "(kickOff Left)(kickOff r)(kickOff)(dropBall)(ball (pos 1 2 0.11) (vel 0 0 0))"
      "(agent (unum 2) (team teamBlue) (pos -3 0 0.7))(agent (unum 2) (team Left) (move -3 0 0.7 90))"
      "(agent (unum 2) (team Right) (move3d -3 0 0.7 1 0 0 0))(playMode PlayOn)(killsim)");
  ASSERT_TRUE(m.issues.empty());
  ASSERT_EQ(m.commands.size(), 10u);
  EXPECT_EQ(std::get<KickOffCommand>(m.commands[0]).left, true);
  EXPECT_EQ(std::get<KickOffCommand>(m.commands[1]).left, false);
  EXPECT_EQ(std::get<KickOffCommand>(m.commands[2]).left, std::nullopt);
  EXPECT_TRUE(std::holds_alternative<DropBallCommand>(m.commands[3]));
  EXPECT_EQ(std::get<BallCommand>(m.commands[4]).x, 1);
  const auto& pos = std::get<AgentCommand>(m.commands[5]);
  EXPECT_EQ(pos.team, TeamRef::kName);
  EXPECT_EQ(pos.team_name, "teamBlue");
  EXPECT_EQ(pos.position, Eigen::Vector3d(-3, 0, 0.7));
  const auto& move = std::get<AgentCommand>(m.commands[6]);
  EXPECT_EQ(move.team, TeamRef::kLeft);
  EXPECT_NEAR(
      move.orientation.angularDistance(Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()))), 0,
      1e-12);
  EXPECT_EQ(std::get<AgentCommand>(m.commands[7]).team, TeamRef::kRight);
  EXPECT_EQ(std::get<PlayModeCommand>(m.commands[8]).mode, "PlayOn");
  EXPECT_TRUE(std::holds_alternative<KillSimCommand>(m.commands[9]));
}

TEST(MjMonitor, RefusalsAreNamed) {
  const MonitorMessage m = ParseMonitorMessage(
      "(kickOff Up)(ball (pos nan 0 0))(ball (pos 1 2))(agent (unum 2) (pos 1 2 3))(agent (unum 2) (team a) (move3d 1 "
      "2 3 0 0 0 0))(fly)(ball (pos 100.5 0 0))(ball (pos 0 0 -101))(agent (unum 2) (team Left) (pos 0 -100.5 0.7))"
      "(agent (unum 2) (team Left) (move 0 0 0.7 1e7))");
  EXPECT_TRUE(m.commands.empty());
  EXPECT_EQ(test::ErrorsOf(m.issues),
            (std::vector<Error>{Error::kBadArguments, Error::kNotFinite, Error::kBadArguments, Error::kBadArguments,
                                Error::kOutOfRange, Error::kUnknownOp, Error::kOutOfRange, Error::kOutOfRange,
                                Error::kOutOfRange, Error::kOutOfRange}));
}

// A placement turf-sim would refuse (kMaxLeggedPlacement) is refused here, where it is named and counted; up to
// the limit, and any yaw, is a placement.
TEST(MjMonitor, PlacementsStopAtTheLeggedScenesLimit) {
  const MonitorMessage m = ParseMonitorMessage(
      "(ball (pos -100 100 0.1))(agent (unum 2) (team Left) (move 100 -100 0.7 -270))(agent (unum 3) (team Left) "
      "(move3d 0 0 100 1e5 0 0 1e5))");
  ASSERT_TRUE(m.issues.empty());
  ASSERT_EQ(m.commands.size(), 3u);
  EXPECT_EQ(std::get<BallCommand>(m.commands[0]).x, -100);
  const auto& move = std::get<AgentCommand>(m.commands[1]);
  EXPECT_EQ(move.position, Eigen::Vector3d(100, -100, 0.7));
  EXPECT_NEAR(
      move.orientation.angularDistance(Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()))), 0,
      1e-12);
  EXPECT_NEAR(
      std::get<AgentCommand>(m.commands[2])
          .orientation.angularDistance(Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()))),
      0, 1e-12);
}

}  // namespace
}  // namespace turf::rcssservermj
