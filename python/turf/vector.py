"""VectorSim: many worlds of one scene (SSL or legged) stepped in worker processes, each worker pinned to a core
(os.sched_setaffinity), with commands and observations in shared memory (no pickling per step).

    vs = turf.VectorSim(8, scene="ssl_div_a", seed=1)        # worlds get seeds 1..8
    obs = vs.step(commands, n=8)   # commands: n_worlds x 2 x robots_per_team x 6 (or None)
    obs["ball"]    n_worlds x 6 (turf.SSL_BALL_COLUMNS)
    obs["robots"]  n_worlds x robots x 9 (turf.SSL_ROBOT_COLUMNS)
    obs["time"]    n_worlds

    vs = turf.VectorSim(8, scene="t1_stand", seed=1)         # a legged scene
    obs = vs.step({"t1": q}, n=4)  # per robot (name or index) n_worlds x joints x 5 (Sim.step's rows); or None
    obs["robots"][r]["joint_position"]   n_worlds x joints, and every other reading of Sim.step's robots[r]
    obs["truth"][r][...], obs["ball"] (n_worlds x 6, scenes with a ball), obs["time"]

The arrays are views of the shared memory, valid until the next call; copy what you keep. A batch is checked
whole before any world steps (the same checks as Sim.step): a refused batch raises TurfError and no world
changes. World i runs on worker i % workers; workers default to one per core this process may use. physics_step, robots_per_team and wall_segments as turf.Sim's."""

import multiprocessing as mp
import os
from multiprocessing import shared_memory

import numpy as np

from . import vector_layout
from .errors import TurfError


def _seeds(seed, n_worlds):
    """World i's seed seed + i, every one a seed turf.Sim takes (0 .. 2**64 - 1), checked before any world uses one."""
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)):
        raise TurfError("malformed", f"seed {seed!r} is not an integer")
    if seed < 0 or int(seed) + n_worlds - 1 >= 2**64:
        raise TurfError("out_of_range", f"seeds {seed}..{int(seed) + n_worlds - 1} are outside 0..2**64 - 1")
    return [int(seed) + i for i in range(n_worlds)]


def _worker(index, worlds, cpu, scene, seeds, realism, options, shm_names, layout, conn):
    from . import Sim  # in the worker process
    if cpu is not None:
        os.sched_setaffinity(0, {cpu})
    shapes = layout["shapes"]
    blocks = {k: shared_memory.SharedMemory(name=v) for k, v in shm_names.items()}
    arrays = {k: np.ndarray(shapes[k], dtype=np.float64, buffer=blocks[k].buf) for k in shapes}
    sims = {w: Sim(scene, seed=seeds[w], realism=realism, **options) for w in worlds}

    def publish(w, obs):
        vector_layout.write(layout, arrays, w, obs)

    for w, sim in sims.items():
        publish(w, sim.observation())
    conn.send(("ok", None))
    while True:
        op, arg = conn.recv()
        try:
            if op == "close":
                break
            if op == "step":
                n, commanded = arg
                for w, sim in sims.items():
                    c = None if commanded is None else vector_layout.world_commands(layout, arrays, w, commanded)
                    publish(w, sim.step(c, n))
                result = None
            elif op == "reset":
                for w, sim in sims.items():
                    publish(w, sim.reset(seed=None if arg is None else arg[w]))
                result = None
            elif op == "save":
                result = {w: sim.save() for w, sim in sims.items()}
            elif op == "restore":
                for w, sim in sims.items():
                    publish(w, sim.restore(arg[w]))
                result = None
            else:
                raise ValueError(f"unknown op {op}")
            conn.send(("ok", result))
        except Exception as e:  # noqa: BLE001 - handed to the caller
            conn.send(("error", e))
    for b in blocks.values():
        b.close()
    conn.close()


