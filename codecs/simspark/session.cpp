#include "codecs/simspark/session.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <string_view>
#include <type_traits>
#include <variant>

#include "codecs/simspark/effectors.h"
#include "codecs/simspark/nao_joints.h"
#include "codecs/simspark/perception.h"
#include "codecs/simspark/trainer.h"

namespace turf::simspark {

namespace {

constexpr double kDeg = 180.0 / M_PI;
constexpr double kSimCycle = 0.02;   // s, one SimSpark cycle
constexpr double kBeamHeight = 0.4;  // m, torso centre after beam / init (SimSpark)
constexpr const char* kSeenParts[] = {"head", "rlowerarm", "llowerarm", "rfoot", "lfoot"};

// The Nao's forward is its model +y: a robot facing `facing_deg` (from field
// +x) has yaw facing - 90 deg about z.
Eigen::Quaterniond FacingToOrientation(double facing_deg) {
  return Eigen::Quaterniond(Eigen::AngleAxisd((facing_deg - 90.0) / kDeg, Eigen::Vector3d::UnitZ()));
}

std::optional<Side> SideOf(TrainerTeam team) {
  if (team == TrainerTeam::kLeft) return Side::kLeft;
  if (team == TrainerTeam::kRight) return Side::kRight;
  return std::nullopt;
}

MonitorGameState MonitorState(const Game& game) {
  MonitorGameState now;
  now.time = game.game_time();
  now.half = game.half();
  now.score_left = game.score(Side::kLeft);
  now.score_right = game.score(Side::kRight);
  now.play_mode = game.play_mode();
  now.team_left = game.TeamName(Side::kLeft).value_or("");
  now.team_right = game.TeamName(Side::kRight).value_or("");
  return now;
}

}  // namespace

const RobotSnapshot::Link* RobotSnapshot::FindLink(const std::string& link) const {
  for (const Link& l : links)
    if (l.name == link) return &l;
  return nullptr;
}

const RobotSnapshot* WorldSnapshot::Find(const std::string& robot) const {
  for (const RobotSnapshot& r : robots)
    if (r.name == robot) return &r;
  return nullptr;
}

namespace {

constexpr double kHeadRadius = 0.065;  // m, the Nao's head sphere

// The box that holds a robot's colliders: its type's boxes where its links are, and the head.
Eigen::AlignedBox3d BoundingBox(const RobotSnapshot& robot, int robot_type) {
  Eigen::AlignedBox3d box;
  for (const NaoBox& b : NaoBoxes(robot_type)) {
    const RobotSnapshot::Link* link = robot.FindLink(b.link);
    if (link == nullptr) continue;
    const Eigen::Matrix3d axes = link->orientation.toRotationMatrix();
    const Eigen::Vector3d reach = axes.cwiseAbs() * b.half;
    box.extend(link->position - reach);
    box.extend(link->position + reach);
  }
  if (const RobotSnapshot::Link* head = robot.FindLink("head"); head != nullptr) {
    box.extend(head->position - Eigen::Vector3d::Constant(kHeadRadius));
    box.extend(head->position + Eigen::Vector3d::Constant(kHeadRadius));
  }
  return box;
}

// The foul referee on the game's field.
FoulRules FoulRulesOf(const GameRules& game) {
  FoulRules rules;
  rules.field_length = game.field_length;
  rules.field_width = game.field_width;
  rules.goal_width = game.goal_width;
  rules.penalty_depth = game.penalty_depth;
  rules.penalty_width = game.penalty_width;
  return rules;
}

}  // namespace

// The players as the referee sees them after a cycle, and the robots they are in.
struct Session::RefereeView {
  using Player = std::pair<Side, int>;
  std::vector<RefereePlayer> players;
  std::map<Player, std::string> robot_of;
  std::map<Player, Eigen::Quaterniond> orientation_of;  // the torso's
  std::map<std::string, Player> player_of;              // by robot

