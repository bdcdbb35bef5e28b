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

The arrays are views of the shared memory, valid until the next call; copy what you keep. After close() (or once
the VectorSim is collected) arrays already handed out keep their last contents and stay readable: each holds the
memory it views, freed with the last of them. A batch is checked whole before any world steps (the same checks as
Sim.step): a refused batch raises TurfError and no world changes; a refused restore changes no world either. A
VectorSim is used from one thread at a time: a call while another is in progress raises TurfError (not_allowed).
World i runs on worker i % workers; workers default to one per core this process may use (cpus: which cores).
physics_step, robots_per_team and wall_segments as turf.Sim's."""

import contextlib
import mmap
import multiprocessing as mp
import os
import threading
from multiprocessing import shared_memory

import numpy as np

from . import vector_layout
from .errors import TurfError


def _integer(value):
    return isinstance(value, (int, np.integer)) and not isinstance(value, bool)


def _seeds(seed, n_worlds):
    """World i's seed seed + i, every one a seed turf.Sim takes (0 .. 2**64 - 1), checked before any world uses one."""
    if not _integer(seed):
        raise TurfError("malformed", f"seed {seed!r} is not an integer")
    if seed < 0 or int(seed) + n_worlds - 1 >= 2**64:
        raise TurfError("out_of_range", f"seeds {seed}..{int(seed) + n_worlds - 1} are outside 0..2**64 - 1")
    return [int(seed) + i for i in range(n_worlds)]


def _cpus(cpus):
    """The cores workers are pinned to, sorted: by default every core this process may use; given, each one of them."""
    allowed = os.sched_getaffinity(0)
    if cpus is None:
        return sorted(allowed)
    try:
        cpus = list(cpus)
    except TypeError:
        raise TurfError("malformed", f"cpus {cpus!r}: a list of core numbers") from None
    if not cpus or not all(_integer(c) for c in cpus):
        raise TurfError("malformed", f"cpus {cpus!r}: a non-empty list of core numbers")
    outside = sorted(set(int(c) for c in cpus) - allowed)
    if outside:
        raise TurfError("out_of_range", f"cpus {outside}: not cores this process may use ({sorted(allowed)})")
    return sorted(set(int(c) for c in cpus))


def _map(blocks, shapes):
    """A float64 array per block, each on a mapping of its own (from the block's descriptor) that lives as long as any
    view of it: closing and unlinking the blocks leaves arrays handed out readable, never dangling."""
    arrays = {}
    for k, shape in shapes.items():
        mapping = mmap.mmap(blocks[k]._fd, blocks[k].size)  # SharedMemory's file descriptor (POSIX)
        arrays[k] = np.frombuffer(mapping, dtype=np.float64, count=int(np.prod(shape))).reshape(shape)
    return arrays


