// Accelerometers in a body whose parent is the world (every legged robot's IMU, in its floating base), read
// without MuJoCo's whole-model pass. MuJoCo 2.2.2 computes an accelerometer from mj_rnePostConstraint, which in
// each step takes every body's acceleration and internal force and every contact's force (about 5 % of a 22-T1
// step); such a body's acceleration needs only its own dofs: the world's (gravity) plus cdof_dot qvel plus cdof qacc.
// The same operations in the same order as MuJoCo's, so the readings are the same bits.
//
// TakeRootAccelerometers takes those sensors out of MuJoCo's stages (their type, place and name stay; any other
// sensor that needs the pass, as a force sensor, still has it) and returns them; after each mj_forward
// SenseRootAccelerometers fills them in, and Step2 is mj_step2 with them filled in where MuJoCo would (after the
// acceleration-stage sensors, before integrating).
#pragma once

#include <mujoco/mujoco.h>

#include <vector>

namespace turf {

struct RootAccelerometer {
  int site = -1;
  int body = -1;
  int adr = -1;  // into sensordata
};

// Only where the result is MuJoCo's own: a site accelerometer without cutoff, in a body whose parent is the world,
// with Euler or RK4 (mj_step2 then integrates with mj_Euler) and without the forward/inverse comparison.
std::vector<RootAccelerometer> TakeRootAccelerometers(mjModel* m);

// The readings from the acceleration stage (cdof, cdof_dot, cvel, qacc of the same state): after mj_forward or
// mj_fwdConstraint.
void SenseRootAccelerometers(const mjModel* m, mjData* d, const std::vector<RootAccelerometer>& sensors);

// mj_step2 with the readings.
void Step2(const mjModel* m, mjData* d, const std::vector<RootAccelerometer>& sensors);

}  // namespace turf
