"""The Gymnasium-shaped environments against the contract checker (written from Gymnasium's documented API),
and their refusals of bad actions."""

import numpy as np
import pytest

import turf
from turf import envs


def make(name):
    return {"kick": lambda: envs.SslGoToBallKickEnv(),
            "match": lambda: envs.SslMatchEnv(),
            "t1": lambda: envs.T1WalkEnv(task="walk")}[name]()


@pytest.mark.parametrize("name", ["kick", "match", "t1"])
def test_contract(name):
    checked = envs.check_env(make(name), seed=3, steps=20)
    assert "determinism" in checked and "observations not aliased" in checked


def test_checker_finds_a_broken_environment():
    class Broken(envs.SslGoToBallKickEnv):
        def reset(self, *, seed=None, options=None):
            return super().reset(seed=seed, options=options)[0]  # no info

    with pytest.raises(AssertionError, match=r"\(obs, info\)"):
        envs.check_env(Broken())


def test_bad_actions_raise_and_change_nothing():
    env = envs.SslGoToBallKickEnv()
    env.reset(seed=1)
    before = env.sim.save()
    for action, error in [([np.nan, 0, 0, 0], "not_finite"), ([0, 0, 0], "malformed"), ("go", "malformed")]:
        with pytest.raises(turf.TurfError) as e:
            env.step(action)
        assert e.value.error == error
    assert env.sim.save() == before
    match = envs.SslMatchEnv()
    match.reset(seed=1)
    before = match.sim.save()
    action = match.action_space.sample()
    action["yellow"] = action["yellow"][:3]
    with pytest.raises(turf.TurfError):
        match.step(action)
    with pytest.raises(turf.TurfError):
        match.step({"blue": action["blue"]})
    assert match.sim.save() == before


def kick_policy(obs, goal_x):
    """Get behind the ball on its line to the goal, face the goal, then drive through the ball kicking."""
    x, y, c, s = obs[:4]
    bx, by = obs[7:9]
    g = np.array([goal_x - bx, -by])
    g /= np.linalg.norm(g)
    behind = np.array([bx, by]) - 0.2 * g - [x, y]
    err = (np.arctan2(g[1], g[0]) - np.arctan2(s, c) + np.pi) % (2 * np.pi) - np.pi
    ready = np.linalg.norm(behind) < 0.05 and abs(err) < 0.2
    d = 0.5 * g if ready else behind
    local = 2 * np.array([c * d[0] + s * d[1], -s * d[0] + c * d[1]])
    return np.array([*np.clip(local, -1, 1), np.clip(2 * err, -1, 1), 1.0 if ready else -1.0], dtype=np.float32)


def test_kick_task_can_be_solved_by_a_scripted_policy():
    """Over five seeded episodes the scripted policy earns reward and scores at least once."""
    env = envs.SslGoToBallKickEnv()
    goals, total = 0, 0.0
    for seed in range(5):
        obs, _ = env.reset(seed=seed)
        for _ in range(600):
            obs, reward, terminated, truncated, info = env.step(kick_policy(obs, env.sim.field["length"] / 2))
            total += reward
            if terminated or truncated:
                break
        goals += info["goal"] > 0
    assert goals >= 1
    assert total > 10.0


def test_t1_stands_with_zero_actions():
    env = envs.T1WalkEnv(task="stand")
    env.reset(seed=0)
    for _ in range(50):  # 1 s
        _, reward, terminated, _, info = env.step(np.zeros(env.action_space.shape, dtype=np.float32))
        assert not terminated
    assert info["height"] > 0.55


def test_spaces():
    box = envs.Box(-1.0, 1.0, (3, 2), dtype=np.float32)
    box.seed(1)
    a = box.sample()
    assert a.shape == (3, 2) and a.dtype == np.float32 and box.contains(a)
    assert not box.contains(np.full((3, 2), 2.0, dtype=np.float32))
    assert not box.contains(np.zeros(6, dtype=np.float32))
    d = envs.Dict({"a": box, "b": envs.Box(0, 1, (1,))})
    d.seed(2)
    s = d.sample()
    assert d.contains(s) and not d.contains({"a": s["a"]})