  // A move of the player's torso to `to`, as it lies (orientation and joints kept), before the next step.
  RobotMove MoveTo(Side side, int unum, const Eigen::Vector3d& to) const {
    return {robot_of.at({side, unum}), to, orientation_of.at({side, unum}), false};
  }
  // The player's torso (and its box) where a move put it.
  void Moved(Side side, int unum, const Eigen::Vector3d& to) {
    for (RefereePlayer& p : players) {
      if (p.side != side || p.unum != unum) continue;
      if (!p.box.isEmpty()) p.box.translate(to - p.torso);
      p.torso = to;
    }
  }
};

Session::Session(SessionOptions options, std::vector<std::string> robots, std::vector<RobotMove> park)
    : options_(std::move(options)),
      robots_(std::move(robots)),
      park_(std::move(park)),
      robot_owner_(robots_.size(), -1),
      game_(options_.rules, StreamSeed(options_.seed, "simspark/game")),
      fouls_(FoulRulesOf(options_.rules), StreamSeed(options_.seed, "simspark/fouls")),
      field_(StandardField3d()),
      beam_rng_(StreamSeed(options_.seed, "simspark/beam")) {
  park_.resize(robots_.size());
}

int Session::Connect() {
  const int id = next_agent_++;
  Agent& a = agents_[id];
  a.id = id;
  a.rng = Rng(StreamSeed(options_.seed, fmt::format("simspark/agent/{}", id)));
  a.calibration = DrawCalibrationOffset(&a.rng);
  return id;
}

Session::Agent* Session::FindAgent(int id) {
  auto it = agents_.find(id);
  return it == agents_.end() ? nullptr : &it->second;
}

Session::Agent* Session::FindPlayer(Side side, int unum) {
  for (auto& [id, a] : agents_)
    if (a.inited && a.side == side && a.unum == unum) return &a;
  return nullptr;
}

int Session::agents_with_robot() const {
  int n = 0;
  for (const auto& [id, a] : agents_) n += a.robot >= 0;
  return n;
}

void Session::Issue(int agent, const std::string& kind, const std::string& detail) {
  issues_.push_back({agent, kind, detail});
}

void Session::Disconnect(int agent) {
  Agent* a = FindAgent(agent);
  if (a == nullptr) return;
  LeaveTeam(a);
  ReleaseRobot(a);
  agents_.erase(agent);
}

void Session::LeaveTeam(Agent* agent) {
  if (!agent->inited) return;
  game_.Leave(agent->side, agent->unum, agent->type);
  radio_.Forget(agent->side, agent->unum);
  agent->inited = false;
}

void Session::Kick(Agent* agent) {
  if (agent->kicked) return;
  agent->kicked = true;
  kicked_.push_back(agent->id);
}

void Session::SetRobotTypes(std::vector<int> types) {
  robot_types_ = std::move(types);
  robot_types_.resize(robots_.size(), -1);
}

// The first free robot of `type`, else the last free one (scenes list the commonest type first);
// `other_type`: that one was built as another type.
std::optional<size_t> Session::FreeRobot(int type, bool* other_type) const {
  std::optional<size_t> any;
  for (size_t i = 0; i < robots_.size(); ++i) {
    if (robot_owner_[i] >= 0) continue;
    if (robot_types_.empty() || robot_types_[i] == type) {
      *other_type = false;
      return i;
    }
    any = i;
  }
  *other_type = any && robot_types_[*any] >= 0;
  return any;
}

void Session::TakeRobot(Agent* agent, int type) {
  bool other_type = false;
  if (const std::optional<size_t> free = FreeRobot(type, &other_type)) {
    const size_t i = *free;
    if (other_type)
      notes_.push_back(fmt::format("agent {}: no free robot of type {} in the scene: {} (type {}) serves", agent->id,
                                   type, robots_[i], robot_types_[i]));
    robot_owner_[i] = agent->id;
    agent->robot = static_cast<int>(i);
    agent->type = type;
    agent->scene_cycle = cycle_;
    RobotMove fresh = park_[i];  // a fresh robot: zero pose, standing where it was parked
    fresh.reset_joints = true;
    requests_.moves.push_back(fresh);
    return;
  }
  Issue(agent->id, "no_robot_free", fmt::format("all {} robots of the scene are taken", robots_.size()));
}

void Session::ReleaseRobot(Agent* agent) {
  if (agent->robot < 0) return;
  RobotMove park = park_[agent->robot];
  park.reset_joints = true;
  requests_.moves.push_back(park);
  requests_.joints.erase(robots_[agent->robot]);
  held_joints_.erase(robots_[agent->robot]);
  robot_owner_[agent->robot] = -1;
  agent->robot = -1;
}

void Session::PlaceAgent(Agent* agent, const Pose2& pose) {
  RobotMove move;
  move.robot = robots_[agent->robot];
  move.position = Eigen::Vector3d(pose.x, pose.y, kBeamHeight);
  move.orientation = FacingToOrientation(pose.facing_deg);
  requests_.moves.push_back(move);
}

void Session::Receive(int agent_id, const std::string& payload) {
  Agent* agent = FindAgent(agent_id);
  if (agent == nullptr || agent->kicked) return;
  const AgentMessage m = ParseAgentMessage(payload);
  for (const EffectorIssue& issue : m.issues) Issue(agent_id, EffectorErrorName(issue.error), issue.detail);
  if (m.scene) {
    if (agent->robot >= 0) {
      Issue(agent_id, "scene_twice", "the agent already has a robot");
    } else {
      TakeRobot(agent, m.scene->type);
    }
  }
  if (m.init) {
    if (agent->robot < 0) {
      Issue(agent_id, "init_before_scene", "send (scene ...) first");
    } else if (agent->inited) {
      Issue(agent_id, "init_twice", "the agent is already in a team");
    } else {
      const InitResult r = game_.Init(m.init->team, m.init->unum, agent->type);
      if (!r.ok) {
        Issue(agent_id, "init_refused", r.error);
      } else {
        agent->inited = true;
        agent->announce = true;
        agent->side = r.side;
        agent->unum = r.unum;
        agent->team = m.init->team;
        PlaceAgent(agent, game_.StartPose(r.side, r.unum));
      }
    }
  }
  if (m.beam) {
    if (!agent->inited) {
      Issue(agent_id, "beam_before_init", "send (init ...) first");
    } else if (game_.BeamAllowed()) {
      PlaceAgent(agent, game_.BeamPose(agent->side, m.beam->x, m.beam->y, m.beam->rot_deg, &beam_rng_));
    }  // else ignored, as the reference does outside BeforeKickOff and Goal_X
  }
  if (!m.hinges.empty() && agent->robot >= 0) {
    const RobotSnapshot* robot = last_ ? last_->Find(robots_[agent->robot]) : nullptr;
    for (const HingeEffector& h : m.hinges) {
      const std::optional<std::string> joint = JointForEffector(h.effector, agent->type);
      if (!joint) {
        Issue(agent_id, "unknown_effector", fmt::format("{} (robot type {})", h.effector, agent->type));
        continue;
      }
      // Type 4's toes (lle7, rle7) are accepted but the one Nao model has none.
      if (robot == nullptr ||
          std::find(robot->joint_names.begin(), robot->joint_names.end(), *joint) == robot->joint_names.end())
        continue;
      // Here, not before the loop: a message without a usable joint asks nothing (no empty command).
      std::vector<JointVelocity>& targets = requests_.joints[robots_[agent->robot]];
      const double limit = NaoMaxSpeed(agent->type, *joint);
      const double v = std::clamp(h.velocity, -limit, limit);
      bool replaced = false;
      for (JointVelocity& t : targets) {
        if (t.joint == *joint) {
          t.velocity = v;
          replaced = true;
        }
      }
      if (!replaced) targets.push_back({*joint, v});
    }
  }
  if (m.say && agent->inited && last_) {
    const RobotSnapshot* robot = last_->Find(robots_[agent->robot]);
    const RobotSnapshot::Link* torso = robot != nullptr ? robot->FindLink("torso") : nullptr;
    Speaker who{agent->team, agent->side, agent->unum, torso != nullptr ? torso->position : Eigen::Vector3d::Zero()};
    radio_.Say(who, *m.say, game_.game_time());
  }
  if (m.syn) agent->synced = true;
}

bool Session::ReadyToStep() const {
  if (!options_.sync_mode) return true;
  for (const auto& [id, a] : agents_) {
    if (a.robot < 0 || a.synced) continue;
    if (cycle_ - a.scene_cycle >= static_cast<uint64_t>(options_.sync_grace_cycles)) return false;
  }
  return true;
}

std::vector<int> Session::Waiting() const {
  std::vector<int> out;
  for (const auto& [id, a] : agents_)
    if (a.robot >= 0 && !a.synced) out.push_back(id);
  return out;
}

WorldRequests Session::TakeRequests() {
  WorldRequests out = std::move(requests_);
  requests_ = WorldRequests{};
  // rcssserver3d sends, in cycle n, the perception generated at the end of
  // cycle n-1, after realizing the messages read at the start of cycle n: an
  // answer to the state after step k moves the joints from step k+2 on
  // (shared/protocols/simspark.md, "Order inside cycle"). turf sends a
  // perception right after its step, so the joint velocities asked in this
  // cycle go to the world with the next one.
  std::swap(out.joints, held_joints_);
  ApplyFreezes(&out.joints);
  for (const RobotMove& m : out.moves) StartTorsoPosesAt(m.robot, m.position);
  for (auto& [id, a] : agents_) a.synced = false;
  return out;
}

// What the trainer asks, applied to the game and the world requests.
struct TrainerCommandVisitor {
  Session* s;
  void operator()(const MoveAgent& c) const {
    const std::optional<Side> side = SideOf(c.team);
    Session::Agent* a = side ? s->FindPlayer(*side, c.unum) : nullptr;
    if (a == nullptr || a->robot < 0) {
      s->Issue(-1, "unknown_agent", fmt::format("no player {} of that team", c.unum));
      return;
    }
    RobotMove move;
    move.robot = s->robots_[a->robot];
    move.position = Eigen::Vector3d(c.pos[0], c.pos[1], c.pos[2]);
    move.orientation = Eigen::Quaterniond::Identity();
    const RobotSnapshot* robot = s->last_ ? s->last_->Find(move.robot) : nullptr;
    const RobotSnapshot::Link* torso = robot != nullptr ? robot->FindLink("torso") : nullptr;
    if (c.yaw_deg) {
      move.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(*c.yaw_deg / kDeg, Eigen::Vector3d::UnitZ()));
    } else if (torso != nullptr) {
      move.orientation = torso->orientation;
    }
    s->requests_.moves.push_back(move);
  }
  void operator()(const SetBall& c) const {
    BallMove move;
    move.position = s->last_ ? s->last_->ball : Eigen::Vector3d(0, 0, s->game_.rules().ball_radius);
    move.velocity = Eigen::Vector3d::Zero();
    if (c.pos) move.position = Eigen::Vector3d((*c.pos)[0], (*c.pos)[1], (*c.pos)[2]);
    if (c.vel) move.velocity = Eigen::Vector3d((*c.vel)[0], (*c.vel)[1], (*c.vel)[2]);
    s->requests_.ball = move;
  }
  void operator()(const SetPlayModeCmd& c) const { s->game_.SetPlayMode(c.mode); }
  void operator()(const KickOffCmd& c) const { s->game_.KickOff(SideOf(c.team), &s->beam_rng_); }
  void operator()(const DropBallCmd&) const { s->DropBall(); }
  void operator()(const RequestFullState&) const {}  // every monitor frame is full
  void operator()(const SetGameTime& c) const { s->game_.SetGameTime(c.time); }
  void operator()(const SetScoreCmd& c) const { s->game_.SetScore(c.left, c.right); }
  void operator()(const KillAgent& c) const {
    const std::optional<Side> side = SideOf(c.team);
    Session::Agent* a = side ? s->FindPlayer(*side, c.unum) : nullptr;
    if (a != nullptr) s->Kick(a);
  }
  void operator()(const SelectAgent&) const {}  // selection only matters to a monitor's display
  void operator()(const ReposAgent& c) const {
    // Off the ball: 1 m further from it, towards the player's own goal.
    const std::optional<Side> side = SideOf(c.team);
    Session::Agent* a = side ? s->FindPlayer(*side, c.unum) : nullptr;
    if (a == nullptr || a->robot < 0 || !s->last_) return;
    const RobotSnapshot* robot = s->last_->Find(s->robots_[a->robot]);
    const RobotSnapshot::Link* torso = robot != nullptr ? robot->FindLink("torso") : nullptr;
    if (torso == nullptr) return;
    const double back = a->side == Side::kLeft ? -1.0 : 1.0;
    s->PlaceAgent(a, {torso->position.x() + back, torso->position.y(), a->side == Side::kLeft ? 0.0 : 180.0});
  }
  void operator()(const KillSim&) const { s->quit_ = true; }
  void operator()(const AgentStateCmd&) const {}
  void operator()(const ResetTeamCmd& c) const {
    // The players leave the team now, not when the participant has dropped
    // their connections: a team that claims the side meanwhile keeps its
    // players whatever unums the old ones had.
    const Side side = SideOf(c.team).value_or(Side::kLeft);
    for (auto& [id, a] : s->agents_) {
      if (!a.inited || a.side != side) continue;
      s->LeaveTeam(&a);
      s->Kick(&a);
    }
    s->game_.ResetTeam(side);
  }
};

