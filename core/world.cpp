#include "core/world.h"

#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "core/ball_handling.h"
#include "core/ball_model.h"
#include "core/drive.h"
#include "core/input_limits.h"
#include "core/mjcf.h"
#include "core/state_fields.h"

namespace turf {

struct World::RobotSlot {
  Team team = Team::kBlue;
  int id = 0;
  int qpos = 0;  // x, y, yaw are consecutive
  int dof = 0;
  bool on_field = false;
  RobotCommand command;
  int64_t command_time_ns = 0;
  bool has_command = false;
  ArmedKick kick;  // what the kicker does when the ball is within reach
  bool ball_contact = false;
  uint32_t kick_count = 0;
  KickKind last_kick = KickKind::kNone;
};

namespace {

MjModelPtr CompileModel(const Scene& scene);

// mj_step for turf's SSL model (Euler) in MuJoCo's own order, with a stage of turf's between MuJoCo's collision
// and the constraints it makes from the contacts: there a contact's parameters can still change. MuJoCo 2.2.2's
// mj_step is mj_checkPos, mj_checkVel, mj_forward (mj_fwdPosition's calls below, then mj_sensorPos and the rest
// of mj_forwardSkip), mj_checkAcc and mj_Euler.
template <class ContactStage>
void StepWithContactStage(const mjModel* m, mjData* d, ContactStage contacts) {
  mj_checkPos(m, d);
  mj_checkVel(m, d);
  mj_kinematics(m, d);
  mj_comPos(m, d);
  mj_camlight(m, d);
  mj_tendon(m, d);
  mj_crb(m, d);
  mj_factorM(m, d);
  mj_collision(m, d);
  contacts();
  mj_makeConstraint(m, d);
  mj_transmission(m, d);
  mj_projectConstraint(m, d);
  mj_sensorPos(m, d);
  if (m->opt.enableflags & mjENBL_ENERGY) mj_energyPos(m, d);
  mj_forwardSkip(m, d, mjSTAGE_POS, 0);
  mj_checkAcc(m, d);
  mj_Euler(m, d);
}

double WrapAngle(double a) { return std::remainder(a, 2.0 * M_PI); }

}  // namespace

World::World(Scene scene) : scene_(std::move(scene)) {
  const std::vector<std::string> errors = ValidateScene(scene_);
  if (!errors.empty()) {
    std::string all;
    for (const std::string& e : errors) all += "\n  " + e;
    throw std::invalid_argument("invalid scene '" + scene_.name + "':" + all);
  }
  model_ = CompileModel(scene_);
  data_.reset(mj_makeData(model_.get()));
  step_ns_ = std::llround(scene_.physics.step * 1e9);

  ball_body_ = mj_name2id(model_.get(), mjOBJ_BODY, kBallBody);
  ball_geom_ = mj_name2id(model_.get(), mjOBJ_GEOM, kBallBody);
  floor_geom_ = mj_name2id(model_.get(), mjOBJ_GEOM, kFloorGeom);
  const int ball_joint = model_->body_jntadr[ball_body_];
  ball_qpos_ = model_->jnt_qposadr[ball_joint];
  ball_qvel_ = model_->jnt_dofadr[ball_joint];
  ball_inertia_ = model_->body_inertia[3 * ball_body_];
  for (Team team : {Team::kBlue, Team::kYellow}) {
    for (int id = 0; id < scene_.robots_per_team; ++id) {
      const int body = mj_name2id(model_.get(), mjOBJ_BODY, RobotBodyName(team, id).c_str());
      const int j = model_->body_jntadr[body];
      RobotSlot slot;
      slot.team = team;
      slot.id = id;
      slot.qpos = model_->jnt_qposadr[j];
      slot.dof = model_->jnt_dofadr[j];
      robots_.push_back(slot);
    }
  }
  Reset();
}

World::~World() = default;

int World::RobotIndex(Team team, int id) const {
  if (id < 0 || id >= scene_.robots_per_team) return -1;
  return static_cast<int>(team) * scene_.robots_per_team + id;
}

void World::Reset() {
  mj_resetData(model_.get(), data_.get());
  frame_ = 0;
  for (RobotSlot& slot : robots_) {
    const RobotSlot fresh = slot;
    slot = RobotSlot{};
    slot.team = fresh.team;
    slot.id = fresh.id;
    slot.qpos = fresh.qpos;
    slot.dof = fresh.dof;
    const Pose2 park = ParkingPose(scene_, slot.team, slot.id);
    PlaceRobot(slot, park.x, park.y, park.theta, {});
  }
  for (const RobotSetup& setup : scene_.robots) {
    RobotSlot& slot = robots_[RobotIndex(setup.team, setup.id)];
    if (!setup.on_field) continue;
    slot.on_field = true;
    PlaceRobot(slot, setup.pose.x, setup.pose.y, setup.pose.theta, {});
  }
  double* q = data_->qpos + ball_qpos_;
  q[0] = scene_.ball_start_x;
  q[1] = scene_.ball_start_y;
  q[2] = scene_.ball.radius;
  q[3] = 1.0;
  q[4] = q[5] = q[6] = 0.0;
  mj_forward(model_.get(), data_.get());
  floor_normal_force_ = FloorNormalForce();
  last_good_.Accept(model_.get(), data_.get());
}

// Listed once (core/state_io.h).
template <class Io, class Self>
void World::Fields(Io& io, Self& self) {
  io.Tag(StateTag("SSLW"));
  io(MjWorld(self.model_, self.data_, self.frame_, self.step_ns_));
  io(self.floor_normal_force_, self.last_good_, self.health_.containment_corrections,
     self.health_.instability_recoveries, self.health_.solver_capped_steps);
  for (auto& slot : self.robots_) {
    io(slot.on_field, slot.command, slot.command_time_ns, slot.has_command, slot.kick, slot.ball_contact,
       slot.kick_count, InRange(slot.last_kick, kKickEnd));
  }
}

void World::Save(StateWriter& out) const { Fields(out, *this); }

void World::Restore(StateReader& in) { Fields(in, *this); }

void World::PlaceRobot(RobotSlot& slot, double x, double y, double yaw, const Vec3& velocity) {
  data_->qpos[slot.qpos] = x;
  data_->qpos[slot.qpos + 1] = y;
  data_->qpos[slot.qpos + 2] = yaw;
  data_->qvel[slot.dof] = velocity.x;
  data_->qvel[slot.dof + 1] = velocity.y;
  data_->qvel[slot.dof + 2] = velocity.z;
}

InputError World::SetCommand(const RobotCommand& c) {
  const int index = RobotIndex(c.team, c.id);
  if (index < 0) return InputError::kUnknownRobot;
  const InputError error = CheckCommand(c);
  if (error != InputError::kOk) return error;
  RobotSlot& slot = robots_[index];
  slot.command = c;
  slot.command_time_ns = time_ns();
  slot.has_command = true;
  // A kick arms the kicker (replacing an armed one); a command without a kick
  // leaves it armed: team software sends one kick and then plain commands.
  if (c.kick != KickKind::kNone && c.kick_speed > 0.0) {
    slot.kick = {c.kick, c.kick_speed, c.chip_angle, time_ns() + std::llround(scene_.robot.kicker.arm_time * 1e9)};
  }
  return InputError::kOk;
}

InputError World::TeleportBall(const BallTeleport& t) {
  const InputError error = CheckBallTeleport(t, scene_);
  if (error != InputError::kOk) return error;
  double* q = data_->qpos + ball_qpos_;
  q[0] = t.position.x;
  q[1] = t.position.y;
  q[2] = std::max(t.position.z, scene_.ball.radius);
  q[3] = 1.0;  // identity orientation: the local and world spin frames agree
  q[4] = q[5] = q[6] = 0.0;
  double* v = data_->qvel + ball_qvel_;
  v[0] = t.velocity.x;
  v[1] = t.velocity.y;
  v[2] = t.velocity.z;
  const double r = scene_.ball.radius;
  // Rolling along v spins about z x v / r.
  v[3] = t.roll ? -t.velocity.y / r : 0.0;
  v[4] = t.roll ? t.velocity.x / r : 0.0;
  v[5] = 0.0;
  return InputError::kOk;
}

InputError World::TeleportRobot(const RobotTeleport& t) {
  const int index = RobotIndex(t.team, t.id);
  if (index < 0) return InputError::kUnknownRobot;
  const InputError error = CheckRobotTeleport(t, scene_);
  if (error != InputError::kOk) return error;
  RobotSlot& slot = robots_[index];
  slot.on_field = t.on_field;
  if (!t.on_field) slot.kick = {};
  if (t.on_field) {
    PlaceRobot(slot, t.x, t.y, t.orientation, t.velocity);
  } else {
    const Pose2 park = ParkingPose(scene_, slot.team, slot.id);
    PlaceRobot(slot, park.x, park.y, park.theta, {});
  }
  return InputError::kOk;
}

RobotKinematics World::Kinematics(const RobotSlot& slot) const {
  const double* q = data_->qpos + slot.qpos;
  const double* v = data_->qvel + slot.dof;
  return {q[0], q[1], q[2], v[0], v[1], v[2]};
}

BallState World::Ball() const {
  const double* q = data_->qpos + ball_qpos_;
  const double* v = data_->qvel + ball_qvel_;
  BallState b;
  b.position = {q[0], q[1], q[2]};
  b.velocity = {v[0], v[1], v[2]};
  // A free joint's angular velocity is in the body frame; report the world's.
  double world[3];
  mju_rotVecQuat(world, v + 3, q + 3);
  b.angular_velocity = {world[0], world[1], world[2]};
  return b;
}

void World::Step() {
  StageWatchdog();
  StageDrive();
  StageBallHandling();
  StageBallModel();
  if (StagePhysics()) {
    StageContainment();
  }
  StageFeedback();
  ++frame_;
}

void World::StageWatchdog() {
  const int64_t timeout_ns = std::llround(scene_.rates.command_timeout * 1e9);
  for (RobotSlot& slot : robots_) {
    if (slot.has_command && time_ns() - slot.command_time_ns > timeout_ns) {
      slot.command = RobotCommand{};
      slot.command.team = slot.team;
      slot.command.id = slot.id;
      slot.has_command = false;
      slot.kick = {};
    }
  }
}

void World::StageDrive() {
  const RobotParams& params = scene_.robot;
  const double inertia = 0.5 * params.mass * params.radius * params.radius;
  for (RobotSlot& slot : robots_) {
    double* f = data_->qfrc_applied + slot.dof;
    if (!slot.on_field) {
      f[0] = f[1] = f[2] = 0.0;
      continue;
    }
    const RobotKinematics k = Kinematics(slot);
    const PlanarVelocity desired = DesiredVelocity(slot.command, k.yaw, params.drive);
    const PlanarForce force =
        DriveForce({k.vx, k.vy, k.omega}, desired, params.mass, inertia, scene_.physics.step, params.drive);
    f[0] = force.x;
    f[1] = force.y;
    f[2] = force.torque;
  }
}

void World::StageBallHandling() {
  const RobotParams& params = scene_.robot;
  const double r = scene_.ball.radius;
  double* xfrc = data_->xfrc_applied + 6 * ball_body_;
  std::fill(xfrc, xfrc + 6, 0.0);
  for (RobotSlot& slot : robots_) {
    if (!slot.on_field) continue;
    const RobotKinematics k = Kinematics(slot);
    const BallState ball = Ball();
    const RobotCommand& c = slot.command;
    if (slot.kick.kind != KickKind::kNone && time_ns() > slot.kick.until_ns) slot.kick = {};  // not fired in time
    if (slot.kick.kind != KickKind::kNone && BallAtFront(k, ball.position, params, r, params.kicker.reach)) {
      const Vec3 v =
          KickVelocity(k, ball.velocity, slot.kick.kind, slot.kick.speed, slot.kick.chip_angle, params.kicker);
      double* qv = data_->qvel + ball_qvel_;
      qv[0] = v.x;
      qv[1] = v.y;
      qv[2] = v.z;
      qv[3] = qv[4] = qv[5] = 0.0;  // a kicked ball starts sliding
      ++slot.kick_count;
      slot.last_kick = slot.kick.kind;
      slot.kick = {};
      continue;
    }
    if (c.dribbler_speed > 0.0 && BallAtFront(k, ball.position, params, r, params.dribbler.capture_distance)) {
      const Vec3 f = DribblerForce(k, ball, params, r);
      xfrc[0] += f.x;
      xfrc[1] += f.y;
    }
  }
}

void World::StageBallModel() {
  const BallState ball = Ball();
  const double dt = scene_.physics.step;
  const Wrench friction = CarpetFriction(ball, floor_normal_force_, scene_.ball, ball_inertia_, dt);
  const Wrench rolling = RollingResistance(ball, floor_normal_force_, scene_.ball, ball_inertia_, dt);
  double* xfrc = data_->xfrc_applied + 6 * ball_body_;
  for (const Wrench& w : {friction, rolling}) {
    xfrc[0] += w.force.x;
    xfrc[1] += w.force.y;
    xfrc[2] += w.force.z;
    xfrc[3] += w.torque.x;
    xfrc[4] += w.torque.y;
    xfrc[5] += w.torque.z;
  }
}

double World::FloorNormalForce() const {
  for (int i = 0; i < data_->ncon; ++i) {
    const mjContact& c = data_->contact[i];
    if ((c.geom1 == floor_geom_ && c.geom2 == ball_geom_) || (c.geom1 == ball_geom_ && c.geom2 == floor_geom_)) {
      mjtNum force[6];
      mj_contactForce(model_.get(), data_.get(), i, force);
      return force[0];
    }
  }
  return 0.0;
}

// The ball against a robot's flat front (the dribbler bar) bounces with the bar's restitution, not the body's: in
// MuJoCo's contacts of this step, before they become constraints.
void World::StageDribblerContacts() {
  const RobotParams& r = scene_.robot;
  // The flat front's edges seen from the centre: a contact whose normal lies closer to the heading than they do is
  // on the front (a sphere on the flat face has the heading as its normal, on the round body a radial one).
  const double half_face = std::sqrt(r.radius * r.radius - r.center_to_dribbler * r.center_to_dribbler);
  const double cos_face = r.center_to_dribbler / std::hypot(r.center_to_dribbler, half_face);
  for (int i = 0; i < data_->ncon; ++i) {
    mjContact& c = data_->contact[i];
    const int other = c.geom1 == ball_geom_ ? c.geom2 : (c.geom2 == ball_geom_ ? c.geom1 : -1);
    if (other < 0) continue;
    const int body = model_->geom_bodyid[other];
    if (model_->body_jntnum[body] != 3) continue;  // a robot: x, y, yaw; walls, goals and the carpet have none
    const double* q = data_->qpos + model_->jnt_qposadr[model_->body_jntadr[body]];
    const double along = std::abs(c.frame[0] * std::cos(q[2]) + c.frame[1] * std::sin(q[2]));  // |normal . heading|
    const double ahead = (c.pos[0] - q[0]) * std::cos(q[2]) + (c.pos[1] - q[1]) * std::sin(q[2]);
    if (along < cos_face || ahead <= 0.0) continue;  // the round body, or the back
    const BallSpring bar = BallContactSpring(r.dribbler.restitution, scene_.physics.step);
    c.solref[0] = bar.timeconst;
    c.solref[1] = bar.dampratio;
  }
}

bool World::StagePhysics() {
  last_good_.Accept(model_.get(), data_.get());
  const int bad_before = data_->warning[mjWARN_BADQACC].number + data_->warning[mjWARN_BADQVEL].number +
                         data_->warning[mjWARN_BADQPOS].number;
  StepWithContactStage(model_.get(), data_.get(), [this] { StageDribblerContacts(); });
  if (data_->solver_iter >= model_->opt.iterations) ++health_.solver_capped_steps;
  floor_normal_force_ = FloorNormalForce();
  const int bad_after = data_->warning[mjWARN_BADQACC].number + data_->warning[mjWARN_BADQVEL].number +
                        data_->warning[mjWARN_BADQPOS].number;
  if (bad_after == bad_before && StateFinite(model_.get(), data_.get(), 1e3)) return true;
  // Undo the step and stop everything: a frozen frame beats an exploded world.
  ++health_.instability_recoveries;
  last_good_.Undo(model_.get(), data_.get());
  floor_normal_force_ = FloorNormalForce();
  return false;
}

void World::StageContainment() {
  const FieldParams& f = scene_.field;
  const double x_in = f.length / 2 + f.boundary_width_goal_line;
  const double y_in = f.width / 2 + f.boundary_width;
  // Pushes a coordinate back inside [-limit, limit] and reverses its speed.
  auto contain = [this](double* pos, double* vel, double limit, double restitution) {
    if (std::abs(*pos) <= limit) return;
    *pos = std::copysign(limit, *pos);
    if (*vel * *pos > 0) *vel = -restitution * *vel;
    ++health_.containment_corrections;
  };
  const double rb = scene_.ball.radius;
  const double e = scene_.ball.wall_restitution;
  contain(data_->qpos + ball_qpos_, data_->qvel + ball_qvel_, x_in - rb, e);
  contain(data_->qpos + ball_qpos_ + 1, data_->qvel + ball_qvel_ + 1, y_in - rb, e);
  const double rr = scene_.robot.radius;
  for (RobotSlot& slot : robots_) {
    if (!slot.on_field) {
      // Parked robots stay where they were put.
      const Pose2 park = ParkingPose(scene_, slot.team, slot.id);
      PlaceRobot(slot, park.x, park.y, park.theta, {});
      continue;
    }
    contain(data_->qpos + slot.qpos, data_->qvel + slot.dof, x_in - rr, 0.0);
    contain(data_->qpos + slot.qpos + 1, data_->qvel + slot.dof + 1, y_in - rr, 0.0);
  }
}

void World::StageFeedback() {
  const RobotParams& params = scene_.robot;
  const Vec3 ball = Ball().position;
  for (RobotSlot& slot : robots_) {
    slot.ball_contact =
        slot.on_field && BallAtFront(Kinematics(slot), ball, params, scene_.ball.radius, params.kicker.reach);
  }
}

WorldSnapshot World::Snapshot() const {
  WorldSnapshot s;
  Snapshot(&s);
  return s;
}

void World::Snapshot(WorldSnapshot* out) const {
  out->time_ns = time_ns();
  out->frame = frame_;
  const BallState b = Ball();
  out->ball = {b.position, b.velocity, b.angular_velocity};
  out->robots.resize(robots_.size());
  for (size_t i = 0; i < robots_.size(); ++i) {
    const RobotSlot& slot = robots_[i];
    const RobotKinematics k = Kinematics(slot);
    RobotSnapshot& r = out->robots[i];
    r.team = slot.team;
    r.id = slot.id;
    r.on_field = slot.on_field;
    r.x = k.x;
    r.y = k.y;
    r.yaw = WrapAngle(k.yaw);
    r.vx = k.vx;
    r.vy = k.vy;
    r.omega = k.omega;
    r.ball_contact = slot.ball_contact;
    r.kick_count = slot.kick_count;
    r.last_kick = slot.last_kick;
  }
}

namespace {

MjModelPtr CompileModel(const Scene& scene) {
  const std::string xml = BuildMjcf(scene);
  // mjVFS is large (~2 MB): keep it off the stack.
  auto vfs = std::make_unique<mjVFS>();
  mj_defaultVFS(vfs.get());
  const char* file = "turf_scene.xml";
  if (mj_makeEmptyFileVFS(vfs.get(), file, static_cast<int>(xml.size())) != 0)
    throw std::invalid_argument("MuJoCo VFS full");
  std::copy(xml.begin(), xml.end(), static_cast<char*>(vfs->filedata[vfs->nfile - 1]));
  char error[1024] = "";
  mjModel* m = mj_loadXML(file, vfs.get(), error, sizeof(error));
  mj_deleteVFS(vfs.get());
  if (m == nullptr) throw std::invalid_argument(fmt::format("MuJoCo rejected the scene model: {}", error));
  return MjModelPtr(m);
}

}  // namespace

}  // namespace turf
