"""What the SSL environments share: the robot rows of a team, actions to command rows, observation rows."""

import numpy as np

from .. import Sim, _turf
from ..errors import TurfError
from .sim_env import SimEnv
from .timing import StepClock

ROBOT_FEATURES = 7  # x, y, cos(yaw), sin(yaw), vx, vy, omega
POSITION_LIMIT = 8.0  # m: beyond any division's walls
SPEED_LIMIT = 40.0  # m/s, rad/s: beyond any robot's or ball's (observations are clipped to the bounds)


class SslEnv(SimEnv):
    """An SSL environment: its Sim, an environment step of 1/60 s (self.clock) and the field (self.field)."""
    metadata = {"render_modes": [], "render_fps": 60}

    def _attach_ssl(self, scene, seed, realism, physics_step, robots_per_team, wall_segments, max_episode_steps,
                    render_mode):
        sim = Sim(scene, seed=seed, realism=realism, physics_step=physics_step, robots_per_team=robots_per_team,
                  wall_segments=wall_segments)
        self._attach(sim, max_episode_steps, render_mode)
        self.clock = StepClock(1 / 60, self.sim.step_seconds)
        self.field = Field(self.sim)


def robot_rows(sim, team, on_field_only=True):
    """Rows of ``team``'s robots in obs["robots"], by id (only those on the field now, if asked)."""
    ids = sim.robot_ids
    obs = sim.observation()["robots"]
    t = 0 if team == "blue" else 1
    rows = [i for i in range(len(ids)) if ids[i, 0] == t and (not on_field_only or obs[i, 6] > 0)]
    return np.array(sorted(rows, key=lambda i: ids[i, 1]), dtype=np.int64)


def _clip(x, limit):
    """x clipped to [-limit, limit] in place (np.clip's dispatch costs more than the work here)."""
    np.minimum(x, limit, out=x)
    np.maximum(x, -limit, out=x)
    return x


def robot_features(robots, rows):
    """n x ROBOT_FEATURES float32, clipped to the observation bounds."""
    r = robots[rows]
    out = np.empty((len(rows), ROBOT_FEATURES), dtype=np.float32)
    out[:, 0:2] = r[:, 0:2]
    out[:, 2] = np.cos(r[:, 2])
    out[:, 3] = np.sin(r[:, 2])
    out[:, 4:7] = r[:, 3:6]
    return _clip(out, np.float32(SPEED_LIMIT))


def robot_bounds(n):
    high = np.tile(np.array([POSITION_LIMIT, POSITION_LIMIT, 1, 1, SPEED_LIMIT, SPEED_LIMIT, SPEED_LIMIT],
                            dtype=np.float32), (n, 1))
    return -high, high


def ball_features(ball):
    return _clip(np.array(ball, dtype=np.float32), np.float32(SPEED_LIMIT))


def as_action(action, shape, what="action"):
    """The action as float64 of exactly ``shape``; refuses another shape or a non-number (the sim refuses NaN)."""
    try:
        a = np.asarray(action, dtype=np.float64)
    except (TypeError, ValueError):
        raise TurfError("malformed", f"{what}: expected numbers of shape {shape}") from None
    if a.shape != tuple(shape):
        raise TurfError("malformed", f"{what}: expected shape {tuple(shape)}, got {a.shape}")
    if not np.all(np.isfinite(a)):
        raise TurfError("not_finite", f"{what}: a NaN or infinite number")
    return a


class Commands:
    """Actions to command rows: each action row (vx, vy, omega in [-1, 1] of the robot's limits, kick > 0: a flat
    kick at the rules' limit) for the robot of that id; the other ids get no motion."""

    def __init__(self, sim, ids):
        f = sim.field
        self.ids = np.asarray(ids, dtype=np.int64)
        self.scale = np.array([f["max_speed"], f["max_speed"], f["max_angular_speed"]])
        self.kick = f["max_flat_kick_speed"]
        self.rows = np.zeros((sim.robots_per_team, len(_turf.SSL_COMMAND_COLUMNS)))

    def __call__(self, action):
        a = np.minimum(np.maximum(action, -1.0), 1.0)
        rows = self.rows.copy()
        rows[self.ids, 0:3] = a[:, 0:3] * self.scale
        rows[self.ids, 3] = (a[:, 3] > 0) * self.kick
        return rows


class Field:
    """The field's numbers the tasks use, read once."""

    def __init__(self, sim):
        f = sim.field
        self.half_length = f["length"] / 2
        self.half_width = f["width"] / 2
        self.half_goal = f["goal_width"] / 2

    def goal(self, ball):
        """+1 if the ball is in the yellow goal (x > 0), -1 in the blue one, else 0."""
        if abs(ball[1]) < self.half_goal and abs(ball[0]) > self.half_length:
            return 1 if ball[0] > 0 else -1
        return 0

    def out(self, ball):
        return abs(ball[0]) > self.half_length or abs(ball[1]) > self.half_width
