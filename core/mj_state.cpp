#include "core/mj_state.h"

#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>

namespace turf {

void MjDeleter::operator()(mjModel_* m) const { mj_deleteModel(m); }
void MjDeleter::operator()(mjData_* d) const { mj_deleteData(d); }

uint64_t ModelFingerprint(const mjModel* m) {
  uint64_t h = 1469598103934665603ull;
  for (int v : {m->nq, m->nv, m->nu, m->na, m->nbody, m->njnt, m->ngeom, m->nsite, m->nsensor, m->nsensordata,
                m->nmocap, m->nuserdata, m->nconmax, m->njmax, m->nbuffer}) {
    h = (h ^ static_cast<uint64_t>(static_cast<uint32_t>(v))) * 1099511628211ull;
  }
  const double step = m->opt.timestep;
  uint64_t bits = 0;
  std::memcpy(&bits, &step, sizeof(bits));
  return (h ^ bits) * 1099511628211ull;
}

namespace {

// A snapshot's time at most: its frame's bound (MaxFrame), 2^62 ns.
constexpr double kMaxTime = static_cast<double>(uint64_t{1} << 62) * 1e-9;

// The first kStateArrays of Arrays() are the integration state, qpos to userdata.
constexpr size_t kStateArrays = 10;

// The arrays of the integration state (what the next step starts from), then
// the last step's results that outputs read between steps (sensors, body and
// site and shape frames). Each is (pointer, length) for a model and its data.
template <class Data>
std::vector<std::pair<decltype(Data::qpos), int>> Arrays(const mjModel* m, Data* d) {
  return {{d->qpos, m->nq},
          {d->qvel, m->nv},
          {d->act, m->na},
          {d->qacc_warmstart, m->nv},
          {d->ctrl, m->nu},
          {d->qfrc_applied, m->nv},
          {d->xfrc_applied, 6 * m->nbody},
          {d->mocap_pos, 3 * m->nmocap},
          {d->mocap_quat, 4 * m->nmocap},
          {d->userdata, m->nuserdata},
          {d->sensordata, m->nsensordata},
          {d->xpos, 3 * m->nbody},
          {d->xquat, 4 * m->nbody},
          {d->xmat, 9 * m->nbody},
          {d->site_xpos, 3 * m->nsite},
          {d->site_xmat, 9 * m->nsite},
          // The shapes' frames: the legged islands regroup robots by them before the next step.
          {d->geom_xpos, 3 * m->ngeom},
          {d->geom_xmat, 9 * m->ngeom}};
}

void SaveContact(const mjContact& c, StateWriter& out) {
  out.Put(c.dist);
  for (double v : c.pos) out.Put(v);
  for (double v : c.frame) out.Put(v);
  out.Put(c.includemargin);
  for (double v : c.friction) out.Put(v);
  for (double v : c.solref) out.Put(v);
  for (double v : c.solimp) out.Put(v);
  out.Put(c.mu);
  for (double v : c.H) out.Put(v);
  for (int v : {c.dim, c.geom1, c.geom2, c.exclude, c.efc_address}) out.Put(v);
}

void RestoreContact(const mjModel* m, StateReader& in, mjContact* c) {
  c->dist = in.Get<double>();
  for (double& v : c->pos) v = in.Get<double>();
  for (double& v : c->frame) v = in.Get<double>();
  c->includemargin = in.Get<double>();
  for (double& v : c->friction) v = in.Get<double>();
  for (double& v : c->solref) v = in.Get<double>();
  for (double& v : c->solimp) v = in.Get<double>();
  c->mu = in.Get<double>();
  for (double& v : c->H) v = in.Get<double>();
  for (int* v : {&c->dim, &c->geom1, &c->geom2, &c->exclude, &c->efc_address}) *v = in.Get<int>();
  const bool ok = c->dim >= 1 && c->dim <= 6 && c->geom1 >= 0 && c->geom1 < m->ngeom && c->geom2 >= 0 &&
                  c->geom2 < m->ngeom && c->efc_address >= -1 && c->efc_address <= m->njmax;
  if (!ok) in.Fail("contact out of range");
}

// Whether a snapshot's numbers are ones MuJoCo can step from: every one finite, and the first `bounded` (the
// integration state) within MuJoCo's own bound for a sane value, mjMAXVAL (its step resets a world past it).
// A snapshot is untrusted input: a changed byte had made a position 1e76, and the next step's Cholesky ended the
// process through MuJoCo's fatal error handler.
bool SaneValues(const std::vector<double>& values, size_t bounded) {
  for (size_t i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i]) || (i < bounded && std::abs(values[i]) > mjMAXVAL)) return false;
  }
  return true;
}

bool SaneContact(const mjContact& c) {
  std::vector<double> v = {c.dist, c.includemargin, c.mu};
  v.insert(v.end(), std::begin(c.pos), std::end(c.pos));
  v.insert(v.end(), std::begin(c.frame), std::end(c.frame));
  v.insert(v.end(), std::begin(c.friction), std::end(c.friction));
  v.insert(v.end(), std::begin(c.solref), std::end(c.solref));
  v.insert(v.end(), std::begin(c.solimp), std::end(c.solimp));
  v.insert(v.end(), std::begin(c.H), std::end(c.H));
  return SaneValues(v, 0);
}

}  // namespace

