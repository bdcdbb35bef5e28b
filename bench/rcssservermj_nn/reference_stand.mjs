// A turf standing scene's start pose and PD gains (configs/scenes/t1_stand.yaml or k1_stand.yaml) on MuJoCo 3 with
// RCSSServerMJ's own robot file (reference_world.mjs): where the robot settles after 1 s, its range from 1 to 60 s
// and its stance joints' deflection at 60 s. The values tests/core/legged/booster_physics_test.cpp holds turf to.
//   node bench/rcssservermj_nn/reference_stand.mjs MUJOCO_JS_DIR ROBOT_DIR SCENE_YAML

import {loadReference, setGains, standScene} from './reference_world.mjs';

const [mujocoDir, robotDir, scene] = process.argv.slice(2);
if (!scene) {
  console.error('usage: node reference_stand.mjs MUJOCO_JS_DIR ROBOT_DIR SCENE_YAML');
  process.exit(2);
}
const {mj, m, d} = await loadReference(mujocoDir, robotDir);
const {startZ, pose} = standScene(scene);
const kObj = mj.mjtObj;
const qposOf = (name) => {
  const j = mj.mj_name2id(m, kObj.mjOBJ_JOINT.value, name);
  if (j < 0) throw new Error(`the robot file has no joint ${name}`);
  return {joint: j, adr: m.jnt_qposadr[j]};
};
const root = qposOf('root').adr;
d.qpos[root + 2] = startZ;
for (const p of pose) {
  const {joint, adr} = qposOf(p.name);
  d.qpos[adr] = p.q;
  const actuator = (suffix) => [...Array(m.nu).keys()].find((a) =>
    m.actuator_trnid[2 * a] === joint && mj.mj_id2name(m, kObj.mjOBJ_ACTUATOR.value, a).endsWith(suffix));
  const pos = actuator('_pos');
  d.ctrl[pos] = p.q;
  setGains(m, pos, actuator('_vel'), p.kp, p.kd);
}
let settled = 0;
let low = Infinity;
let high = -Infinity;
for (let i = 1; i <= 12000; ++i) {
  mj.mj_step(m, d);
  const z = d.qpos[root + 2];
  if (i === 200) settled = z;
  if (i >= 200) [low, high] = [Math.min(low, z), Math.max(high, z)];
}
const deflection = pose.filter((p) => /^Left_(Hip_Pitch|Knee_Pitch|Ankle_Pitch)$/.test(p.name))
    .map((p) => `${p.name} ${(d.qpos[qposOf(p.name).adr] - p.q).toFixed(5)}`).join(', ');
console.log(`MuJoCo ${mj.mj_versionString()}, ${robotDir}: settled z ${settled.toFixed(5)} m, 1..60 s in ` +
    `[${low.toFixed(5)}, ${high.toFixed(5)}]; at 60 s rad from the pose: ${deflection}`);