void Session::Trainer(const std::string& payload, TrainerRole role) {
  const TrainerMessage m = ParseTrainerMessage(payload);
  for (const TrainerIssue& issue : m.issues) Issue(-1, "trainer." + issue.error, issue.detail);
  const TrainerCommandVisitor visitor{this};
  for (const TrainerCommand& c : m.commands) {
    if (role != TrainerRole::kOperator && IsMatchControl(c)) {
      Issue(-1, "trainer.not_operator",
            fmt::format("({} ...) ends, restarts or rewrites the match: operators only", TrainerCommandName(c)));
      continue;
    }
    std::visit(visitor, c);
  }
}

void Session::Advance(WorldSnapshot snapshot) {
  // The cycle's touches are the ones after the last look (the first cycle: within one cycle).
  const double since = last_ ? last_->time : snapshot.time - kSimCycle;
  last_ = std::move(snapshot);
  const WorldSnapshot& world = *last_;
  ++cycle_;
  RecordTorsoPoses(world);
  // The players touching the ball: a body of the player touched it in a physics step of the cycle (the
  // reference's ball recorder: its collisions of the whole step).
  std::vector<Toucher> touchers;
  for (const auto& [id, a] : agents_) {
    if (!a.inited || a.robot < 0) continue;
    const RobotSnapshot* robot = world.Find(robots_[a.robot]);
    if (robot != nullptr && robot->ball_touch_time > since) touchers.push_back(Toucher{a.side, a.unum});
  }
  const GameUpdate update = game_.Update(kSimCycle, world.ball, touchers);
  if (update.place_ball) requests_.ball = BallMove{*update.place_ball, Eigen::Vector3d::Zero()};
  CheckSelfCollisions(world);
  RefereeView view = ViewOf(world, touchers);
  ClearPlayers(update.clearings, &view);
  CheckFouls(view, world, update.place_ball.value_or(world.ball));
  // Every player's seen parts, once per cycle for all agents' vision.
  players_.clear();
  for (const auto& [id, other] : agents_) {
    if (!other.inited || other.robot < 0) continue;
    const RobotSnapshot* r = world.Find(robots_[other.robot]);
    if (r == nullptr) continue;
    VisionPlayer player{other.team, other.unum, {}};
    for (const char* part : kSeenParts) {
      const RobotSnapshot::Link* l = r->FindLink(part);
      if (l != nullptr) player.parts.push_back({part, l->position});
    }
    players_.push_back(std::move(player));
  }
  for (auto& [id, a] : agents_) {
    if (a.robot < 0) continue;
    outputs_.emplace_back(id, Perceive(&a, world));
  }
  radio_.EndCycle();
  if (cycle_ % 2 == 0) monitor_ = FormatMonitorGame(MonitorState(game_), nullptr);
}

