// Session::SaveLeague / RestoreLeague: the SimSpark league's state in a snapshot of its own, next to the kernel's
// (the world): the game, the referee's rules, every agent's robot, commands and noise streams
// (codecs/simspark/session.h). The RCSSServerMJ session's (codecs/rcssservermj/session_snapshot.cpp) is its twin.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "codecs/simspark/session.h"
#include "core/state_io.h"

namespace turf::simspark {

namespace {

constexpr uint32_t kLeagueVersion = 7;
constexpr size_t kMaxTorsoPoses = 4;  // RecordTorsoPoses keeps the last four

}  // namespace

// The world and requests the session keeps, each struct's fields listed once (core/state_io.h).
template <class Io>
void Fields(Io& io, IoRef<Io, RobotSnapshot::Foot> f) {
  io(f.name, f.contact, FiniteValue(f.point), FiniteValue(f.force));
}

template <class Io>
void Fields(Io& io, IoRef<Io, RobotSnapshot::Link> l) {
  io(l.name, l.position, l.orientation);
}

template <class Io>
void Fields(Io& io, IoRef<Io, RobotSnapshot> r) {
  io(r.name, r.joint_names);
  io(Exactly(r.joint_positions, r.joint_names.size()), FiniteValue(r.gyro), FiniteValue(r.accelerometer), r.feet,
     r.links, r.velocity, FiniteValue(r.ball_touch_time));
}

template <class Io>
void Fields(Io& io, IoRef<Io, RobotTouch> t) {
  io(t.robot_a, t.robot_b, t.point);
}

template <class Io>
void Fields(Io& io, IoRef<Io, WorldSnapshot> w) {
  io(FiniteValue(w.time), w.ball, w.ball_velocity, w.robots, w.robot_contacts);
}

template <class Io>
void Fields(Io& io, IoRef<Io, RobotMove> m) {
  io(m.robot, m.position, m.orientation, m.reset_joints);
}

template <class Io>
void Fields(Io& io, IoRef<Io, BallMove> b) {
  io(b.position, b.velocity);
}

template <class Io>
void Fields(Io& io, IoRef<Io, JointVelocity> j) {
  io(j.joint, FiniteValue(j.velocity));
}

std::string Session::SaveLeague() const {
  StateWriter out;
  out.Tag(StateTag("TSLG"));
  out(kLeagueVersion, cycle_, game_, self_collision_, fouls_, radio_, beam_rng_);
  out.Tag(StateTag("SREQ"));
  out(requests_.moves, requests_.ball, requests_.joints, held_joints_, last_, torso_poses_);
  out.Tag(StateTag("SPLY"));
  std::vector<const Agent*> players;
  for (const auto& [id, a] : agents_)
    if (a.inited) players.push_back(&a);
  // By (side, unum), not by connection: the same league gives the same bytes.
  std::sort(players.begin(), players.end(), [](const Agent* x, const Agent* y) {
    return std::make_pair(x->side, x->unum) < std::make_pair(y->side, y->unum);
  });
  out.Put<uint64_t>(players.size());
  for (const Agent* a : players) {
    out(a->side, a->unum, a->team, a->type, a->robot >= 0 ? robots_[a->robot] : std::string(), a->announce,
        a->scene_cycle, a->perceptions, a->calibration, a->rng);
  }
  return out.Take();
}

std::string Session::RestoreLeague(std::string_view snapshot) {
  StateReader in(snapshot);
  if (in.Get<uint32_t>() != StateTag("TSLG") || !in.ok()) return "not a SimSpark league snapshot";
  if (in.Get<uint32_t>() != kLeagueVersion || !in.ok()) return "league snapshot format version differs";
  // Everything into copies first: a refused snapshot changes nothing.
  uint64_t cycle = 0;
  Game game = game_;
  SelfCollisionRule self_collision = self_collision_;
  FoulReferee fouls = fouls_;
  Radio radio = radio_;
  Rng beam_rng;
  in(cycle, game, self_collision, fouls, radio, beam_rng);
  in.Tag(StateTag("SREQ"));
  WorldRequests requests;
  std::map<std::string, std::vector<JointVelocity>> held;
  std::optional<WorldSnapshot> last;
  std::map<std::string, std::vector<TorsoPose>> torso_poses;
  in(requests.moves, requests.ball, requests.joints, held, last, torso_poses);
  const auto known_robot = [&](const std::string& name) {
    if (std::find(robots_.begin(), robots_.end(), name) == robots_.end()) in.Fail("a robot not in the scene");
  };
  for (const RobotMove& m : requests.moves) known_robot(m.robot);
  for (const auto* joints : {&requests.joints, &held})
    for (const auto& [robot, targets] : *joints) known_robot(robot);
  for (const auto& [robot, poses] : torso_poses) {
    known_robot(robot);
    if (poses.size() > kMaxTorsoPoses) in.Fail("length out of range");
  }
  in.Tag(StateTag("SPLY"));
  // Each player of the snapshot onto the connected agent that is that player.
  std::map<int, Agent> players;  // by agent id: the agent with its league state replaced
  std::string refused;
  const size_t n = in.Count(kMaxSnapshotItems);
  for (size_t i = 0; i < n && in.ok() && refused.empty(); ++i) {
    Side side = Side::kLeft;
    int unum = 0;
    std::string team;
    int type = 0;
    std::string robot;
    Agent state;
    in(side, unum, team, type, robot, state.announce, state.scene_cycle, state.perceptions, state.calibration,
       state.rng);
    if (type < 0 || type >= kRobotTypes) in.Fail("robot type out of range");
    if (!in.ok()) break;
    const std::string who = fmt::format("player {} {}", SideName(side), unum);
    const Agent* a = nullptr;
    for (const auto& [id, agent] : agents_)
      if (agent.inited && agent.side == side && agent.unum == unum) a = &agent;
    if (a == nullptr) {
      refused = fmt::format("the snapshot's {} is not connected (or has no team)", who);
    } else if (a->robot < 0 || robots_[a->robot] != robot) {
      refused = fmt::format("the snapshot's {} drove {}, now {}", who, robot.empty() ? "no robot" : robot,
                            a->robot < 0 ? "none" : robots_[a->robot]);
    } else if (players.count(a->id) > 0) {
      in.Fail("a player twice");
    } else {
      Agent restored = *a;
      restored.type = type;
      restored.team = team;
      restored.announce = state.announce;
      restored.scene_cycle = state.scene_cycle;
      restored.perceptions = state.perceptions;
      restored.calibration = state.calibration;
      restored.rng = state.rng;
      players.emplace(a->id, std::move(restored));
    }
  }
  if (in.ok() && refused.empty() && !in.AtEnd()) in.Fail("trailing bytes");
  if (!in.ok()) return std::string("invalid league snapshot: ") + in.error();
  if (!refused.empty()) return refused;
  // The game's teams must be the players' (a snapshot from SaveLeague always is).
  int per_side[2] = {0, 0};
  for (const auto& [id, a] : players) {
    ++per_side[a.side == Side::kLeft ? 0 : 1];
    if (game.TeamName(a.side) != a.team) return "invalid league snapshot: a player's team is not its side's";
  }
  if (game.PlayerCount(Side::kLeft) != per_side[0] || game.PlayerCount(Side::kRight) != per_side[1])
    return "invalid league snapshot: the game's teams are not the players";
  for (const auto& [id, a] : agents_) {
    if (a.inited && players.count(id) == 0)
      return fmt::format("player {} {} is connected but not in the snapshot", SideName(a.side), a.unum);
  }
  cycle_ = cycle;
  game_ = std::move(game);
  self_collision_ = std::move(self_collision);
  fouls_ = std::move(fouls);
  radio_ = std::move(radio);
  beam_rng_ = beam_rng;
  requests_ = std::move(requests);
  held_joints_ = std::move(held);
  last_ = std::move(last);
  torso_poses_ = std::move(torso_poses);
  for (auto& [id, a] : players) agents_.at(id) = std::move(a);
  return "";
}

}  // namespace turf::simspark
