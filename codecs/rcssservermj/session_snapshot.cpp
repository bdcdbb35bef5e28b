// Session::SaveLeague / RestoreLeague: the RCSSServerMJ league's state in a snapshot of its own, next to the
// kernel's (the world). Same contract as the SimSpark session's (codecs/simspark/session.h).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "codecs/rcssservermj/session.h"
#include "core/state_io.h"

namespace turf::rcssservermj {

namespace {

constexpr uint32_t kLeagueVersion = 1;
constexpr size_t kMaxMonitor = 1 << 20;  // a queued monitor message (bytes)
constexpr double kRad = M_PI / 180.0;
constexpr double kSlack = 1e-9;  // rad: a bound converted from degrees, read back

using Player = std::pair<Side, int>;  // (side, number): a player across reconnections

// The bounds the action parser enforces (codecs/rcssservermj/actions.h), in radians.
bool WithinActionBounds(double q, double dq, double kp, double kd, double tau) {
  return std::abs(q) <= kMaxAbsQDeg * kRad + kSlack && std::abs(dq) <= kMaxAbsDqDegS * kRad + kSlack && kp >= 0 &&
         kp <= kMaxKp && kd >= 0 && kd <= kMaxKd && std::abs(tau) <= kMaxAbsTau;
}

}  // namespace

// Requests, agents' messages not yet taken and perceptions not yet released (the parallel loop's): each struct's
// fields listed once (core/state_io.h), refused when not finite or beyond what the parsers accept.
// A PD command's targets and gains (a PdCommand's or a MotorAction's), within the parser's bounds.
template <class Io, class Command>
void PdFields(Io& io, Command& c) {
  io(FiniteValue(c.q), FiniteValue(c.dq), FiniteValue(c.kp), FiniteValue(c.kd), FiniteValue(c.tau));
  io.Check(WithinActionBounds(c.q, c.dq, c.kp, c.kd, c.tau), "motor command out of range");
}

template <class Io>
void Fields(Io& io, IoRef<Io, PdCommand> c) {
  io(c.joint);
  PdFields(io, c);
}

template <class Io>
void Fields(Io& io, IoRef<Io, RobotMove> m) {
  io(m.robot, m.position, m.orientation, m.reset_joints);
}

template <class Io>
void Fields(Io& io, IoRef<Io, MotorAction> a) {
  io(a.joint);
  PdFields(io, a);
}

template <class Io>
void Fields(Io& io, IoRef<Io, BeamAction> b) {
  io(FiniteValue(b.x), FiniteValue(b.y), FiniteValue(b.theta_deg));
  io.Check(std::abs(b.x) <= kMaxAbsBeam && std::abs(b.y) <= kMaxAbsBeam, "beam out of range");
}

template <class Io>
void Fields(Io& io, IoRef<Io, ActionMessage> m) {
  io(m.motors, m.beam, m.say, m.syn);
}

template <class Io>
void Fields(Io& io, IoRef<Io, SeenMarker> m) {
  io(m.name, FiniteValue(m.pol.distance), FiniteValue(m.pol.azimuth), FiniteValue(m.pol.elevation));
}

template <class Io>
void Fields(Io& io, IoRef<Io, SeenPlayer> p) {
  io(p.team, p.number, p.parts);
}

template <class Io>
void Fields(Io& io, IoRef<Io, SeeItems> see) {
  io(see.markers, see.players);
}

template <class Io>
void Fields(Io& io, IoRef<Io, JointReading> j) {
  io(j.name, FiniteValue(j.position), FiniteValue(j.velocity));
}

template <class Io>
void Fields(Io& io, IoRef<Io, MjPerception> p) {
  io(FiniteValue(p.time), FiniteValue(p.game.play_time), p.game.play_mode, p.game.team_left, p.game.team_right,
     p.game.score_left, p.game.score_right, p.has_robot, FiniteValue(p.quat), FiniteValue(p.pos), FiniteValue(p.gyro),
     FiniteValue(p.acc), p.joints, p.see);
}

std::string Session::SaveLeague() const {
  StateWriter out;
  out.Tag(StateTag("TMJL"));
  out(kLeagueVersion, cycle_, referee_, rng_);
  out.Put<uint64_t>(monitor_queue_.size());
  for (const std::string& m : monitor_queue_) out.Str(m);
  out.Tag(StateTag("MREQ"));
  out(requests_.moves, requests_.ball, requests_.joints);
  out.Tag(StateTag("MPLY"));
  // By (side, number), not by connection: the same league gives the same bytes.
  std::vector<const Agent*> players;
  for (const auto& [id, a] : agents_)
    if (a.active) players.push_back(&a);
  std::sort(players.begin(), players.end(),
            [](const Agent* x, const Agent* y) { return Player(x->side, x->number) < Player(y->side, y->number); });
  out.Put<uint64_t>(players.size());
  for (const Agent* a : players) {
    out(a->side, a->number, std::string(a->model->name), robots_[a->robot].name, a->motors, a->perceptions, a->answers);
    out.Put<uint64_t>(a->queue.size());
    for (const ActionMessage& m : a->queue) out(m);
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
    out(a.side, a.number, entry->second);
  }
  return out.Take();
}

std::string Session::RestoreLeague(std::string_view snapshot) {
  StateReader in(snapshot);
  if (in.Get<uint32_t>() != StateTag("TMJL") || !in.ok()) return "not an RCSSServerMJ league snapshot";
  if (in.Get<uint32_t>() != kLeagueVersion || !in.ok()) return "league snapshot format version differs";
  // Everything into copies first: a refused snapshot changes nothing.
  uint64_t cycle = 0;
  Referee referee = referee_;
  Rng rng = rng_;
  in(cycle, referee, rng);
  std::vector<std::string> monitor(in.Count(kMaxQueuedMonitor));
  for (std::string& m : monitor) m = in.Str(kMaxMonitor);
  in.Tag(StateTag("MREQ"));
  WorldRequests requests;
  in(requests.moves, requests.ball, requests.joints);
  const auto known_robot = [&](const std::string& name) {
    const bool known = std::any_of(robots_.begin(), robots_.end(), [&](const SceneRobot& r) { return r.name == name; });
    if (!known) in.Fail("a robot not in the scene");
  };
  for (const RobotMove& m : requests.moves) known_robot(m.robot);
  for (const auto& [robot, commands] : requests.joints) known_robot(robot);
  in.Tag(StateTag("MPLY"));
  // Each player of the snapshot onto the connected agent that is that player.
  std::map<int, Agent> players;  // by agent id: the agent with its league state replaced
  std::map<Player, int> ids;
  std::string refused;
  const size_t n = in.Count(kMaxSnapshotItems);
  for (size_t i = 0; i < n && in.ok() && refused.empty(); ++i) {
    Player player;
    std::string model_name, robot;
    std::vector<PdCommand> motors;
    uint64_t perceptions = 0, answers = 0;
    in(player.first, player.second, model_name, robot, motors, perceptions, answers);
    const MjRobotModel* model = FindModel(model_name);
    if (model == nullptr) in.Fail("no such robot model");
    std::deque<ActionMessage> queue(in.Count(options_.max_queued + 1));
    for (ActionMessage& m : queue) {
      in(m);
      const size_t joints = model != nullptr ? model->joints.size() : 0;
      for (const MotorAction& a : m.motors)
        if (a.joint < 0 || static_cast<size_t>(a.joint) >= joints) in.Fail("joint index out of range");
    }
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
    pending.resize(in.Count(kMaxSnapshotItems));
    for (auto& [id, perception] : pending) {
      Player player;
      in(player.first, player.second, perception);
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