class VectorSim:
    def __init__(self, n_worlds, scene="ssl_div_a", seed=1, realism=None, workers=None, cpus=None, physics_step=None,
                 robots_per_team=None, wall_segments=None):
        from . import Sim
        if n_worlds < 1:
            raise TurfError("out_of_range", "n_worlds must be at least 1")
        self.n_worlds = n_worlds
        self.seeds = _seeds(seed, n_worlds)
        options = {"physics_step": physics_step, "robots_per_team": robots_per_team, "wall_segments": wall_segments}
        self.probe = Sim(scene, seed=seed, realism=realism, **options)  # shapes, and the checks of every batch
        self.kind = self.probe.kind
        cpus = sorted(cpus if cpus is not None else os.sched_getaffinity(0))
        self.workers = min(n_worlds, workers or len(cpus))
        make = vector_layout.ssl_layout if self.kind == "ssl" else vector_layout.legged_layout
        self._layout = make(self.probe, n_worlds)
        self.shapes = self._layout["shapes"]
        self._blocks = {k: shared_memory.SharedMemory(create=True, size=max(8, 8 * int(np.prod(s))))
                        for k, s in self.shapes.items()}
        self._arrays = {k: np.ndarray(s, dtype=np.float64, buffer=self._blocks[k].buf)
                        for k, s in self.shapes.items()}
        ctx = mp.get_context("spawn")
        self._conns, self._procs = [], []
        names = {k: b.name for k, b in self._blocks.items()}
        for i in range(self.workers):
            parent, child = ctx.Pipe()
            worlds = list(range(i, n_worlds, self.workers))
            p = ctx.Process(target=_worker, daemon=True,
                            args=(i, worlds, cpus[i % len(cpus)], scene, self.seeds, realism or "", options, names,
                                  self._layout, child))
            p.start()
            child.close()
            self._conns.append(parent)
            self._procs.append(p)
        self._closed = False
        self._gather()

    def _gather(self):
        results, error = [], None
        for c in self._conns:
            status, value = c.recv()
            if status == "error" and error is None:
                error = value
            results.append(value)
        if error is not None:
            raise error
        return results

    def _all(self, op, arg=None):
        if self._closed:
            raise TurfError("not_allowed", "this VectorSim is closed")
        for c in self._conns:
            c.send((op, arg))
        return self._gather()

    def observation(self):
        return vector_layout.observation(self._layout, self._arrays)

    def step(self, commands=None, n=1):
        """Sends each world its commands, then n physics steps. SSL: n_worlds x 2 x robots_per_team x 6; legged: a
        dict of robot (name or index) -> n_worlds x joints x 5, robots left out keep their targets; None: none.
        The whole batch is checked first: a refused one raises TurfError naming the world and changes none."""
        if not isinstance(n, (int, np.integer)) or not 1 <= n <= 1000000:
            raise TurfError("out_of_range", f"step count {n}")
        commanded = None
        if commands is not None:
            checked = self._check_ssl(commands) if self.kind == "ssl" else self._check_legged(commands)
            commanded = self._store(checked)
        self._all("step", (int(n), commanded))
        return self.observation()

    @staticmethod
    def _numbers(value, what):
        try:
            return np.asarray(value, dtype=np.float64)
        except (TypeError, ValueError):
            raise TurfError("malformed", f"{what}: numbers") from None

    def _check_each_world(self, per_world):
        for w in range(self.n_worlds):
            try:
                self.probe.check_commands(per_world(w))
            except TurfError as e:
                raise TurfError(e.error, f"world {w}: {e.reason}") from None

    def _check_ssl(self, commands):
        c = self._numbers(commands, "commands")
        if c.shape != self.shapes["commands"]:
            raise TurfError("malformed", f"commands: expected shape {self.shapes['commands']}, got {c.shape}")
        self._check_each_world(lambda w: c[w])
        return c

    def _check_legged(self, commands):
        if not isinstance(commands, dict):
            raise TurfError("malformed", "commands: a dict of robot (name or index) -> n_worlds x joints x 5 array")
        robots = {}
        for key, value in commands.items():
            r = self._robot_index(key)
            c = self._numbers(value, f"commands of robot {key!r}")
            shape = (self.n_worlds, self._layout["joints"][r], 5)
            if c.shape != shape:
                raise TurfError("malformed", f"commands of robot {key!r}: expected shape {shape}, got {c.shape}")
            robots[r] = c
        self._check_each_world(lambda w: {r: c[w] for r, c in robots.items()})
        return robots

    def _robot_index(self, key):
        names = self._layout["names"]
        if isinstance(key, str) and key in names:
            return names.index(key)
        if isinstance(key, (int, np.integer)) and not isinstance(key, bool) and 0 <= key < len(names):
            return int(key)
        raise TurfError("unknown_robot", f"robot {key!r} (one of {names} or an index)")

    def _store(self, checked):
        """Checked commands into shared memory; what the workers are told was commanded."""
        if self.kind == "ssl":
            self._arrays["commands"][...] = checked
            return True
        offsets = self._layout["joint_offsets"]
        for r, c in checked.items():
            self._arrays["commands"][:, offsets[r]:offsets[r + 1]] = c
        return sorted(checked)

    def reset(self, seed=None):
        """Every world back to its start; a seed gives world i the seed seed + i."""
        seeds = None if seed is None else _seeds(seed, self.n_worlds)
        self._all("reset", seeds)
        if seeds is not None:
            self.seeds = seeds
        return self.observation()

    def save(self):
        """One snapshot (bytes) per world."""
        merged = {}
        for part in self._all("save"):
            merged.update(part)
        return [merged[w] for w in range(self.n_worlds)]

    def restore(self, snapshots):
        if len(snapshots) != self.n_worlds:
            raise TurfError("malformed", f"restore: {self.n_worlds} snapshots, got {len(snapshots)}")
        self._all("restore", list(snapshots))
        return self.observation()

    def close(self):
        if self._closed:
            return
        self._closed = True
        for c in self._conns:
            try:
                c.send(("close", None))
            except (BrokenPipeError, OSError):
                pass
        for p in self._procs:
            p.join(timeout=10)
            if p.is_alive():
                p.kill()
                p.join()
        self._arrays = {}
        for b in self._blocks.values():
            b.close()
            b.unlink()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def __del__(self):
        try:
            self.close()
        except Exception:  # noqa: BLE001 - interpreter shutdown
            pass
