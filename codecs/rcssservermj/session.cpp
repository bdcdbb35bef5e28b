#include "codecs/rcssservermj/session.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <type_traits>
#include <variant>

#include "codecs/rcssservermj/monitor.h"
#include "codecs/rcssservermj/perception.h"

namespace turf::rcssservermj {

namespace {

constexpr double kRad = M_PI / 180.0;
// A player touches the ball when the origin of one of its bodies is this close to the ball's surface.
constexpr double kTouchDistance = 0.15;  // m

Eigen::Quaterniond Yaw(double deg) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(deg * kRad, Eigen::Vector3d::UnitZ()));
}

const MjField& FieldFor(const SessionOptions& o) {
  const RuleBook* rules = FindRuleBook(o.rules);
  if (rules == nullptr) throw std::invalid_argument("unknown rule book '" + o.rules + "'");
  const MjField* field = FindField(o.field.empty() ? std::string(rules->field) : o.field);
  if (field == nullptr) throw std::invalid_argument("unknown field '" + o.field + "'");
  return *field;
}

Eigen::Vector3d PointOf(const MjRobotSnapshot& robot, const BodyPoint& point, bool* found) {
  const MjLink* link = robot.FindLink(point.body);
  *found = link != nullptr;
  return link == nullptr ? Eigen::Vector3d::Zero() : Eigen::Vector3d(link->position + link->orientation * point.offset);
}

}  // namespace

const MjLink* MjRobotSnapshot::FindLink(const std::string& body) const {
  for (const MjLink& l : links)
    if (l.name == body) return &l;
  return nullptr;
}

const MjRobotSnapshot* MjWorldSnapshot::Find(const std::string& robot) const {
  for (const MjRobotSnapshot& r : robots)
    if (r.name == robot) return &r;
  return nullptr;
}

Session::Session(SessionOptions options, std::vector<SceneRobot> robots)
    : options_(std::move(options)),
      robots_(std::move(robots)),
      owner_(robots_.size(), -1),
      field_(&FieldFor(options_)),
      markers_(FieldMarkers(*field_)),
      referee_(*FindRuleBook(options_.rules), *field_, options_.ball_radius),
      rng_(options_.seed) {}

int Session::Connect() {
  const int id = next_agent_++;
  agents_[id].id = id;
  return id;
}

Session::Agent* Session::FindAgent(int id) {
  auto it = agents_.find(id);
  return it == agents_.end() ? nullptr : &it->second;
}

Session::Agent* Session::FindPlayer(Side side, int number) {
  for (auto& [id, a] : agents_)
    if (a.active && a.side == side && a.number == number) return &a;
  return nullptr;
}

int Session::active_agents() const {
  int n = 0;
  for (const auto& [id, a] : agents_) n += a.active;
  return n;
}

bool Session::HasPendingInit() const {
  for (const auto& [id, a] : agents_)
    if (!a.active && a.init && !a.kicked) return true;
  return false;
}

void Session::Issue(int agent, const std::string& kind, const std::string& detail) {
  issues_.push_back({agent, kind, detail});
}

void Session::Kick(Agent* agent, const std::string& why) {
  if (agent->kicked) return;
  Issue(agent->id, "dropped", why);
  agent->kicked = true;
  kicked_.push_back(agent->id);
}

void Session::Disconnect(int id) {
  Agent* a = FindAgent(id);
  if (a == nullptr) return;
  if (a->active) {
    RobotMove park = robots_[a->robot].park;
    park.reset_joints = true;
    requests_.moves.push_back(park);
    owner_[a->robot] = -1;
    const Side side = a->side;
    agents_.erase(id);
    bool others = false;
    for (const auto& [other, b] : agents_) others = others || (b.active && b.side == side);
    if (!others) referee_.Leave(side);  // the team's name is free again
    return;
  }
  agents_.erase(id);
}

