// Session::SaveLeague / RestoreLeague: the SimSpark league's state in a snapshot of its own, next to the kernel's
// (the world): the game, the referee's rules, every agent's robot, commands and noise streams
// (codecs/simspark/session.h). The RCSSServerMJ session's (codecs/rcssservermj/session_snapshot.cpp) is its twin.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "codecs/simspark/session.h"
#include "core/state_io_eigen.h"

namespace turf::simspark {

namespace {

constexpr uint32_t kLeagueVersion = 7;
constexpr size_t kMaxItems = 4096;  // robots, joints, links, moves, players: far above any scene
constexpr size_t kMaxName = 256;    // a robot, joint, link or team name

void SaveWorld(const WorldSnapshot& w, StateWriter& out) {
  out.Put(w.time);
  PutVector(w.ball, out);
  PutVector(w.ball_velocity, out);
  out.Put<uint64_t>(w.robots.size());
  for (const RobotSnapshot& r : w.robots) {
    out.Str(r.name);
    out.Put<uint64_t>(r.joint_names.size());
    for (const std::string& j : r.joint_names) out.Str(j);
    out.Doubles(r.joint_positions);
    PutArray(r.gyro, out);
    PutArray(r.accelerometer, out);
    out.Put<uint64_t>(r.feet.size());
    for (const RobotSnapshot::Foot& f : r.feet) {
      out.Str(f.name);
      out.Put(f.contact);
      PutArray(f.point, out);
      PutArray(f.force, out);
    }
    out.Put<uint64_t>(r.links.size());
    for (const RobotSnapshot::Link& l : r.links) {
      out.Str(l.name);
      PutVector(l.position, out);
      PutQuaternion(l.orientation, out);
    }
    PutVector(r.velocity, out);
    out.Put(r.ball_touch_time);
  }
  out.Put<uint64_t>(w.robot_contacts.size());
  for (const RobotTouch& t : w.robot_contacts) {
    out.Str(t.robot_a);
    out.Str(t.robot_b);
    PutVector(t.point, out);
  }
}

WorldSnapshot RestoreWorld(StateReader& in) {
  WorldSnapshot w;
  w.time = GetFinite(in);
  w.ball = GetVector(in);
  w.ball_velocity = GetVector(in);
  w.robots.resize(in.Count(kMaxItems));
  for (RobotSnapshot& r : w.robots) {
    r.name = in.Str(kMaxName);
    r.joint_names.resize(in.Count(kMaxItems));
    for (std::string& j : r.joint_names) j = in.Str(kMaxName);
    in.Doubles(&r.joint_positions, r.joint_names.size());
    r.gyro = GetArray<3>(in);
    r.accelerometer = GetArray<3>(in);
    r.feet.resize(in.Count(kMaxItems));
    for (RobotSnapshot::Foot& f : r.feet) {
      f.name = in.Str(kMaxName);
      f.contact = in.Bool();
      f.point = GetArray<3>(in);
      f.force = GetArray<3>(in);
    }
    r.links.resize(in.Count(kMaxItems));
    for (RobotSnapshot::Link& l : r.links) {
      l.name = in.Str(kMaxName);
      l.position = GetVector(in);
      l.orientation = GetQuaternion(in);
    }
    r.velocity = GetVector(in);
    r.ball_touch_time = GetFinite(in);
    if (!in.ok()) break;
  }
  w.robot_contacts.resize(in.Count(kMaxItems));
  for (RobotTouch& t : w.robot_contacts) {
    t.robot_a = in.Str(kMaxName);
    t.robot_b = in.Str(kMaxName);
    t.point = GetVector(in);
    if (!in.ok()) break;
  }
  return w;
}

void SaveJoints(const std::map<std::string, std::vector<JointVelocity>>& joints, StateWriter& out) {
  out.Put<uint64_t>(joints.size());
  for (const auto& [robot, targets] : joints) {
    out.Str(robot);
    out.Put<uint64_t>(targets.size());
    for (const JointVelocity& t : targets) {
      out.Str(t.joint);
      out.Put(t.velocity);
    }
  }
}

std::map<std::string, std::vector<JointVelocity>> RestoreJoints(StateReader& in) {
  std::map<std::string, std::vector<JointVelocity>> joints;
  const size_t n = in.Count(kMaxItems);
  for (size_t i = 0; i < n && in.ok(); ++i) {
    const std::string robot = in.Str(kMaxName);
    std::vector<JointVelocity> targets(in.Count(kMaxItems));
    for (JointVelocity& t : targets) {
      t.joint = in.Str(kMaxName);
      t.velocity = GetFinite(in);
    }
    if (!joints.emplace(robot, std::move(targets)).second) in.Fail("robot twice");
  }
  return joints;
}

}  // namespace

std::string Session::SaveLeague() const {
  StateWriter out;
  out.Tag(StateTag("TSLG"));
  out.Put(kLeagueVersion);
  out.Put(cycle_);
  game_.Save(out);
  self_collision_.Save(out);
  fouls_.Save(out);
  radio_.Save(out);
  beam_rng_.Save(out);
  out.Tag(StateTag("SREQ"));
  out.Put<uint64_t>(requests_.moves.size());
  for (const RobotMove& m : requests_.moves) PutMove(m, out);
  out.Put(requests_.ball.has_value());
  if (requests_.ball) {
    PutVector(requests_.ball->position, out);
    PutVector(requests_.ball->velocity, out);
  }
  SaveJoints(requests_.joints, out);
  SaveJoints(held_joints_, out);
  out.Put(last_.has_value());
  if (last_) SaveWorld(*last_, out);
  out.Put<uint64_t>(torso_poses_.size());
  for (const auto& [robot, poses] : torso_poses_) {
    out.Str(robot);
    out.Put<uint64_t>(poses.size());
    for (const TorsoPose& t : poses) {
      PutVector(t.position, out);
      PutQuaternion(t.orientation, out);
    }
  }
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
    out.Put(a->side);
    out.Put<int32_t>(a->unum);
    out.Str(a->team);
    out.Put<int32_t>(a->type);
    out.Str(a->robot >= 0 ? robots_[a->robot] : std::string());
    out.Put(a->announce);
    out.Put(a->scene_cycle);
    out.Put(a->perceptions);
    PutVector(a->calibration, out);
    a->rng.Save(out);
  }
  return out.Take();
}

