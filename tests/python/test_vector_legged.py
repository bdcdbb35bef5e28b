"""VectorSim on a legged scene (one Booster T1): worlds in pinned workers give exactly what Sim gives in this
process, every reading; refused batches (NaN, wrong shapes, unknown robots) raise and change no world."""

import numpy as np
import pytest

import turf
from turf.vector_layout import LEGGED_FIELDS

SCENE = "t1_stand"


def pd_rows(sim, k, w):
    """PD rows holding the start pose with a sway that differs per world."""
    start = sim.start_joints(0)
    rows = np.zeros((len(start), 5))
    rows[:, 0] = np.nan_to_num(start[:, 0]) + 0.05 * np.sin(0.1 * k + w + np.arange(len(start)))
    rows[:, 2] = np.nan_to_num(start[:, 1], nan=50.0)
    rows[:, 3] = np.nan_to_num(start[:, 2], nan=1.0)
    return rows


def batch(sim, k, n_worlds):
    return {"t1": np.stack([pd_rows(sim, k, w) for w in range(n_worlds)])}


def test_worlds_match_in_process_sims():
    n, steps = 3, 15
    probe = turf.Sim(SCENE, seed=7)
    with turf.VectorSim(n, scene=SCENE, seed=7, realism="realistic", workers=2) as vs:
        assert vs.kind == "legged" and vs.workers == 2
        assert vs.shapes["commands"] == (n, 23, 5)
        for k in range(steps):
            obs = vs.step(batch(probe, k, n), 4)
        got = {part: [{f: np.array(r[f]) for f in LEGGED_FIELDS} for r in obs[part]] for part in ("robots", "truth")}
        times = np.array(obs["time"])
        snapshots = vs.save()
    for w in range(n):
        sim = turf.Sim(SCENE, seed=7 + w, realism="realistic")
        for k in range(steps):
            o = sim.step({"t1": pd_rows(probe, k, w)}, 4)
        assert times[w] == o["time"]
        for part in ("robots", "truth"):
            for field in LEGGED_FIELDS:
                np.testing.assert_array_equal(got[part][0][field][w], o[part][0][field], err_msg=f"{part} {field}")
        assert snapshots[w] == sim.save()
    # the worlds differ (seeds 7, 8, 9 and their sway): the test could fail
    assert not np.array_equal(got["robots"][0]["joint_position"][0], got["robots"][0]["joint_position"][1])


def test_refused_batches_change_no_world():
    probe = turf.Sim(SCENE, seed=1)
    with turf.VectorSim(2, scene=SCENE, seed=1, workers=2) as vs:
        vs.step(batch(probe, 0, 2), 4)
        before = vs.save()
        bad = batch(probe, 1, 2)
        bad["t1"][1, 5, 0] = np.nan  # world 1, joint 5's target
        with pytest.raises(turf.TurfError) as e:
            vs.step(bad, 4)
        assert e.value.error == "not_finite" and "world 1" in str(e.value)
        with pytest.raises(turf.TurfError) as e:
            vs.step({"t1": np.zeros((2, 22, 5))}, 4)
        assert e.value.error == "malformed"
        with pytest.raises(turf.TurfError) as e:
            vs.step({"nao": np.zeros((2, 23, 5))}, 4)
        assert e.value.error == "unknown_robot"
        with pytest.raises(turf.TurfError) as e:
            vs.step(np.zeros((2, 23, 5)), 4)
        assert e.value.error == "malformed"
        with pytest.raises(turf.TurfError) as e:
            vs.step(batch(probe, 1, 2), 0)
        assert e.value.error == "out_of_range"
        assert vs.save() == before
        vs.step(None, 4)  # no commands: the targets held
        vs.restore(before)
        assert vs.save() == before
