// LeggedWorld's motor stages (legged_world.h): rcssserver3d's hinge stops before mj_step1 (stage 0) and each
// joint's motor row between mj_step1 and mj_step2 (stage 1), ODE's hinge motor and the PD motor of RCSSServerMJ and
// the Booster SDK.
#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>

#include "core/legged/legged_world.h"
#include "core/legged/legged_world_slots.h"

namespace turf {

namespace {

// A stiff motor row's compliance R relative to its inverse inertia (MuJoCo's
// largest impedance, mjMAXIMP): a load f creeps through at dt R f. Stiffer
// rows need far more solver iterations than a match scene affords (measured:
// 1e-5 spikes at 50 iterations, not at 200), so velocity mode feeds the creep
// back instead: its target carries (reference - q) / kCreepTime, where the
// reference angle integrates the commanded velocity and the difference is
// kept within kCreepLead (a blocked joint does not wind it up). A step in which
// the motor is at its bound resets the reference to where the joint is: ODE's
// motor, overpowered, loses the angle for good.
constexpr double kStiffCompliance = 1e-4;
// ... and at most this much (1 / (kg m^2)): a light body's relative compliance is a large absolute one. The type-4
// Nao's toe (22 g; inverse inertia 1.3e5) would give 12.6, through which a push-off's 3 N m bends it 0.8 deg in one
// 20 ms step, where ODE's motor (joint CFM 1e-8) holds it at exactly 0 (rcssserver3d's traces); the Nao's other
// rows range from 0.014 (hip roll) to 1.2 (elbow yaw).
constexpr double kMaxStiffCompliance = 0.5;
double StiffCompliance(double diag_approx) { return std::min(diag_approx * kStiffCompliance, kMaxStiffCompliance); }
constexpr double kCreepTime = 0.1;   // s
constexpr double kCreepLead = 0.01;  // rad
// A joint margin no joint reaches: MuJoCo instantiates no limit row (ODE stops between their tests).
constexpr double kNoLimitRow = -1e9;
// A reference acceleration no joint reaches: the row stays inactive.
constexpr double kInactiveRow = -1e10;

}  // namespace

// Stage 1 (between mj_step1 and mj_step2): each joint's command becomes its
// motor row, as ODE's hinge motor (dParamVel, dParamFMax): a velocity
// constraint solved with the contacts and limits of this step, whose force is
// bounded by max_torque; it reaches the target velocity at the end of the step
// when the bound allows. Position mode is an implicit PD on the same row
// (force kp (target - q - dt qd') - kd qd', bounded, no faster than
// max_speed); torque mode drives towards +-max_speed with at most the
// commanded torque. A motor never turns faster than max_speed by itself.
void LeggedWorld::StageServos() {
  const mjModel* m = model_.get();
  mjData* d = data_.get();
  const double dt = m->opt.timestep;
  for (RobotSlot& r : robots_) {
    for (JointSlot& j : r.joints) {
      j.row = -1;
      j.stop_row = -1;
      d->qfrc_applied[j.dof] = 0.0;
    }
  }
  for (int i = 0; i < d->nefc; ++i) {
    if (d->efc_type[i] == mjCNSTR_LIMIT_JOINT && stop_steps_ > 0) {
      const auto [robot, joint] = motor_of_dof_[m->jnt_dofadr[d->efc_id[i]]];
      if (robot >= 0) robots_[robot].joints[joint].stop_row = i;
      continue;
    }
    if (d->efc_type[i] != mjCNSTR_FRICTION_DOF) continue;
    const auto [robot, joint] = motor_of_dof_[d->efc_id[i]];
    if (robot >= 0) robots_[robot].joints[joint].row = i;
  }
  for (RobotSlot& r : robots_) {
    const MotorParams& motors = r.spec->motors;
    for (JointSlot& j : r.joints) {
      if (j.command.mode == JointMode::kPd) {
        ServoPd(&j);
        continue;
      }
      double target = 0.0;  // velocity at the end of the step
      double bound = j.effort_limit;
      double gain = 0.0;  // N m s / rad; 0 = stiff (ODE's joint CFM 1e-8)
      switch (j.command.mode) {
        case JointMode::kVelocity: {
          const double q = d->qpos[j.qpos];
          const double creep = std::clamp(j.reference - q, -kCreepLead, kCreepLead);
          target = j.command.value + creep / kCreepTime;
          j.reference = q + creep + j.command.value * dt;
          // ODE's motor knows no stops: with them (scene joint_stops) the reference is not held inside either.
          if (j.limited && stop_steps_ == 0) j.reference = std::clamp(j.reference, j.lo, j.hi);
          bound = ImpulseBound(&j);
          break;
        }
        case JointMode::kPosition: {
          const double kp = j.command.kp >= 0 ? j.command.kp : motors.position_kp;
          const double kd = j.command.kd >= 0 ? j.command.kd : motors.position_kd;
          gain = kp * dt + kd;
          if (gain > 0) {
            target = std::clamp(kp * (j.command.value - d->qpos[j.qpos]) / gain, -motors.max_speed, motors.max_speed);
          } else {
            bound = 0.0;
          }
          break;
        }
        case JointMode::kPd:
          break;  // ServoPd above
        case JointMode::kTorque:
          // A motor with a speed limit (ODE's way of torque control): the
          // torque drives the joint up to max_speed, and no faster.
          target = j.command.value >= 0 ? motors.max_speed : -motors.max_speed;
          bound = std::abs(j.command.value);
          break;
      }
      j.effort = 0.0;
      if (j.stop != 0) {
        StopMotor(&j, j.command.mode == JointMode::kVelocity ? j.command.value : target, bound);
        bound = 0.0;
      }
      if (j.row < 0) continue;
      const int i = j.row;
      d->efc_frictionloss[i] = bound;
      d->efc_aref[i] = (target - d->efc_vel[i]) / dt;
      // The row's force is -(J qacc - aref) / R inside the bound: R = 1 / (dt
      // gain) makes it gain (target - qd'); a stiff row uses MuJoCo's largest
      // impedance (mjMAXIMP).
      d->efc_R[i] = gain > 0 ? 1.0 / (dt * gain) : StiffCompliance(d->efc_diagApprox[i]);
      d->efc_D[i] = 1.0 / d->efc_R[i];
    }
  }
  for (const RobotSlot& r : robots_) {
    for (const JointSlot& j : r.joints) {
      if (j.stop_row >= 0) StopRow(j, j.stop_row);
    }
  }
}

// A velocity motor's force bound in this step. With an impulse window (scene
// physics.motor_impulse_window) it is what the bound leaves of the impulse
// since the window began: max_torque x the time elapsed in the window, less
// what the motor spent in its earlier steps. ODE's bound holds for the force of
// one whole 20 ms step, so a landing in the cycle's last physics step meets
// the impulse the lighter steps before it left; saturated from the window's
// start, the motor gets max_torque in every step, as before. Causal: nothing
// is borrowed from later steps (that variant made the motors pulse, and the
// UT agents fell more).
double LeggedWorld::ImpulseBound(JointSlot* j) const {
  if (impulse_steps_ <= 1) return j->effort_limit;
  const int k = static_cast<int>(frame_ % static_cast<uint64_t>(impulse_steps_));
  if (k == 0) j->impulse = 0.0;
  return std::max(0.0, j->effort_limit * (k + 1) - j->impulse / model_->opt.timestep);
}

// PD mode (RCSSServerMJ's and the Booster SDK's motor): an explicit torque
// from this step's angle and velocity, clamped to the joint's effort limit.
// The joint's constraint row keeps what MuJoCo made of it (its reference
// acceleration and impedance from the joint's solref/solimp) with the robot
// file's frictionloss as its bound: the passive friction, nothing else.
void LeggedWorld::ServoPd(JointSlot* j) {
  mjData* d = data_.get();
  const JointCommand& c = j->command;
  const double torque = c.kp * (c.value - d->qpos[j->qpos]) + c.kd * (c.dq - d->qvel[j->dof]) + c.tau;
  j->effort = std::clamp(torque, -j->effort_limit, j->effort_limit);
  d->qfrc_applied[j->dof] = j->effort;
  if (j->row >= 0) d->efc_frictionloss[j->row] = j->frictionloss;
}

// Stage 0 (before mj_step1): rcssserver3d's hinge stops (scene joint_stops).
// At the start of each ODE step every limited joint's stop is tested. An ODE
// step starts with the first physics step after joint commands came in (a
// SimSpark cycle: the bridge applies the agents' commands, then steps 20 ms),
// else `step` after the last one. Until the next test MuJoCo instantiates a
// joint's limit row exactly while its stop holds (the joint's margin: half
// the range, so only the stop's side; else no row at all), and StopRow gives
// the row ODE's target.
void LeggedWorld::StageStops() {
  mjModel* m = model_.get();
  const bool test = commanded_ || steps_since_stop_test_ >= stop_steps_;
  if (test) steps_since_stop_test_ = 0;
  ++steps_since_stop_test_;
  commanded_ = false;
  for (RobotSlot& r : robots_) {
    for (JointSlot& j : r.joints) {
      if (!j.limited) continue;
      if (test) LatchStop(&j);
      m->jnt_margin[j.id] = j.stop != 0 ? 0.5 * (j.hi - j.lo) : kNoLimitRow;
    }
  }
}

// ODE's limit test (dxJointLimitMotor::testRotationalLimit) and its row's
// target (addLimot): -erp depth / step, or the incoming velocity reversed and
// scaled by bounce if that is faster.
void LeggedWorld::LatchStop(JointSlot* j) const {
  const int before = j->stop;
  j->stop = 0;
  if (stop_steps_ == 0 || !j->limited || j->lo >= j->hi) return;
  const OdeJointStops& s = scene_.joint_stops;
  const double q = data_->qpos[j->qpos];
  const double v = data_->qvel[j->dof];
  j->stop = q <= j->lo ? 1 : q >= j->hi ? 2 : 0;
  if (before != 0 || j->stop != 0) j->reference = q;  // the motor starts from here (no creep across a stop)
  if (j->stop == 0) return;
  double target = -s.erp * (q - (j->stop == 1 ? j->lo : j->hi)) / s.step;
  if (j->stop == 1 && v < 0) target = std::max(target, -s.bounce * v);
  if (j->stop == 2 && v > 0) target = std::min(target, -s.bounce * v);
  j->stop_target = target;
}

// A limit row of a joint with ODE stops: a stiff one-sided row towards the
// latched target velocity (lower side: the row's Jacobian is +1, upper: -1).
// The motor's torque into the stop would creep through the row's compliance
// (dt R f per step, 0.04 rad/s for an elbow); the reference acceleration
// makes up for it, as ODE's stop CFM of 1e-8 lets nothing through.
// A row on the other side than the latched stop stays inactive.
void LeggedWorld::StopRow(const JointSlot& j, int i) {
  mjData* d = data_.get();
  const double q = d->qpos[j.qpos];
  const int side = q - j.lo < j.hi - q ? 1 : 2;
  if (side != j.stop) {
    d->efc_aref[i] = kInactiveRow;
    return;
  }
  const double jacobian = side == 1 ? 1.0 : -1.0;
  d->efc_R[i] = d->efc_diagApprox[i] * kStiffCompliance;
  const double load = std::max(0.0, -jacobian * d->qfrc_applied[j.dof]);
  d->efc_aref[i] = (jacobian * j.stop_target - d->efc_vel[i]) / model_->opt.timestep + d->efc_R[i] * load;
  d->efc_D[i] = 1.0 / d->efc_R[i];
}

// ODE's motor during a stop step (addLimot): no velocity row, its full torque
// in the commanded direction (into the stop when the command is 0), or fudge
// times it when the command points away from the stop.
void LeggedWorld::StopMotor(JointSlot* j, double command, double torque) {
  const bool away = (j->stop == 1 && command > 0) || (j->stop == 2 && command < 0);
  const double direction = command > 0 ? 1.0 : command < 0 ? -1.0 : (j->stop == 2 ? 1.0 : -1.0);
  data_->qfrc_applied[j->dof] = direction * torque * (away ? scene_.joint_stops.fudge : 1.0);
  j->reference = data_->qpos[j->qpos];
}

}  // namespace turf
