#include "kernel/simspark/self_collision.h"

#include <algorithm>
#include <cmath>

namespace turf::simspark {

namespace {

// The joints an arm's or a leg's box freezes (rcssserver3d's addSCFreezeJointEffName, as perceptor names).
std::vector<std::string> Limb(const std::string& side, const char* limb, int joints) {
  std::vector<std::string> out;
  for (int j = 1; j <= joints; ++j) out.push_back(side + limb + std::to_string(j));
  return out;
}

// The reference's rsg files (rsg/agent/nao/nao_hetero.rsg, naoarm.rsg, naoleg.rsg, naolegtoe.rsg): box lengths
// halved. Type 4's foot is shortened at the front for its toe (shared/protocols/simspark.md, "Nao physical model").
std::vector<NaoBox> Boxes(bool toes) {
  constexpr double kToeLength = 0.035517656;
  constexpr double kToeFootLength = 0.124482344;
  std::vector<NaoBox> out = {{"torso", {0.05, 0.05, 0.09}, {}}};
  for (const std::string side : {"r", "l"}) {
    for (const char* part : {"upperarm", "lowerarm"})
      out.push_back({side + part,
                     part[0] == 'u' ? Eigen::Vector3d(0.035, 0.04, 0.03) : Eigen::Vector3d(0.025, 0.055, 0.025),
                     Limb(side, "aj", 4)});
  }
  for (const std::string side : {"r", "l"}) {
    const std::vector<std::string> leg = Limb(side, "lj", toes ? 7 : 6);
    out.push_back({side + "thigh", {0.035, 0.035, 0.07}, leg});
    out.push_back({side + "shank", {0.04, 0.035, 0.055}, leg});
    out.push_back({side + "foot", {0.04, toes ? kToeFootLength / 2 : 0.08, 0.01}, leg});
    if (toes) out.push_back({side + "toe", {0.04, kToeLength / 2, 0.005}, leg});
  }
  return out;
}

// The reference's margin on one axis: the boxes' projected radii on it less the distance of their centres along it.
double Margin(const PlacedBox& a, const PlacedBox& b, const Eigen::Vector3d& axis) {
  double radii = 0.0;
  for (int k = 0; k < 3; ++k)
    radii += std::abs((a.axes.col(k) * a.half[k]).dot(axis)) + std::abs((b.axes.col(k) * b.half[k]).dot(axis));
  return radii - std::abs((b.centre - a.centre).dot(axis));
}

constexpr size_t kMaxPlayers = 64;
constexpr int kMaxUnum = 99;
constexpr size_t kMaxJoints = 64;

}  // namespace

const std::vector<NaoBox>& NaoBoxes(int robot_type) {
  static const std::vector<NaoBox> kPlain = Boxes(false);
  static const std::vector<NaoBox> kToes = Boxes(true);
  static const std::vector<NaoBox> kNone;
  if (robot_type < 0 || robot_type > 4) return kNone;
  return robot_type == 4 ? kToes : kPlain;
}

bool NeverTested(const std::string& link1, const std::string& link2) {
  static const char* const kPairs[][2] = {
      {"torso", "rthigh"}, {"torso", "lthigh"}, {"rthigh", "rshank"}, {"lthigh", "lshank"},
      {"rshank", "rfoot"}, {"lshank", "lfoot"}, {"rfoot", "rtoe"},    {"lfoot", "ltoe"},
  };
  for (const auto& p : kPairs)
    if ((link1 == p[0] && link2 == p[1]) || (link1 == p[1] && link2 == p[0])) return true;
  return false;
}

double OverlapDepth(const PlacedBox& a, const PlacedBox& b) {
  double depth = INFINITY;
  for (int i = 0; i < 3; ++i) depth = std::min({depth, Margin(a, b, a.axes.col(i)), Margin(a, b, b.axes.col(i))});
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) depth = std::min(depth, Margin(a, b, a.axes.col(i).cross(b.axes.col(j))));
  return depth;
}

bool BoxesOverlap(const PlacedBox& a, const PlacedBox& b, double tolerance) { return OverlapDepth(a, b) >= tolerance; }