// The referee's self-collision rule on every player's links after the cycle; a note for each freeze.
void Session::CheckSelfCollisions(const WorldSnapshot& world) {
  std::vector<PlayerLinks> players;
  for (const auto& [id, a] : agents_) {
    if (!a.inited || a.robot < 0) continue;
    const RobotSnapshot* robot = world.Find(robots_[a.robot]);
    if (robot == nullptr) continue;
    PlayerLinks p{a.side, a.unum, a.type, {}};
    for (const RobotSnapshot::Link& l : robot->links) p.links.push_back({l.name, l.position, l.orientation});
    players.push_back(std::move(p));
  }
  for (const SelfCollision& c : self_collision_.Update(game_.paused(), game_.game_time(), players))
    notes_.push_back(fmt::format(
        "self-collision of player {} {}: {} and {} overlap by {:.3f} m; joints {} frozen for {} s", SideName(c.side),
        c.unum, c.link1, c.link2, c.depth, fmt::join(c.frozen, " "), kSelfCollisionFrozenTime));
}

// The trainer's dropBall at once, on the last cycle's world with the moves asked since (the reference's monitor
// commands act before the next step, on the bodies where earlier commands put them): the ball placed and both
// teams cleared from it.
void Session::DropBall() {
  Eigen::Vector3d ball = last_ ? last_->ball : Eigen::Vector3d(0, 0, game_.rules().ball_radius);
  if (requests_.ball) ball = requests_.ball->position;
  const GameUpdate update = game_.DropBall(ball);
  if (update.place_ball) requests_.ball = BallMove{*update.place_ball, Eigen::Vector3d::Zero()};
  if (!last_) return;
  RefereeView view = ViewOf(*last_, {});
  for (const RobotMove& m : requests_.moves) {
    const auto who = view.player_of.find(m.robot);
    if (who != view.player_of.end()) view.Moved(who->second.first, who->second.second, m.position);
  }
  ClearPlayers(update.clearings, &view);
}