void SaveMjData(const mjModel* m, const mjData* d, StateWriter& out) {
  out.Tag(StateTag("MJDA"));
  out.Put(ModelFingerprint(m));
  out.Put(d->time);
  for (const mjWarningStat& w : d->warning) {
    out.Put(w.lastinfo);
    out.Put(w.number);
  }
  for (const auto& [array, n] : Arrays(m, d)) out.Bytes(array, n * sizeof(double));
  out.Put(d->ncon);
  for (int i = 0; i < d->ncon; ++i) SaveContact(d->contact[i], out);
  out.Put(d->nefc);
  out.Bytes(d->efc_force, d->nefc * sizeof(double));
}

void RestoreMjData(const mjModel* m, mjData* d, StateReader& in) {
  in.Tag(StateTag("MJDA"));
  if (in.Get<uint64_t>() != ModelFingerprint(m)) in.Fail("snapshot of another model");
  // Everything is read and checked before `d` changes: a bad snapshot leaves it as it was.
  const double time = in.Get<double>();
  mjWarningStat warning[mjNWARNING];
  for (mjWarningStat& w : warning) {
    w.lastinfo = in.Get<int>();
    w.number = in.Get<int>();
  }
  const auto arrays = Arrays(m, d);
  size_t total = 0;
  for (const auto& a : arrays) total += a.second;
  std::vector<double> values(total);
  in.Bytes(values.data(), total * sizeof(double));
  if (!std::isfinite(time) || time < 0 || time > kMaxTime) in.Fail("time out of range");
  size_t state_values = 0;
  for (size_t i = 0; i < kStateArrays; ++i) state_values += arrays[i].second;
  if (in.ok() && !SaneValues(values, state_values)) in.Fail("a state value not finite or past MuJoCo's bound");
  const int ncon = in.Get<int>();
  if (ncon < 0 || ncon > m->nconmax) in.Fail("contact count out of range");
  std::vector<mjContact> contacts(in.ok() ? ncon : 0);
  for (mjContact& c : contacts) {
    RestoreContact(m, in, &c);
    if (in.ok() && !SaneContact(c)) in.Fail("a contact value not finite");
  }
  const int nefc = in.Get<int>();
  if (nefc < 0 || nefc > m->njmax) in.Fail("constraint count out of range");
  for (size_t i = 0; in.ok() && i < contacts.size(); ++i) {
    if (int64_t{contacts[i].efc_address} + contacts[i].dim > nefc)
      in.Fail("contact refers to a missing constraint row");
  }
  std::vector<double> efc_force(in.ok() ? nefc : 0);
  in.Bytes(efc_force.data(), efc_force.size() * sizeof(double));
  if (in.ok() && !SaneValues(efc_force, 0)) in.Fail("a constraint force not finite");
  if (!in.ok()) return;

  d->time = time;
  std::copy(std::begin(warning), std::end(warning), d->warning);
  const double* v = values.data();
  for (const auto& [array, n] : arrays) {
    std::copy(v, v + n, array);
    v += n;
  }
  d->ncon = ncon;
  std::copy(contacts.begin(), contacts.end(), d->contact);
  d->nefc = nefc;
  std::copy(efc_force.begin(), efc_force.end(), d->efc_force);
  d->pstack = 0;  // no step is under way between steps; one MuJoCo's error ended leaves its stack marked
}

void LastGoodState::Accept(const mjModel* m, const mjData* d) {
  qpos_.assign(d->qpos, d->qpos + m->nq);
  qvel_.assign(d->qvel, d->qvel + m->nv);
}

void LastGoodState::Undo(const mjModel* m, mjData* d) const {
  std::copy(qpos_.begin(), qpos_.end(), d->qpos);
  std::fill(d->qvel, d->qvel + m->nv, 0.0);
  mj_forward(m, d);
}

void LastGoodState::Save(StateWriter& out) const {
  out.Doubles(qpos_);
  out.Doubles(qvel_);
}

void LastGoodState::Restore(StateReader& in) {
  constexpr size_t kMax = 1 << 20;
  std::vector<double> qpos;
  std::vector<double> qvel;
  qpos.resize(in.Count(kMax));
  in.Bytes(qpos.data(), qpos.size() * sizeof(double));
  qvel.resize(in.Count(kMax));
  in.Bytes(qvel.data(), qvel.size() * sizeof(double));
  if (in.ok() && (qpos.size() != qpos_.size() || qvel.size() != qvel_.size())) in.Fail("wrong state size");
  if (in.ok() && !(SaneValues(qpos, qpos.size()) && SaneValues(qvel, qvel.size())))
    in.Fail("a last good state value not finite or past MuJoCo's bound");
  if (!in.ok()) return;
  qpos_ = std::move(qpos);
  qvel_ = std::move(qvel);
}

bool StateFinite(const mjModel* m, const mjData* d, double max_speed) {
  for (int i = 0; i < m->nv; ++i) {
    if (!std::isfinite(d->qvel[i]) || std::abs(d->qvel[i]) >= max_speed) return false;
  }
  for (int i = 0; i < m->nq; ++i) {
    if (!std::isfinite(d->qpos[i])) return false;
  }
  return true;
}

}  // namespace turf
