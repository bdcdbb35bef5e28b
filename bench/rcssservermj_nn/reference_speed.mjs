// The reference engine's speed on this machine: N copies of RCSSServerMJ's own robot file (reference_world.mjs) in a
// row 2 m apart, each holding a turf standing scene's pose with its PD gains (configs/scenes/t1_stand.yaml), stepped
// on MuJoCo 3 with constraint islands (MuJoCo's default since 3.3.6, so RCSSServerMJ's 3.4.0) and without. Prints
// one table row per robot count and island setting; turf-bench-engine prints turf's rows for the same world.
//   node bench/rcssservermj_nn/reference_speed.mjs MUJOCO_JS_DIR ROBOT_DIR SCENE_YAML [COUNTS] [STEPS]
// COUNTS: comma-separated robot counts (default 1,2,11,22); STEPS: measured steps per row (default 1000).
import fs from 'fs';

import {loadMujocoWithRobot, setGains, standScene} from './reference_world.mjs';

const [mujocoDir, robotDir, scene, countsArg = '1,2,11,22', stepsArg = '1000'] = process.argv.slice(2);
if (!scene) {
  console.error('usage: node reference_speed.mjs MUJOCO_JS_DIR ROBOT_DIR SCENE_YAML [COUNTS] [STEPS]');
  process.exit(2);
}
const kWarmup = 200;  // the robots settle on their feet
const kSpacing = 2.0;

const {startZ, pose} = standScene(scene);

// The robot file's sections, once (defaults, assets) or per copy (bodies, actuators, sensors, exclusions) with
// every name and name reference prefixed.
const robotXml = fs.readFileSync(robotDir + '/robot.xml', 'utf8');
const section = (tag) => {
  const m = robotXml.match(new RegExp(`<${tag}>([\\s\\S]*?)\\n  </${tag}>`));
  return m ? m[1] : '';
};
const defaults = robotXml.match(/\n  <default>[\s\S]*?\n  <\/default>/)[0];
const compiler = robotXml.match(/<compiler[^>]*>/)[0];
const prefixed = (text, p) =>
  text.replace(/\b(name|joint|body1|body2|site|objname)="([^"]+)"/g, (_, attr, v) => `${attr}="${p}${v}"`);
const placed = (bodies, x) => bodies.replace(/<body([^>]*?)\bpos="[^"]*"/, `<body$1pos="${x} 0 ${startZ}"`);

function worldXml(n) {
  const copies = (tag, f) => `<${tag}>${[...Array(n).keys()].map((i) => f(section(tag), i)).join('')}</${tag}>`;
  const x = (i) => (i - (n - 1) / 2) * kSpacing;
  return `<mujoco model="reference-${n}">
  ${compiler}
  <option timestep="0.005" density="1.2" viscosity="0.00002"/>
  ${defaults}
  <asset>${section('asset')}</asset>
  <worldbody><geom name="pitch" type="plane" size="60 40 40"/>
  ${[...Array(n).keys()].map((i) => placed(prefixed(section('worldbody'), `r${i}_`), x(i))).join('')}</worldbody>
  ${copies('actuator', (s, i) => prefixed(s, `r${i}_`))}
  ${copies('sensor', (s, i) => prefixed(s, `r${i}_`))}
  ${copies('contact', (s, i) => prefixed(s, `r${i}_`))}
</mujoco>`;
}

const mj = await loadMujocoWithRobot(mujocoDir, robotDir);
const kObj = mj.mjtObj;

// Every copy holds the pose: start angles, targets and gains through the file's _pos and _vel actuators.
function holdPose(m, d, n) {
  const actuatorOf = (joint, suffix) => [...Array(m.nu).keys()].find((a) =>
    m.actuator_trnid[2 * a] === joint && mj.mj_id2name(m, kObj.mjOBJ_ACTUATOR.value, a).endsWith(suffix));
  for (let i = 0; i < n; ++i) {
    for (const p of pose) {
      const joint = mj.mj_name2id(m, kObj.mjOBJ_JOINT.value, `r${i}_${p.name}`);
      if (joint < 0) throw new Error(`the robot file has no joint ${p.name}`);
      d.qpos[m.jnt_qposadr[joint]] = p.q;
      const pos = actuatorOf(joint, '_pos');
      d.ctrl[pos] = p.q;
      setGains(m, pos, actuatorOf(joint, '_vel'), p.kp, p.kd);
    }
  }
}

function row(n, islands, print = true) {
  mj.FS.writeFile('/r/speed.xml', worldXml(n));
  const m = mj.MjModel.mj_loadXML('/r/speed.xml');
  const d = new mj.MjData(m);
  if (!islands) m.opt.disableflags |= mj.mjtDisableBit.mjDSBL_ISLAND.value;
  holdPose(m, d, n);
  for (let i = 0; i < kWarmup; ++i) mj.mj_step(m, d);
  const steps = Number(stepsArg);
  let iterations = 0;
  let rows = 0;
  const start = process.hrtime.bigint();
  for (let i = 0; i < steps; ++i) {
    mj.mj_step(m, d);
    const solved = Math.max(1, Math.min(d.nisland, d.solver_niter.length));  // each island's solver runs on its own
    for (let k = 0; k < solved; ++k) iterations += d.solver_niter[k] / solved;
    rows += d.nefc;
  }
  const us = Number(process.hrtime.bigint() - start) / 1e3 / steps;
  d.delete();
  m.delete();
  if (!print) return;
  const engine = `MuJoCo ${mj.mj_versionString()} (WebAssembly), islands ${islands ? 'on' : 'off'}`;
  console.log(`| ${engine.padEnd(43)} | ${String(n).padStart(6)} | ${us.toFixed(1).padStart(8)} | ${
    (us / n).toFixed(1).padStart(8)} | ${(5000 / us).toFixed(1).padStart(5)}x | ${
    (iterations / steps).toFixed(2).padStart(10)} | ${(rows / steps).toFixed(0).padStart(5)} |`);
}

row(1, true, false);  // the WebAssembly engine warms up (compiles its hot paths): not a row
for (const n of countsArg.split(',').map(Number)) {
  for (const islands of [true, false]) row(n, islands);
}