def _worker(index, worlds, cpu, scene, seeds, realism, options, shm_names, layout, conn):
    from . import Sim  # in the worker process
    try:
        if cpu is not None:
            os.sched_setaffinity(0, {cpu})
        blocks = {k: shared_memory.SharedMemory(name=v) for k, v in shm_names.items()}
        arrays = _map(blocks, layout["shapes"])
        sims = {w: Sim(scene, seed=seeds[w], realism=realism, **options) for w in worlds}
    except Exception as e:  # noqa: BLE001 - handed to the caller
        conn.send(("error", e))
        return

    def publish(w, obs):
        vector_layout.write(layout, arrays, w, obs)

    for w, sim in sims.items():
        publish(w, sim.observation())
    conn.send(("ok", None))
    undo = {}  # this worker's worlds as they were before the last restore, for "undo" if another world refused it
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
                undo = {w: sim.save() for w, sim in sims.items()}
                for w, sim in sims.items():
                    try:
                        publish(w, sim.restore(arg[w]))
                    except TurfError as e:
                        raise TurfError(e.error, f"world {w}: {e.reason}") from None
                result = None
            elif op == "undo":
                for w, snapshot in undo.items():
                    publish(w, sims[w].restore(snapshot))
                undo = {}
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
        self._closed, self._blocks, self._conns, self._procs = True, {}, [], []  # what close() finds if this fails
        self._lock = threading.Lock()
        if not _integer(n_worlds):
            raise TurfError("malformed", f"n_worlds {n_worlds!r} is not an integer")
        if n_worlds < 1:
            raise TurfError("out_of_range", f"n_worlds {n_worlds}: at least 1")
        if workers is not None and not _integer(workers):
            raise TurfError("malformed", f"workers {workers!r} is not an integer (None: one per core)")
        if workers is not None and workers < 1:
            raise TurfError("out_of_range", f"workers {workers}: at least 1 (None: one per core)")
        self.n_worlds = int(n_worlds)
        self.seeds = _seeds(seed, self.n_worlds)
        cpus = _cpus(cpus)
        options = {"physics_step": physics_step, "robots_per_team": robots_per_team, "wall_segments": wall_segments}
        self.probe = Sim(scene, seed=seed, realism=realism, **options)  # shapes, and the checks of every batch
        self.kind = self.probe.kind
        self.workers = min(self.n_worlds, int(workers or len(cpus)))
        make = vector_layout.ssl_layout if self.kind == "ssl" else vector_layout.legged_layout
        self._layout = make(self.probe, self.n_worlds)
        self.shapes = self._layout["shapes"]
        self._closed = False
        self._blocks = {k: shared_memory.SharedMemory(create=True, size=max(8, 8 * int(np.prod(s))))
                        for k, s in self.shapes.items()}
        self._arrays = _map(self._blocks, self.shapes)
        ctx = mp.get_context("spawn")
        names = {k: b.name for k, b in self._blocks.items()}
        for i in range(self.workers):
            parent, child = ctx.Pipe()
            worlds = list(range(i, self.n_worlds, self.workers))
            p = ctx.Process(target=_worker, daemon=True,
                            args=(i, worlds, cpus[i % len(cpus)], scene, self.seeds, realism or "", options, names,
                                  self._layout, child))
            p.start()
            child.close()
            self._conns.append(parent)
            self._procs.append(p)
        try:
            self._gather()
        except BaseException:
            self.close()
            raise

    @contextlib.contextmanager
    def _call(self):
        """One call at a time (a second thread's would interleave with this one's messages to the workers)."""
        if not self._lock.acquire(blocking=False):
            raise TurfError("not_allowed", "this VectorSim is in a call in another thread: use it from one thread at "
                                           "a time")
        try:
            if self._closed:
                raise TurfError("not_allowed", "this VectorSim is closed")
            yield
        finally:
            self._lock.release()

    def _send(self, op, arg=None):
        for c in self._conns:
            c.send((op, arg))

    def _replies(self):
        """Every worker's (status, value), all of them read whatever they are."""
        return [c.recv() for c in self._conns]

    def _gather(self):
        replies = self._replies()
        for status, value in replies:
            if status == "error":
                raise value
        return [value for _, value in replies]

    def _all(self, op, arg=None):
        self._send(op, arg)
        return self._gather()

    def observation(self):
        with self._call():
            return vector_layout.observation(self._layout, self._arrays)

    def step(self, commands=None, n=1):
        """Sends each world its commands, then n physics steps. SSL: n_worlds x 2 x robots_per_team x 6; legged: a
        dict of robot (name or index) -> n_worlds x joints x 5, robots left out keep their targets; None: none.
        The whole batch is checked first: a refused one raises TurfError naming the world and changes none."""
        with self._call():
            if not _integer(n) or not 1 <= n <= 1000000:
                raise TurfError("out_of_range", f"step count {n}")
            commanded = None
            if commands is not None:
                checked = self._check_ssl(commands) if self.kind == "ssl" else self._check_legged(commands)
                commanded = self._store(checked)
            self._all("step", (int(n), commanded))
            return vector_layout.observation(self._layout, self._arrays)

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
        if _integer(key) and 0 <= key < len(names):
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
        with self._call():
            seeds = None if seed is None else _seeds(seed, self.n_worlds)
            self._all("reset", seeds)
            if seeds is not None:
                self.seeds = seeds
            return vector_layout.observation(self._layout, self._arrays)

    def save(self):
        """One snapshot (bytes) per world."""
        with self._call():
            merged = {}
            for part in self._all("save"):
                merged.update(part)
            return [merged[w] for w in range(self.n_worlds)]

    def restore(self, snapshots):
        """Every world to its snapshot (save()'s list), or none: a refused snapshot raises TurfError naming its world,
        and the worlds already restored go back to where they were."""
        with self._call():
            try:
                snapshots = list(snapshots)
            except TypeError:
                raise TurfError("malformed", "restore: a list of snapshots (bytes), one per world") from None
            if len(snapshots) != self.n_worlds:
                raise TurfError("malformed", f"restore: {self.n_worlds} snapshots, got {len(snapshots)}")
            for w, s in enumerate(snapshots):
                if not isinstance(s, bytes):
                    raise TurfError("malformed", f"world {w}: a snapshot is bytes (save()'s), not {type(s).__name__}")
            self._send("restore", snapshots)
            refused = [value for status, value in self._replies() if status == "error"]
            if refused:  # every world back to where it was
                self._all("undo")
                raise refused[0]
            return vector_layout.observation(self._layout, self._arrays)

    def close(self):
        """Stops the workers and frees the shared memory's names; arrays handed out keep their last contents."""
        if self._closed:
            return
        with self._call():
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
            self._arrays = {}  # arrays handed out keep their mappings (see _map)
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
