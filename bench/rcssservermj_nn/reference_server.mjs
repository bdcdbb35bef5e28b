// The reference for bench/rcssservermj_nn/run.sh --reference-mujoco DIR --reference-robot DIR: one RCSSServerMJ agent's
// T1 on MuJoCo 3 (the @mujoco/mujoco WebAssembly package from npm, kept outside turf, like the client) with
// RCSSServerMJ's own robot file, served the way RCSSServerMJ serves it in sync mode, so that the same unchanged
// client walks on both and the differences are the model's and the engine's, not the protocol's. Written from the
// facts in shared/protocols/rcssservermj.md, only as far as this client needs:
//   - cycle: 4 steps of 5 ms; the parallel loop (the perception of the state before a cycle's steps is sent after
//     the actions are collected, so an answer acts one cycle after the state it saw);
//   - activation: the first message (init) places the robot where RCSSServerMJ spawns it (x -(2n+1), y 37 (half
//     the FIFA field's width and its border), the file's torso height, yaw -90 deg, joints 0), sends the first
//     perception, and the world steps without an action;
//   - beam: x -> -|x| (left team), z 0.6745, yaw theta, joints and velocities zeroed;
//   - motors: (<effector> q dq kp kd tau), degrees, through the file's <effector>_pos/_vel/_tau actuators;
//   - perceptions: time, GS, quat, pos, GYR, ACC, then every HJ, numbers truncated toward zero.
// Not a server: no referee, no vision, one agent, no checks beyond what keeps this process alive. The world:
// reference_world.mjs.
//   node reference_server.mjs PORT MUJOCO_JS_DIR ROBOT_DIR   (ROBOT_DIR: robot.xml and meshes/)
import net from 'net';

import {loadReference, setGains} from './reference_world.mjs';

const [port, mujocoDir, robotDir] = [Number(process.argv[2]), process.argv[3], process.argv[4]];
if (!port || !mujocoDir || !robotDir) {
  console.error('usage: node reference_server.mjs PORT MUJOCO_JS_DIR ROBOT_DIR');
  process.exit(2);
}
const {mj, m, d} = await loadReference(mujocoDir, robotDir, {withBall: true});
const DEG = 180 / Math.PI;
const kObj = mj.mjtObj;
const id = (type, name) => {
  const i = mj.mj_name2id(m, type.value, name);
  if (i < 0) throw new Error(`the robot file has no ${name}`);
  return i;
};
const rootQpos = m.jnt_qposadr[id(kObj.mjOBJ_JOINT, 'root')];
const rootDof = m.jnt_dofadr[id(kObj.mjOBJ_JOINT, 'root')];
const sensor = (name) => m.sensor_adr[id(kObj.mjOBJ_SENSOR, name)];
const kSides = ['l', 'r'];
const kHj = ['hj1', 'hj2', ...kSides.flatMap((s) => [1, 2, 3, 4].map((k) => `${s}aj${k}`)), 'tj1',
  ...kSides.flatMap((s) => [1, 2, 3, 4, 5, 6].map((k) => `${s}lj${k}`))];
const joints = kHj.map((hj) => ({name: `q_${hj}`, q: sensor(`q_${hj}`), dq: sensor(`dq_${hj}`)}));
const motors = new Map();
for (const e of ['he1', 'he2', ...kSides.flatMap((s) => [1, 2, 3, 4].map((k) => `${s}ae${k}`)), 'te1',
  ...kSides.flatMap((s) => [1, 2, 3, 4, 5, 6].map((k) => `${s}le${k}`))]) {
  motors.set(e, ['pos', 'vel', 'tau'].map((kind) => id(kObj.mjOBJ_ACTUATOR, `${e}_${kind}`)));
}
const torso = ['torso_quat', 'torso_pos', 'torso_gyro', 'torso_acc'].map(sensor);

const kFileTorsoHeight = m.body_pos[3 * m.jnt_bodyid[id(kObj.mjOBJ_JOINT, 'root')] + 2];