Session::RefereeView Session::ViewOf(const WorldSnapshot& world, const std::vector<Toucher>& touchers) const {
  RefereeView view;
  for (const auto& [id, a] : agents_) {
    if (!a.inited || a.robot < 0) continue;
    const RobotSnapshot* robot = world.Find(robots_[a.robot]);
    const RobotSnapshot::Link* torso = robot != nullptr ? robot->FindLink("torso") : nullptr;
    if (torso == nullptr) continue;
    const bool touching = std::find(touchers.begin(), touchers.end(), Toucher{a.side, a.unum}) != touchers.end();
    view.players.push_back({a.side, a.unum, torso->position, robot->velocity, touching, BoundingBox(*robot, a.type)});
    view.robot_of[{a.side, a.unum}] = robots_[a.robot];
    view.orientation_of[{a.side, a.unum}] = torso->orientation;
    view.player_of[robots_[a.robot]] = {a.side, a.unum};
  }
  return view;
}

// The game's own moves of players away from the ball (clearing.h), before the referee judges fouls: they see where
// the players were put, and a player moved is not judged for charging for 1 s (as after the referee's moves).
void Session::ClearPlayers(const std::vector<Clearing>& clearings, RefereeView* view) {
  if (clearings.empty()) return;
  std::vector<SpotPlayer> spots;
  for (const RefereePlayer& p : view->players) spots.push_back({p.side, p.unum, p.torso, p.box});
  SpotBoard board(std::move(spots), clearings.front().ball, SpotRulesOf(FoulRulesOf(options_.rules)));
  for (const ClearingMove& m : Clear(clearings, options_.rules.field_length, &board)) {
    view->Moved(m.side, m.unum, m.position);
    fouls_.Moved(m.side, m.unum);
    requests_.moves.push_back(view->MoveTo(m.side, m.unum, m.position));
    notes_.push_back(
        fmt::format("player {} {} moved away from the ball (the game's clearing in {}) to ({:.2f}, {:.2f})",
                    SideName(m.side), m.unum, PlayModeName(game_.play_mode()), m.position.x(), m.position.y()));
  }
}

