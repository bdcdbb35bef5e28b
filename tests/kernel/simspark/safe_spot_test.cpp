// rcssserver3d's search for a safe spot for a referee's move (kernel/simspark/safe_spot.h) against the reference's
// GetSafeReposition as its code states it: away from the ball, other robots and goals, in steps of 0.4 m.
#include "kernel/simspark/safe_spot.h"

#include <gtest/gtest.h>

#include <cmath>

namespace turf::simspark {
namespace {

constexpr Side L = Side::kLeft;
constexpr Side R = Side::kRight;
const Eigen::Vector3d kFarBall(10.0, 8.0, 0.042);

SpotPlayer Standing(Side side, int unum, double x, double y) {
  SpotPlayer p{side, unum, {x, y, 0.35}, {}};
  p.box = Eigen::AlignedBox3d(Eigen::Vector3d(x - 0.1, y - 0.1, 0.0), Eigen::Vector3d(x + 0.1, y + 0.1, 0.55));
  return p;
}

// The search moves in whole steps of 0.4 m along x and y from the spot wanted.
void ExpectOnTheGrid(const Eigen::Vector3d& spot, const Eigen::Vector3d& wanted) {
  for (int k = 0; k < 2; ++k) {
    const double steps = (spot[k] - wanted[k]) / 0.4;
    EXPECT_NEAR(steps, std::round(steps), 1e-9) << "axis " << k;
  }
  EXPECT_EQ(spot.z(), wanted.z()) << "height kept";
}

TEST(SafeSpot, AFreeSpotIsKept) {
  const std::vector<SpotPlayer> players = {Standing(L, 4, 0, 0), Standing(R, 9, 3, 3)};
  const Eigen::Vector3d wanted(1.0, 1.0, 0.4);
  EXPECT_EQ(SafeSpot(wanted, L, 4, players, kFarBall), wanted);
}

// Within 1 m of the ball: the nearest spot on the 0.4 m grid (from the player) that is 1 m or more from it.
TEST(SafeSpot, AwayFromTheBall) {
  const std::vector<SpotPlayer> players = {Standing(L, 4, 0, 0)};
  const Eigen::Vector3d ball(0.5, 0.0, 0.042);
  const Eigen::Vector3d wanted(0.4, 0.0, 0.35);
  const Eigen::Vector3d spot = SafeSpot(wanted, L, 4, players, ball);
  EXPECT_GE(std::hypot(spot.x() - ball.x(), spot.y() - ball.y()), 1.0);
  EXPECT_LT((spot - wanted).norm(), 2.0) << "not far";
  ExpectOnTheGrid(spot, wanted);
}

// A 0.4 m sphere around the spot may not touch another robot's box (team mate or opponent); the player's own box
// does not count.
TEST(SafeSpot, AwayFromOtherRobots) {
  const std::vector<SpotPlayer> players = {Standing(L, 4, 0, 0), Standing(R, 9, 1.2, 0), Standing(L, 5, 1.2, 0.6)};
  const Eigen::Vector3d wanted(1.0, 0.1, 0.35);
  const Eigen::Vector3d spot = SafeSpot(wanted, L, 4, players, kFarBall);
  for (size_t i = 1; i < players.size(); ++i)
    EXPECT_GT(players[i].box.squaredExteriorDistance(spot), 0.4 * 0.4) << "robot " << i;
  ExpectOnTheGrid(spot, wanted);
  EXPECT_EQ(SafeSpot({0.05, 0.0, 0.35}, L, 4, players, kFarBall), Eigen::Vector3d(0.05, 0.0, 0.35)) << "its own box";
}

TEST(SafeSpot, NotInOrBehindAGoal) {
  const std::vector<SpotPlayer> players = {Standing(R, 9, 14.0, 0.5)};
  const Eigen::Vector3d spot = SafeSpot({15.2, 0.5, 0.4}, R, 9, players, kFarBall);
  EXPECT_FALSE(std::abs(spot.x()) > 15.0 && std::abs(spot.y()) < 1.05 + 0.4) << spot.transpose();
}

// A spot in the player's own penalty area (grown by 0.4 m) while three team mates are in it is moved out first.
TEST(SafeSpot, NotIntoAFullOwnPenaltyArea) {
  const std::vector<SpotPlayer> players = {Standing(L, 4, -10, 0), Standing(L, 1, -14.5, 0), Standing(L, 2, -14, 1),
                                           Standing(L, 3, -14, -1)};
  const Eigen::Vector3d spot = SafeSpot({-13.5, 0.6, 0.4}, L, 4, players, kFarBall);
  const bool in_grown_area = spot.x() > -15.4 && spot.x() < -13.2 + 0.4 && std::abs(spot.y()) < 1.95 + 0.4;
  EXPECT_FALSE(in_grown_area) << spot.transpose();
  // With two team mates in it, the spot stands.
  const std::vector<SpotPlayer> two(players.begin(), players.begin() + 3);
  EXPECT_EQ(SafeSpot({-12.5, 3.0, 0.4}, L, 4, two, kFarBall), Eigen::Vector3d(-12.5, 3.0, 0.4));
}

// No safe spot within 100 tries: the spot wanted.
TEST(SafeSpot, NoSafeSpotKeepsTheOneWanted) {
  SafeSpotRules rules;
  rules.min_ball_distance = 1000.0;
  const Eigen::Vector3d wanted(1.0, 1.0, 0.4);
  EXPECT_EQ(SafeSpot(wanted, L, 4, {Standing(L, 4, 0, 0)}, kFarBall, rules), wanted);
}

// avoid_ball false (the reference's fAvoidBall, off for the kick's repel): the ball is no reason to move on; the
// other robots still are.
TEST(SafeSpot, AvoidBallFalseIgnoresTheBall) {
  const std::vector<SpotPlayer> players = {Standing(L, 4, 0, 0)};
  const Eigen::Vector3d ball(0.5, 0.0, 0.042);
  const Eigen::Vector3d wanted(0.4, 0.0, 0.35);
  EXPECT_EQ(SafeSpot(wanted, L, 4, players, ball, {}, false), wanted);
  EXPECT_NE(SafeSpot(wanted, L, 4, players, ball, {}, true), wanted);
  const std::vector<SpotPlayer> crowded = {Standing(L, 4, 0, 0), Standing(R, 9, 0.6, 0)};
  const Eigen::Vector3d spot = SafeSpot(wanted, L, 4, crowded, ball, {}, false);
  EXPECT_GT(crowded[1].box.squaredExteriorDistance(spot), 0.4 * 0.4) << spot.transpose();
  EXPECT_LT(std::hypot(spot.x() - ball.x(), spot.y() - ball.y()), 1.0) << "near the ball is fine";
  ExpectOnTheGrid(spot, wanted);
}

// SpotBoard::Place moves the torso and translates the box with it; later searches see the moved box.
TEST(SpotBoard, PlaceMovesTheTorsoAndItsBox) {
  SpotBoard board({Standing(L, 4, 0, 0), Standing(R, 9, 3, 3)}, kFarBall, {});
  const Eigen::Vector3d to(2.0, -1.0, 0.4);
  EXPECT_EQ(board.Place(L, 4, to, false), to);
  const SpotPlayer* p = board.Find(L, 4);
  ASSERT_NE(p, nullptr);
  EXPECT_EQ(p->torso, to);
  EXPECT_NEAR(p->box.min().x(), 1.9, 1e-12);
  EXPECT_NEAR(p->box.max().x(), 2.1, 1e-12);
  EXPECT_NEAR(p->box.min().y(), -1.1, 1e-12);
  EXPECT_NEAR(p->box.max().y(), -0.9, 1e-12);
  EXPECT_NEAR(p->box.min().z(), 0.05, 1e-12);
  EXPECT_NEAR(p->box.max().z(), 0.6, 1e-12);
  EXPECT_EQ(board.Find(R, 9)->torso, Eigen::Vector3d(3, 3, 0.35)) << "the others stay";
  // Wanted right on the moved robot: the safe spot clears its box where it is now.
  const Eigen::Vector3d spot = board.Place(R, 9, {2.0, -1.0, 0.35}, true);
  EXPECT_GT(board.Find(L, 4)->box.squaredExteriorDistance(spot), 0.4 * 0.4) << spot.transpose();
  EXPECT_EQ(board.Find(R, 9)->torso, spot);
  ExpectOnTheGrid(spot, {2.0, -1.0, 0.35});
}

// An empty box stays empty; a robot not on the board is not moved and gets the spot wanted.
TEST(SpotBoard, EmptyBoxesAndStrangers) {
  SpotPlayer point{L, 2, {1, 1, 0.3}, {}};
  SpotBoard board({point}, kFarBall, {});
  EXPECT_EQ(board.Place(L, 2, {4, 4, 0.3}, false), Eigen::Vector3d(4, 4, 0.3));
  EXPECT_TRUE(board.Find(L, 2)->box.isEmpty());
  EXPECT_EQ(board.Find(R, 2), nullptr);
  EXPECT_EQ(board.Place(R, 2, {4, 4, 0.3}, true), Eigen::Vector3d(4, 4, 0.3));
  ASSERT_EQ(board.players().size(), 1u);
  EXPECT_EQ(board.players()[0].torso, Eigen::Vector3d(4, 4, 0.3));
}

}  // namespace
}  // namespace turf::simspark
