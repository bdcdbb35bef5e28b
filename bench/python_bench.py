"""Environment steps per second of `import turf` (1/60 s of simulated time per environment step: 8 or 9
physics steps of 2 ms), next to the UDP sync port of turf-sim measured in the same run.

    PYTHONPATH=build/python /usr/bin/python3 bench/python_bench.py [--seconds 20] [--sync-requests 1000]

Rows: the kernel alone through Sim.step (2 x 11: every on-field robot commanded at every environment step; 1
robot: blue 0 alone on the field, commanded), in the shipped scene and in the learning configuration (turf.FAST_SSL:
2.5 ms steps, no boundary wall boxes, goals static bodies; only the ids the task uses, no parked
substitutes), that again while publishing on DDS (Sim.publish, nobody reading), the Gymnasium-shaped environments
(actions sampled beforehand, so the policy costs nothing), and VectorSim with 2 worker processes pinned to the 2 cores. The sync port rows come
from build/bench/turf-bench-sync (a UDP client, one SimulationSyncRequest of 1/60 s at a time, 6 robots
commanded): (a) turf-sim with a separate bridge over Fast DDS, (b) turf-sim --simproto."""

import argparse
import os
import re
import subprocess
import sys
import time

import numpy as np

import turf
from turf import envs
from turf.envs.timing import StepClock

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def match_commands(sim, k):
    """Both teams' 11 on-field robots driving (a function of k), a kick now and then."""
    c = np.zeros((2, sim.robots_per_team, 6))
    n = min(11, sim.robots_per_team)
    ids = np.arange(n)
    c[:, :n, 0] = np.sin(0.05 * k + ids)
    c[:, :n, 1] = 0.5 * np.cos(0.07 * k + ids)
    c[:, :n, 2] = np.sin(0.03 * k)
    c[:, :n, 3] = np.where((k + ids) % 60 == 0, 3.0, 0.0)
    return c


def SCENE(robots):
    """The shipped scene as it is: 2 ms steps, ids 0..15 a team (the substitutes parked beside the field)."""
    return {"physics_step": None, "robots_per_team": None, "wall_segments": None}


def FAST(robots):
    """The learning configuration: turf.FAST_SSL and only the robots the task uses."""
    return dict(turf.FAST_SSL, robots_per_team=robots)


CPU_RATES = []  # env-steps per second of this process's CPU time, for the rows measured in this process


def timed(steps, body):
    start, cpu = time.perf_counter(), time.process_time()
    for k in range(steps):
        body(k)
    CPU_RATES.append(steps / (time.process_time() - cpu))
    return steps / (time.perf_counter() - start)


def sim_rate(steps, one_robot, fast, publish=False):
    options = FAST if fast else SCENE
    if one_robot:
        env = envs.SslGoToBallKickEnv(realism="realistic", **options(1))
        env.reset(seed=1)
        sim = env.sim
    else:
        sim = turf.Sim("ssl_div_a", seed=1, realism="realistic", **options(11))
    if publish:  # a domain and prefix of this run's own, nobody reading
        sim.publish(domain=1 + os.getpid() % 99, prefix=f"bench{os.getpid()}")
    clock = StepClock(1 / 60, sim.step_seconds)
    commands = [match_commands(sim, k) for k in range(steps)]
    if one_robot:
        for c in commands:
            c[:, 1:] = 0.0
            c[1] = 0.0
    return timed(steps, lambda k: sim.step(commands[k], clock.next()))


def env_rate(steps, env):
    env.reset(seed=1)
    env.action_space.seed(1)
    actions = [env.action_space.sample() for _ in range(steps)]

    def body(k):
        _, _, terminated, truncated, _ = env.step(actions[k])
        if terminated or truncated:
            env.reset()
    return timed(steps, body)