// The referee's fouls of single players: after incapable and charging the player is held in the air, then put
// outside the field, as it lies (torso orientation and joints kept); after touching it is pushed out of the crowd.
void Session::CheckFouls(const RefereeView& view, const WorldSnapshot& world, const Eigen::Vector3d& ball) {
  std::vector<PlayerContact> contacts;
  for (const RobotTouch& t : world.robot_contacts) {
    const auto a = view.player_of.find(t.robot_a);
    const auto b = view.player_of.find(t.robot_b);
    if (a == view.player_of.end() || b == view.player_of.end()) continue;  // a parked robot: no player
    contacts.push_back({a->second.first, a->second.second, b->second.first, b->second.second, t.point});
  }
  for (const RefereeMove& m : fouls_.Update(game_.paused(), view.players, contacts, ball)) {
    requests_.moves.push_back(view.MoveTo(m.side, m.unum, m.position));
    if (m.foul == Foul::kIllegalDefence) {
      notes_.push_back(
          fmt::format("player {} {} moved out of its penalty area (the referee's illegal defence: a fourth "
                      "player of its team in it) to ({:.2f}, {:.2f})",
                      SideName(m.side), m.unum, m.position.x(), m.position.y()));
    } else if (m.foul == Foul::kTouching) {
      notes_.push_back(
          fmt::format("player {} {} pushed out of a group of {} players touching (the referee's touching "
                      "foul) to ({:.2f}, {:.2f})",
                      SideName(m.side), m.unum, m.group_size, m.position.x(), m.position.y()));
    } else if (m.outside) {
      notes_.push_back(fmt::format("player {} {} {}: put outside the field at ({:.1f}, {:.1f})", SideName(m.side),
                                   m.unum,
                                   m.foul == Foul::kCharging ? "ran into an opponent (the referee's charging foul)"
                                                             : "could not stand up (the referee's incapable foul)",
                                   m.position.x(), m.position.y()));
    }
  }
}

