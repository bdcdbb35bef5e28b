"""turf.Sim on SSL scenes: observations, camera detections, determinism, snapshots, controls, refusals."""

import numpy as np
import pytest

import turf

RPT = 16  # ssl_div_a: ids 0..15 a team


def commands(frame, rpt=RPT):
    """Both teams driven by a function of the step count: turning, driving, kicking now and then."""
    c = np.zeros((2, rpt, 6))
    ids = np.arange(rpt)
    c[:, :, 0] = np.sin(0.05 * frame + ids)
    c[:, :, 1] = 0.5 * np.cos(0.07 * frame + ids)
    c[:, :, 2] = np.sin(0.03 * frame)
    c[:, :, 3] = np.where((frame + ids) % 13 == 0, 3.0, 0.0)
    return c


def run(sim, steps, start=0):
    """Observations of `steps` env steps (8 physics steps each), copied."""
    out = []
    for k in range(start, start + steps):
        o = sim.step(commands(k), 8)
        out.append({key: np.array(v, copy=True) for key, v in o.items()})
    return out


def same(a, b):
    assert len(a) == len(b)
    for x, y in zip(a, b):
        assert x.keys() == y.keys()
        for key in x:
            np.testing.assert_array_equal(x[key], y[key], err_msg=key)


def test_observation_shapes_and_columns():
    sim = turf.Sim("ssl_div_a", seed=1, realism="realistic")
    o = sim.observation()
    assert o["ball"].shape == (6,) and len(turf.SSL_BALL_COLUMNS) == 6
    assert o["robots"].shape == (32, 9) and len(turf.SSL_ROBOT_COLUMNS) == 9
    assert sim.robot_ids.shape == (32, 2)
    assert int(o["robots"][:, 6].sum()) == 22  # 11 a team on the field
    assert not o["robots"].flags.writeable  # a view of the kernel's output
    assert sim.step_seconds == pytest.approx(0.002)


def test_camera_detections_carry_the_modelled_noise():
    ideal = turf.Sim("ssl_div_a", seed=1, realism="ideal")
    noisy = turf.Sim("ssl_div_a", seed=1, realism="realistic")
    for sim in (ideal, noisy):
        sim.teleport_ball(1.0, 1.0)
    errors = {}
    for name, sim in (("ideal", ideal), ("realistic", noisy)):
        seen = []
        for _ in range(120):  # 1 s: 60 camera frames per camera
            o = sim.step(None, 8)
            seen.append(o["ball_detections"])
        d = np.concatenate(seen)
        assert d.shape[1] == 7 and len(d) > 30
        errors[name] = np.abs(d[:, 3:5] - [1.0, 1.0]).max()
    assert errors["ideal"] < 1e-5  # a resting ball sits micrometres off its radius; vision projects from the camera
    assert errors["realistic"] > 1e-4  # millimetres of noise, well inside 5 cm
    assert errors["realistic"] < 0.05


def test_same_seed_and_actions_same_observations():
    a = run(turf.Sim("ssl_div_a", seed=7, realism="realistic"), 60)
    b = run(turf.Sim("ssl_div_a", seed=7, realism="realistic"), 60)
    same(a, b)
    c = run(turf.Sim("ssl_div_a", seed=8, realism="realistic"), 60)
    assert not all(np.array_equal(x["ball_detections"], y["ball_detections"]) for x, y in zip(a, c))


def test_restore_continues_byte_for_byte():
    sim = turf.Sim("ssl_div_a", seed=3, realism="harsh")
    run(sim, 30)
    snapshot = sim.save()
    assert isinstance(snapshot, bytes)
    first = run(sim, 60, start=30)
    end = sim.save()
    sim.restore(snapshot)
    second = run(sim, 60, start=30)
    same(first, second)
    assert sim.save() == end
    other = turf.Sim("ssl_div_a", seed=3, realism="harsh")  # another kernel, the same snapshot
    other.restore(snapshot)
    same(first, run(other, 60, start=30))


def test_reset_with_a_seed_is_a_new_run_of_that_seed():
    sim = turf.Sim("ssl_div_a", seed=1, realism="realistic")
    run(sim, 10)
    sim.reset(seed=5)
    assert sim.seed == 5 and sim.frame == 0
    same(run(sim, 30), run(turf.Sim("ssl_div_a", seed=5, realism="realistic"), 30))
    sim.reset()
    assert sim.frame == 0 and sim.seed == 5


def test_robots_drive_and_kick():
    sim = turf.Sim("ssl_div_a", seed=1, realism="ideal")
    row = int(np.flatnonzero((sim.robot_ids[:, 0] == 0) & (sim.robot_ids[:, 1] == 10))[0])
    start = sim.observation()["robots"][row].copy()
    c = np.zeros((RPT, 6))
    c[10, 0] = 1.0  # blue 10 forwards (it faces +x, the ball 0.7 m ahead) at 1 m/s, kicking
    c[10, 3] = 4.0
    fastest = 0.0
    for _ in range(60):
        o = sim.step({"blue": c}, 8)
        fastest = max(fastest, o["ball"][3])
    assert o["robots"][row, 0] - start[0] > 0.3
    assert o["robots"][row, 8] >= 1  # kick count
    assert fastest > 2.0  # kicked towards +x (then it meets yellow 10)


