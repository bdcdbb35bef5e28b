"""turf.Sim on a legged scene (one Booster T1): joints, IMU and touch readings, PD commands, snapshots,
refusals."""

import numpy as np
import pytest

import turf


def hold(sim, scale=0.0, k=0):
    """PD rows holding the scene's start pose (plus a small sway)."""
    start = sim.start_joints(0)
    rows = np.zeros((len(start), 5))
    rows[:, 0] = np.nan_to_num(start[:, 0]) + scale * np.sin(0.1 * k + np.arange(len(start)))
    rows[:, 2] = np.nan_to_num(start[:, 1], nan=50.0)
    rows[:, 3] = np.nan_to_num(start[:, 2], nan=1.0)
    return rows


def run(sim, steps, start=0):
    out = []
    for k in range(start, start + steps):
        o = sim.step({"t1": hold(sim, 0.05, k)}, 4)
        r = o["robots"][0]
        out.append(np.concatenate([r[key] for key in ("joint_position", "joint_velocity", "gyro", "accelerometer",
                                                      "orientation", "force")]
                                  + [o["truth"][0]["base_position"]]))
    return np.array(out)


def test_readings_and_standing():
    sim = turf.Sim("t1_stand", seed=1, realism="realistic")
    assert sim.kind == "legged" and sim.robot_names == ["t1"]
    names = sim.joint_names(0)
    assert len(names) == 23 and "Left_Knee_Pitch" in names
    o = sim.observation()
    r = o["robots"][0]
    assert r["joint_position"].shape == (23,) and r["gyro"].shape == (3,) and r["orientation"].shape == (4,)
    assert len(r["contact"]) >= 2
    for k in range(50):  # 1 s of sim time holding the start pose
        o = sim.step({"t1": hold(sim)}, 4)
    assert o["time"] == pytest.approx(1.0)
    assert o["truth"][0]["base_position"][2] > 0.55  # still standing (starts at 0.665 m)
    assert np.linalg.norm(o["truth"][0]["base_velocity"]) < 0.1  # and at rest
    assert np.linalg.norm(o["robots"][0]["accelerometer"]) == pytest.approx(9.81, abs=1.0)
    assert o["robots"][0]["contact"].sum() >= 1


def test_determinism_and_snapshots():
    a = turf.Sim("t1_stand", seed=2, realism="realistic")
    b = turf.Sim("t1_stand", seed=2, realism="realistic")
    np.testing.assert_array_equal(run(a, 30), run(b, 30))
    snapshot = a.save()
    first = run(a, 30, 30)
    a.restore(snapshot)
    np.testing.assert_array_equal(first, run(a, 30, 30))


def test_bad_joint_commands_raise_and_change_nothing():
    sim = turf.Sim("t1_stand", seed=1)
    run(sim, 3)
    before = sim.save()
    good = hold(sim)
    nan = good.copy()
    nan[5, 0] = np.nan
    negative_gain = good.copy()
    negative_gain[3, 2] = -1.0
    garbage_target = good.copy()  # past the PD guard of ten turns (a target past the joint's range is a command)
    garbage_target[14, 0] = 100.0
    for commands, error in [({"t1": nan}, "not_finite"), ({"t1": negative_gain}, "out_of_range"),
                            ({"t1": garbage_target}, "out_of_range"), ({"t1": good[:5]}, "malformed"),
                            ({"nao_9": good}, "unknown_robot"), ({7: good}, "unknown_robot"),
                            ({2**40: good}, "unknown_robot")]:
        with pytest.raises(turf.TurfError) as e:
            sim.step(commands, 4)
        assert e.value.error == error, e.value
    for call, error in [(lambda: sim.teleport_robot("t1", [500.0, 0, 1]), "out_of_range"),
                        (lambda: sim.teleport_robot("t1", [np.nan, 0, 1]), "not_finite"),
                        (lambda: sim.joint_command("t1", "No_Such_Joint", "pd"), "unknown_joint"),
                        (lambda: sim.joint_command("t1", "Waist", "fly"), "unknown_enum"),
                        (lambda: sim.joint_command(2**40, "Waist", "pd"), "unknown_robot"),
                        (lambda: sim.teleport_ball([0, 0, 1]), "no_ball")]:
        with pytest.raises(turf.TurfError) as e:
            call()
        assert e.value.error == error, e.value
    assert sim.save() == before


def test_ball_touches_from_contacts():
    """A ball rolled into one T1 is touched by it, at a time inside the step that touched; the other never."""
    sim = turf.Sim("rcssservermj_fifa_1v1", seed=1)
    o = sim.observation()
    assert [r["ball_touch_time"][0] for r in o["truth"]] == [-1.0, -1.0]
    base = o["truth"][0]["base_position"]
    sim.teleport_ball([base[0] + 0.6, base[1], 0.11], [-3.0, 0.0, 0.0])
    before = o["time"]
    for _ in range(50):  # 1 s of sim time at most
        o = sim.step(None, 4)
        touch = o["truth"][0]["ball_touch_time"][0]
        if touch >= 0:
            break
        before = o["time"]
    assert before < touch <= o["time"], (before, touch, o["time"])
    assert o["robots"][0]["ball_touch_time"][0] == touch  # a fact of the contacts, not a noisy reading
    assert o["truth"][1]["ball_touch_time"][0] == -1.0
