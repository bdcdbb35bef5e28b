"""VectorSim: worlds in pinned worker processes give exactly what Sim gives in this process; determinism across
processes; refused batches change no world."""

import hashlib
import os
import subprocess
import sys

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