@pytest.mark.parametrize("bad,error", [
    (np.full((RPT, 6), np.nan), "not_finite"),
    (np.zeros((RPT, 5)), "malformed"),
    (np.zeros((3, 6)), "malformed"),
    ("fast", "malformed"),
    (np.tile([50.0, 0, 0, 0, 0, 0], (RPT, 1)), "out_of_range"),
    (np.tile([0.0, 0, 0, 1.0, 2.0, 0], (RPT, 1)), "unknown_enum"),
])
def test_bad_commands_raise_and_change_nothing(bad, error):
    sim = turf.Sim("ssl_div_a", seed=1, realism="realistic")
    run(sim, 5)
    before = sim.save()
    if isinstance(bad, np.ndarray) and bad.shape == (RPT, 6):
        bad = bad.copy()
        bad[:3] = 0.0  # the first robots' commands are fine: the batch is refused whole
    with pytest.raises(turf.TurfError) as e:
        sim.step({"blue": bad}, 8)
    assert e.value.error == error
    assert isinstance(e.value, ValueError)
    assert sim.save() == before


def test_bad_step_counts_and_teams():
    sim = turf.Sim("ssl_div_a", seed=1)
    before = sim.save()
    for n in (0, -1, 2_000_000, 2**63, -(2**70)):
        with pytest.raises(turf.TurfError) as e:
            sim.step(None, n)
        assert e.value.error == "out_of_range"
    with pytest.raises(turf.TurfError) as e:
        sim.step(None, 2.5)
    assert e.value.error == "malformed"
    for team in ("green", 2, 2**70):
        with pytest.raises(turf.TurfError) as e:
            sim.step({team: np.zeros((RPT, 6))})
        assert e.value.error == "unknown_team"
    assert sim.save() == before


def test_teleports_and_their_errors():
    sim = turf.Sim("ssl_div_a", seed=1)
    o = sim.teleport_ball(2.0, -1.0, vx=0.5)
    np.testing.assert_allclose(o["ball"][:2], [2.0, -1.0])
    o = sim.teleport_robot("yellow", 3, x=1.0, y=2.0, orientation=0.5)
    ids = sim.robot_ids
    row = int(np.flatnonzero((ids[:, 0] == 1) & (ids[:, 1] == 3))[0])
    np.testing.assert_allclose(o["robots"][row, :3], [1.0, 2.0, 0.5], atol=1e-9)
    o = sim.teleport_robot("yellow", 3, on_field=False)
    assert o["robots"][row, 6] == 0
    before = sim.save()
    cases = [
        (lambda: sim.teleport_ball(50.0, 0.0), "outside_field"),
        (lambda: sim.teleport_ball(float("nan"), 0.0), "not_finite"),
        (lambda: sim.teleport_ball(0.0, 0.0, vx=100.0), "out_of_range"),
        (lambda: sim.teleport_robot("blue", 16), "unknown_robot"),
        (lambda: sim.teleport_robot("blue", 1, x=float("inf")), "not_finite"),
        (lambda: sim.command("blue", 1, vx=float("nan")), "not_finite"),
        (lambda: sim.command("blue", 1, frame="polar"), "unknown_enum"),
    ]
    for call, error in cases:
        with pytest.raises(turf.TurfError) as e:
            call()
        assert e.value.error == error, e.value
    assert sim.save() == before


def test_a_teleport_returns_no_camera_frames_of_the_step_before():
    sim = turf.Sim("ssl_div_a", seed=1)
    o = sim.step(None, 50)
    assert len(o["ball_detections"]) > 0
    for o in (sim.teleport_ball(1.0, 1.0), sim.teleport_robot("blue", 0, x=-1.0, y=0.5)):
        assert len(o["ball_detections"]) == 0 and len(o["robot_detections"]) == 0 and len(o["camera_frames"]) == 0


def test_a_damaged_snapshot_is_refused_and_the_sim_steps_on():
    """A changed byte made a position 1e76: restore() took it and the next step() ended the Python process in
    MuJoCo's fatal error handler ("Rank-defficient Hessian ... Press Enter to exit")."""
    sim = turf.Sim("ssl_div_a", seed=1, realism="harsh")
    sim.step({"blue": np.tile([1, 0, 0, 3, 0, 100.0], (RPT, 1))}, 200)
    good = sim.save()
    qpos = good.index(b"MJDA") + 4 + 8 + 8 + 64  # tag, model fingerprint, time, warnings: then MuJoCo's qpos
    refused = 0
    for i in range(48):
        for top in (0x4F, 0x7F):  # the top byte of a double: ~1e76, or NaN/inf
            bad = bytearray(good)
            bad[qpos + 8 * i + 7] = top
            try:
                sim.restore(bytes(bad))
            except turf.TurfError as e:
                assert e.error == "malformed", e
                refused += 1
            sim.step(None, 5)  # a snapshot accepted is one MuJoCo steps from
            sim.restore(good)
    assert refused >= 48
    o = sim.step(None, 5)
    assert np.isfinite(o["ball"]).all()


