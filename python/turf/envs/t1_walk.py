"""Booster T1: stand, or walk to a point.

One T1 on flat ground (configs/scenes/t1_stand.yaml, 5 ms physics steps); an environment step is 20 ms (4
physics steps), the rate of MuJoCo Playground's T1 tasks. Every joint is in the PD motor mode with the scene's
gains; the action moves each joint's target around the scene's start pose.

task="stand": the target is where the robot starts. task="walk": each reset picks a target 1-3 m away
(np_random, seeded by reset(seed=...)).

Observation: Box(59) float32: joint positions minus the start pose (23), joint velocities (23), gyro (3),
accelerometer / 9.81 (3), IMU orientation w, x, y, z (4), the target in the robot's heading frame x, y (2), torso
height (1); the sensor values carry the realism's noise. Action: Box(23) in [-1, 1]: target = start + 0.5 rad
x action. Reward: 1 per step upright, plus 5 x the approach to the target (m), minus 0.01 x |action|^2; the
episode terminates when the torso falls below 0.45 m, and is truncated after max_episode_steps."""

import numpy as np

from .. import Sim
from .ssl_common import as_action
from .sim_env import SimEnv
from .spaces import Box

ACTION_SCALE = 0.5  # rad
FALLEN_HEIGHT = 0.45  # m
LIMIT = 100.0  # observation bound (velocities are clipped to it)


class T1WalkEnv(SimEnv):
    metadata = {"render_modes": [], "render_fps": 50}

    def __init__(self, task="walk", scene="t1_stand", realism=None, seed=1, max_episode_steps=1000,
                 physics_steps=4, render_mode=None):
        if task not in ("stand", "walk"):
            raise ValueError("task: 'stand' or 'walk'")
        self.task = task
        self.physics_steps = physics_steps
        self._attach(Sim(scene, seed=seed, realism=realism), max_episode_steps, render_mode)
        self.robot = 0
        start = self.sim.start_joints(self.robot)
        self.q0 = np.nan_to_num(start[:, 0])
        self.kp = np.nan_to_num(start[:, 1], nan=50.0)
        self.kd = np.nan_to_num(start[:, 2], nan=1.0)
        limits = self.sim.joint_limits(self.robot)
        self.q_lo, self.q_hi = limits[:, 0], limits[:, 1]
        self.n = len(self.q0)
        high = np.full(2 * self.n + 3 + 3 + 4 + 2 + 1, LIMIT, dtype=np.float32)
        self.observation_space = Box(-high, high, dtype=np.float32)
        self.action_space = Box(-1.0, 1.0, (self.n,), dtype=np.float32)
        self.target = np.zeros(2)

    def _base(self, o):
        t = o["truth"][self.robot]
        return t["base_position"], t["base_orientation"]

    def _obs(self, o):
        r = o["robots"][self.robot]
        pos, quat = self._base(o)
        w, x, y, z = quat
        yaw = np.arctan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z))
        d = self.target - pos[:2]
        local = np.array([np.cos(yaw) * d[0] + np.sin(yaw) * d[1], -np.sin(yaw) * d[0] + np.cos(yaw) * d[1]])
        obs = np.concatenate([r["joint_position"] - self.q0, r["joint_velocity"], r["gyro"],
                              r["accelerometer"] / 9.81, r["orientation"], local, [pos[2]]])
        return np.clip(obs, -LIMIT, LIMIT).astype(np.float32)

    def _distance(self, o):
        return float(np.hypot(*(self.target - self._base(o)[0][:2])))

    def reset(self, *, seed=None, options=None):
        super().reset(seed=seed)
        o = self._restart(seed)
        pos = self._base(o)[0]
        self.target = pos[:2].copy()
        if self.task == "walk":
            angle, distance = self.np_random.uniform(-np.pi, np.pi), self.np_random.uniform(1.0, 3.0)
            self.target += distance * np.array([np.cos(angle), np.sin(angle)])
        self.steps = 0
        self.last = self._distance(o)
        return self._obs(o), {"time": o["time"], "target": self.target.copy()}

    def step(self, action):
        a = as_action(action, self.action_space.shape)
        q = np.clip(self.q0 + ACTION_SCALE * np.clip(a, -1, 1), self.q_lo, self.q_hi)
        rows = np.zeros((self.n, 5))
        rows[:, 0] = q
        rows[:, 2] = self.kp
        rows[:, 3] = self.kd
        o = self.sim.step({self.robot: rows}, self.physics_steps)
        self.steps += 1
        height = self._base(o)[0][2]
        distance = self._distance(o)
        fallen = height < FALLEN_HEIGHT
        reward = (0.0 if fallen else 1.0) + 5.0 * (self.last - distance) - 0.01 * float(np.dot(a, a))
        self.last = distance
        truncated = bool(not fallen and self.steps >= self.max_episode_steps)
        info = {"time": o["time"], "distance": distance, "height": float(height)}
        return self._obs(o), float(reward), bool(fallen), truncated, info
