"""Where VectorSim keeps each kind of world's commands and observations in shared memory: one float64 block per
name, world-major (block[w] is world w's), described by plain data so that spawned workers get the same layout.

SSL: commands n_worlds x 2 x robots_per_team x 6; ball n_worlds x 6; robots n_worlds x robots x 9; time n_worlds.
Legged: commands n_worlds x (every robot's joints x 5, robot after robot); observation n_worlds x width, where each
robot's readings (measured and truth: joint positions, velocities, efforts, orientation, gyro, accelerometer, base
position, orientation and velocity, force values, contacts) and the ball (6, scenes with one) have fixed columns."""

import numpy as np

LEGGED_FIELDS = ("joint_position", "joint_velocity", "joint_effort", "orientation", "gyro", "accelerometer",
                 "base_position", "base_orientation", "base_velocity", "force", "contact", "ball_touch_time")


def ssl_layout(sim, n_worlds):
    rpt, robots = sim.robots_per_team, sim.robot_count
    return {"kind": "ssl",
            "shapes": {"commands": (n_worlds, 2, rpt, 6), "ball": (n_worlds, 6), "robots": (n_worlds, robots, 9),
                       "time": (n_worlds,)}}


def legged_layout(sim, n_worlds):
    obs = sim.observation()
    columns, width = {}, 0
    for part in ("robots", "truth"):
        for r, readings in enumerate(obs[part]):
            for field in LEGGED_FIELDS:
                size = len(readings[field])
                columns[(part, r, field)] = (width, width + size)
                width += size
    if "ball" in obs:
        columns[("ball",)] = (width, width + 6)
        width += 6
    joints = [len(sim.joint_names(r)) for r in range(sim.robot_count)]
    offsets = np.concatenate([[0], np.cumsum(joints)]).tolist()
    return {"kind": "legged", "columns": columns, "joints": joints, "joint_offsets": offsets,
            "names": list(sim.robot_names),
            "shapes": {"commands": (n_worlds, offsets[-1], 5), "observation": (n_worlds, max(1, width)),
                       "time": (n_worlds,)}}


def write(layout, arrays, w, obs):
    """World w's observation (a Sim's dict) into the shared arrays."""
    arrays["time"][w] = obs["time"]
    if layout["kind"] == "ssl":
        arrays["ball"][w] = obs["ball"]
        arrays["robots"][w] = obs["robots"]
        return
    row = arrays["observation"][w]
    for key, (a, b) in layout["columns"].items():
        row[a:b] = obs["ball"] if key == ("ball",) else obs[key[0]][key[1]][key[2]]


def world_commands(layout, arrays, w, robots):
    """What world w's Sim.step takes, from the shared commands (legged: only `robots`, by index)."""
    if layout["kind"] == "ssl":
        return arrays["commands"][w]
    offsets = layout["joint_offsets"]
    return {r: arrays["commands"][w, offsets[r]:offsets[r + 1]] for r in robots}


def observation(layout, arrays):
    """Views of the shared arrays: world-major, valid until the next call."""
    if layout["kind"] == "ssl":
        return {"ball": arrays["ball"], "robots": arrays["robots"], "time": arrays["time"]}
    table = arrays["observation"]
    out = {"time": arrays["time"], "robots": [], "truth": []}
    for part in ("robots", "truth"):
        for r, name in enumerate(layout["names"]):
            readings = {"name": name}
            for field in LEGGED_FIELDS:
                a, b = layout["columns"][(part, r, field)]
                readings[field] = table[:, a:b]
            out[part].append(readings)
    if ("ball",) in layout["columns"]:
        a, b = layout["columns"][("ball",)]
        out["ball"] = table[:, a:b]
    return out
