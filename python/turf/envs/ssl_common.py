"""What the SSL environments share: the robot rows of a team, actions to command rows, observation rows."""

import numpy as np

from .. import _turf
from ..errors import TurfError

ROBOT_FEATURES = 7  # x, y, cos(yaw), sin(yaw), vx, vy, omega
POSITION_LIMIT = 8.0  # m: beyond any division's walls
SPEED_LIMIT = 40.0  # m/s, rad/s: beyond any robot's or ball's (observations are clipped to the bounds)


def robot_rows(sim, team, on_field_only=True):
    """Rows of ``team``'s robots in obs["robots"], by id (only those on the field now, if asked)."""
    ids = sim.robot_ids
    obs = sim.observation()["robots"]
    t = 0 if team == "blue" else 1
    rows = [i for i in range(len(ids)) if ids[i, 0] == t and (not on_field_only or obs[i, 6] > 0)]
    return np.array(sorted(rows, key=lambda i: ids[i, 1]), dtype=np.int64)


def robot_features(robots, rows):
    """n x ROBOT_FEATURES float32, clipped to the observation bounds."""
    r = robots[rows]
    out = np.stack([r[:, 0], r[:, 1], np.cos(r[:, 2]), np.sin(r[:, 2]), r[:, 3], r[:, 4], r[:, 5]], axis=1)
    return np.clip(out, -SPEED_LIMIT, SPEED_LIMIT).astype(np.float32)


def robot_bounds(n):
    high = np.tile(np.array([POSITION_LIMIT, POSITION_LIMIT, 1, 1, SPEED_LIMIT, SPEED_LIMIT, SPEED_LIMIT],
                            dtype=np.float32), (n, 1))
    return -high, high


def ball_features(ball):
    return np.clip(np.asarray(ball, dtype=np.float64), -SPEED_LIMIT, SPEED_LIMIT).astype(np.float32)


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


def command_rows(sim, ids, action):
    """robots_per_team x 6 command rows: each action row (vx, vy, omega in [-1, 1] of the robot's limits, kick
    > 0: a flat kick at the rules' limit) for the robot of that id; the other ids get no motion."""
    f = sim.field
    rows = np.zeros((sim.robots_per_team, len(_turf.SSL_COMMAND_COLUMNS)))
    a = np.clip(action, -1.0, 1.0)
    rows[ids, 0] = a[:, 0] * f["max_speed"]
    rows[ids, 1] = a[:, 1] * f["max_speed"]
    rows[ids, 2] = a[:, 2] * f["max_angular_speed"]
    rows[ids, 3] = np.where(a[:, 3] > 0, f["max_flat_kick_speed"], 0.0)
    return rows


def goal_of(sim, ball):
    """+1 if the ball is in the yellow goal (x > 0), -1 in the blue one, else 0."""
    f = sim.field
    if abs(ball[1]) < f["goal_width"] / 2 and abs(ball[0]) > f["length"] / 2:
        return 1 if ball[0] > 0 else -1
    return 0


def out_of_field(sim, ball):
    f = sim.field
    return abs(ball[0]) > f["length"] / 2 or abs(ball[1]) > f["width"] / 2
