#include "core/legged/legged_islands.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <numeric>
#include <stdexcept>
#include <utility>

#include "core/worker_thread.h"

namespace turf {

namespace {

// How far a robot's limbs may move relative to its root in the two steps between the boxes' kinematics and the end
// of the next step (a kicking foot is well below it).
constexpr double kLimbSpeed = 10.0;  // m/s
// A better balance of the groups is taken only this often and only if it moves the imbalance by this many robots.
constexpr double kRebalanceSeconds = 1.0;
constexpr int kRebalanceGain = 4;
// How long a group's thread polls for its next step, and the stepping thread for the groups' end, before sleeping
// (core/worker_thread.h): within a cycle the steps follow each other a few hundred microseconds apart.
constexpr std::chrono::microseconds kPoll{300};

bool SameCamera(const CameraDecl& a, const CameraDecl& b) {
  return a.name == b.name && a.body == b.body && a.pos == b.pos && a.xyaxes == b.xyaxes && a.width == b.width &&
         a.height == b.height && a.hfov == b.hfov && a.rate_hz == b.rate_hz && a.encoding == b.encoding &&
         a.jpeg_quality == b.jpeg_quality && a.noise_stddev == b.noise_stddev && a.enabled == b.enabled;
}

bool SameMotors(const MotorParams& a, const MotorParams& b) {
  return a.max_torque == b.max_torque && a.max_speed == b.max_speed && a.position_kp == b.position_kp &&
         a.position_kd == b.position_kd && a.velocity_kp == b.velocity_kp && a.velocity_kd == b.velocity_kd &&
         a.max_reference_lead == b.max_reference_lead;
}

// Two scene entries that compile to the same robot wherever they stand: all but name, number and placement.
bool SameKind(const LeggedRobot& a, const LeggedRobot& b) {
  if (a.model_xml != b.model_xml || a.model != b.model || a.robot_type != b.robot_type || a.z != b.z ||
      !SameMotors(a.motors, b.motors) || a.start_joints.size() != b.start_joints.size() ||
      a.cameras.size() != b.cameras.size())
    return false;
  for (size_t i = 0; i < a.start_joints.size(); ++i) {
    const JointStart& x = a.start_joints[i];
    const JointStart& y = b.start_joints[i];
    if (x.joint != y.joint || x.position != y.position || x.kp != y.kp || x.kd != y.kd) return false;
  }
  for (size_t i = 0; i < a.cameras.size(); ++i)
    if (!SameCamera(a.cameras[i], b.cameras[i])) return false;
  return true;
}

bool Overlap(const std::array<double, 6>& a, const std::array<double, 6>& b) {
  for (int k = 0; k < 3; ++k)
    if (a[k] > b[3 + k] || b[k] > a[3 + k]) return false;
  return true;
}

int Find(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

void Add(LeggedHealth* to, const LeggedHealth& h) {
  to->instability_recoveries += h.instability_recoveries;
  to->solver_capped_steps += h.solver_capped_steps;
  to->solver_iterations += h.solver_iterations;
  to->constraint_rows += h.constraint_rows;
}

}  // namespace

LeggedIslands::LeggedIslands(LeggedScene scene) : scene_(std::move(scene)) {
  const int n = RobotCount();
  threads_ = std::max(1, std::min(scene_.physics.island_threads, n));
  for (int r = 0; r < n; ++r) {
    int k = 0;
    while (!SameKind(scene_.robots[k], scene_.robots[r])) ++k;
    kind_.push_back(k);
  }
  std::vector<int> all(n);
  std::iota(all.begin(), all.end(), 0);
  auto whole = std::make_unique<LeggedWorld>(scene_);
  step_ns_ = whole->step_ns();
  if (!Split()) {
    groups_.push_back({all, whole->CarryBall().qpos.size() > 0, std::move(whole)});
    group_of_.assign(n, 0);
    slot_of_ = all;
    return;
  }
  // The start as one world has it, and its islands.
  std::vector<std::array<double, 6>> boxes;
  for (int r = 0; r < n; ++r) {
    start_robots_.push_back(whole->CarryRobot(r));
    boxes.push_back(whole->Bounds(r, kLimbSpeed * 2e-9 * step_ns_, 2e-9 * step_ns_));
  }
  start_ball_ = whole->CarryBall();
  if (!start_ball_.qpos.empty()) boxes.push_back(whole->Bounds(-1, 0.0, 2e-9 * step_ns_));
  whole.reset();
  for (int t = 1; t < threads_; ++t) workers_.push_back(std::make_unique<WorkerThread>(kPoll));
  start_plan_ = Deal(Islands(boxes));
  Reset();
}

LeggedIslands::~LeggedIslands() = default;

// --- Groups ---

std::string LeggedIslands::Key(const std::vector<int>& robots, bool ball) const {
  std::string key = ball ? "ball" : "-";
  for (int r : robots) key += fmt::format(",{}", kind_[r]);
  return key;
}

// A group's world: its robots' models at canonical places and names (its state is only ever what is landed in it).
LeggedScene LeggedIslands::GroupScene(const std::vector<int>& robots, bool ball) const {
  LeggedScene s = scene_;
  s.physics.island_threads = 1;
  s.field.ball = s.field.ball && ball;
  s.robots.clear();
  for (size_t k = 0; k < robots.size(); ++k) {
    LeggedRobot r = scene_.robots[kind_[robots[k]]];
    r.name = fmt::format("island{}", k);
    r.id = static_cast<int>(k);
    r.x = 3.0 * static_cast<double>(k);
    r.y = 0.0;
    r.yaw = 0.0;
    s.robots.push_back(std::move(r));
  }
  return s;
}

std::unique_ptr<LeggedWorld> LeggedIslands::Take(const std::vector<int>& robots, bool ball) {
  if (robots.empty() && !ball) return nullptr;  // a group with nothing to step
  std::vector<std::unique_ptr<LeggedWorld>>& spare = spare_[Key(robots, ball)];
  if (spare.empty()) return std::make_unique<LeggedWorld>(GroupScene(robots, ball));
  std::unique_ptr<LeggedWorld> world = std::move(spare.back());
  spare.pop_back();
  return world;
}

void LeggedIslands::Install(const Plan& plan) {
  for (Group& g : groups_) {
    if (!g.world) continue;
    Add(&retired_, g.world->health());
    spare_[Key(g.robots, g.ball)].push_back(std::move(g.world));
  }
  groups_.clear();
  group_of_.assign(RobotCount(), -1);
  slot_of_.assign(RobotCount(), -1);
  for (size_t g = 0; g < plan.robots.size(); ++g) {
    const bool ball = plan.ball == static_cast<int>(g);
    groups_.push_back({plan.robots[g], ball, Take(plan.robots[g], ball)});
    for (size_t k = 0; k < plan.robots[g].size(); ++k) {
      group_of_[plan.robots[g][k]] = static_cast<int>(g);
      slot_of_[plan.robots[g][k]] = static_cast<int>(k);
    }
  }
}

void LeggedIslands::Apply(const Plan& plan, uint64_t frame, const std::vector<LeggedCarry>& robots,
                          const LeggedCarry& ball, bool forward) {
  Install(plan);
  for (Group& g : groups_) {
    if (!g.world) continue;
    g.world->Reuse(frame);
    for (size_t k = 0; k < g.robots.size(); ++k) g.world->LandRobot(static_cast<int>(k), robots[g.robots[k]]);
    if (g.ball) g.world->LandBall(ball);
    g.world->Settle(forward);
  }
  regrouped_frame_ = frame;
  ++regroups_;
}

int LeggedIslands::BallGroup() const {
  for (size_t g = 0; g < groups_.size(); ++g)
    if (groups_[g].ball) return static_cast<int>(g);
  return -1;
}

std::vector<std::array<double, 6>> LeggedIslands::Boxes() const {
  const double horizon = 2e-9 * static_cast<double>(step_ns_);
  std::vector<std::array<double, 6>> boxes;
  for (int r = 0; r < RobotCount(); ++r) boxes.push_back(WorldOf(r).Bounds(SlotOf(r), kLimbSpeed * horizon, horizon));
  const int ball = BallGroup();
  if (ball >= 0) boxes.push_back(groups_[ball].world->Bounds(-1, 0.0, horizon));
  return boxes;
}

// Members (robots by index, the ball as RobotCount()) whose boxes overlap, directly or through others; each island
// ascending, islands by their first member.
std::vector<std::vector<int>> LeggedIslands::Islands(const std::vector<std::array<double, 6>>& boxes) const {
  const int n = static_cast<int>(boxes.size());
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  for (int a = 0; a < n; ++a) {
    for (int b = a + 1; b < n; ++b) {
      if (Overlap(boxes[a], boxes[b])) parent[Find(parent, b)] = Find(parent, a);
    }
  }
  std::vector<std::vector<int>> islands;
  std::vector<int> index(n, -1);
  for (int i = 0; i < n; ++i) {
    const int root = Find(parent, i);
    if (index[root] < 0) {
      index[root] = static_cast<int>(islands.size());
      islands.emplace_back();
    }
    islands[index[root]].push_back(i);
  }
  return islands;
}

// Islands to groups, largest first, each to the group with the fewest robots (the first of equals); the ball alone
// to the group with the fewest robots that has any.
LeggedIslands::Plan LeggedIslands::Deal(const std::vector<std::vector<int>>& islands) const {
  const int n = RobotCount();
  auto robots_in = [n](const std::vector<int>& island) {
    return static_cast<int>(std::count_if(island.begin(), island.end(), [n](int i) { return i < n; }));
  };
  std::vector<const std::vector<int>*> order;
  for (const auto& island : islands) order.push_back(&island);
  std::stable_sort(order.begin(), order.end(),
                   [&](const std::vector<int>* a, const std::vector<int>* b) { return robots_in(*a) > robots_in(*b); });
  Plan plan;
  plan.robots.resize(threads_);
  for (const std::vector<int>* island : order) {
    const bool alone = robots_in(*island) == 0;
    size_t g = 0;
    for (size_t h = 1; h < plan.robots.size(); ++h) {
      const bool fewer = plan.robots[h].size() < plan.robots[g].size();
      if (alone ? !plan.robots[h].empty() && (fewer || plan.robots[g].empty()) : fewer) g = h;
    }
    for (int i : *island) {
      if (i < n)
        plan.robots[g].push_back(i);
      else
        plan.ball = static_cast<int>(g);
    }
  }
  for (auto& robots : plan.robots) std::sort(robots.begin(), robots.end());
  return plan;
}

bool LeggedIslands::Spans(const std::vector<std::vector<int>>& islands) const {
  const int ball = BallGroup();
  for (const auto& island : islands) {
    int group = -1;
    for (int i : island) {
      const int g = i < RobotCount() ? group_of_[i] : ball;
      if (group >= 0 && g != group) return true;
      group = g;
    }
  }
  return false;
}

int LeggedIslands::Imbalance(const Plan& plan) const {
  auto [lo, hi] = std::minmax_element(plan.robots.begin(), plan.robots.end(),
                                      [](const auto& a, const auto& b) { return a.size() < b.size(); });
  return static_cast<int>(hi->size() - lo->size());
}

LeggedIslands::Plan LeggedIslands::Current() const {
  Plan plan;
  for (const Group& g : groups_) plan.robots.push_back(g.robots);
  plan.ball = BallGroup();
  return plan;
}

void LeggedIslands::Regroup() {
  const std::vector<std::vector<int>> islands = Islands(Boxes());
  const Plan plan = Deal(islands);
  if (!Spans(islands)) {
    const double since = static_cast<double>(frame_ - regrouped_frame_) * 1e-9 * static_cast<double>(step_ns_);
    if (since < kRebalanceSeconds || Imbalance(Current()) - Imbalance(plan) < kRebalanceGain) return;
  }
  std::vector<LeggedCarry> robots;
  for (int r = 0; r < RobotCount(); ++r) robots.push_back(WorldOf(r).CarryRobot(SlotOf(r)));
  const int ball = BallGroup();
  const LeggedCarry ball_carry = ball >= 0 ? groups_[ball].world->CarryBall() : LeggedCarry{};
  Apply(plan, frame_, robots, ball_carry, false);
}

// --- Inputs ---

JointCommandError LeggedIslands::SetJointCommand(int robot, const JointCommand& command) {
  if (robot < 0 || robot >= RobotCount()) return JointCommandError::kUnknownRobot;
  return WorldOf(robot).SetJointCommand(SlotOf(robot), command);
}

JointCommandError LeggedIslands::CheckJointCommand(int robot, const JointCommand& command) const {
  if (robot < 0 || robot >= RobotCount()) return JointCommandError::kUnknownRobot;
  return WorldOf(robot).CheckJointCommand(SlotOf(robot), command);
}

JointCommandError LeggedIslands::CheckJointCommands(int robot, const std::vector<JointCommand>& commands) const {
  if (robot < 0 || robot >= RobotCount()) return JointCommandError::kUnknownRobot;
  return WorldOf(robot).CheckJointCommands(SlotOf(robot), commands);
}

PlacementError LeggedIslands::PlaceRobot(int robot, const RobotPlacement& placement) {
  if (robot < 0 || robot >= RobotCount()) return PlacementError::kUnknownRobot;
  return WorldOf(robot).PlaceRobot(SlotOf(robot), placement);
}

PlacementError LeggedIslands::PlaceBall(const std::array<double, 3>& position, const std::array<double, 3>& velocity) {
  const int ball = BallGroup();
  if (ball < 0) return PlacementError::kNoBall;
  return groups_[ball].world->PlaceBall(position, velocity);
}

void LeggedIslands::Reset() {
  frame_ = 0;
  if (!Split()) {
    groups_[0].world->Reset();
    return;
  }
  Apply(start_plan_, 0, start_robots_, start_ball_, true);
}

// --- Step ---

void LeggedIslands::Step() {
  if (Split()) Regroup();
  for (size_t g = 1; g < groups_.size(); ++g) {
    if (LeggedWorld* world = groups_[g].world.get()) workers_[g - 1]->Start([world] { world->Step(); });
  }
  if (groups_[0].world) groups_[0].world->Step();
  for (size_t g = 1; g < groups_.size(); ++g)
    if (groups_[g].world) workers_[g - 1]->Wait();
  ++frame_;
}

// --- Snapshot ---

void LeggedIslands::Save(StateWriter& out) const {
  out.Tag(StateTag("LEGI"));
  out.Put(frame_);
  out.Put(regrouped_frame_);
  out.Put(retired_.instability_recoveries);
  out.Put(retired_.solver_capped_steps);
  out.Put(static_cast<uint32_t>(groups_.size()));
  for (const Group& g : groups_) {
    out.Put(static_cast<uint64_t>(g.robots.size()));
    for (int r : g.robots) out.Put(static_cast<uint32_t>(r));
    out.Put(static_cast<uint8_t>(g.ball));
  }
  for (const Group& g : groups_)
    if (g.world) g.world->Save(out);
}

void LeggedIslands::Restore(StateReader& in) {
  in.Tag(StateTag("LEGI"));
  const uint64_t frame = RestoreFrame(in, step_ns_);
  const uint64_t regrouped = in.Get<uint64_t>();
  in.Check(regrouped <= frame, "regroup frame out of range");
  LeggedHealth retired;
  retired.instability_recoveries = in.Get<uint64_t>();
  retired.solver_capped_steps = in.Get<uint64_t>();
  in.Check(in.Get<uint32_t>() == groups_.size(), "another number of island groups");
  Plan plan;
  std::vector<int> seen(RobotCount(), 0);
  const bool has_ball = Split() ? !start_ball_.qpos.empty() : groups_[0].ball;
  for (size_t g = 0; g < groups_.size() && in.ok(); ++g) {
    std::vector<int>& robots = plan.robots.emplace_back(in.Count(RobotCount()));
    for (size_t k = 0; k < robots.size(); ++k) {
      robots[k] = static_cast<int>(in.Get<uint32_t>());
      const bool fresh = robots[k] >= 0 && robots[k] < RobotCount() && seen[robots[k]]++ == 0;
      in.Check(fresh && (k == 0 || robots[k] > robots[k - 1]), "island group robots out of range");
      if (!in.ok()) return;
    }
    if (in.Bool()) {
      in.Check(has_ball && plan.ball < 0, "island group ball out of range");
      plan.ball = static_cast<int>(g);
    }
  }
  if (!in.ok()) return;
  in.Check(std::count(seen.begin(), seen.end(), 1) == RobotCount() && (plan.ball >= 0) == has_ball,
           "island groups incomplete");
  if (!in.ok()) return;
  if (Split()) Install(plan);
  for (Group& g : groups_)
    if (g.world) g.world->Restore(in);
  frame_ = frame;
  regrouped_frame_ = regrouped;
  retired_ = retired;
}

// --- Outputs ---

int LeggedIslands::RobotIndex(const std::string& name) const {
  for (int r = 0; r < RobotCount(); ++r)
    if (scene_.robots[r].name == name) return r;
  return -1;
}

int LeggedIslands::JointIndex(int robot, const std::string& joint) const {
  return robot < 0 || robot >= RobotCount() ? -1 : WorldOf(robot).JointIndex(SlotOf(robot), joint);
}

LeggedJointInfo LeggedIslands::JointInfo(int robot, int joint) const {
  return robot < 0 || robot >= RobotCount() ? LeggedJointInfo{} : WorldOf(robot).JointInfo(SlotOf(robot), joint);
}

double LeggedIslands::RobotMass(int robot) const {
  return robot < 0 || robot >= RobotCount() ? 0.0 : WorldOf(robot).RobotMass(SlotOf(robot));
}

std::array<double, 3> LeggedIslands::RobotCenterOfMass(int robot) const {
  if (robot < 0 || robot >= RobotCount()) return {};
  return WorldOf(robot).RobotCenterOfMass(SlotOf(robot));
}

std::vector<LeggedGeom> LeggedIslands::RobotGeoms(int robot) const {
  if (robot < 0 || robot >= RobotCount()) return {};
  return WorldOf(robot).RobotGeoms(SlotOf(robot));
}

const LeggedHealth& LeggedIslands::health() const {
  health_ = retired_;
  for (const Group& g : groups_)
    if (g.world) Add(&health_, g.world->health());
  return health_;
}

LeggedWorldState LeggedIslands::State() const {
  LeggedWorldState out;
  State(&out);
  return out;
}

void LeggedIslands::State(LeggedWorldState* out) const {
  if (!Split()) {
    groups_[0].world->State(out);
    return;
  }
  scratch_.resize(groups_.size());
  for (size_t g = 0; g < groups_.size(); ++g)
    if (groups_[g].world) groups_[g].world->State(&scratch_[g]);
  out->time_ns = time_ns();
  out->frame = frame_;
  out->robots.resize(RobotCount());
  out->robot_contacts.clear();
  for (int r = 0; r < RobotCount(); ++r) {
    LeggedRobotState& s = out->robots[r];
    std::swap(s, scratch_[group_of_[r]].robots[slot_of_[r]]);  // the storage goes back for the next call
    s.name = scene_.robots[r].name;
    s.id = scene_.robots[r].id;
  }
  for (size_t g = 0; g < groups_.size(); ++g) {
    if (!groups_[g].world) continue;  // emptied: its scratch is an older make-up's (its robots are gone)
    for (RobotContact c : scratch_[g].robot_contacts) {
      c.robot_a = groups_[g].robots[c.robot_a];
      c.robot_b = groups_[g].robots[c.robot_b];
      if (c.robot_a > c.robot_b) std::swap(c.robot_a, c.robot_b);
      out->robot_contacts.push_back(c);
    }
  }
  std::sort(out->robot_contacts.begin(), out->robot_contacts.end(), [](const RobotContact& a, const RobotContact& b) {
    return std::make_pair(a.robot_a, a.robot_b) < std::make_pair(b.robot_a, b.robot_b);
  });
  const int ball = BallGroup();
  out->has_ball = ball >= 0;
  out->ball_position = ball >= 0 ? scratch_[ball].ball_position : std::array<double, 3>{};
  out->ball_velocity = ball >= 0 ? scratch_[ball].ball_velocity : std::array<double, 3>{};
}

}  // namespace turf