std::vector<SelfCollision> SelfCollisionRule::Update(bool paused, double game_time,
                                                     const std::vector<PlayerLinks>& players) {
  std::vector<SelfCollision> out;
  if (paused) {
    joints_.clear();
    return out;
  }
  for (const PlayerLinks& p : players) {
    std::vector<std::pair<const NaoBox*, PlacedBox>> boxes;
    for (const NaoBox& box : NaoBoxes(p.robot_type)) {
      const auto link =
          std::find_if(p.links.begin(), p.links.end(), [&](const PlayerLinks::Link& l) { return l.name == box.link; });
      // A pose that is not finite (a bad sample from elsewhere) is no box: it neither collides nor freezes.
      if (link != p.links.end() && link->position.allFinite() && link->orientation.coeffs().allFinite() &&
          link->orientation.norm() > 1e-9)
        boxes.push_back({&box, {link->position, link->orientation.normalized().toRotationMatrix(), box.half}});
    }
    for (size_t i = 0; i < boxes.size(); ++i) {
      for (size_t j = i + 1; j < boxes.size(); ++j) {
        const NaoBox& a = *boxes[i].first;
        const NaoBox& b = *boxes[j].first;
        if (NeverTested(a.link, b.link)) continue;
        const double depth = OverlapDepth(boxes[i].second, boxes[j].second);
        if (depth < kSelfCollisionTolerance) continue;
        std::vector<std::string> frozen = Freeze({p.side, p.unum}, a, b, game_time);
        if (!frozen.empty()) out.push_back({p.side, p.unum, a.link, b.link, depth, std::move(frozen)});
      }
    }
  }
  Thaw(game_time);
  return out;
}

namespace {

// The reference's times are floats (TTime): its game time minus a float time, in float.
double FloatSince(double now, double then) {
  return static_cast<float>(static_cast<float>(now) - static_cast<float>(then));
}

}  // namespace

// Each joint of both boxes' limbs that may freeze (never frozen, or more than the frozen and thaw times ago).
std::vector<std::string> SelfCollisionRule::Freeze(const Player& player, const NaoBox& a, const NaoBox& b,
                                                   double game_time) {
  std::vector<std::string> frozen;
  std::map<std::string, Joint>& joints = joints_[player];
  for (const std::vector<std::string>* names : {&a.freeze, &b.freeze}) {
    for (const std::string& name : *names) {
      const auto it = joints.find(name);
      if (it != joints.end() &&
          FloatSince(game_time, it->second.frozen_at) <= kSelfCollisionFrozenTime + kSelfCollisionThawTime)
        continue;
      joints[name] = {game_time, true};
      frozen.push_back(name);
    }
  }
  if (joints.empty()) joints_.erase(player);
  return frozen;
}

// The reference's UpdateSelfCollisions: control back after the frozen time, free to freeze again after the thaw.
void SelfCollisionRule::Thaw(double game_time) {
  for (auto player = joints_.begin(); player != joints_.end();) {
    for (auto joint = player->second.begin(); joint != player->second.end();) {
      const double since = FloatSince(game_time, joint->second.frozen_at);
      if (since >= kSelfCollisionFrozenTime) joint->second.frozen = false;
      joint =
          since >= kSelfCollisionFrozenTime + kSelfCollisionThawTime ? player->second.erase(joint) : std::next(joint);
    }
    player = player->second.empty() ? joints_.erase(player) : std::next(player);
  }
}

bool SelfCollisionRule::Frozen(Side side, int unum, const std::string& joint) const {
  const auto player = joints_.find({side, unum});
  if (player == joints_.end()) return false;
  const auto it = player->second.find(joint);
  return it != player->second.end() && it->second.frozen;
}

void SelfCollisionRule::Save(StateWriter& out) const {
  out.Tag(StateTag("SCOL"));
  out(Sized(joints_, kMaxPlayers));
}

void SelfCollisionRule::Restore(StateReader& in) {
  in.Tag(StateTag("SCOL"));
  std::map<Player, std::map<std::string, Joint>> restored;
  in(Sized(restored, kMaxPlayers));
  for (const auto& [player, joints] : restored) {
    if (player.second < 0 || player.second > kMaxUnum) in.Fail("self-collision player number out of range");
    if (joints.size() > kMaxJoints) in.Fail("length out of range");
  }
  if (!in.ok()) return;
  joints_ = std::move(restored);
}

}  // namespace turf::simspark