void Session::Receive(int id, const std::string& payload) {
  Agent* a = FindAgent(id);
  if (a == nullptr || a->kicked) return;
  if (a->active) {
    // Parsed now, while the world steps and other agents think, not when the next cycle takes it (its issues are
    // reported now too).
    ActionMessage m = ParseActions(payload, *a->model);
    for (const ActionIssue& issue : m.issues) Issue(id, turf::ErrorName(issue.error), issue.detail);
    a->queue.push_back(std::move(m));
    if (a->queue.size() > options_.max_queued)
      Kick(a, fmt::format("more than {} messages waiting (in sync mode: one per cycle)", options_.max_queued));
    return;
  }
  if (a->init) return;  // ignored until activated, as the reference does
  InitAction init;
  const turf::Error error = ParseInit(payload, &init);
  if (error != turf::Error::kOk) {
    Issue(id, "bad_init",
          fmt::format("{}: the first message must be (init <model> <team> <player_no>)", turf::ErrorName(error)));
    Kick(a, "no valid init");
    return;
  }
  a->init = init;
}

void Session::Monitor(const std::string& payload) {
  if (monitor_queue_.size() >= kMaxQueuedMonitor) {
    Issue(-1, "monitor_queue_full",
          fmt::format("{} monitor messages already wait for the next cycle (in sync mode none runs until the agents "
                      "answer): dropped",
                      kMaxQueuedMonitor));
    return;
  }
  monitor_queue_.push_back(payload);
}

bool Session::Owes(const Agent& a) const { return sync() && a.active && !a.kicked && a.answers < a.perceptions; }

bool Session::ReadyToStep() const {
  for (const auto& [id, a] : agents_)
    if (Owes(a) && a.queue.empty()) return false;
  return true;
}

std::vector<int> Session::Waiting() const {
  std::vector<int> out;
  for (const auto& [id, a] : agents_)
    if (Owes(a) && a.queue.empty()) out.push_back(id);
  return out;
}

void Session::Activate(Agent* a) {
  const InitAction init = *a->init;
  auto refuse = [&](const std::string& why) {
    Issue(a->id, "init_refused", why);
    Kick(a, "init refused: " + why);
  };
  const MjRobotModel* model = FindModel(init.model);
  if (model == nullptr) return refuse(fmt::format("no robot model '{}' (T1, K1)", init.model));
  const bool had_team = referee_.team(Side::kLeft) == init.team || referee_.team(Side::kRight) == init.team;
  const std::optional<Side> side = referee_.Join(init.team);
  if (!side) return refuse(fmt::format("two teams play already; '{}' is a third", init.team));
  int players = 0;
  for (const auto& [id, b] : agents_) players += b.active && b.side == *side;
  int robot = -1;
  for (size_t i = 0; i < robots_.size() && robot < 0; ++i)
    if (owner_[i] < 0 && robots_[i].model == model->name) robot = static_cast<int>(i);
  std::string why;
  if (FindPlayer(*side, init.player_no) != nullptr) {
    why = fmt::format("team '{}' has a player {} already", init.team, init.player_no);
  } else if (players >= referee_.rules().max_players) {
    why = fmt::format("team '{}' has {} players already", init.team, players);
  } else if (robot < 0) {
    why = fmt::format("no free {} robot in the scene", model->name);
  }
  if (!why.empty()) {
    if (!had_team && players == 0) referee_.Leave(*side);
    return refuse(why);
  }
  a->active = true;
  a->model = model;
  a->robot = robot;
  a->side = *side;
  a->number = init.player_no;
  owner_[robot] = a->id;
  a->motors.clear();
  for (const MjJoint& j : model->joints) a->motors.push_back(PdCommand{j.joint, 0, 0, 1, 1, 0});
  const double x = (2 * init.player_no + 1) * (*side == Side::kLeft ? -1.0 : 1.0);
  const double y = field_->half_width() + field_->border;
  requests_.moves.push_back({robots_[robot].name, Eigen::Vector3d(x, y, model->torso_height), Yaw(-90), true});
}

void Session::Beam(Agent* a, const BeamAction& beam) {
  const bool left = a->side == Side::kLeft;
  const double x = left ? -std::abs(beam.x) : std::abs(beam.x);
  const double yaw = left ? beam.theta_deg : beam.theta_deg + 180.0;
  const double z = std::string_view(a->model->name) == "T1" ? kBeamHeight : a->model->torso_height + 0.001;
  requests_.moves.push_back({robots_[a->robot].name, Eigen::Vector3d(x, beam.y, z), Yaw(yaw), true});
}

