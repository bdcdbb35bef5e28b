"""VectorSim: worlds in pinned worker processes give exactly what Sim gives in this process; determinism across
processes; refused batches and restores change no world; arrays outlive close(); one thread at a time; bad
arguments refused before any process starts."""

import hashlib
import multiprocessing
import os
import subprocess
import sys
import threading

import numpy as np
import pytest

import turf

RPT = 16


def commands(k, n_worlds):
    c = np.zeros((n_worlds, 2, RPT, 6))
    for w in range(n_worlds):
        c[w, :, :, 0] = np.sin(0.05 * k + w + np.arange(RPT))
        c[w, :, :, 2] = 0.5 * np.cos(0.03 * k + w)
    return c


def test_worlds_match_in_process_sims():
    n = 3
    with turf.VectorSim(n, seed=10, realism="realistic", workers=2) as vs:
        assert vs.workers == 2
        for k in range(20):
            obs = vs.step(commands(k, n), 8)
        got = {key: np.array(v) for key, v in obs.items()}
        snapshots = vs.save()
    for w in range(n):
        sim = turf.Sim("ssl_div_a", seed=10 + w, realism="realistic")
        for k in range(20):
            o = sim.step(commands(k, n)[w], 8)
        np.testing.assert_array_equal(got["ball"][w], o["ball"])
        np.testing.assert_array_equal(got["robots"][w], o["robots"])
        assert snapshots[w] == sim.save()


def test_refused_batch_changes_no_world():
    with turf.VectorSim(2, seed=1, workers=2) as vs:
        vs.step(commands(0, 2), 8)
        before = vs.save()
        bad = commands(1, 2)
        bad[1, 0, 4, 1] = np.nan  # world 1, blue 4
        with pytest.raises(turf.TurfError) as e:
            vs.step(bad, 8)
        assert e.value.error == "not_finite" and "world 1" in str(e.value)
        with pytest.raises(turf.TurfError):
            vs.step(np.zeros((2, 2, RPT, 5)), 8)
        with pytest.raises(turf.TurfError):
            vs.step(None, 0)
        assert vs.save() == before
        vs.restore(before)
        vs.reset(seed=4)
        assert vs.seeds == [4, 5]
        # A seed a world would refuse is refused before any world resets: nothing changes.
        vs.step(None, 8)
        times = np.array(vs.observation()["time"], copy=True)
        for seed, error in ((-1, "out_of_range"), (2**64 - 1, "out_of_range"), (1.5, "malformed"), ("3", "malformed")):
            with pytest.raises(turf.TurfError) as e:
                vs.reset(seed=seed)
            assert e.value.error == error, seed
        assert vs.seeds == [4, 5]
        np.testing.assert_array_equal(vs.observation()["time"], times)


SCRIPT = """
import hashlib, numpy as np, turf
sim = turf.Sim("ssl_div_a", seed=21, realism="harsh")
h = hashlib.sha256()
for k in range(40):
    c = np.zeros((2, 16, 6)); c[:, :, 0] = np.sin(0.1 * k + np.arange(16)); c[:, :, 3] = (k % 7 == 0) * 3.0
    o = sim.step(c, 8)
    for key in ("ball", "robots", "ball_detections", "robot_detections", "camera_frames"):
        h.update(np.ascontiguousarray(o[key]).tobytes())
print(h.hexdigest())
"""


def test_same_run_in_two_processes():
    env = dict(os.environ)
    digests = {subprocess.run([sys.executable, "-c", SCRIPT], env=env, capture_output=True, text=True,
                              check=True).stdout.strip() for _ in range(2)}
    assert len(digests) == 1 and len(next(iter(digests))) == 64
    # and in this process
    ns = {}
    exec(compile(SCRIPT.replace("print(h.hexdigest())", "digest = h.hexdigest()"), "script", "exec"), ns)
    assert ns["digest"] in digests
    assert hashlib.sha256(b"").hexdigest() not in digests


KEEP_SCRIPT = """
import os, numpy as np, turf
def first():
    vs = turf.VectorSim(2, robots_per_team=1, workers=1)
    return vs.step(None, 5)  # vs is collected on return
gone = first()
with turf.VectorSim(2, robots_per_team=1, workers=1) as vs:
    obs = vs.step(None, 10)
    kept = {k: np.array(v) for k, v in obs.items()}
    names = [b.name for b in vs._blocks.values()]
assert not any(os.path.exists("/dev/shm/" + name) for name in names)  # unlinked, though arrays still map them
for k in kept:
    np.testing.assert_array_equal(obs[k], kept[k])
obs["ball"][0, 0] = 7.0
print(gone["time"].tolist(), obs["time"].tolist(), obs["ball"][0, 0])
"""


