#include "core/legged/legged_world.h"

#include <fmt/format.h>
#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

#include "core/legged/legged_mjcf.h"
#include "core/legged/legged_world_slots.h"

namespace turf {

namespace {
bool StartsWith(const char* s, const std::string& prefix) {
  return s != nullptr && std::string(s).compare(0, prefix.size(), prefix) == 0;
}

}  // namespace

LeggedWorld::LeggedWorld(LeggedScene scene) : scene_(std::move(scene)) {
  const std::vector<std::string> problems = ValidateLeggedScene(scene_);
  if (!problems.empty()) throw std::invalid_argument("invalid legged scene: " + problems.front());
  LeggedMjcf composed = ComposeLeggedMjcf(scene_);
  if (!composed.errors.empty()) throw std::invalid_argument(composed.errors.front());
  mjcf_ = std::move(composed.xml);
  model_.reset(CompileLeggedMjcf(mjcf_));
  data_.reset(mj_makeData(model_.get()));
  // The air is applied in StageBodyForces (the same forces, in one pass), not by MuJoCo's mj_passive.
  air_ = FluidOf(model_.get());
  model_->opt.density = 0.0;
  model_->opt.viscosity = 0.0;
  const mjModel* m = model_.get();
  step_ns_ = std::llround(m->opt.timestep * 1e9);
  compiled_jnt_margin_.assign(m->jnt_margin, m->jnt_margin + m->njnt);
  ball_body_ = scene_.field.enabled ? mj_name2id(m, mjOBJ_BODY, kLeggedBall) : -1;
  if (ball_body_ >= 0) {
    ball_qvel_ = m->jnt_dofadr[m->body_jntadr[ball_body_]];
    // The ball's drag as its free joint's damping: linear dofs first, then angular (MJCF has one damping per joint).
    for (int k = 0; k < 3; ++k) {
      model_->dof_damping[ball_qvel_ + k] = scene_.field.ball_linear_drag;
      model_->dof_damping[ball_qvel_ + 3 + k] = scene_.field.ball_angular_drag;
    }
  }

  for (const LeggedRobot& spec : scene_.robots) {
    RobotSlot slot;
    slot.spec = &spec;
    const std::string prefix = LeggedElementName(spec.name, "");
    for (int b = 1; b < m->nbody && slot.base_body < 0; ++b) {
      if (m->body_parentid[b] == 0 && StartsWith(mj_id2name(m, mjOBJ_BODY, b), prefix)) slot.base_body = b;
    }
    if (slot.base_body < 0) throw std::invalid_argument(fmt::format("robot {} has no body", spec.name));
    const int root_joint = m->body_jntadr[slot.base_body];
    if (root_joint >= 0 && m->jnt_type[root_joint] == mjJNT_FREE) {
      slot.root_qpos = m->jnt_qposadr[root_joint];
      slot.root_dof = m->jnt_dofadr[root_joint];
    }
    for (int b = 1; b < m->nbody; ++b) {
      if (m->body_rootid[b] != slot.base_body) continue;
      slot.bodies.push_back(b);
      slot.body_names.push_back(std::string(mj_id2name(m, mjOBJ_BODY, b)).substr(prefix.size()));
    }
    for (int j = 0; j < m->njnt; ++j) {
      const char* name = mj_id2name(m, mjOBJ_JOINT, j);
      if (!StartsWith(name, prefix)) continue;
      if (m->jnt_type[j] != mjJNT_HINGE && m->jnt_type[j] != mjJNT_SLIDE) continue;
      JointSlot js;
      js.name = std::string(name).substr(prefix.size());
      js.id = j;
      js.qpos = m->jnt_qposadr[j];
      js.dof = m->jnt_dofadr[j];
      js.limited = m->jnt_limited[j] != 0;
      js.lo = m->jnt_range[2 * j];
      js.hi = m->jnt_range[2 * j + 1];
      const double user = m->nuser_jnt > 0 ? m->jnt_user[j * m->nuser_jnt] : 0.0;
      js.effort_limit = user > 0.0 ? user : spec.motors.max_torque;
      js.frictionloss = m->dof_frictionloss[js.dof];
      js.start_position = m->qpos0[js.qpos];
      slot.joints.push_back(js);
    }
    SliceOf(m, &slot);
    ApplyStartJoints(spec, &slot.joints);
    // Each joint's motor is a constraint row bounded by max_torque: MuJoCo's
    // dof friction row, whose target velocity and bound the servo stage sets.
    for (const JointSlot& js : slot.joints) model_->dof_frictionloss[js.dof] = spec.motors.max_torque;
    for (int s = 0; s < m->nsensor; ++s) {
      const char* name = mj_id2name(m, mjOBJ_SENSOR, s);
      if (!StartsWith(name, prefix)) continue;
      const int adr = m->sensor_adr[s];
      switch (m->sensor_type[s]) {
        case mjSENS_GYRO:
          if (slot.gyro < 0) slot.gyro = adr;
          break;
        case mjSENS_ACCELEROMETER:
          if (slot.accelerometer < 0) slot.accelerometer = adr;
          break;
        case mjSENS_FRAMEQUAT:
          if (slot.orientation < 0) slot.orientation = adr;
          break;
        case mjSENS_TOUCH:
        case mjSENS_FORCE:
        case mjSENS_TORQUE:
          slot.forces.push_back({std::string(name).substr(prefix.size()), adr, m->sensor_dim[s],
                                 m->sensor_type[s] == mjSENS_TOUCH ? m->sensor_objid[s] : -1});
          break;
        default:
          break;
      }
    }
    robots_.push_back(std::move(slot));
  }
  ball_touch_ns_.assign(robots_.size(), -1);
  robot_of_body_.assign(m->nbody, -1);
  for (size_t r = 0; r < robots_.size(); ++r) {
    for (int b : robots_[r].bodies) robot_of_body_[b] = static_cast<int>(r);
  }
  motor_of_dof_.assign(m->nv, {-1, -1});
  for (size_t r = 0; r < robots_.size(); ++r) {
    for (size_t j = 0; j < robots_[r].joints.size(); ++j)
      motor_of_dof_[robots_[r].joints[j].dof] = {static_cast<int>(r), static_cast<int>(j)};
  }
  if (scene_.physics.motor_impulse_window > 0)
    impulse_steps_ = static_cast<int>(std::lround(scene_.physics.motor_impulse_window / m->opt.timestep));
  if (scene_.joint_stops.enabled)
    stop_steps_ = static_cast<int>(std::max<long>(1, std::lround(scene_.joint_stops.step / m->opt.timestep)));
  if (scene_.contacts.enabled) {
    std::vector<int> roots;
    for (const RobotSlot& r : robots_) roots.push_back(r.base_body);
    const int ball_geom = ball_body_ >= 0 ? m->body_geomadr[ball_body_] : -1;
    ode_contacts_ =
        std::make_unique<OdeContacts>(m, scene_.contacts, roots, mj_name2id(m, mjOBJ_GEOM, kLeggedFloor), ball_geom);
  }
  accelerometers_ = TakeRootAccelerometers(model_.get());  // the IMUs: read in turf's pass
  Reset();
}

LeggedWorld::~LeggedWorld() = default;

// The robot's run of qpos and qvel (MuJoCo numbers a body tree's joints in a row) and its collision geoms.
void LeggedWorld::SliceOf(const mjModel* m, RobotSlot* slot) {
  slot->qpos_begin = m->nq;
  slot->dof_begin = m->nv;
  int nq = 0;
  for (int j = 0; j < m->njnt; ++j) {
    if (m->body_rootid[m->jnt_bodyid[j]] != slot->base_body) continue;
    const int size = m->jnt_type[j] == mjJNT_FREE ? 7 : m->jnt_type[j] == mjJNT_BALL ? 4 : 1;
    slot->qpos_begin = std::min(slot->qpos_begin, m->jnt_qposadr[j]);
    slot->qpos_end = std::max(slot->qpos_end, m->jnt_qposadr[j] + size);
    slot->dof_begin = std::min(slot->dof_begin, m->jnt_dofadr[j]);
    nq += size;
  }
  slot->dof_end = slot->dof_begin;
  for (int v = 0; v < m->nv; ++v) {
    if (m->body_rootid[m->dof_bodyid[v]] == slot->base_body) slot->dof_end = std::max(slot->dof_end, v + 1);
  }
  if (nq == 0) slot->qpos_begin = slot->qpos_end = slot->dof_begin = slot->dof_end = 0;
  if (slot->qpos_end - slot->qpos_begin != nq)
    throw std::invalid_argument(
        fmt::format("robot {}: its joints are not one run of MuJoCo's state", slot->spec->name));
  for (int g = 0; g < m->ngeom; ++g) {
    if (m->body_rootid[m->geom_bodyid[g]] == slot->base_body && (m->geom_contype[g] || m->geom_conaffinity[g]))
      slot->geoms.push_back(g);
  }
}

// The scene's start angles and PD gains: every joint named must exist and the
// angle must lie in its range (the scene is refused otherwise).
void LeggedWorld::ApplyStartJoints(const LeggedRobot& spec, std::vector<JointSlot>* joints) {
  for (const JointStart& start : spec.start_joints) {
    auto it = std::find_if(joints->begin(), joints->end(), [&](const JointSlot& j) { return j.name == start.joint; });
    if (it == joints->end())
      throw std::invalid_argument(
          fmt::format("robots.{}.joints.{}: no such joint in {}", spec.name, start.joint, spec.model));
    if (it->limited && (start.position < it->lo || start.position > it->hi))
      throw std::invalid_argument(fmt::format("robots.{}.joints.{}: q {} is outside the joint's range [{}, {}]",
                                              spec.name, start.joint, start.position, it->lo, it->hi));
    it->start_position = start.position;
    it->start.mode = JointMode::kPd;
    it->start.value = start.position;
    it->start.kp = start.kp;
    it->start.kd = start.kd;
  }
}

void LeggedWorld::ResetCommands() {
  for (RobotSlot& r : robots_) ResetCommands(&r);
}

void LeggedWorld::ResetCommands(RobotSlot* r) {
  for (JointSlot& j : r->joints) {
    j.command = j.start;
    j.reference = data_->qpos[j.qpos];
    j.effort = 0.0;
    j.row = -1;
    LatchStop(&j);
  }
}

void LeggedWorld::SenseJoints() {
  for (RobotSlot& r : robots_) {
    for (JointSlot& j : r.joints) {
      j.sensed_q = data_->qpos[j.qpos];
      j.sensed_qd = data_->qvel[j.dof];
    }
  }
}

void LeggedWorld::AcceptState() { last_good_.Accept(model_.get(), data_.get()); }

PlacementError LeggedWorld::PlaceRobot(int robot, const RobotPlacement& p) {
  if (robot < 0 || robot >= RobotCount() || robots_[robot].root_qpos < 0) return PlacementError::kUnknownRobot;
  for (double v : p.position)
    if (!std::isfinite(v)) return PlacementError::kNotFinite;
  // Any finite quaternion of some length, normalized without overflow: scaled by its largest component first (the
  // squares of 1e200 were infinite, and the robot got a zero quaternion).
  double scale = 0.0;
  for (double v : p.orientation) {
    if (!std::isfinite(v)) return PlacementError::kNotFinite;
    scale = std::max(scale, std::abs(v));
  }
  if (scale < 1e-6) return PlacementError::kNotFinite;
  double norm = 0.0;
  for (double v : p.orientation) norm += (v / scale) * (v / scale);
  RobotSlot& r = robots_[robot];
  mjData* d = data_.get();
  for (int k = 0; k < 3; ++k) d->qpos[r.root_qpos + k] = p.position[k];
  for (int k = 0; k < 4; ++k) d->qpos[r.root_qpos + 3 + k] = p.orientation[k] / scale / std::sqrt(norm);
  for (int k = 0; k < 6; ++k) d->qvel[r.root_dof + k] = 0.0;
  for (JointSlot& j : r.joints) {
    if (p.reset_joints) d->qpos[j.qpos] = j.start_position;
    d->qvel[j.dof] = 0.0;
    j.reference = d->qpos[j.qpos];
    LatchStop(&j);
  }
  if (p.reset_joints) ResetCommands(&r);
  Forward();
  SenseJoints();
  AcceptState();
  return PlacementError::kOk;
}

PlacementError LeggedWorld::PlaceBall(const std::array<double, 3>& position, const std::array<double, 3>& velocity) {
  if (ball_body_ < 0) return PlacementError::kNoBall;
  for (int k = 0; k < 3; ++k)
    if (!std::isfinite(position[k]) || !std::isfinite(velocity[k])) return PlacementError::kNotFinite;
  const mjModel* m = model_.get();
  mjData* d = data_.get();
  const int qpos = m->jnt_qposadr[m->body_jntadr[ball_body_]];
  for (int k = 0; k < 3; ++k) d->qpos[qpos + k] = position[k];
  for (int k = 0; k < 3; ++k) {
    d->qvel[ball_qvel_ + k] = velocity[k];
    d->qvel[ball_qvel_ + 3 + k] = 0.0;
  }
  Forward();
  SenseJoints();
  AcceptState();
  return PlacementError::kOk;
}

std::vector<LeggedGeom> LeggedWorld::RobotGeoms(int robot) const {
  std::vector<LeggedGeom> out;
  if (robot < 0 || robot >= RobotCount()) return out;
  const mjModel* m = model_.get();
  const RobotSlot& r = robots_[robot];
  for (size_t i = 0; i < r.bodies.size(); ++i) {
    const int b = r.bodies[i];
    for (int g = m->body_geomadr[b]; g >= 0 && g < m->body_geomadr[b] + m->body_geomnum[b]; ++g) {
      LeggedGeom geom;
      geom.body = r.body_names[i];
      switch (m->geom_type[g]) {
        case mjGEOM_BOX:
          geom.shape = LeggedGeom::Shape::kBox;
          break;
        case mjGEOM_SPHERE:
          geom.shape = LeggedGeom::Shape::kSphere;
          break;
        case mjGEOM_CAPSULE:
          geom.shape = LeggedGeom::Shape::kCapsule;
          break;
        case mjGEOM_CYLINDER:
          geom.shape = LeggedGeom::Shape::kCylinder;
          break;
        case mjGEOM_ELLIPSOID:
          geom.shape = LeggedGeom::Shape::kEllipsoid;
          break;
        default:
          geom.shape = LeggedGeom::Shape::kOther;
          break;
      }
      for (int k = 0; k < 3; ++k) geom.size[k] = m->geom_size[3 * g + k];
      for (int k = 0; k < 3; ++k) geom.position[k] = m->geom_pos[3 * g + k];
      for (int k = 0; k < 4; ++k) geom.orientation[k] = m->geom_quat[4 * g + k];
      out.push_back(geom);
    }
  }
  return out;
}

// Listed once (core/state_io.h).
template <class Io, class Self>
void LeggedWorld::Fields(Io& io, Self& self) {
  io.Tag(StateTag("LEGW"));
  io(MjWorld(self.model_, self.data_, self.frame_, self.step_ns_));
  io(self.last_good_, self.health_.instability_recoveries, self.health_.solver_capped_steps,
     self.steps_since_stop_test_, self.commanded_);
  io.Check(self.steps_since_stop_test_ >= 0 && self.steps_since_stop_test_ <= 1'000'000,
           "stop step counter out of range");
  for (auto& t : self.ball_touch_ns_) {
    io(t);
    io.Check(t >= -1 && t <= self.time_ns(), "ball touch time out of range");
  }
  for (auto& r : self.robots_) {
    for (auto& j : r.joints) {
      io(InRange(j.command.mode, static_cast<JointMode>(kJointModeCount)), j.command.value, j.command.kp, j.command.kd,
         j.command.dq, j.command.tau, j.reference, j.effort, j.row);
      io.Check(j.row >= -1 && j.row < self.model_->njmax, "motor row out of range");
      io(j.stop, j.stop_target);
      io.Check(j.stop >= 0 && j.stop <= 2 && std::isfinite(j.stop_target), "joint stop out of range");
      io(j.impulse);
      io.Check(j.impulse >= 0.0 && j.impulse <= 1e6, "motor impulse out of range");
      io(j.sensed_q, j.sensed_qd);
      io.Check(std::isfinite(j.sensed_q) && std::isfinite(j.sensed_qd), "sensed joint not finite");
    }
  }
}

void LeggedWorld::Save(StateWriter& out) const { Fields(out, *this); }

void LeggedWorld::Restore(StateReader& in) { Fields(in, *this); }

void LeggedWorld::Reset() {
  // The joint stops rewrite the model's margins each step (StageStops): back to the compiled ones, so that a reset
  // world starts bit for bit as a new one (its first solve warm-starts from the forward pass below).
  std::copy(compiled_jnt_margin_.begin(), compiled_jnt_margin_.end(), model_->jnt_margin);
  mj_resetData(model_.get(), data_.get());
  for (const RobotSlot& r : robots_) {
    for (const JointSlot& j : r.joints) data_->qpos[j.qpos] = j.start_position;
  }
  frame_ = 0;
  steps_since_stop_test_ = 0;
  commanded_ = false;
  std::fill(ball_touch_ns_.begin(), ball_touch_ns_.end(), -1);
  Forward();
  SenseJoints();
  ResetCommands();
  AcceptState();
}

int LeggedWorld::RobotCount() const { return static_cast<int>(robots_.size()); }

int LeggedWorld::RobotIndex(const std::string& name) const {
  for (size_t i = 0; i < robots_.size(); ++i) {
    if (robots_[i].spec->name == name) return static_cast<int>(i);
  }
  return -1;
}

LeggedJointInfo LeggedWorld::JointInfo(int robot, int joint) const {
  LeggedJointInfo info;
  if (robot < 0 || robot >= RobotCount() || joint < 0 || joint >= static_cast<int>(robots_[robot].joints.size()))
    return info;
  const JointSlot& j = robots_[robot].joints[joint];
  info.limited = j.limited;
  info.lo = j.lo;
  info.hi = j.hi;
  info.effort_limit = j.effort_limit;
  info.frictionloss = j.frictionloss;
  info.armature = model_->dof_armature[j.dof];
  return info;
}

double LeggedWorld::RobotMass(int robot) const {
  if (robot < 0 || robot >= RobotCount()) return 0.0;
  double mass = 0.0;
  for (int b : robots_[robot].bodies) mass += model_->body_mass[b];
  return mass;
}

std::array<double, 3> LeggedWorld::RobotCenterOfMass(int robot) const {
  std::array<double, 3> com{};
  if (robot < 0 || robot >= RobotCount()) return com;
  for (int k = 0; k < 3; ++k) com[k] = data_->subtree_com[3 * robots_[robot].base_body + k];
  return com;
}

int LeggedWorld::JointIndex(int robot, const std::string& joint) const {
  if (robot < 0 || robot >= RobotCount()) return -1;
  const std::vector<JointSlot>& joints = robots_[robot].joints;
  for (size_t i = 0; i < joints.size(); ++i) {
    if (joints[i].name == joint) return static_cast<int>(i);
  }
  return -1;
}

JointCommandError LeggedWorld::CheckJointCommand(int robot, const JointCommand& c) const {
  if (robot < 0 || robot >= RobotCount()) return JointCommandError::kUnknownRobot;
  const int index = JointIndex(robot, c.joint);
  if (index < 0) return JointCommandError::kUnknownJoint;
  for (double v : {c.value, c.kp, c.kd, c.dq, c.tau})
    if (!std::isfinite(v)) return JointCommandError::kNotFinite;
  const JointSlot& j = robots_[robot].joints[index];
  const MotorParams& motors = robots_[robot].spec->motors;
  switch (c.mode) {
    case JointMode::kVelocity:
      return std::abs(c.value) > motors.max_speed ? JointCommandError::kOutOfRange : JointCommandError::kOk;
    case JointMode::kPosition:  // gains: negative for the robot's defaults, else as PD's (1e308 made the row inf)
      if (c.kp > kMaxPdKp || c.kd > kMaxPdKd) return JointCommandError::kOutOfRange;
      return j.limited && (c.value < j.lo || c.value > j.hi) ? JointCommandError::kOutOfRange : JointCommandError::kOk;
    case JointMode::kTorque:
      return std::abs(c.value) > j.effort_limit ? JointCommandError::kOutOfRange : JointCommandError::kOk;
    case JointMode::kPd: {
      const bool bad = std::abs(c.value) > kMaxPdTarget || std::abs(c.dq) > kMaxPdSpeed ||
                       std::abs(c.tau) > kMaxPdTau || c.kp < 0 || c.kp > kMaxPdKp || c.kd < 0 || c.kd > kMaxPdKd;
      return bad ? JointCommandError::kOutOfRange : JointCommandError::kOk;
    }
  }
  return JointCommandError::kOutOfRange;
}

int LeggedWorld::JointCount(int robot) const { return static_cast<int>(robots_[robot].joints.size()); }

JointCommandError LeggedWorld::CheckJointCommands(int robot, const std::vector<JointCommand>& commands) const {
  if (robot < 0 || robot >= RobotCount()) return JointCommandError::kUnknownRobot;
  // One entry per joint at most (a batch of a million cost every step a matching of names against all joints).
  if (commands.size() > robots_[robot].joints.size()) return JointCommandError::kTooMany;
  for (const JointCommand& c : commands) {
    const JointCommandError e = CheckJointCommand(robot, c);
    if (e != JointCommandError::kOk) return e;
  }
  return JointCommandError::kOk;
}

JointCommandError LeggedWorld::SetJointCommand(int robot, const JointCommand& c) {
  const JointCommandError error = CheckJointCommand(robot, c);
  if (error != JointCommandError::kOk) return error;
  JointSlot& j = robots_[robot].joints[JointIndex(robot, c.joint)];
  commanded_ = true;
  // rcssserver3d's HingeEffector: at or beyond a stop a velocity command is ignored (the old one stays).
  if (stop_steps_ > 0 && scene_.joint_stops.hold_commands_at_stop && j.limited && c.mode == JointMode::kVelocity &&
      j.command.mode == JointMode::kVelocity) {
    const double q = data_->qpos[j.qpos];
    if (!(q > j.lo && q < j.hi)) return JointCommandError::kOk;
  }
  // A switch into velocity mode starts holding from where the joint is.
  if (c.mode == JointMode::kVelocity && j.command.mode != JointMode::kVelocity) j.reference = data_->qpos[j.qpos];
  j.command = c;
  return JointCommandError::kOk;
}

// Stage 1b (after mj_step1, which computed the velocities): forces on bodies at their centres of mass, for this
// step, as generalized forces next to MuJoCo's passive ones (core/legged/body_forces.h): rcssserver3d's
// DragController on every robot body, a force and a torque against its velocity (scene physics.body_drag), and
// the scene's air on every body (physics.fluid_*), MuJoCo's inertia-box model, which the model's options would
// otherwise apply far more slowly.
void LeggedWorld::StageBodyForces() {
  const double linear = scene_.physics.body_linear_drag;
  const double angular = scene_.physics.body_angular_drag;
  const bool drag = linear != 0.0 || angular != 0.0;
  if (!drag && !air_.enabled()) return;
  const mjModel* m = model_.get();
  mjData* d = data_.get();
  body_wrenches_.assign(6 * m->nbody, 0.0);
  for (int b = 1; b < m->nbody; ++b) {
    mjtNum* wrench = &body_wrenches_[6 * b];  // torque, then force
    if (drag && robot_of_body_[b] >= 0) {
      mjtNum velocity[6];  // angular, then linear; world frame, at the body's centre of mass
      mj_objectVelocity(m, d, mjOBJ_BODY, b, velocity, 0);
      for (int k = 0; k < 3; ++k) {
        wrench[k] = -angular * velocity[k];
        wrench[3 + k] = -linear * velocity[3 + k];
      }
    }
    AddInertiaBoxFluid(m, d, air_, b, wrench);
  }
  AddBodyWrenches(m, d, body_wrenches_, &wrench_scratch_, d->qfrc_passive);
}

// Stage 2: the rest of the MuJoCo step (mj_step2: constraint solver and
// integration); false if it produced a non-finite state.
bool LeggedWorld::StagePhysics() {
  Step2(model_.get(), data_.get(), accelerometers_);
  if (data_->solver_iter >= model_->opt.iterations) ++health_.solver_capped_steps;
  health_.solver_iterations += static_cast<uint64_t>(data_->solver_iter);
  health_.constraint_rows += static_cast<uint64_t>(data_->nefc);
  if (scene_.physics.sensors_after_step) {
    mj_kinematics(model_.get(), data_.get());
    mj_comPos(model_.get(), data_.get());
    mj_comVel(model_.get(), data_.get());
    mj_sensorPos(model_.get(), data_.get());
    mj_sensorVel(model_.get(), data_.get());
    SenseJoints();
  }
  for (RobotSlot& r : robots_) {
    for (JointSlot& j : r.joints) {
      if (j.command.mode == JointMode::kPd) continue;
      j.effort = j.stop != 0 ? data_->qfrc_applied[j.dof] : j.row >= 0 ? data_->efc_force[j.row] : 0.0;
      if (j.command.mode == JointMode::kVelocity) j.impulse += std::abs(j.effort) * model_->opt.timestep;
      // A motor at its bound gave way, as ODE's does: what it lost is lost (no creep back to the reference;
      // measured against rcssserver3d, tests/simspark/reference_replay_test.cpp).
      if (j.command.mode == JointMode::kVelocity && j.stop == 0 && j.row >= 0 &&
          std::abs(j.effort) >= data_->efc_frictionloss[j.row] * (1.0 - 1e-9))
        j.reference = data_->qpos[j.qpos];
    }
  }
  return StateFinite(model_.get(), data_.get(), INFINITY);
}

void LeggedWorld::Forward() {
  mj_forward(model_.get(), data_.get());
  SenseRootAccelerometers(model_.get(), data_.get(), accelerometers_);
}

void LeggedWorld::Step() {
  if (stop_steps_ > 0) StageStops();
  mj_step1(model_.get(), data_.get());
  SenseJoints();  // mj_step1 computed the position and velocity sensors of this state
  if (ode_contacts_) ode_contacts_->Apply(model_.get(), data_.get());
  StageServos();
  StageBodyForces();
  if (StagePhysics()) {
    AcceptState();
    RecordBallTouches();
  } else {
    // Stage 3: undo a step that blew up, at rest, and hold every joint there.
    ++health_.instability_recoveries;
    last_good_.Undo(model_.get(), data_.get());
    SenseRootAccelerometers(model_.get(), data_.get(), accelerometers_);
    SenseJoints();
    ResetCommands();
  }
  ++frame_;
}

void LeggedWorld::ContactWrench(int site, ForceReading* out) const {
  out->contact = false;
  out->force = {0, 0, 0};
  out->point = {0, 0, 0};
  if (site < 0) return;
  const mjModel* m = model_.get();
  const mjData* d = data_.get();
  const int body = m->site_bodyid[site];
  double force[3] = {0, 0, 0};
  double point[3] = {0, 0, 0};
  double weight = 0.0;
  for (int i = 0; i < d->ncon; ++i) {
    const mjContact& c = d->contact[i];
    const int b1 = m->geom_bodyid[c.geom1];
    const int b2 = m->geom_bodyid[c.geom2];
    if (b1 != body && b2 != body) continue;
    mjtNum local[6];
    mj_contactForce(m, d, i, local);
    // The contact frame's rows are its axes in world; the force acts from
    // geom1 on geom2, so the body as geom1 feels the opposite.
    const double sign = b2 == body ? 1.0 : -1.0;
    double world[3];
    mju_mulMatTVec(world, c.frame, local, 3, 3);
    for (int k = 0; k < 3; ++k) {
      force[k] += sign * world[k];
      point[k] += std::abs(local[0]) * c.pos[k];
    }
    weight += std::abs(local[0]);
    out->contact = true;
  }
  if (!out->contact) return;
  const double* r = d->site_xmat + 9 * site;  // site to world, row-major
  const double* origin = d->site_xpos + 3 * site;
  double rel[3];
  for (int k = 0; k < 3; ++k) rel[k] = weight > 0 ? point[k] / weight - origin[k] : 0.0;
  for (int k = 0; k < 3; ++k) {
    out->force[k] = r[k] * force[0] + r[3 + k] * force[1] + r[6 + k] * force[2];
    out->point[k] = weight > 0 ? r[k] * rel[0] + r[3 + k] * rel[1] + r[6 + k] * rel[2] : 0.0;
  }
}

void LeggedWorld::RecordBallTouches() {
  if (ball_body_ < 0) return;
  const mjModel* m = model_.get();
  const mjData* d = data_.get();
  const int64_t end = static_cast<int64_t>(frame_ + 1) * step_ns_;
  for (int i = 0; i < d->ncon; ++i) {
    const mjContact& c = d->contact[i];
    const int b1 = m->geom_bodyid[c.geom1];
    const int b2 = m->geom_bodyid[c.geom2];
    if (b1 != ball_body_ && b2 != ball_body_) continue;
    const int robot = robot_of_body_[b1 == ball_body_ ? b2 : b1];
    if (robot >= 0) ball_touch_ns_[robot] = end;
  }
}

// The contacts of the last step between bodies of two robots, one entry per pair with the mean point.
void LeggedWorld::RobotContacts(std::vector<RobotContact>* out) const {
  const mjModel* m = model_.get();
  const mjData* d = data_.get();
  std::map<std::pair<int, int>, RobotContact> pairs;
  for (int i = 0; i < d->ncon; ++i) {
    const mjContact& c = d->contact[i];
    int a = robot_of_body_[m->geom_bodyid[c.geom1]];
    int b = robot_of_body_[m->geom_bodyid[c.geom2]];
    if (a < 0 || b < 0 || a == b) continue;
    if (a > b) std::swap(a, b);
    RobotContact& p = pairs[{a, b}];
    p.robot_a = a;
    p.robot_b = b;
    for (int k = 0; k < 3; ++k) p.point[k] += c.pos[k];
    ++p.points;
  }
  out->clear();
  for (auto& [key, p] : pairs) {
    for (double& x : p.point) x /= p.points;
    out->push_back(p);
  }
}

LeggedWorldState LeggedWorld::State() const {
  LeggedWorldState out;
  State(&out);
  return out;
}

void LeggedWorld::State(LeggedWorldState* out) const {
  const mjData* d = data_.get();
  out->time_ns = time_ns();
  out->frame = frame_;
  out->robots.resize(robots_.size());
  for (size_t i = 0; i < robots_.size(); ++i) {
    const RobotSlot& r = robots_[i];
    LeggedRobotState& s = out->robots[i];
    s.name = r.spec->name;
    s.id = r.spec->id;
    for (int k = 0; k < 3; ++k) s.base_position[k] = d->xpos[3 * r.base_body + k];
    for (int k = 0; k < 4; ++k) s.base_orientation[k] = d->xquat[4 * r.base_body + k];
    for (int k = 0; k < 3; ++k) s.base_velocity[k] = r.root_dof >= 0 ? d->qvel[r.root_dof + k] : 0.0;
    const size_t n = r.joints.size();
    s.joint_names.resize(n);
    s.joint_positions.resize(n);
    s.joint_velocities.resize(n);
    s.joint_efforts.resize(n);
    for (size_t j = 0; j < n; ++j) {
      s.joint_names[j] = r.joints[j].name;
      s.joint_positions[j] = r.joints[j].sensed_q;
      s.joint_velocities[j] = r.joints[j].sensed_qd;
      s.joint_efforts[j] = r.joints[j].effort;
    }
    s.has_imu = r.gyro >= 0 || r.accelerometer >= 0;
    for (int k = 0; k < 3; ++k) {
      s.gyro[k] = r.gyro >= 0 ? d->sensordata[r.gyro + k] : 0.0;
      s.accelerometer[k] = r.accelerometer >= 0 ? d->sensordata[r.accelerometer + k] : 0.0;
    }
    for (int k = 0; k < 4; ++k)
      s.orientation[k] = r.orientation >= 0 ? d->sensordata[r.orientation + k] : s.base_orientation[k];
    s.forces.resize(r.forces.size());
    for (size_t f = 0; f < r.forces.size(); ++f) {
      s.forces[f].name = r.forces[f].name;
      s.forces[f].values.assign(d->sensordata + r.forces[f].adr, d->sensordata + r.forces[f].adr + r.forces[f].dim);
      ContactWrench(r.forces[f].site, &s.forces[f]);
    }
    s.ball_touch_ns = ball_touch_ns_[i];
    s.links.resize(r.bodies.size());
    for (size_t b = 0; b < r.bodies.size(); ++b) {
      LinkPose& link = s.links[b];
      link.name = r.body_names[b];
      for (int k = 0; k < 3; ++k) link.position[k] = d->xpos[3 * r.bodies[b] + k];
      for (int k = 0; k < 4; ++k) link.orientation[k] = d->xquat[4 * r.bodies[b] + k];
    }
  }
  RobotContacts(&out->robot_contacts);
  out->has_ball = ball_body_ >= 0;
  if (out->has_ball) {
    for (int k = 0; k < 3; ++k) {
      out->ball_position[k] = d->xpos[3 * ball_body_ + k];
      out->ball_velocity[k] = d->qvel[ball_qvel_ + k];
    }
  }
}

}  // namespace turf
