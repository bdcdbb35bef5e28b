// The reference's ball (RCSSServerMJ's, in reference_world.mjs) rolling from 1.2 m/s on MuJoCo 3: its
// deceleration between 0.3 s and 0.8 s, m/s^2, as tests/core/legged/ball_test.cpp measures turf's.
//   node bench/rcssservermj_nn/reference_ball.mjs MUJOCO_JS_DIR ROBOT_DIR
import {loadReference} from './reference_world.mjs';

const [mujocoDir, robotDir] = process.argv.slice(2);
if (!robotDir) {
  console.error('usage: node reference_ball.mjs MUJOCO_JS_DIR ROBOT_DIR');
  process.exit(2);
}
const {mj, m, d} = await loadReference(mujocoDir, robotDir, {withBall: true});
const kObj = mj.mjtObj;
const ballBody = mj.mj_name2id(m, kObj.mjOBJ_BODY.value, 'ball');
const ball = [...Array(m.njnt).keys()].find((j) => m.jnt_bodyid[j] === ballBody);
const [qpos, dof] = [m.jnt_qposadr[ball], m.jnt_dofadr[ball]];
d.qpos[m.jnt_qposadr[mj.mj_name2id(m, kObj.mjOBJ_JOINT.value, 'root')]] = -20;  // the robot out of the way
d.qpos.set([0, 5, 0.11], qpos);
d.qvel[dof] = 1.2;
mj.mj_forward(m, d);
const speedAt = (t) => {
  while (d.time < t - 1e-9) mj.mj_step(m, d);
  return Math.hypot(d.qvel[dof], d.qvel[dof + 1]);
};
const early = speedAt(0.3);
const late = speedAt(0.8);
console.log(`MuJoCo ${mj.mj_versionString()}: the ball at 1.2 m/s slows at ${((early - late) / 0.5).toFixed(3)} m/s^2`);