def vector_rate(steps, n_worlds, one_robot, fast=True):
    options = (FAST if fast else SCENE)(1 if one_robot else 11)
    with turf.VectorSim(n_worlds, seed=1, realism="realistic", workers=2, **options) as vs:
        if one_robot:
            snapshot = envs.SslGoToBallKickEnv(realism="realistic", seed=1, **options)
            vs.restore([snapshot.start] * n_worlds)
        clock = StepClock(1 / 60, vs.probe.step_seconds)
        base = [match_commands(vs.probe, k) for k in range(steps)]
        if one_robot:
            for c in base:
                c[:, 1:] = 0.0
                c[1] = 0.0
        commands = [np.broadcast_to(c, (n_worlds,) + c.shape) for c in base]
        return n_worlds * timed(steps, lambda k: vs.step(commands[k], clock.next()))


def sync_port(requests):
    binary = os.path.join(os.environ.get("TURF_BUILD_DIR", os.path.join(ROOT, "build")), "bench", "turf-bench-sync")
    if not os.path.exists(binary):
        return {}
    out = subprocess.run([binary, "--requests", str(requests), "--only", "ab"], capture_output=True, text=True,
                         check=True).stdout
    rates = {}
    for label, key in (("(a)", "a"), ("(b)", "b")):
        m = re.search(re.escape(label) + r"[^|]*\| (\d+) \|", out)
        if m:
            rates[key] = 1e6 / float(m.group(1))
    return rates


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=20.0, help="simulated seconds per row")
    parser.add_argument("--sync-requests", type=int, default=1000, help="requests to the sync port (0: skip)")
    args = parser.parse_args()
    steps = int(args.seconds * 60)
    cores = len(os.sched_getaffinity(0))
    load = os.getloadavg()[0]
    print(f"turf Python, env step 1/60 s of 2 ms physics steps, realism realistic, {steps} env steps a row; "
          f"{cores} cores, load average {load:.1f} at the start")
    print("| what | 2x11 env-steps/s (per CPU second) | 1 robot env-steps/s (per CPU second) |")
    print("| --- | --- | --- |")
    rows = [
        ("Sim.step, shipped scene (2 ms, 16 ids a team), one core", lambda: sim_rate(steps, False, False),
         lambda: sim_rate(steps, True, False), True),
        ("Sim.step, turf.FAST_SSL (2.5 ms, no wall boxes, goals static bodies), only the robots used, "
         "one core", lambda: sim_rate(steps, False, True), lambda: sim_rate(steps, True, True), True),
        ("the row above with sim.publish(domain=...) (every topic written to DDS, no reader)",
         lambda: sim_rate(steps, False, True, True), lambda: sim_rate(steps, True, True, True), True),
        ("Gymnasium-shaped env (SslMatchEnv / SslGoToBallKickEnv, their defaults), one core",
         lambda: env_rate(steps, envs.SslMatchEnv()), lambda: env_rate(steps, envs.SslGoToBallKickEnv()), True),
        ("VectorSim, 2 worlds, 2 workers pinned to 2 cores (as the row above)", lambda: vector_rate(steps, 2, False),
         lambda: vector_rate(steps, 2, True), False),
        ("VectorSim, 8 worlds, 2 workers pinned to 2 cores", lambda: vector_rate(steps // 4, 8, False),
         lambda: vector_rate(steps // 4, 8, True), False),
    ]
    for name, match, one, cpu in rows:
        m, o = match(), one()
        if cpu:
            print(f"| {name} | {m:.0f} ({CPU_RATES[-2]:.0f}) | {o:.0f} ({CPU_RATES[-1]:.0f}) |", flush=True)
        else:
            print(f"| {name} | {m:.0f} | {o:.0f} |", flush=True)
    if args.sync_requests > 0:
        rates = sync_port(args.sync_requests)
        if rates:
            print(f"| UDP sync port (a): turf-sim + separate bridge over Fast DDS, 6 robots commanded | "
                  f"{rates.get('a', 0):.0f} | |")
            print(f"| UDP sync port (b): turf-sim --simproto, 6 robots commanded | {rates.get('b', 0):.0f} | |")
        else:
            print("(turf-bench-sync not built: no sync port rows)")
    print(f"load average at the end {os.getloadavg()[0]:.1f}")


if __name__ == "__main__":
    sys.exit(main())
