"""SSL, one robot: go to the ball and kick it into the goal at +x.

Blue robot 0 alone on the field (every other robot parked off it; by default the scene has only id 0 a team,
and physics steps of turf.FAST_SSL (2.5 ms, no wall boxes)). Each reset places the robot and the ball at
random (the environment's np_random, seeded by reset(seed=...)). An environment step is 1/60 s.

Observation: Box(12) float32: robot x, y, cos(yaw), sin(yaw), vx, vy, omega; ball x, y, vx, vy; ball contact.
Action: Box(4) in [-1, 1]: vx, vy (robot frame, times the robot's top speed), omega (times its top turn rate),
kick (> 0: a flat kick at the rules' 6.5 m/s when the ball is at the kicker).
Reward: the robot's approach to the ball plus the ball's approach to the goal (m), +10 for a goal, -1 if the
ball leaves the field. Terminated on a goal or the ball out; truncated after max_episode_steps."""

import numpy as np

from .. import FAST_SSL_STEP
from . import ssl_common as c
from .spaces import Box


class SslGoToBallKickEnv(c.SslEnv):
    def __init__(self, scene="ssl_div_a", realism="ideal", seed=1, max_episode_steps=600, render_mode=None,
                 physics_step=FAST_SSL_STEP, wall_segments=0, robots_per_team=1):
        self._attach_ssl(scene, seed, realism, physics_step, robots_per_team, wall_segments, max_episode_steps,
                         render_mode)
        self.commands = c.Commands(self.sim, [0])
        limit = np.array([c.POSITION_LIMIT] * 2 + [1, 1] + [c.SPEED_LIMIT] * 3 + [c.POSITION_LIMIT] * 2
                         + [c.SPEED_LIMIT] * 2 + [1], dtype=np.float32)
        low = -limit
        low[-1] = 0
        self.observation_space = Box(low, limit, dtype=np.float32)
        self.action_space = Box(-1.0, 1.0, (4,), dtype=np.float32)

    def _take_start(self):
        """Every robot but blue 0 off the field, kept as the snapshot each reset starts from."""
        self.sim.reset()
        for team, id_ in self.sim.robot_ids:
            if (team, id_) != (0, 0):
                self.sim.teleport_robot(int(team), int(id_), on_field=False)
        self.start = self.sim.save()
        self.row = int(c.robot_rows(self.sim, "blue")[0])

    def _obs(self, o):
        r = c.robot_features(o["robots"], [self.row])[0]
        b = c.ball_features(o["ball"])
        contact = np.float32(o["robots"][self.row, 7])
        return np.concatenate([r, b[[0, 1, 3, 4]], [contact]]).astype(np.float32)

    def _distances(self, o):
        ball = o["ball"]
        robot = o["robots"][self.row]
        to_ball = np.hypot(ball[0] - robot[0], ball[1] - robot[1])
        to_goal = np.hypot(ball[0] - self.field.half_length, ball[1])
        return to_ball, to_goal

    def reset(self, *, seed=None, options=None):
        super().reset(seed=seed)
        self._restart(seed)
        f = self.sim.field
        rng = self.np_random
        hx, hy = f["length"] / 2 - 0.5, f["width"] / 2 - 0.5
        rx, ry, bx, by = rng.uniform(-hx, hx), rng.uniform(-hy, hy), rng.uniform(-hx, hx), rng.uniform(-hy, hy)
        while np.hypot(rx - bx, ry - by) < 0.3:
            bx, by = rng.uniform(-hx, hx), rng.uniform(-hy, hy)
        self.sim.teleport_robot("blue", 0, x=rx, y=ry, orientation=rng.uniform(-np.pi, np.pi))
        o = self.sim.teleport_ball(bx, by)
        self.clock.reset()
        self.steps = 0
        self.last = self._distances(o)
        return self._obs(o), {"time": o["time"]}

    def step(self, action):
        a = c.as_action(action, self.action_space.shape)
        rows = self.commands(a[None, :])
        o = self.sim.step({"blue": rows}, self.clock.next())
        self.steps += 1
        now = self._distances(o)
        reward = float((self.last[0] - now[0]) + (self.last[1] - now[1]))
        self.last = now
        goal = self.field.goal(o["ball"])
        out = goal == 0 and self.field.out(o["ball"])
        reward += 10.0 * (goal > 0) - 10.0 * (goal < 0) - 1.0 * out
        terminated = bool(goal != 0 or out)
        truncated = bool(not terminated and self.steps >= self.max_episode_steps)
        return self._obs(o), reward, terminated, truncated, {"time": o["time"], "goal": goal}
