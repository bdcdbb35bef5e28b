#include "core/legged/root_accelerometers.h"

namespace turf {

namespace {

// MuJoCo's mju_mulDofVec (not exported): res = dofs' spatial vectors (n x 6) times vec.
void MulDofVec(mjtNum* res, const mjtNum* dof, const mjtNum* vec, int n) {
  if (n == 1) {
    mju_scl(res, dof, vec[0], 6);
  } else if (n <= 0) {
    mju_zero(res, 6);
  } else {
    mju_mulMatTVec(res, dof, vec, n, 6);
  }
}

}  // namespace

std::vector<RootAccelerometer> TakeRootAccelerometers(mjModel* m) {
  std::vector<RootAccelerometer> sensors;
  if (m->opt.integrator == mjINT_IMPLICIT || (m->opt.enableflags & mjENBL_FWDINV)) return sensors;
  for (int i = 0; i < m->nsensor; ++i) {
    if (m->sensor_type[i] != mjSENS_ACCELEROMETER || m->sensor_objtype[i] != mjOBJ_SITE || m->sensor_cutoff[i] > 0)
      continue;
    const int site = m->sensor_objid[i];
    const int body = m->site_bodyid[site];
    if (body <= 0 || m->body_parentid[body] != 0) continue;
    m->sensor_needstage[i] = mjSTAGE_NONE;  // no stage of MuJoCo's sensors computes it
    sensors.push_back({site, body, m->sensor_adr[i]});
  }
  return sensors;
}

void SenseRootAccelerometers(const mjModel* m, mjData* d, const std::vector<RootAccelerometer>& sensors) {
  if (sensors.empty() || (m->opt.disableflags & mjDSBL_SENSOR)) return;
  // mj_rnePostConstraint's world: no acceleration but gravity's opposite.
  mjtNum world[6] = {0, 0, 0, 0, 0, 0};
  if (!(m->opt.disableflags & mjDSBL_GRAVITY)) mju_scl3(world + 3, m->opt.gravity, -1);
  for (const RootAccelerometer& s : sensors) {
    const int dof = m->body_dofadr[s.body];
    const int n = m->body_dofnum[s.body];
    mjtNum* cacc = d->cacc + 6 * s.body;
    mjtNum tmp[6];
    MulDofVec(tmp, d->cdof_dot + 6 * dof, d->qvel + dof, n);
    mju_add(cacc, world, tmp, 6);
    MulDofVec(tmp, d->cdof + 6 * dof, d->qacc + dof, n);
    mju_addTo(cacc, tmp, 6);
    mjtNum acc[6];
    mj_objectAcceleration(m, d, mjOBJ_SITE, s.site, acc, 1);
    mju_copy3(d->sensordata + s.adr, acc + 3);
  }
}

void Step2(const mjModel* m, mjData* d, const std::vector<RootAccelerometer>& sensors) {
  if (sensors.empty()) {
    mj_step2(m, d);
    return;
  }
  // MuJoCo 2.2.2's mj_step2 (src/engine/engine_forward.c), less its timers.
  mj_fwdActuation(m, d);
  mj_fwdAcceleration(m, d);
  mj_fwdConstraint(m, d);
  mj_sensorAcc(m, d);
  SenseRootAccelerometers(m, d, sensors);
  mj_checkAcc(m, d);
  mj_Euler(m, d);
}

}  // namespace turf
