// Compiles one of RCSSServerMJ's robot files and turf's file for the same robot in MuJoCo 3 and prints every
// difference above 1e-6 in the bodies (pose, mass, centre of mass, inertia), joints (axis, range, limits, effort
// limit: the reference's actuatorfrcrange, turf's first `user` value), degrees of freedom (armature, damping,
// friction loss) and collision geoms (shape, pose, contact parameters; named body#k, the body's k-th collision geom,
// as the reference's are mostly unnamed); visual-only geoms of the reference (no contype, no conaffinity) are skipped.
//   node bench/rcssservermj_nn/reference_model_diff.mjs MUJOCO_JS_DIR ROBOT_DIR configs/robots/t1.xml
import fs from 'fs';

import {loadMujocoWithRobot} from './reference_world.mjs';

const [mujocoDir, robotDir, turfFile] = process.argv.slice(2);
if (!turfFile) {
  console.error('usage: node reference_model_diff.mjs MUJOCO_JS_DIR ROBOT_DIR TURF_ROBOT_FILE');
  process.exit(2);
}
const mj = await loadMujocoWithRobot(mujocoDir, robotDir);
mj.FS.writeFile('/r/turf.xml', fs.readFileSync(turfFile));
const ref = mj.MjModel.mj_loadXML('/r/robot.xml');
const turf = mj.MjModel.mj_loadXML('/r/turf.xml');
const kObj = mj.mjtObj;
let differences = 0;

function byName(m, type, count) {
  const map = new Map();
  for (let i = 0; i < count; ++i) {
    const name = mj.mj_id2name(m, type.value, i);
    if (name) map.set(name, i);
  }
  return map;
}

// Collision geoms as body#k.
function collisionGeoms(m) {
  const map = new Map();
  const seen = new Map();
  for (let i = 0; i < m.ngeom; ++i) {
    if (!m.geom_contype[i] && !m.geom_conaffinity[i]) continue;
    const body = mj.mj_id2name(m, kObj.mjOBJ_BODY.value, m.geom_bodyid[i]);
    const k = seen.get(body) ?? 0;
    seen.set(body, k + 1);
    map.set(`${body}#${k}`, i);
  }
  return map;
}

function compare(kind, index, fields) {
  const a = index(ref);
  const b = index(turf);
  for (const [name, i] of a) {
    if (!b.has(name)) {
      console.log(`${kind} ${name}: only in the reference`);
      ++differences;
      continue;
    }
    const j = b.get(name);
    for (const [field, width] of fields) {
      const va = Array.from(ref[field].slice(i * width, (i + 1) * width));
      const vb = Array.from(turf[field].slice(j * width, (j + 1) * width));
      if (va.every((v, k) => Math.abs(v - vb[k]) <= 1e-6)) continue;
      const show = (v) => v.map((x) => +x.toPrecision(6)).join(' ');
      console.log(`${kind} ${name} ${field}: reference ${show(va)}, turf ${show(vb)}`);
      ++differences;
    }
  }
  for (const [name] of b) {
    if (!a.has(name)) {
      console.log(`${kind} ${name}: only in turf`);
      ++differences;
    }
  }
}

const named = (type, count) => (m) => byName(m, type, m[count]);
compare('body', named(kObj.mjOBJ_BODY, 'nbody'), [['body_parentid', 1], ['body_pos', 3], ['body_quat', 4],
  ['body_mass', 1], ['body_ipos', 3], ['body_iquat', 4], ['body_inertia', 3]]);
compare('joint', named(kObj.mjOBJ_JOINT, 'njnt'), [['jnt_type', 1], ['jnt_pos', 3], ['jnt_axis', 3],
  ['jnt_range', 2], ['jnt_solref', 2], ['jnt_solimp', 5], ['jnt_margin', 1]]);
for (const [name, i] of byName(ref, kObj.mjOBJ_JOINT, ref.njnt)) {
  const j = mj.mj_name2id(turf, kObj.mjOBJ_JOINT.value, name);
  if (j < 0 || ref.jnt_type[i] === 0) continue;  // the free joint has no motor
  const limit = turf.nuser_jnt > 0 ? turf.jnt_user[j * turf.nuser_jnt] : 0;
  if (Math.abs(ref.jnt_actfrcrange[2 * i + 1] - limit) > 1e-6) {
    console.log(`joint ${name} effort limit: reference ${ref.jnt_actfrcrange[2 * i + 1]}, turf ${limit}`);
    ++differences;
  }
}
compare('geom', collisionGeoms, [['geom_type', 1], ['geom_size', 3], ['geom_pos', 3], ['geom_quat', 4],
  ['geom_contype', 1], ['geom_conaffinity', 1], ['geom_condim', 1], ['geom_priority', 1], ['geom_friction', 3],
  ['geom_solref', 2], ['geom_solimp', 5], ['geom_solmix', 1], ['geom_margin', 1], ['geom_gap', 1]]);
for (const field of ['dof_armature', 'dof_damping', 'dof_frictionloss']) {
  const va = Array.from(ref[field]);
  const vb = Array.from(turf[field]);
  if (va.length !== vb.length || va.some((v, k) => Math.abs(v - vb[k]) > 1e-6)) {
    console.log(`${field}: reference ${va.join(' ')}, turf ${vb.join(' ')}`);
    ++differences;
  }
}
if (ref.nexclude !== turf.nexclude) {
  console.log(`contact excludes: reference ${ref.nexclude}, turf ${turf.nexclude}`);
  ++differences;
}
console.log(`MuJoCo ${mj.mj_versionString()}: ${differences} differences`);