void Session::Apply(Agent* a, const ActionMessage& m) {
  for (const MotorAction& motor : m.motors)
    a->motors[static_cast<size_t>(motor.joint)] = PdCommand{
        a->model->joints[static_cast<size_t>(motor.joint)].joint, motor.q, motor.dq, motor.kp, motor.kd, motor.tau};
  if (m.beam && referee_.BeamAllowed()) Beam(a, *m.beam);  // else ignored, as the reference does
}

WorldRequests Session::TakeRequests() {
  for (auto& [id, a] : agents_)
    if (!a.active && a.init && !a.kicked) Activate(&a);
  for (auto& [id, a] : agents_) {
    if (!a.active || a.kicked) continue;
    const size_t take = sync() ? (Owes(a) ? std::min<size_t>(1, a.queue.size()) : 0) : a.queue.size();
    a.answers += sync() ? take : 0;
    for (size_t i = 0; i < take; ++i) {
      const ActionMessage m = std::move(a.queue.front());
      a.queue.pop_front();
      Apply(&a, m);
    }
  }
  Release();  // the parallel loop's perceptions of the state before this step: after the actions, as the reference
  for (const auto& [id, a] : agents_) {
    if (!a.active) continue;
    std::vector<PdCommand>& joints = requests_.joints[robots_[a.robot].name];
    joints.insert(joints.end(), a.motors.begin(), a.motors.end());
  }
  return std::exchange(requests_, WorldRequests{});
}

struct MonitorVisitor {
  Session* s;
  void operator()(const KickOffCommand& c) const {
    const bool left = c.left ? *c.left : s->rng_.Bernoulli(0.5);
    s->referee_.KickOff(left ? Side::kLeft : Side::kRight);
  }
  void operator()(const DropBallCommand&) const { s->referee_.DropBall(); }
  void operator()(const BallCommand& c) const {
    s->requests_.ball = Eigen::Vector3d(c.x, c.y, s->options_.ball_radius);
  }
  void operator()(const AgentCommand& c) const {
    Session::Agent* a = nullptr;
    for (Side side : {Side::kLeft, Side::kRight}) {
      const bool match = c.team == TeamRef::kName ? s->referee_.team(side) == c.team_name
                                                  : (c.team == TeamRef::kLeft) == (side == Side::kLeft);
      if (match && a == nullptr) a = s->FindPlayer(side, c.unum);
    }
    if (a == nullptr) {
      s->Issue(-1, "unknown_agent", fmt::format("no player {} of team {}", c.unum, c.team_name));
      return;
    }
    s->requests_.moves.push_back({s->robots_[a->robot].name, c.position, c.orientation, true});
  }
  void operator()(const PlayModeCommand& c) const {
    const std::optional<PlayMode> mode = ParsePlayMode(c.mode);
    if (!mode) {
      s->Issue(-1, "unknown_enum", "no play mode " + c.mode.substr(0, 32));
      return;
    }
    s->referee_.SetPlayMode(*mode);
  }
  void operator()(const KillSimCommand&) const { s->quit_ = true; }
};

void Session::ApplyMonitor() {
  const MonitorVisitor visitor{this};
  for (const std::string& payload : std::exchange(monitor_queue_, {})) {
    const MonitorMessage m = ParseMonitorMessage(payload);
    for (const MonitorIssue& issue : m.issues) Issue(-1, turf::ErrorName(issue.error), issue.detail);
    for (const MonitorCommand& c : m.commands) std::visit(visitor, c);
  }
}

std::optional<Side> Session::Toucher(const MjWorldSnapshot& world) const {
  for (const auto& [id, a] : agents_) {
    if (!a.active) continue;
    const MjRobotSnapshot* r = world.Find(robots_[a.robot].name);
    if (r == nullptr) continue;
    for (const MjLink& l : r->links)
      if ((l.position - world.ball).norm() < options_.ball_radius + kTouchDistance) return a.side;
  }
  return std::nullopt;
}

