// LeggedWorld: moving a robot's or the ball's state out of one world and into another (legged_world.h, "Moving
// robots between worlds"), and the boxes that tell which robots may touch.
#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/legged/legged_world.h"
#include "core/legged/legged_world_slots.h"

namespace turf {

namespace {

void CopyOut(const mjtNum* from, int begin, int end, std::vector<double>* to) { to->assign(from + begin, from + end); }

void CopyIn(const std::vector<double>& from, int begin, int end, mjtNum* to, const char* what) {
  if (static_cast<int>(from.size()) != end - begin)
    throw std::invalid_argument(std::string("landing a carry of another model: ") + what);
  std::copy(from.begin(), from.end(), to + begin);
}

}  // namespace

// A joint's state that moves with its robot, listed once for both directions: copy(slot's, carry's).
template <class Slot, class Carry, class Copy>
void LeggedWorld::EachJointField(Slot& j, Carry& c, Copy copy) {
  copy(j.command, c.command);
  copy(j.reference, c.reference);
  copy(j.effort, c.effort);
  copy(j.stop_target, c.stop_target);
  copy(j.impulse, c.impulse);
  copy(j.sensed_q, c.sensed_q);
  copy(j.sensed_qd, c.sensed_qd);
  copy(j.row, c.row);
  copy(j.stop, c.stop);
  copy(j.stop_row, c.stop_row);
}

LeggedCarry LeggedWorld::CarryRobot(int robot) const {
  const RobotSlot& r = robots_.at(static_cast<size_t>(robot));
  const mjData* d = data_.get();
  LeggedCarry c;
  CopyOut(d->qpos, r.qpos_begin, r.qpos_end, &c.qpos);
  CopyOut(d->qvel, r.dof_begin, r.dof_end, &c.qvel);
  CopyOut(d->qacc_warmstart, r.dof_begin, r.dof_end, &c.warmstart);
  c.joints.resize(r.joints.size());
  for (size_t i = 0; i < r.joints.size(); ++i)
    EachJointField(r.joints[i], c.joints[i], [](const auto& slot, auto& carry) { carry = slot; });
  c.ball_touch_ns = ball_touch_ns_[robot];
  return c;
}

void LeggedWorld::LandRobot(int robot, const LeggedCarry& c) {
  RobotSlot& r = robots_.at(static_cast<size_t>(robot));
  mjData* d = data_.get();
  CopyIn(c.qpos, r.qpos_begin, r.qpos_end, d->qpos, "qpos");
  CopyIn(c.qvel, r.dof_begin, r.dof_end, d->qvel, "qvel");
  CopyIn(c.warmstart, r.dof_begin, r.dof_end, d->qacc_warmstart, "warm start");
  if (c.joints.size() != r.joints.size()) throw std::invalid_argument("landing a carry of another model: joints");
  for (size_t i = 0; i < r.joints.size(); ++i)
    EachJointField(r.joints[i], c.joints[i], [](auto& slot, const auto& carry) { slot = carry; });
  ball_touch_ns_[robot] = c.ball_touch_ns;
}

LeggedCarry LeggedWorld::CarryBall() const {
  LeggedCarry c;
  if (ball_body_ < 0) return c;
  const int qpos = model_->jnt_qposadr[model_->body_jntadr[ball_body_]];
  CopyOut(data_->qpos, qpos, qpos + 7, &c.qpos);
  CopyOut(data_->qvel, ball_qvel_, ball_qvel_ + 6, &c.qvel);
  CopyOut(data_->qacc_warmstart, ball_qvel_, ball_qvel_ + 6, &c.warmstart);
  return c;
}

void LeggedWorld::LandBall(const LeggedCarry& c) {
  if (ball_body_ < 0) throw std::invalid_argument("landing a ball in a world without one");
  const int qpos = model_->jnt_qposadr[model_->body_jntadr[ball_body_]];
  CopyIn(c.qpos, qpos, qpos + 7, data_->qpos, "ball qpos");
  CopyIn(c.qvel, ball_qvel_, ball_qvel_ + 6, data_->qvel, "ball qvel");
  CopyIn(c.warmstart, ball_qvel_, ball_qvel_ + 6, data_->qacc_warmstart, "ball warm start");
}

void LeggedWorld::Reuse(uint64_t frame) {
  std::copy(compiled_jnt_margin_.begin(), compiled_jnt_margin_.end(), model_->jnt_margin);
  mj_resetData(model_.get(), data_.get());
  frame_ = frame;
  steps_since_stop_test_ = 0;
  commanded_ = false;
  std::fill(ball_touch_ns_.begin(), ball_touch_ns_.end(), -1);
  health_ = {};
  ResetCommands();
}

void LeggedWorld::Settle(bool forward) {
  if (forward) {
    Forward();
    SenseJoints();
  }
  AcceptState();
}

std::array<double, 6> LeggedWorld::Bounds(int robot, double grow, double horizon) const {
  const mjModel* m = model_.get();
  const mjData* d = data_.get();
  std::array<double, 6> box{INFINITY, INFINITY, INFINITY, -INFINITY, -INFINITY, -INFINITY};
  auto add = [&](int g) {
    const double r = m->geom_rbound[g] + m->geom_margin[g];
    for (int k = 0; k < 3; ++k) {
      box[k] = std::min(box[k], d->geom_xpos[3 * g + k] - r);
      box[3 + k] = std::max(box[3 + k], d->geom_xpos[3 * g + k] + r);
    }
  };
  double speed = 0.0;
  if (robot < 0) {
    if (ball_body_ < 0) return box;
    add(m->body_geomadr[ball_body_]);
    speed = mju_norm3(d->qvel + ball_qvel_);
  } else {
    const RobotSlot& r = robots_.at(static_cast<size_t>(robot));
    for (int g : r.geoms) add(g);
    if (r.root_dof >= 0) speed = mju_norm3(d->qvel + r.root_dof);
  }
  const double pad = grow + horizon * (std::isfinite(speed) ? speed : 0.0);
  for (int k = 0; k < 3; ++k) {
    box[k] -= pad;
    box[3 + k] += pad;
  }
  return box;
}

}  // namespace turf
