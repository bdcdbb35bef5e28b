// Session::SaveLeague / RestoreLeague: the RCSSServerMJ league's state in a snapshot of its own, next to the
// kernel's (the world). Same contract as the SimSpark session's (codecs/simspark/session.h).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "codecs/rcssservermj/session.h"
#include "core/state_io_eigen.h"

namespace turf::rcssservermj {

namespace {

constexpr uint32_t kLeagueVersion = 1;
constexpr size_t kMaxItems = 4096;       // robots, joints, moves, players, markers: far above any scene
constexpr size_t kMaxName = 256;         // a robot, joint, model, team, marker or play mode name
constexpr size_t kMaxMonitor = 1 << 20;  // a queued monitor message (bytes)
constexpr double kRad = M_PI / 180.0;
constexpr double kSlack = 1e-9;  // rad: a bound converted from degrees, read back

using Player = std::pair<Side, int>;  // (side, number): a player across reconnections

// --- world requests ---

// The bounds the action parser enforces (codecs/rcssservermj/actions.h), in radians.
bool WithinActionBounds(double q, double dq, double kp, double kd, double tau) {
  return std::abs(q) <= kMaxAbsQDeg * kRad + kSlack && std::abs(dq) <= kMaxAbsDqDegS * kRad + kSlack && kp >= 0 &&
         kp <= kMaxKp && kd >= 0 && kd <= kMaxKd && std::abs(tau) <= kMaxAbsTau;
}

void PutPd(const PdCommand& c, StateWriter& out) {
  out.Str(c.joint);
  for (double v : {c.q, c.dq, c.kp, c.kd, c.tau}) out.Put(v);
}

PdCommand GetPd(StateReader& in) {
  PdCommand c;
  c.joint = in.Str(kMaxName);
  for (double* v : {&c.q, &c.dq, &c.kp, &c.kd, &c.tau}) *v = GetFinite(in);
  if (!WithinActionBounds(c.q, c.dq, c.kp, c.kd, c.tau)) in.Fail("motor command out of range");
  return c;
}

void PutPds(const std::vector<PdCommand>& commands, StateWriter& out) {
  out.Put<uint64_t>(commands.size());
  for (const PdCommand& c : commands) PutPd(c, out);
}

std::vector<PdCommand> GetPds(StateReader& in) {
  std::vector<PdCommand> commands(in.Count(kMaxItems));
  for (PdCommand& c : commands) c = GetPd(in);
  return commands;
}

// --- agent messages not yet taken ---

void PutMessage(const ActionMessage& m, StateWriter& out) {
  out.Put<uint64_t>(m.motors.size());
  for (const MotorAction& a : m.motors) {
    out.Put<int32_t>(a.joint);
    for (double v : {a.q, a.dq, a.kp, a.kd, a.tau}) out.Put(v);
  }
  PutOptional(m.beam, out, [&](const BeamAction& b) {
    for (double v : {b.x, b.y, b.theta_deg}) out.Put(v);
  });
  out.Put(m.say);
  out.Put(m.syn);
}

ActionMessage GetMessage(StateReader& in, const MjRobotModel& model) {
  ActionMessage m;
  m.motors.resize(in.Count(kMaxItems));
  for (MotorAction& a : m.motors) {
    a.joint = in.Get<int32_t>();
    for (double* v : {&a.q, &a.dq, &a.kp, &a.kd, &a.tau}) *v = GetFinite(in);
    if (a.joint < 0 || static_cast<size_t>(a.joint) >= model.joints.size()) in.Fail("joint index out of range");
    if (!WithinActionBounds(a.q, a.dq, a.kp, a.kd, a.tau)) in.Fail("motor command out of range");
  }
  m.beam = GetOptional<BeamAction>(in, [&] {
    BeamAction b{GetFinite(in), GetFinite(in), GetFinite(in)};
    if (std::abs(b.x) > kMaxAbsBeam || std::abs(b.y) > kMaxAbsBeam) in.Fail("beam out of range");
    return b;
  });
  m.say = in.Bool();
  m.syn = in.Bool();
  return m;
}

// --- perceptions not yet released (the parallel loop's) ---

void PutMarkers(const std::vector<SeenMarker>& markers, StateWriter& out) {
  out.Put<uint64_t>(markers.size());
  for (const SeenMarker& m : markers) {
    out.Str(m.name);
    for (double v : {m.pol.distance, m.pol.azimuth, m.pol.elevation}) out.Put(v);
  }
}

std::vector<SeenMarker> GetMarkers(StateReader& in) {
  std::vector<SeenMarker> markers(in.Count(kMaxItems));
  for (SeenMarker& m : markers) {
    m.name = in.Str(kMaxName);
    for (double* v : {&m.pol.distance, &m.pol.azimuth, &m.pol.elevation}) *v = GetFinite(in);
  }
  return markers;
}

void PutPerception(const MjPerception& p, StateWriter& out) {
  out.Put(p.time);
  out.Put(p.game.play_time);
  out.Str(p.game.play_mode);
  for (const auto* team : {&p.game.team_left, &p.game.team_right})
    PutOptional(*team, out, [&](const std::string& t) { out.Str(t); });
  out.Put<int32_t>(p.game.score_left);
  out.Put<int32_t>(p.game.score_right);
  out.Put(p.has_robot);
  PutArray(p.quat, out);
  PutArray(p.pos, out);
  PutArray(p.gyro, out);
  PutArray(p.acc, out);
  out.Put<uint64_t>(p.joints.size());
  for (const JointReading& j : p.joints) {
    out.Str(j.name);
    out.Put(j.position);
    out.Put(j.velocity);
  }
  PutOptional(p.see, out, [&](const SeeItems& see) {
    PutMarkers(see.markers, out);
    out.Put<uint64_t>(see.players.size());
    for (const SeenPlayer& player : see.players) {
      out.Str(player.team);
      out.Put<int32_t>(player.number);
      PutMarkers(player.parts, out);
    }
  });
}

MjPerception GetPerception(StateReader& in) {
  MjPerception p;
  p.time = GetFinite(in);
  p.game.play_time = GetFinite(in);
  p.game.play_mode = in.Str(kMaxName);
  for (auto* team : {&p.game.team_left, &p.game.team_right})
    *team = GetOptional<std::string>(in, [&] { return in.Str(kMaxName); });
  p.game.score_left = in.Get<int32_t>();
  p.game.score_right = in.Get<int32_t>();
  p.has_robot = in.Bool();
  p.quat = GetArray<4>(in);
  p.pos = GetArray<3>(in);
  p.gyro = GetArray<3>(in);
  p.acc = GetArray<3>(in);
  p.joints.resize(in.Count(kMaxItems));
  for (JointReading& j : p.joints) {
    j.name = in.Str(kMaxName);
    j.position = GetFinite(in);
    j.velocity = GetFinite(in);
  }
  p.see = GetOptional<SeeItems>(in, [&] {
    SeeItems see;
    see.markers = GetMarkers(in);
    see.players.resize(in.Count(kMaxItems));
    for (SeenPlayer& player : see.players) {
      player.team = in.Str(kMaxName);
      player.number = in.Get<int32_t>();
      player.parts = GetMarkers(in);
    }
    return see;
  });
  return p;
}

}  // namespace

std::string Session::SaveLeague() const {
  StateWriter out;
  out.Tag(StateTag("TMJL"));
  out.Put(kLeagueVersion);
  out.Put(cycle_);
  referee_.Save(out);
  rng_.Save(out);
  out.Put<uint64_t>(monitor_queue_.size());
  for (const std::string& m : monitor_queue_) out.Str(m);
  out.Tag(StateTag("MREQ"));
  out.Put<uint64_t>(requests_.moves.size());
  for (const RobotMove& m : requests_.moves) PutMove(m, out);
  PutOptional(requests_.ball, out, [&](const Eigen::Vector3d& b) { PutVector(b, out); });
  out.Put<uint64_t>(requests_.joints.size());
  for (const auto& [robot, commands] : requests_.joints) {
    out.Str(robot);
    PutPds(commands, out);
  }
  out.Tag(StateTag("MPLY"));
  // By (side, number), not by connection: the same league gives the same bytes.
  std::vector<const Agent*> players;
  for (const auto& [id, a] : agents_)
    if (a.active) players.push_back(&a);
  std::sort(players.begin(), players.end(),
            [](const Agent* x, const Agent* y) { return Player(x->side, x->number) < Player(y->side, y->number); });
  out.Put<uint64_t>(players.size());
  for (const Agent* a : players) {
    out.Put(a->side);
    out.Put<int32_t>(a->number);
    out.Str(a->model->name);
    out.Str(robots_[a->robot].name);
    PutPds(a->motors, out);
    out.Put(a->perceptions);
    out.Put(a->answers);
    out.Put<uint64_t>(a->queue.size());
    for (const ActionMessage& m : a->queue) PutMessage(m, out);
  }
  out.Tag(StateTag("MPND"));
  std::vector<const std::pair<int, MjPerception>*> pending;
  for (const auto& entry : pending_) {
    const auto it = agents_.find(entry.first);
    if (it != agents_.end() && it->second.active) pending.push_back(&entry);
  }
  out.Put<uint64_t>(pending.size());
  for (const auto* entry : pending) {
    const Agent& a = agents_.at(entry->first);
    out.Put(a.side);
    out.Put<int32_t>(a.number);
    PutPerception(entry->second, out);
  }
  return out.Take();
}

std::string Session::RestoreLeague(std::string_view snapshot) {
  StateReader in(snapshot);
  if (in.Get<uint32_t>() != StateTag("TMJL") || !in.ok()) return "not an RCSSServerMJ league snapshot";
  if (in.Get<uint32_t>() != kLeagueVersion || !in.ok()) return "league snapshot format version differs";
  // Everything into copies first: a refused snapshot changes nothing.
  const uint64_t cycle = in.Get<uint64_t>();
  Referee referee = referee_;
  referee.Restore(in);
  Rng rng = rng_;
  rng.Restore(in);
  std::vector<std::string> monitor(in.Count(kMaxItems));
  for (std::string& m : monitor) m = in.Str(kMaxMonitor);
  const auto known_robot = [&](const std::string& name) {
    const bool known = std::any_of(robots_.begin(), robots_.end(), [&](const SceneRobot& r) { return r.name == name; });
    if (!known) in.Fail("a robot not in the scene");
  };
  in.Tag(StateTag("MREQ"));
  WorldRequests requests;
  requests.moves.resize(in.Count(kMaxItems));
  for (RobotMove& m : requests.moves) {
    m = GetMove<RobotMove>(in, kMaxName);
    known_robot(m.robot);
  }
  requests.ball = GetOptional<Eigen::Vector3d>(in, [&] { return GetVector(in); });
  const size_t commanded = in.Count(kMaxItems);
  for (size_t i = 0; i < commanded && in.ok(); ++i) {
    const std::string robot = in.Str(kMaxName);
    known_robot(robot);
    if (!requests.joints.emplace(robot, GetPds(in)).second) in.Fail("robot twice");
  }
  in.Tag(StateTag("MPLY"));
  // Each player of the snapshot onto the connected agent that is that player.
  std::map<int, Agent> players;  // by agent id: the agent with its league state replaced
  std::map<Player, int> ids;
  std::string refused;
  const size_t n = in.Count(kMaxItems);
  for (size_t i = 0; i < n && in.ok() && refused.empty(); ++i) {
    const Player player{in.Enum(static_cast<Side>(2)), in.Get<int32_t>()};
    const MjRobotModel* model = FindModel(in.Str(kMaxName));
    const std::string robot = in.Str(kMaxName);
    if (model == nullptr) in.Fail("no such robot model");
    std::vector<PdCommand> motors = GetPds(in);
    const uint64_t perceptions = in.Get<uint64_t>();
    const uint64_t answers = in.Get<uint64_t>();
    std::deque<ActionMessage> queue(in.Count(options_.max_queued + 1));
    for (ActionMessage& m : queue) m = GetMessage(in, model != nullptr ? *model : Models().front());
    if (model != nullptr && motors.size() != model->joints.size()) in.Fail("motor count differs from the model");
    if (!in.ok()) break;
    const std::string who = fmt::format("player {} {}", player.first == Side::kLeft ? "left" : "right", player.second);
    const Agent* a = FindPlayer(player.first, player.second);
    if (a == nullptr) {
      refused = fmt::format("the snapshot's {} is not connected (or not active)", who);
    } else if (a->model != model || robots_[a->robot].name != robot) {
      refused = fmt::format("the snapshot's {} drove {} {}, now {} {}", who, model->name, robot, a->model->name,
                            robots_[a->robot].name);
    } else if (!ids.emplace(player, a->id).second) {
      in.Fail("a player twice");
    } else {
      Agent restored = *a;
      restored.motors = std::move(motors);
      restored.perceptions = perceptions;
      restored.answers = answers;
      restored.queue = std::move(queue);
      players.emplace(a->id, std::move(restored));
    }
  }
  std::vector<std::pair<int, MjPerception>> pending;
  if (refused.empty()) {
    in.Tag(StateTag("MPND"));
    pending.resize(in.Count(kMaxItems));
    for (auto& [id, perception] : pending) {
      const Player player{in.Enum(static_cast<Side>(2)), in.Get<int32_t>()};
      perception = GetPerception(in);
      const auto it = ids.find(player);
      if (in.ok() && it == ids.end()) in.Fail("a perception for a player not in the snapshot");
      id = it == ids.end() ? -1 : it->second;
    }
    if (in.ok() && !in.AtEnd()) in.Fail("trailing bytes");
  }
  if (!in.ok()) return std::string("invalid league snapshot: ") + in.error();
  if (!refused.empty()) return refused;
  for (const auto& [id, a] : agents_) {
    if (a.active && players.count(id) == 0)
      return fmt::format("player {} {} is connected but not in the snapshot", a.side == Side::kLeft ? "left" : "right",
                         a.number);
  }
  // A side's team is named exactly while it has players (as Activate and Disconnect keep it).
  for (Side side : {Side::kLeft, Side::kRight}) {
    const bool has_players =
        std::any_of(players.begin(), players.end(), [&](const auto& p) { return p.second.side == side; });
    if (has_players != referee.team(side).has_value())
      return "invalid league snapshot: the referee's teams are not the players'";
  }
  cycle_ = cycle;
  referee_ = std::move(referee);
  rng_ = rng;
  monitor_queue_ = std::move(monitor);
  requests_ = std::move(requests);
  pending_ = std::move(pending);
  for (auto& [id, a] : players) agents_.at(id) = std::move(a);
  return "";
}

}  // namespace turf::rcssservermj