void Session::Advance(MjWorldSnapshot world) {
  ++cycle_;
  ApplyMonitor();
  const std::optional<Eigen::Vector3d> place = referee_.Update(kCycleSeconds, world.ball, Toucher(world));
  if (place) requests_.ball = *place;
  const bool vision = cycle_ % 2 == 0;
  const std::vector<VisiblePlayer> players = vision ? Players(world) : std::vector<VisiblePlayer>{};
  for (const auto& [id, a] : agents_)
    if (a.active && !a.kicked) pending_.emplace_back(id, Perceive(a, world, vision ? &players : nullptr));
  if (options_.sequential) Release();
}

void Session::Release() {
  for (auto& [id, perception] : std::exchange(pending_, {})) {
    Agent* a = FindAgent(id);
    if (a == nullptr || !a->active || a->kicked) continue;  // left since
    ++a->perceptions;
    outputs_.emplace_back(id, std::move(perception));
  }
}

std::vector<VisiblePlayer> Session::Players(const MjWorldSnapshot& world) const {
  std::vector<VisiblePlayer> out;
  for (const auto& [id, a] : agents_) {
    if (!a.active) continue;
    const MjRobotSnapshot* r = world.Find(robots_[a.robot].name);
    if (r == nullptr) continue;
    VisiblePlayer p{*referee_.team(a.side), a.number, {}};
    const std::pair<const char*, const BodyPoint*> parts[] = {
        {"head", &a.model->head}, {"lfoot", &a.model->lfoot}, {"rfoot", &a.model->rfoot}};
    for (const auto& [name, point] : parts) {
      bool found = false;
      const Eigen::Vector3d at = PointOf(*r, *point, &found);
      if (found) p.parts.push_back({name, at});
    }
    out.push_back(std::move(p));
  }
  return out;
}

MjPerception Session::Perceive(const Agent& a, const MjWorldSnapshot& world,
                               const std::vector<VisiblePlayer>* players) {
  MjPerception p;
  p.time = world.time;
  p.game.play_time = referee_.play_time();
  p.game.play_mode = PlayModeName(referee_.play_mode());
  p.game.team_left = referee_.team(Side::kLeft);
  p.game.team_right = referee_.team(Side::kRight);
  p.game.score_left = referee_.score(Side::kLeft);
  p.game.score_right = referee_.score(Side::kRight);
  const MjRobotSnapshot* r = world.Find(robots_[a.robot].name);
  const MjLink* torso = r != nullptr ? r->FindLink("torso") : nullptr;
  if (torso == nullptr) return p;
  p.has_robot = true;
  const Eigen::Quaterniond& q = torso->orientation;
  p.quat = {q.w(), q.x(), q.y(), q.z()};
  p.pos = {torso->position.x(), torso->position.y(), torso->position.z()};
  p.gyro = r->gyro;
  p.acc = r->acc;
  for (const MjJoint& j : a.model->joints) {
    const auto it = std::find(r->joint_names.begin(), r->joint_names.end(), j.joint);
    if (it == r->joint_names.end()) continue;
    const auto i = static_cast<size_t>(it - r->joint_names.begin());
    if (i >= r->positions.size()) continue;  // a sample with fewer positions than names
    p.joints.push_back({j.perceptor, r->positions[i], i < r->velocities.size() ? r->velocities[i] : 0.0});
  }
  if (players != nullptr) {
    bool found = false;
    VisionInput in;
    in.camera = PointOf(*r, a.model->camera, &found);
    const MjLink* head = r->FindLink(a.model->camera.body);
    if (found && head != nullptr) {
      in.orientation = head->orientation;
      in.ball = world.ball;
      in.markers = &markers_;
      in.players = players;
      p.see = ComputeSee(in);
    }
  }
  return p;
}

std::vector<std::pair<int, MjPerception>> Session::TakePerceptions() { return std::exchange(outputs_, {}); }

std::vector<std::pair<int, std::string>> Session::TakeOutputs() {
  std::vector<std::pair<int, std::string>> out;
  for (const auto& [id, perception] : TakePerceptions()) out.emplace_back(id, FormatPerception(perception));
  return out;
}
std::vector<SessionIssue> Session::TakeIssues() { return std::exchange(issues_, {}); }
std::vector<int> Session::TakeKicked() { return std::exchange(kicked_, {}); }

}  // namespace turf::rcssservermj