def test_arrays_outlive_close_and_collection():
    """Arrays handed out stay readable (their last contents) after close() and after the VectorSim is collected:
    reading them crashed the process."""
    run = subprocess.run([sys.executable, "-c", KEEP_SCRIPT], capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, run.stderr
    assert run.stdout.split() == ["[0.01,", "0.01]", "[0.02,", "0.02]", "7.0"]
    with turf.VectorSim(1, robots_per_team=1, workers=1) as vs:
        vs.step(None, 1)
    for call in (vs.observation, vs.step, vs.save):
        with pytest.raises(turf.TurfError) as e:
            call()
        assert e.value.error == "not_allowed"
    vs.close()  # twice is fine


class HeldReplies:
    """A worker's pipe whose replies wait for `release`: a call in progress for as long as the test needs."""

    def __init__(self, conn):
        self.conn, self.waiting, self.release = conn, threading.Event(), threading.Event()

    def send(self, message):
        self.conn.send(message)

    def recv(self):
        self.waiting.set()
        assert self.release.wait(10)
        return self.conn.recv()


def test_call_from_another_thread_is_refused():
    with turf.VectorSim(2, robots_per_team=1, workers=2) as vs:
        held = HeldReplies(vs._conns[1])
        vs._conns[1] = held
        stepping = threading.Thread(target=vs.step, args=(None, 5))
        stepping.start()
        assert held.waiting.wait(10)  # the step is in progress
        for call in (vs.save, vs.step, vs.observation, vs.close, lambda: vs.restore([b"", b""]), vs.reset):
            with pytest.raises(turf.TurfError) as e:
                call()
            assert e.value.error == "not_allowed" and "thread" in str(e.value)
        held.release.set()
        stepping.join(10)
        vs._conns[1] = held.conn
        # unharmed: every world stepped once, and it goes on
        np.testing.assert_array_equal(vs.observation()["time"], [0.01, 0.01])
        snapshots = vs.save()
        np.testing.assert_array_equal(vs.step(None, 5)["time"], [0.02, 0.02])
        vs.restore(snapshots)
        np.testing.assert_array_equal(vs.observation()["time"], [0.01, 0.01])


@pytest.mark.parametrize("bad", [1, 2])
def test_refused_restore_restores_no_world(bad):
    """World 1 is worker 1's, world 2 worker 0's second (after world 0, which it had restored)."""
    with turf.VectorSim(3, robots_per_team=1, workers=2) as vs:
        snapshots = vs.save()
        vs.step(None, 50)
        before = vs.save()
        broken = list(snapshots)
        broken[bad] = b"garbage"
        with pytest.raises(turf.TurfError) as e:
            vs.restore(broken)
        assert e.value.error == "malformed" and f"world {bad}" in str(e.value)
        np.testing.assert_array_equal(vs.observation()["time"], [0.1, 0.1, 0.1])
        assert vs.save() == before
        for wrong in ("abc", [b"", b"", "x"], 3):
            with pytest.raises(turf.TurfError) as e:
                vs.restore(wrong)
            assert e.value.error == "malformed"
        assert vs.save() == before
        np.testing.assert_array_equal(vs.restore(snapshots)["time"], [0, 0, 0])


@pytest.mark.parametrize("arguments, error", [
    ({"n_worlds": 1.5}, "malformed"), ({"n_worlds": None}, "malformed"), ({"n_worlds": True}, "malformed"),
    ({"n_worlds": 0}, "out_of_range"), ({"workers": -1}, "out_of_range"), ({"workers": 0}, "out_of_range"),
    ({"workers": 1.5}, "malformed"), ({"cpus": [999]}, "out_of_range"), ({"cpus": []}, "malformed"),
    ({"cpus": ["0"]}, "malformed"), ({"cpus": 0}, "malformed")])
def test_bad_arguments_are_refused_before_any_process_starts(arguments, error):
    with pytest.raises(turf.TurfError) as e:
        turf.VectorSim(**{"n_worlds": 2, "robots_per_team": 1, **arguments})
    named = next(iter(arguments))
    assert e.value.error == error and named in str(e.value)
    assert not multiprocessing.active_children()
