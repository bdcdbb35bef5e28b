// MuJoCo 3 (the @mujoco/mujoco WebAssembly package from npm, kept outside turf) with one of RCSSServerMJ's own robot
// files (its src/rcsssmj/resources/robots/<robot>: robot.xml and meshes/, kept outside turf) in RCSSServerMJ's world
// as the facts give it (shared/protocols/rcssservermj.md): 5 ms step, air density 1.2 and viscosity 2e-5, the
// ground plane, and (withBall) the reference's ball. The reference the bench's reference_*.mjs measure turf against.
import fs from 'fs';

// MuJoCo 3 from the package directory, with the robot directory's robot.xml and meshes/ under /r in its file system.
export async function loadMujocoWithRobot(mujocoDir, robotDir) {
  const mj = await (await import(mujocoDir + '/mujoco.js')).default();
  mj.FS.mkdir('/r');
  mj.FS.mkdir('/r/meshes');
  for (const f of fs.readdirSync(robotDir + '/meshes')) {
    mj.FS.writeFile('/r/meshes/' + f, fs.readFileSync(robotDir + '/meshes/' + f));
  }
  mj.FS.writeFile('/r/robot.xml', fs.readFileSync(robotDir + '/robot.xml'));
  return mj;
}

export async function loadReference(mujocoDir, robotDir, {withBall = false} = {}) {
  const mj = await loadMujocoWithRobot(mujocoDir, robotDir);
  const ball = `<body name="ball" pos="0 0 0.11">
      <freejoint/>
      <geom type="sphere" size="0.11" mass="0.41" friction="0.4 0.01 0.01" condim="6" priority="1" solref="-5000 -20"/>
    </body>`;
  mj.FS.writeFile('/r/world.xml', `<mujoco model="reference">
  <option timestep="0.005" density="1.2" viscosity="0.00002"/>
  <worldbody>
    <geom name="pitch" type="plane" size="32 24 40"/>
    ${withBall ? ball : ''}
  </worldbody>
  <include file="robot.xml"/>
</mujoco>`);
  const m = mj.MjModel.mj_loadXML('/r/world.xml');
  return {mj, m, d: new mj.MjData(m)};
}

// Sets a joint's PD law the way RCSSServerMJ does, through the file's <effector>_pos and _vel actuators.
export function setGains(m, pos, vel, kp, kd) {
  m.actuator_gainprm[pos * 10] = kp;
  m.actuator_biasprm[pos * 10 + 1] = -kp;
  m.actuator_gainprm[vel * 10] = kd;
  m.actuator_biasprm[vel * 10 + 2] = -kd;
}

// A turf standing scene's start height and pose with PD gains (configs/scenes/t1_stand.yaml, k1_stand.yaml): the
// first `z:` and every `{name: J, q: Q, kp: KP, kd: KD}` joint line.
export function standScene(sceneFile) {
  const yaml = fs.readFileSync(sceneFile, 'utf8');
  const number = '\\s*([-0-9.]+)';
  const pattern = new RegExp(`\\{name:\\s*(\\w+),\\s*q:${number},\\s*kp:${number},\\s*kd:${number}\\}`, 'g');
  return {
    startZ: Number(yaml.match(/\bz:\s*([-0-9.]+)/)[1]),
    pose: [...yaml.matchAll(pattern)].map((x) => ({name: x[1], q: +x[2], kp: +x[3], kd: +x[4]})),
  };
}