// A command to a frozen joint is realized as velocity 0 (the reference's disabled hinge effector).
void Session::ApplyFreezes(std::map<std::string, std::vector<JointVelocity>>* joints) const {
  for (const auto& [id, a] : agents_) {
    if (!a.inited || a.robot < 0) continue;
    const auto it = joints->find(robots_[a.robot]);
    if (it == joints->end()) continue;
    for (JointVelocity& t : it->second)
      if (self_collision_.Frozen(a.side, a.unum, t.joint)) t.velocity = 0.0;
  }
}

std::string Session::MonitorGreeting() const {
  return FormatMonitorEnvironment() + FormatMonitorGame(MonitorState(game_), nullptr);
}

void Session::RecordTorsoPoses(const WorldSnapshot& world) {
  for (const RobotSnapshot& r : world.robots) {
    const RobotSnapshot::Link* torso = r.FindLink("torso");
    if (torso == nullptr) continue;
    std::vector<TorsoPose>& poses = torso_poses_[r.name];
    poses.push_back({torso->position, torso->orientation});
    if (poses.size() > 4) poses.erase(poses.begin());
  }
}

// A move (beam, trainer) puts the torso at `position` at rest before the next step. rcssserver3d's accelerometer
// reads a body's velocity before the move zeroes it, and the next step's velocity is what that step moved the body
// from where it was put (rcssserver3d 0.7.3 traced: while an agent beams every cycle, ACC reads gravity, 9.7-9.8
// m/s^2 up). So the history is shifted to end where the move put the torso: the velocities of the cycles before
// stay, the next one starts there.
void Session::StartTorsoPosesAt(const std::string& robot, const Eigen::Vector3d& position) {
  const auto it = torso_poses_.find(robot);
  if (it == torso_poses_.end() || it->second.empty()) return;
  const Eigen::Vector3d shift = position - it->second.back().position;
  for (TorsoPose& p : it->second) p.position += shift;
}

// rcssserver3d's Accelerometer::PrePhysicsUpdateInternal: (v - v_last) / dt - gravity, turned into the body's
// frame, before the step; a body's velocity there is what its last 20 ms step moved it by, over 20 ms.
std::optional<Eigen::Vector3d> Session::ReferenceAcc(const std::string& robot) const {
  const auto it = torso_poses_.find(robot);
  if (it == torso_poses_.end() || it->second.size() < 4) return std::nullopt;
  const std::vector<TorsoPose>& p = it->second;
  constexpr double kCycle = 0.02;    // s
  constexpr double kGravity = 9.81;  // m/s^2, rcssserver3d's world (spark.rb)
  const Eigen::Vector3d change = (p[2].position - 2.0 * p[1].position + p[0].position) / (kCycle * kCycle);
  return p[2].orientation.inverse() * (change + Eigen::Vector3d(0.0, 0.0, kGravity));
}

