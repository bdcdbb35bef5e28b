// rcssserver3d's clearings of players by the game (kernel/simspark/clearing.h) against the reference's
// ClearPlayers (circle and box), ClearPlayersBeforeKickOff and RepelPlayers as their code states them, with
// naosoccersim.rb's distances (FreeKickDistance 2, FreeKickMoveDist 2.5, KickRepelDist 0.5).
#include "kernel/simspark/clearing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>

#include "core/rng.h"

namespace turf::simspark {
namespace {

constexpr Side L = Side::kLeft;
constexpr Side R = Side::kRight;
constexpr double kField = 30.0;
constexpr double kTol = 1e-9;

// A standing robot: torso 0.35 m high, its parts within `half` of it on the ground plane, up to 0.55 m.
SpotPlayer Standing(Side side, int unum, double x, double y, double half = 0.1) {
  SpotPlayer p{side, unum, {x, y, 0.35}, {}};
  p.box = Eigen::AlignedBox3d(Eigen::Vector3d(x - half, y - half, 0.0), Eigen::Vector3d(x + half, y + half, 0.55));
  return p;
}

SpotBoard Board(std::vector<SpotPlayer> players) { return SpotBoard(std::move(players), Eigen::Vector3d::Zero(), {}); }

Clearing Circle(Side team, const Eigen::Vector3d& centre, uint64_t seed = 0) {
  Clearing c;
  c.kind = ClearingKind::kCircle;
  c.team = team;
  c.centre = centre;
  c.radius = 2.0;
  c.distance = 2.5;
  c.ball = centre;
  c.order_seed = seed;
  return c;
}

// The half `team` is cleared from at a kick-off (the reference's oversized mLeftHalf / mRightHalf).
Clearing Half(Side team, double keep_in_circle = 0.0, uint64_t seed = 0) {
  Clearing c;
  c.kind = ClearingKind::kBox;
  c.team = team;
  c.box = team == L ? Eigen::AlignedBox2d(Eigen::Vector2d(0, -20), Eigen::Vector2d(25, 20))
                    : Eigen::AlignedBox2d(Eigen::Vector2d(-25, -20), Eigen::Vector2d(0, 20));
  c.keep_in_circle = keep_in_circle;
  c.distance = 2.5;
  c.ball = Eigen::Vector3d(0, 0, 0.042);
  c.order_seed = seed;
  return c;
}

Clearing Repel(Side team, const Eigen::Vector3d& centre, double pad, bool avoid_ball) {
  Clearing c;
  c.kind = ClearingKind::kRepel;
  c.team = team;
  c.centre = centre;
  c.radius = 0.5;
  c.distance = pad;
  c.avoid_ball = avoid_ball;
  c.ball = centre;
  return c;
}

const ClearingMove* MoveOf(const std::vector<ClearingMove>& moves, Side side, int unum) {
  for (const ClearingMove& m : moves)
    if (m.side == side && m.unum == unum) return &m;
  return nullptr;
}

void ExpectAt(const Eigen::Vector3d& got, double x, double y, double z) {
  EXPECT_NEAR(got.x(), x, kTol) << got.transpose();
  EXPECT_NEAR(got.y(), y, kTol) << got.transpose();
  EXPECT_NEAR(got.z(), z, kTol) << got.transpose();
}

// A robot the sphere meets goes 2.5 m from its centre along x towards its own goal; y and height stay.
TEST(Clearing, CircleMovesEachTeamTowardsItsOwnGoal) {
  const Eigen::Vector3d ball(3.0, 1.0, 0.042);
  SpotBoard board = Board({Standing(L, 4, 3.5, 1.5), Standing(R, 7, 2.2, 0.5)});
  const std::vector<ClearingMove> moves = Clear({Circle(L, ball), Circle(R, ball)}, kField, &board);
  ASSERT_EQ(moves.size(), 2u);
  EXPECT_EQ(moves[0].side, L);
  EXPECT_EQ(moves[0].unum, 4);
  ExpectAt(moves[0].position, 0.5, 1.5, 0.35);
  EXPECT_EQ(moves[1].side, R);
  EXPECT_EQ(moves[1].unum, 7);
  ExpectAt(moves[1].position, 5.5, 0.5, 0.35);
  // The board holds the moves, boxes and all.
  ExpectAt(board.Find(L, 4)->torso, 0.5, 1.5, 0.35);
  EXPECT_NEAR(board.Find(L, 4)->box.min().x(), 0.4, kTol);
  EXPECT_NEAR(board.Find(R, 7)->box.max().x(), 5.6, kTol);
  EXPECT_NEAR(board.Find(R, 7)->box.max().z(), 0.55, kTol);
}

// A robot lying low keeps its height too.
TEST(Clearing, CircleKeepsTheTorsosHeight) {
  SpotPlayer lying = Standing(L, 3, 0.5, -0.5);
  lying.torso.z() = 0.08;
  SpotBoard board = Board({lying});
  const std::vector<ClearingMove> moves = Clear({Circle(L, Eigen::Vector3d(0, 0, 0.042))}, kField, &board);
  ASSERT_EQ(moves.size(), 1u);
  ExpectAt(moves[0].position, -2.5, -0.5, 0.08);
}

// 2.5 m towards its own goal would be behind the goal line: 2.5 m from the centre along y towards the middle line,
// x kept.
TEST(Clearing, CircleNearTheOwnGoalLineMovesAlongY) {
  SpotBoard board = Board({Standing(L, 5, -13.0, -2.5), Standing(R, 6, 13.0, 2.5)});
  const std::vector<ClearingMove> moves = Clear(
      {Circle(L, Eigen::Vector3d(-13.5, -3.0, 0.042)), Circle(R, Eigen::Vector3d(13.5, 3.0, 0.042))}, kField, &board);
  ASSERT_EQ(moves.size(), 2u);
  ExpectAt(MoveOf(moves, L, 5)->position, -13.0, -0.5, 0.35);
  ExpectAt(MoveOf(moves, R, 6)->position, 13.0, 0.5, 0.35);
}

// The sphere is tested against the robot's box, not its torso: a torso 2.05 m from the centre whose box reaches
// 1.95 m is cleared; a box 2.1 m away, or a torso point (empty box) 2.05 m away, is not.
TEST(Clearing, OnlyARobotWhoseBoxMeetsTheSphereMoves) {
  SpotPlayer point = Standing(L, 9, 0.0, -2.05);
  point.box = Eigen::AlignedBox3d();
  SpotBoard board = Board({Standing(L, 2, 2.05, 0.0), Standing(L, 3, 0.0, 2.2), point});
  const std::vector<ClearingMove> moves = Clear({Circle(L, Eigen::Vector3d(0, 0, 0.042))}, kField, &board);
  ASSERT_EQ(moves.size(), 1u);
  EXPECT_EQ(moves[0].unum, 2);
  ExpectAt(moves[0].position, -2.5, 0.0, 0.35);
  ExpectAt(board.Find(L, 3)->torso, 0.0, 2.2, 0.35);
  ExpectAt(board.Find(L, 9)->torso, 0.0, -2.05, 0.35);
  // The same torso point 1.95 m away is met.
  SpotPlayer near = point;
  near.torso.y() = -1.95;
  SpotBoard board2 = Board({near});
  const std::vector<ClearingMove> moves2 = Clear({Circle(L, Eigen::Vector3d(0, 0, 0.042))}, kField, &board2);
  ASSERT_EQ(moves2.size(), 1u);
  ExpectAt(moves2[0].position, -2.5, -1.95, 0.35);
}

// The other team's robots are not the clearing's.
TEST(Clearing, OnlyTheClearedTeamMoves) {
  SpotBoard board = Board({Standing(R, 2, 0.5, 0.5)});
  EXPECT_TRUE(Clear({Circle(L, Eigen::Vector3d(0, 0, 0.042))}, kField, &board).empty());
  ExpectAt(board.Find(R, 2)->torso, 0.5, 0.5, 0.35);
}

// The kick-off clearing of a half: 2.5 m beyond the box's side towards the own goal, y and height kept. The
// rectangles are closed: a box touching the half's edge is met.
TEST(Clearing, BoxMovesEachTeamOutOfTheOtherHalf) {
  SpotBoard board = Board({Standing(L, 2, 3.0, 4.0), Standing(L, 3, -0.1, 6.0), Standing(L, 4, -0.2, -7.0),
                           Standing(R, 5, -3.0, -4.0), Standing(R, 6, 4.0, 1.0)});
  const std::vector<ClearingMove> moves = Clear({Half(L), Half(R)}, kField, &board);
  ASSERT_EQ(moves.size(), 3u);
  ExpectAt(MoveOf(moves, L, 2)->position, -2.5, 4.0, 0.35);
  ExpectAt(MoveOf(moves, L, 3)->position, -2.5, 6.0, 0.35);
  ExpectAt(MoveOf(moves, R, 5)->position, 2.5, -4.0, 0.35);
  EXPECT_EQ(MoveOf(moves, L, 4), nullptr) << "its box ends 0.1 m short of the half";
  EXPECT_EQ(MoveOf(moves, R, 6), nullptr) << "in its own half";
  ExpectAt(board.Find(L, 4)->torso, -0.2, -7.0, 0.35);
}

// The kick-off team's robots wholly (all four corners of the box) in the 2 m centre circle stay; one whose torso is
// in it but whose box reaches out of it is moved.
TEST(Clearing, KeepInCircleSparesRobotsWhollyInTheCentreCircle) {
  const std::vector<SpotPlayer> players = {Standing(L, 9, 1.0, 0.5), Standing(L, 10, 1.85, 0.5)};
  ASSERT_LT(players[1].torso.head<2>().norm(), 2.0);
  SpotBoard board = Board(players);
  const std::vector<ClearingMove> moves = Clear({Half(L, 2.0)}, kField, &board);
  ASSERT_EQ(moves.size(), 1u);
  EXPECT_EQ(moves[0].unum, 10);
  ExpectAt(moves[0].position, -2.5, 0.5, 0.35);
  ExpectAt(board.Find(L, 9)->torso, 1.0, 0.5, 0.35);
  // Without the exemption both go.
  SpotBoard all = Board(players);
  EXPECT_EQ(Clear({Half(L)}, kField, &all).size(), 2u);
}

// Within 0.5 m of the spot: to 0.5 m (plus the pad) from it, in the direction the robot stands in; farther: stays.
TEST(Clearing, RepelPushesOutToTheRadius) {
  const Eigen::Vector3d spot(1.0, 1.0, 0.042);
  SpotBoard board = Board({Standing(L, 2, 1.3, 1.0), Standing(L, 3, 1.0, 0.6), Standing(L, 4, 1.0, 1.55)});
  const std::vector<ClearingMove> moves = Clear({Repel(L, spot, 0.0, false)}, kField, &board);
  ASSERT_EQ(moves.size(), 2u);
  ExpectAt(MoveOf(moves, L, 2)->position, 1.5, 1.0, 0.35);
  ExpectAt(MoveOf(moves, L, 3)->position, 1.0, 0.5, 0.35);
  EXPECT_EQ(MoveOf(moves, L, 4), nullptr);
  // A diagonal direction, and the pad.
  SpotBoard padded = Board({Standing(R, 8, 5.0 + 0.24, 5.0 - 0.32)});
  const std::vector<ClearingMove> pad = Clear({Repel(R, {5.0, 5.0, 0.042}, 0.1, false)}, kField, &padded);
  ASSERT_EQ(pad.size(), 1u);
  ExpectAt(pad[0].position, 5.0 + 0.36, 5.0 - 0.48, 0.35);
}

// A torso exactly at the spot goes along +x.
TEST(Clearing, RepelFromTheVerySpotGoesAlongX) {
  SpotBoard board = Board({Standing(R, 5, 5.0, 5.0)});
  const std::vector<ClearingMove> moves = Clear({Repel(R, {5.0, 5.0, 0.042}, 0.0, false)}, kField, &board);
  ASSERT_EQ(moves.size(), 1u);
  ExpectAt(moves[0].position, 5.5, 5.0, 0.35);
}

// The kick's repel (fAvoidBall false) leaves the robot 0.5 m from the ball; avoiding the ball, the safe spot is
// 1 m or more from it.
TEST(Clearing, AvoidBallDecidesWhetherTheBallKeepsRobotsAway) {
  const Eigen::Vector3d ball(0.0, 0.0, 0.042);
  SpotBoard near = Board({Standing(L, 2, 0.24, 0.32)});
  const std::vector<ClearingMove> kept = Clear({Repel(L, ball, 0.0, false)}, kField, &near);
  ASSERT_EQ(kept.size(), 1u);
  ExpectAt(kept[0].position, 0.3, 0.4, 0.35);
  EXPECT_LT(kept[0].position.head<2>().norm(), 1.0);
  SpotBoard away = Board({Standing(L, 2, 0.24, 0.32)});
  const std::vector<ClearingMove> avoided = Clear({Repel(L, ball, 0.0, true)}, kField, &away);
  ASSERT_EQ(avoided.size(), 1u);
  EXPECT_GE(avoided[0].position.head<2>().norm(), 1.0) << avoided[0].position.transpose();
  EXPECT_LT(avoided[0].position.head<2>().norm(), 2.5) << "nearby";
  EXPECT_NEAR(avoided[0].position.z(), 0.35, kTol);
}

// Each move sees the ones before it: two robots wanted at the same spot end at different safe spots, the second
// clear of the first's box.
TEST(Clearing, LaterMovesSeeEarlierOnes) {
  SpotBoard board = Board({Standing(L, 2, 3.0, 1.0, 0.25), Standing(L, 3, 5.0, 1.0, 0.25)});
  const std::vector<ClearingMove> moves = Clear({Half(L)}, kField, &board);
  ASSERT_EQ(moves.size(), 2u);
  ExpectAt(moves[0].position, -2.5, 1.0, 0.35);  // the first goes where it is wanted
  const Eigen::Vector3d& second = moves[1].position;
  EXPECT_GE((second - moves[0].position).head<2>().norm(), 0.8 - kTol) << second.transpose();
  EXPECT_GT(board.Find(L, moves[0].unum)->box.squaredExteriorDistance(second), 0.4 * 0.4);
  ExpectAt(board.Find(L, moves[1].unum)->torso, second.x(), second.y(), second.z());
}

// The order the team's robots are taken in is the seed's shuffle of the board's order: the same seed, the same
// moves; some seeds differ.
TEST(Clearing, TheSeedDrawsTheOrder) {
  std::vector<SpotPlayer> players;
  for (int unum = 1; unum <= 6; ++unum) players.push_back(Standing(L, unum, 1.0 + unum, -3.0 + unum));
  std::set<std::vector<int>> orders;
  for (uint64_t seed = 0; seed < 10; ++seed) {
    SpotBoard a = Board(players);
    SpotBoard b = Board(players);
    const std::vector<ClearingMove> first = Clear({Half(L, 0.0, seed)}, kField, &a);
    const std::vector<ClearingMove> again = Clear({Half(L, 0.0, seed)}, kField, &b);
    ASSERT_EQ(first.size(), players.size());
    ASSERT_EQ(again.size(), players.size());
    std::vector<int> order;
    for (size_t i = 0; i < first.size(); ++i) {
      EXPECT_EQ(first[i].unum, again[i].unum);
      EXPECT_EQ(first[i].position, again[i].position);
      order.push_back(first[i].unum);
    }
    std::vector<int> expected = {1, 2, 3, 4, 5, 6};
    Rng rng(seed);
    Shuffle(&expected, rng);
    EXPECT_EQ(order, expected) << "seed " << seed;
    orders.insert(order);
  }
  EXPECT_GT(orders.size(), 1u);
}

// A robot whose torso is not finite is not moved (nor tested); the others are.
TEST(Clearing, ANonFiniteTorsoIsNotMoved) {
  SpotPlayer broken = Standing(L, 7, 0.5, 0.5);
  broken.torso.x() = std::numeric_limits<double>::quiet_NaN();
  broken.box = Eigen::AlignedBox3d();
  SpotBoard board = Board({broken, Standing(L, 8, 1.0, -1.0)});
  const std::vector<ClearingMove> moves =
      Clear({Circle(L, Eigen::Vector3d(0, 0, 0.042)), Repel(L, Eigen::Vector3d(0.5, 0.5, 0.042), 0.0, false)}, kField,
            &board);
  ASSERT_EQ(moves.size(), 1u);
  EXPECT_EQ(moves[0].unum, 8);
  ExpectAt(moves[0].position, -2.5, -1.0, 0.35);
  EXPECT_TRUE(std::isnan(board.Find(L, 7)->torso.x()));
}

// Each clearing sets the board's ball for its safe spots.
TEST(Clearing, EachClearingBringsItsBall) {
  SpotBoard board = Board({Standing(L, 2, 8.0, 0.0)});
  Clearing c = Circle(L, Eigen::Vector3d(8.0, 0.0, 0.042));
  c.ball = Eigen::Vector3d(5.5, 0.0, 0.042);  // where the robot is wanted
  const std::vector<ClearingMove> moves = Clear({c}, kField, &board);
  ASSERT_EQ(moves.size(), 1u);
  EXPECT_EQ(board.ball(), c.ball);
  EXPECT_GE(std::hypot(moves[0].position.x() - 5.5, moves[0].position.y()), 1.0) << moves[0].position.transpose();
}

}  // namespace
}  // namespace turf::simspark