def test_realism_changes_as_the_control_topic():
    sim = turf.Sim("ssl_div_a", seed=1, realism="ideal")
    assert sim.realism["camera.link.latency"] == 0.0
    sim.set_realism(values={"camera.link.latency": 0.01})
    assert sim.realism["camera.link.latency"] == 0.01
    sim.set_realism(preset="harsh")
    assert sim.realism["camera.robot_vanish"] > 0
    before = sim.realism
    for kwargs, error in [({"preset": "nosuch"}, "unknown_preset"),
                          ({"values": {"camera.nosuch": 1.0}}, "unknown_key"),
                          ({"values": {"camera.link.loss": 2.0}}, "out_of_range"),
                          ({"values": {"camera.link.loss": float("nan")}}, "not_finite"),
                          ({"values": {"command.jitter_kind": 7}}, "unknown_enum")]:
        with pytest.raises(turf.TurfError) as e:
            sim.set_realism(**kwargs)
        assert e.value.error == error, e.value
    assert sim.realism == before


def test_scenes_by_name_and_path_and_bad_ones():
    assert turf.Sim(turf.scene_path("ssl_div_b")).robots_per_team > 0
    with pytest.raises(ValueError):
        turf.Sim("no_such_scene")
    with pytest.raises(turf.TurfError) as e:
        turf.Sim("ssl_div_a").restore(b"not a snapshot")
    assert e.value.error == "malformed"
    assert "not_finite" in turf.error_names()


def test_scene_overrides_for_learning():
    sim = turf.Sim("ssl_div_a", seed=1, robots_per_team=11, **turf.FAST_SSL)
    assert sim.step_seconds == pytest.approx(0.0025) and sim.robot_count == 22
    assert sim.observation()["robots"][:, 6].sum() == 22
    o = sim.step(np.zeros((2, 11, 6)), 7)
    assert o["time"] == pytest.approx(7 * 0.0025)
    for kwargs in ({"robots_per_team": 17}, {"robots_per_team": -1}, {"physics_step": 1.0},
                   {"physics_step": float("nan")}, {"wall_segments": -1}, {"wall_segments": 65}):
        with pytest.raises(ValueError):
            turf.Sim("ssl_div_a", **kwargs)
    with pytest.raises(ValueError):
        turf.Sim("t1_stand", robots_per_team=1)
    with pytest.raises(ValueError):
        turf.Sim("t1_stand", wall_segments=2)


def test_walls_of_two_boxes_bounce_the_ball_as_one_box():
    """The ball hits the touch-line wall at the seam of its two boxes (x = 0) and beside it: the same rebound as
    from the whole wall, and as without wall boxes (0, turf.FAST_SSL: the containment stage alone)."""
    rebounds = set()
    for segments in (1, 2, 0):
        for x in (0.0, 0.01, 2.0):
            sim = turf.Sim("ssl_div_a", seed=1, realism="ideal", robots_per_team=1, wall_segments=segments)
            sim.teleport_robot("blue", 0, on_field=False)
            sim.teleport_robot("yellow", 0, on_field=False)
            sim.teleport_ball(x, 4.3, vy=3.0, roll=True)
            slowest = min(sim.step(None, 1)["ball"][4] for _ in range(150))
            rebounds.add(round(slowest, 9))
    assert len(rebounds) == 1 and next(iter(rebounds)) < -1.0


def test_a_call_from_another_thread_while_stepping_is_refused_not_a_crash():
    """step() releases the GIL; another thread's reset with a new seed rebuilt the world under the step (SIGSEGV).
    Now every other call on that Sim raises not_allowed while it steps; afterwards the Sim works as before."""
    import threading
    import time

    sim = turf.Sim("ssl_div_a", seed=1)
    started = threading.Event()
    results = []

    def stepping():
        started.set()
        while len(results) < 200:
            try:
                results.append(sim.step(None, 200)["time"])
            except turf.TurfError:  # the main thread's step() was running
                pass

    worker = threading.Thread(target=stepping)
    worker.start()
    started.wait(30)
    refused = {}
    deadline = time.monotonic() + 120
    calls = {
        "reset": lambda: sim.reset(seed=7),
        "step": lambda: sim.step(None, 1),
        "observation": sim.observation,
        "teleport_ball": lambda: sim.teleport_ball(0, 0),
        "time": lambda: sim.time,
        "save": sim.save,
    }
    while worker.is_alive() and len(refused) < len(calls) and time.monotonic() < deadline:
        for name, call in calls.items():
            try:
                call()
            except turf.TurfError as e:
                assert e.error == "not_allowed", e
                refused[name] = str(e)
    worker.join()
    assert sorted(refused) == sorted(calls), refused  # each was refused at least once while stepping
    assert "another thread" in refused["reset"]
    assert len(results) == 200
    assert sim.reset(seed=7)["time"] == 0.0
    assert sim.seed == 7
