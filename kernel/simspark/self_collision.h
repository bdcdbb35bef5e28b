// rcssserver3d's self-collision rule (shared/protocols/simspark.md, "Self-collision rule"; the reference's
// SoccerRuleAspect::AnalyseSelfCollisionFouls and UpdateSelfCollisions with naosoccersim.rb's settings:
// FoulOnSelfCollisions true, SelfCollisionsTolerance 0.04, SelfCollisionJointFrozenTime 1, ThawTime 2, no beam
// penalty).
//
// A robot's own parts never collide physically. Instead, after every cycle while the game is not paused, the
// referee tests each pair of one player's box colliders (torso, upper and lower arms, thighs, shanks, feet, type 4's
// toes; not a thigh with the torso, a shank with its thigh, a foot with its shank, a toe with its foot). Two that
// overlap freeze the joints of the limbs they belong to (an arm's 4, a leg's 6, or 7 with the toe; the torso's
// none): for 1 s of game time a command to a frozen joint turns into velocity 0 (a joint nobody commands keeps its
// velocity, as any hinge does). A joint cannot freeze again until 3 s after it froze.
//
// While the game is paused (the reference's flag, Game::paused()) nothing is judged and every freeze ends. Times
// are game time (it stands still in BeforeKickOff and GameOver), in double where the reference sums floats, so a
// freeze may end a cycle earlier or later than there. The times are kept per side and number, also after a player
// leaves (the reference's arrays): a new player with that number takes them over. A link pose that is not finite
// is no box.
#pragma once

#include <Eigen/Geometry>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "core/state_io.h"
#include "kernel/simspark/types.h"

namespace turf::simspark {

inline constexpr double kSelfCollisionTolerance = 0.04;  // m
inline constexpr double kSelfCollisionFrozenTime = 1.0;  // s of game time
inline constexpr double kSelfCollisionThawTime = 2.0;    // s, after the frozen time

// A box collider of the Nao: centred on its link's origin, along the link's axes.
struct NaoBox {
  std::string link;                 // "torso", "rlowerarm", ...
  Eigen::Vector3d half;             // half extents along the link's x, y, z (m)
  std::vector<std::string> freeze;  // the joints (perceptor names) a collision of this box freezes
};

// The box colliders of robot type 0..4 (the reference's rsg files), in their scene-graph order; empty for another.
const std::vector<NaoBox>& NaoBoxes(int robot_type);
// Whether the reference never tests these two boxes against each other (links of one robot).
bool NeverTested(const std::string& link1, const std::string& link2);

struct PlacedBox {
  Eigen::Vector3d centre;
  Eigen::Matrix3d axes;  // columns: the box's x, y, z in the world
  Eigen::Vector3d half;
};

// The reference's test (BoxCollider::CheckCollisions): no separating axis among the 15 of two boxes, each axis
// separating when |d . L| + tolerance > the boxes' projected radii on L (d: from one centre to the other). As in the
// reference, the 9 edge-edge axes L = a x b are not normalised, so the tolerance weighs more on them and two nearly
// parallel edges always separate.
bool BoxesOverlap(const PlacedBox& a, const PlacedBox& b, double tolerance);
// The largest tolerance at which BoxesOverlap still holds: the smallest of the 15 axes' radii less |d . L| (m;
// negative when the boxes are apart).
double OverlapDepth(const PlacedBox& a, const PlacedBox& b);

// One player's links after the cycle (name, pose in the world).
struct PlayerLinks {
  Side side = Side::kLeft;
  int unum = 0;
  int robot_type = 0;
  struct Link {
    std::string name;
    Eigen::Vector3d position = Eigen::Vector3d::Zero();
    Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  };
  std::vector<Link> links;
};

// A pair that froze joints this cycle, for the log.
struct SelfCollision {
  Side side = Side::kLeft;
  int unum = 0;
  std::string link1, link2;
  double depth = 0.0;               // OverlapDepth, m
  std::vector<std::string> frozen;  // the joints that froze now
};

class SelfCollisionRule {
 public:
  // After a cycle: the game's paused flag and game time after it. Returns the pairs that froze joints.
  std::vector<SelfCollision> Update(bool paused, double game_time, const std::vector<PlayerLinks>& players);
  // Whether a command to `joint` (perceptor name) of that player turns into velocity 0 now.
  bool Frozen(Side side, int unum, const std::string& joint) const;

  // Every player's joint times, for league snapshots. A restore that fails changes nothing.
  void Save(StateWriter& out) const;
  void Restore(StateReader& in);

 private:
  struct Joint {
    double frozen_at = 0.0;  // game time the joint froze
    bool frozen = false;     // commands to it turn into 0 (until frozen_at + frozen time)
    template <class Io>
    friend void Fields(Io& io, IoRef<Io, Joint> j) {
      io(FiniteValue(j.frozen_at), j.frozen);
    }
  };
  using Player = std::pair<Side, int>;
  void Thaw(double game_time);
  std::vector<std::string> Freeze(const Player& player, const NaoBox& a, const NaoBox& b, double game_time);

  std::map<Player, std::map<std::string, Joint>> joints_;  // only joints that froze within the last 3 s
};

}  // namespace turf::simspark