function place(x, y, yaw, z = 0.6745) {
  const q = d.qpos;
  q.set([x, y, z, Math.cos(yaw / 2), 0, 0, Math.sin(yaw / 2)], rootQpos);
  for (let i = rootQpos + 7; i < m.nq; ++i) q[i] = 0;
  for (let i = rootDof; i < m.nv; ++i) d.qvel[i] = 0;
}

const trunc = (v, n) => (Math.trunc(v * 10 ** n) / 10 ** n).toFixed(n);
const list = (adr, count, n, scale = 1) =>
  Array.from({length: count}, (_, i) => trunc(d.sensordata[adr + i] * scale, n)).join(' ');

function perception() {
  const [quat, pos, gyro, acc] = torso;
  let s = `(time (now ${trunc(d.time, 2)}))(GS (t 0.00)(pm BeforeKickOff)(tl reference)(sl 0)(sr 0))`;
  s += `(quat (n torso_quat) (q ${list(quat, 4, 3)}))(pos (n torso_pos) (p ${list(pos, 3, 3)}))`;
  s += `(GYR (n torso_gyro) (rt ${list(gyro, 3, 2, DEG)}))(ACC (n torso_acc) (a ${list(acc, 3, 2)}))`;
  for (const j of joints) {
    s += `(HJ (n ${j.name})(ax ${trunc(d.sensordata[j.q] * DEG, 2)})(vx ${trunc(d.sensordata[j.dq] * DEG, 2)}))`;
  }
  return s;
}

function act(message) {
  for (const [, body] of message.matchAll(/\(([^()]*)\)/g)) {
    const t = body.trim().split(/\s+/);
    const v = t.slice(1).map(Number);
    if (!v.every(Number.isFinite)) continue;
    if (t[0] === 'beam' && v.length === 3) place(-Math.abs(v[0]), v[1], v[2] / DEG);
    const actuators = motors.get(t[0]);
    if (!actuators || v.length !== 5) continue;
    const [pos, vel, tau] = actuators;
    const [q, dq, kp, kd, torque] = v;
    d.ctrl[pos] = q / DEG;
    d.ctrl[vel] = dq / DEG;
    d.ctrl[tau] = torque;
    setGains(m, pos, vel, kp, kd);
  }
}

function spawn(init) {
  const player = Number(/\(init\s+\S+\s+\S+\s+(\d+)\)/.exec(init)?.[1] ?? 1);
  place(-(2 * player + 1), 37, -Math.PI / 2, kFileTorsoHeight);
  mj.mj_forward(m, d);
}

console.error(`reference: MuJoCo ${mj.mj_versionString()}, ${m.nu} actuators; listening on 127.0.0.1:${port}`);

net.createServer((socket) => {
  socket.setNoDelay(true);
  let pending = Buffer.alloc(0);
  let started = false;
  const send = (text) => {
    const body = Buffer.from(text);
    const head = Buffer.alloc(4);
    head.writeUInt32BE(body.length);
    socket.write(Buffer.concat([head, body]));
  };
  const cycle = (answer) => {  // one cycle of the parallel loop
    const seen = perception();
    if (answer !== null) act(answer);
    send(seen);
    for (let i = 0; i < 4; ++i) mj.mj_step(m, d);
  };
  socket.on('data', (chunk) => {
    pending = Buffer.concat([pending, chunk]);
    while (pending.length >= 4) {
      const n = pending.readUInt32BE(0);
      if (n > 1 << 20) return socket.destroy();
      if (pending.length < 4 + n) break;
      const message = pending.subarray(4, 4 + n).toString();
      pending = pending.subarray(4 + n);
      if (!started) spawn(message);
      cycle(started ? message : null);  // the first message is the init
      started = true;
    }
  });
  const end = () => started && process.exit(0);  // a port probe's connection does not end the run
  socket.on('close', end);
  socket.on('error', end);
}).listen(port, '127.0.0.1');