std::string Session::RestoreLeague(std::string_view snapshot) {
  StateReader in(snapshot);
  if (in.Get<uint32_t>() != StateTag("TSLG") || !in.ok()) return "not a SimSpark league snapshot";
  if (in.Get<uint32_t>() != kLeagueVersion || !in.ok()) return "league snapshot format version differs";
  // Everything into copies first: a refused snapshot changes nothing.
  const uint64_t cycle = in.Get<uint64_t>();
  Game game = game_;
  game.Restore(in);
  SelfCollisionRule self_collision = self_collision_;
  self_collision.Restore(in);
  FoulReferee fouls = fouls_;
  fouls.Restore(in);
  Radio radio = radio_;
  radio.Restore(in);
  Rng beam_rng;
  beam_rng.Restore(in);
  in.Tag(StateTag("SREQ"));
  const auto known_robot = [&](const std::string& name) {
    if (std::find(robots_.begin(), robots_.end(), name) == robots_.end()) in.Fail("a robot not in the scene");
  };
  WorldRequests requests;
  requests.moves.resize(in.Count(kMaxItems));
  for (RobotMove& m : requests.moves) {
    m = GetMove<RobotMove>(in, kMaxName);
    known_robot(m.robot);
  }
  if (in.Bool()) requests.ball = BallMove{GetVector(in), GetVector(in)};
  requests.joints = RestoreJoints(in);
  std::map<std::string, std::vector<JointVelocity>> held = RestoreJoints(in);
  for (const auto* joints : {&requests.joints, &held})
    for (const auto& [robot, targets] : *joints) known_robot(robot);
  std::optional<WorldSnapshot> last;
  if (in.Bool()) last = RestoreWorld(in);
  std::map<std::string, std::vector<TorsoPose>> torso_poses;
  const size_t posed = in.Count(kMaxItems);
  for (size_t i = 0; i < posed && in.ok(); ++i) {
    const std::string robot = in.Str(kMaxName);
    known_robot(robot);
    std::vector<TorsoPose>& poses = torso_poses[robot];
    poses.resize(in.Count(4));
    for (TorsoPose& t : poses) {
      t.position = GetVector(in);
      t.orientation = GetQuaternion(in);
    }
  }
  in.Tag(StateTag("SPLY"));
  // Each player of the snapshot onto the connected agent that is that player.
  std::map<int, Agent> players;  // by agent id: the agent with its league state replaced
  std::string refused;
  const size_t n = in.Count(kMaxItems);
  for (size_t i = 0; i < n && in.ok() && refused.empty(); ++i) {
    const Side side = in.Enum(static_cast<Side>(2));
    const int unum = in.Get<int32_t>();
    const std::string team = in.Str(kMaxName);
    const int type = in.Get<int32_t>();
    const std::string robot = in.Str(kMaxName);
    if (type < 0 || type >= kRobotTypes) in.Fail("robot type out of range");
    Agent state;
    state.announce = in.Bool();
    state.scene_cycle = in.Get<uint64_t>();
    state.perceptions = in.Get<uint64_t>();
    state.calibration = GetVector(in);
    state.rng.Restore(in);
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