std::string Session::Perceive(Agent* a, const WorldSnapshot& world) {
  Perception p;
  p.time = world.time;
  if (a->announce) {
    p.unum = a->unum;
    p.side = a->side;
    a->announce = false;
  }
  p.score_left = game_.score(Side::kLeft);
  p.score_right = game_.score(Side::kRight);
  p.game_time = game_.game_time();
  p.play_mode = game_.play_mode();
  const RobotSnapshot* robot = world.Find(robots_[a->robot]);
  if (robot != nullptr) {
    for (int k = 0; k < 3; ++k) {
      p.gyro_deg_s[k] = robot->gyro[k] * kDeg;
      p.acc[k] = robot->accelerometer[k];
    }
    if (const std::optional<Eigen::Vector3d> acc = ReferenceAcc(robot->name)) {
      for (int k = 0; k < 3; ++k) p.acc[k] = (*acc)[k];
    }
    const std::vector<NaoJoint>& joints = NaoJoints(a->type);
    const std::vector<int>& index = HingeIndex(a->type, *robot);
    for (size_t j = 0; j < joints.size(); ++j) {
      if (index[j] >= 0) p.joints_deg.emplace_back(joints[j].perceptor, robot->joint_positions[index[j]] * kDeg);
    }
    for (const RobotSnapshot::Foot& f : robot->feet) {
      if (f.contact) p.forces.push_back({f.name, f.point, f.force});
    }
    if (a->perceptions % 3 == 0) p.see = See(*a, *robot, world);
  }
  if (a->inited && robot != nullptr) {
    const RobotSnapshot::Link* torso = robot->FindLink("torso");
    Speaker me{a->team, a->side, a->unum, torso != nullptr ? torso->position : Eigen::Vector3d::Zero()};
    p.heard = radio_.Deliver(me, cycle_);
  }
  ++a->perceptions;
  return FormatPerception(p);
}

// Where each of the type's hinges is in the robots' joint arrays (-1: the
// model lacks it). Every robot of the scene is the same model: found once.
const std::vector<int>& Session::HingeIndex(int type, const RobotSnapshot& robot) {
  std::vector<int>& index = hinge_index_[type];
  if (index.empty() || hinge_joint_count_ != robot.joint_names.size()) {
    hinge_joint_count_ = robot.joint_names.size();
    hinge_index_.clear();
    std::vector<int>& fresh = hinge_index_[type];
    for (const NaoJoint& j : NaoJoints(type)) {
      int found = -1;
      for (size_t i = 0; i < robot.joint_names.size() && found < 0; ++i)
        if (robot.joint_names[i] == j.perceptor) found = static_cast<int>(i);
      fresh.push_back(found);
    }
    return fresh;
  }
  return index;
}

SeeItems Session::See(const Agent& agent, const RobotSnapshot& robot, const WorldSnapshot& world) {
  VisionScene scene;
  const RobotSnapshot::Link* head = robot.FindLink("head");
  if (head == nullptr) return {};
  scene.head_position = head->position;
  scene.head_orientation = head->orientation;
  scene.calibration_offset = agent.calibration;
  scene.ball = world.ball;
  scene.players = players_;
  VisionParams params = options_.vision;
  Rng& rng = agents_.at(agent.id).rng;
  return ComputeSee(scene, field_, params, &rng);
}

std::vector<std::pair<int, std::string>> Session::TakeOutputs() { return std::exchange(outputs_, {}); }
std::vector<SessionIssue> Session::TakeIssues() { return std::exchange(issues_, {}); }
std::vector<int> Session::TakeKicked() { return std::exchange(kicked_, {}); }
std::string Session::TakeMonitorOutput() { return std::exchange(monitor_, {}); }

}  // namespace turf::simspark
