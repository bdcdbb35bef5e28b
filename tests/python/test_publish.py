"""Sim.publish(domain=...) in the Python process: options refused as turf-sim refuses them, publishing changes
no observation, unpublish. (What a DDS reader in another process receives: publish_test.cpp.)"""

import os

import numpy as np
import pytest

import turf

# A domain of this process (as tests/test_domain.h: 1..99, below Linux's ephemeral ports), nobody listening.
DOMAIN = 1 + (os.getpid() + 57) % 99


def drive(sim, calls):
    c = np.zeros((2, sim.robots_per_team, 6))
    out = []
    for k in range(calls):
        c[:, :, 0] = np.sin(0.1 * k + np.arange(sim.robots_per_team))
        c[:, :, 3] = 3.0 if k % 7 == 0 else 0.0
        o = sim.step(c, 8)
        out.append(np.concatenate([o["ball"], o["robots"].ravel(), o["ball_detections"].ravel(),
                                   o["robot_detections"].ravel()]))
    return out


def test_bad_options_are_refused_and_change_nothing():
    sim = turf.Sim("ssl_div_a", seed=1)
    for domain in (-1, 233):
        with pytest.raises(turf.TurfError) as e:
            sim.publish(domain=domain)
        assert e.value.error == "out_of_range"
    for prefix in ("", "two words", "team*"):
        with pytest.raises(turf.TurfError) as e:
            sim.publish(domain=DOMAIN, prefix=prefix)
        assert e.value.error == "malformed"
    assert sim.publishing is None and sim.state_readers == 0
    sim.publish(domain=DOMAIN, prefix="pytest_refused_%d" % os.getpid())
    for bad in ({"domain": 999}, {"prefix": ""}, {"qos_file": "/nonexistent/turf_qos.xml"}):
        with pytest.raises(turf.TurfError):
            sim.publish(**{"domain": DOMAIN, "prefix": "pytest_other", **bad})
        assert sim.publishing["prefix"].startswith("pytest_refused_"), bad  # refused: the running one goes on
    sim.unpublish()


def test_publishing_changes_no_observation():
    quiet = turf.Sim("ssl_div_a", seed=3, realism="realistic")
    loud = turf.Sim("ssl_div_a", seed=3, realism="realistic")
    loud.publish(domain=DOMAIN, prefix="pytest_publish_%d" % os.getpid())
    assert loud.publishing["domain"] == DOMAIN and "domain %d" % DOMAIN in loud.publishing["description"]
    assert loud.state_readers == 0  # nobody listens on this prefix
    for a, b in zip(drive(quiet, 40), drive(loud, 40)):
        np.testing.assert_array_equal(a, b)
    snapshot = loud.save()
    loud.teleport_ball(0.5, 0.5)
    loud.restore(snapshot)
    loud.reset(seed=4)
    quiet.reset(seed=4)
    for a, b in zip(drive(quiet, 10), drive(loud, 10)):
        np.testing.assert_array_equal(a, b)
    loud.unpublish()
    assert loud.publishing is None
    drive(loud, 2)


def test_a_legged_sim_publishes_too():
    sim = turf.Sim("t1_stand", seed=1)
    sim.publish(domain=DOMAIN, prefix="pytest_publish_legged_%d" % os.getpid())
    start = sim.start_joints(0)
    rows = np.zeros((len(start), 5))
    rows[:, 0] = np.nan_to_num(start[:, 0])
    rows[:, 2] = 50.0
    o = sim.step({"t1": rows}, 20)
    assert o["frame"] == 20 and sim.publishing["prefix"].startswith("pytest_publish_legged_")
    sim.reset()
    sim.unpublish()
