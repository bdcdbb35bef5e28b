// rcssserver3d's moves of players away from the ball that the game itself makes (not fouls): SoccerRuleAspect's
// ClearPlayers (a circle or a box), ClearPlayersBeforeKickOff and RepelPlayers, with naosoccersim.rb's settings
// (FreeKickDistance 2, FreeKickMoveDist 2.5, KickRepelDist 0.5). Game (game.h) decides which clearings a cycle
// makes and in which order; Clear() carries them out on the players as they stand. Pure: no time, no world.
//
// Each clearing takes the players of one team in an order drawn from its seed (the reference's random_shuffle) and
// moves each one it applies to at once, so later moves see earlier ones:
// - kCircle: a player whose bounding box meets the sphere (centre, radius) goes `distance` from the centre along x
//   towards its own goal (left team: centre.x - distance), its y and height kept; where that would be behind its
//   own goal line (|x| beyond L/2), it goes `distance` from the centre along y towards the field's middle line
//   instead (centre.y < 0: centre.y + distance, else centre.y - distance), its x kept.
// - kBox: a player whose bounding rectangle (x, y) meets `box` goes to `distance` beyond the box's side towards its
//   own goal (left team: box.min.x - distance, right team: box.max.x + distance), its y and height kept. With
//   keep_in_circle > 0 a player whose rectangle's four corners are all within that radius of the field's centre
//   stays (the kick-off team's players in the centre circle).
// - kRepel: a player whose torso is within `radius` of the centre on the ground plane goes to radius + distance
//   from the centre, in the direction it stands in (a torso exactly at the centre: along +x, which the reference
//   leaves undefined).
// Every move then goes through the reference's safe-spot search (safe_spot.h: when the spot is unsafe, candidates in
// order of their distance from where the player stands), avoiding the ball when avoid_ball.
//
// Not modelled: the reference moves a player's bodies relative to a transform that is only updated by the next
// physics step, so a player moved twice in one cycle (cleared, then moved by the foul referee) ends at the second
// spot plus the first move; here each move is absolute.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

#include "kernel/simspark/safe_spot.h"
#include "kernel/simspark/types.h"

namespace turf::simspark {

enum class ClearingKind : uint8_t { kCircle, kBox, kRepel };

struct Clearing {
  ClearingKind kind = ClearingKind::kCircle;
  Side team = Side::kLeft;                           // whose players move
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  // kCircle, kRepel
  double radius = 0.0;                               // kCircle, kRepel
  Eigen::AlignedBox2d box;                           // kBox
  double keep_in_circle = 0.0;                       // kBox: players wholly in this centre circle stay (0: none)
  double distance = 0.0;                             // kCircle, kBox: how far beyond; kRepel: the pad
  bool avoid_ball = true;                            // the safe spot keeps away from the ball
  Eigen::Vector3d ball = Eigen::Vector3d::Zero();    // where the ball is when the clearing is made
  uint64_t order_seed = 0;                           // the order the team's players are taken in
};

struct ClearingMove {
  Side side = Side::kLeft;
  int unum = 0;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // the torso's, where the move put it
};

// Carries out `clearings` in order on `board`'s players (moved there too); the moves made, in order. A player whose
// torso is not finite is not moved. field_length: L, for kCircle.
std::vector<ClearingMove> Clear(const std::vector<Clearing>& clearings, double field_length, SpotBoard* board);

}  // namespace turf::simspark
