"""SSL 2 x 11: a whole division A match with an action per team.

Starts from the scene's kick-off formation (the robots on the field at the scene's start, 11 a team in
ssl_div_a). By default the scene has ids 0..10 a team (no parked substitutes) and physics steps of
turf.FAST_SSL (2.5 ms, no wall boxes). An environment step is 1/60 s.

Observation: Dict(ball: Box(6) x, y, z, vx, vy, vz; blue, yellow: Box(n, 7) per robot by id: x, y, cos(yaw),
sin(yaw), vx, vy, omega). Action: Dict(blue, yellow: Box(n, 4) in [-1, 1], as SslGoToBallKick's per robot).
Reward: blue's: +1 when blue scores, -1 when yellow does (info["rewards"] has both teams'). Terminated on a
goal; truncated after max_episode_steps (default 60 s of play)."""

import numpy as np

from .. import FAST_SSL_STEP
from . import ssl_common as c
from .spaces import Box, Dict

TEAMS = ("blue", "yellow")


class SslMatchEnv(c.SslEnv):
    def __init__(self, scene="ssl_div_a", realism="realistic", seed=1, max_episode_steps=3600, render_mode=None,
                 physics_step=FAST_SSL_STEP, wall_segments=0, robots_per_team=11):
        self._attach_ssl(scene, seed, realism, physics_step, robots_per_team, wall_segments, max_episode_steps,
                         render_mode)
        self.rows = {t: c.robot_rows(self.sim, t) for t in TEAMS}
        self.ids = {t: self.sim.robot_ids[self.rows[t], 1] for t in TEAMS}
        self.commands = {t: c.Commands(self.sim, self.ids[t]) for t in TEAMS}
        ball_high = np.full(6, c.SPEED_LIMIT, dtype=np.float32)
        spaces = {"ball": Box(-ball_high, ball_high, dtype=np.float32)}
        for t in TEAMS:
            low, high = c.robot_bounds(len(self.rows[t]))
            spaces[t] = Box(low, high, dtype=np.float32)
        self.observation_space = Dict(spaces)
        self.action_space = Dict({t: Box(-1.0, 1.0, (len(self.rows[t]), 4), dtype=np.float32) for t in TEAMS})

    def _obs(self, o):
        out = {"ball": c.ball_features(o["ball"])}
        for t in TEAMS:
            out[t] = c.robot_features(o["robots"], self.rows[t])
        return out

    def reset(self, *, seed=None, options=None):
        super().reset(seed=seed)
        o = self._restart(seed)
        self.clock.reset()
        self.steps = 0
        return self._obs(o), {"time": o["time"]}

    def step(self, action):
        if not isinstance(action, dict) or set(action) != set(TEAMS):
            raise c.TurfError("malformed", "action: a dict with 'blue' and 'yellow'")
        commands = {}
        for t in TEAMS:
            a = c.as_action(action[t], self.action_space[t].shape, f"action['{t}']")
            commands[t] = self.commands[t](a)
        o = self.sim.step(commands, self.clock.next())
        self.steps += 1
        goal = self.field.goal(o["ball"])
        terminated = goal != 0
        truncated = bool(not terminated and self.steps >= self.max_episode_steps)
        info = {"time": o["time"], "goal": goal, "rewards": {"blue": float(goal), "yellow": float(-goal)}}
        return self._obs(o), float(goal), bool(terminated), truncated, info
