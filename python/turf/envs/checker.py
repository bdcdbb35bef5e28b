"""check_env: an environment against Gymnasium's documented API contract (gymnasium.Env's reset and step,
gymnasium.spaces' Space), written from that documentation, without gymnasium:

  - action_space and observation_space are spaces (sample, contains, seed, shape, dtype);
  - metadata is a dict; render_mode is None or one of metadata["render_modes"];
  - reset(seed=..., options=...) returns (obs, info): obs in observation_space (with its dtype), info a dict;
  - reset with the same seed gives the same observation (and the same actions then the same trajectory);
  - step(action) returns (obs, reward, terminated, truncated, info): obs in observation_space, reward a real
    number, terminated and truncated bools, info a dict;
  - an observation handed out is not changed by later steps (no aliasing of internal buffers);
  - action_space.seed(s) makes sample() repeatable, and its samples are in the space;
  - after terminated or truncated, reset starts a new episode;
  - close() may be called more than once.
Raises AssertionError naming the first clause an environment breaks; returns the clauses checked."""

import copy
from numbers import Real

import numpy as np


def _check_space(space, name):
    for attr in ("sample", "contains", "seed", "shape", "dtype"):
        assert hasattr(space, attr), f"{name} has no {attr} (not a gymnasium-shaped space)"


def _leaves(x):
    if isinstance(x, dict):
        for k in sorted(x):
            yield from _leaves(x[k])
    else:
        yield np.asarray(x)


def _equal(a, b):
    la, lb = list(_leaves(a)), list(_leaves(b))
    return len(la) == len(lb) and all(x.shape == y.shape and np.array_equal(x, y) for x, y in zip(la, lb))


def _check_obs(space, obs, where):
    assert space.contains(obs), f"{where}: the observation is not in observation_space"
    if isinstance(obs, dict):
        for k, v in obs.items():
            _check_obs(space[k], v, f"{where}['{k}']")
    elif getattr(space, "dtype", None) is not None:
        assert isinstance(obs, np.ndarray), f"{where}: the observation is no NumPy array"
        assert obs.dtype == space.dtype, f"{where}: dtype {obs.dtype}, the space says {space.dtype}"


def _check_reset(env, seed):
    out = env.reset(seed=seed, options=None)
    assert isinstance(out, tuple) and len(out) == 2, "reset must return (obs, info)"
    obs, info = out
    assert isinstance(info, dict), "reset's info must be a dict"
    _check_obs(env.observation_space, obs, "reset")
    return obs


def _check_step(env, action):
    out = env.step(action)
    assert isinstance(out, tuple) and len(out) == 5, "step must return (obs, reward, terminated, truncated, info)"
    obs, reward, terminated, truncated, info = out
    _check_obs(env.observation_space, obs, "step")
    assert isinstance(reward, Real) and not isinstance(reward, bool), f"reward must be a real number: {reward!r}"
    assert isinstance(terminated, (bool, np.bool_)), f"terminated must be a bool: {terminated!r}"
    assert isinstance(truncated, (bool, np.bool_)), f"truncated must be a bool: {truncated!r}"
    assert isinstance(info, dict), "step's info must be a dict"
    return obs, reward, bool(terminated), bool(truncated)


def _rollout(env, seed, actions):
    obs = [copy.deepcopy(_check_reset(env, seed))]
    rewards = []
    for a in actions:
        o, r, terminated, truncated = _check_step(env, a)
        obs.append(copy.deepcopy(o))
        rewards.append(r)
        if terminated or truncated:
            break
    return obs, rewards


def check_env(env, seed=0, steps=30):
    checked = []
    _check_space(env.action_space, "action_space")
    _check_space(env.observation_space, "observation_space")
    checked.append("spaces")
    assert isinstance(getattr(env, "metadata", None), dict), "metadata must be a dict"
    modes = env.metadata.get("render_modes", [])
    assert env.render_mode is None or env.render_mode in modes, "render_mode must be None or in render_modes"
    checked.append("metadata")

    env.action_space.seed(seed)
    actions = [env.action_space.sample() for _ in range(steps)]
    env.action_space.seed(seed)
    again = [env.action_space.sample() for _ in range(steps)]
    assert all(_equal(a, b) for a, b in zip(actions, again)), "action_space.seed does not make sample repeatable"
    assert all(env.action_space.contains(a) for a in actions), "a sample is not in action_space"
    checked.append("action sampling")

    first = _check_reset(env, seed)
    kept = copy.deepcopy(first)
    for a in actions[:3]:
        o, _, terminated, truncated = _check_step(env, a)
        if terminated or truncated:
            break
    assert _equal(first, kept), "a later step changed an observation already handed out"
    checked.append("reset and step signatures")
    checked.append("observations not aliased")

    obs_a, rewards_a = _rollout(env, seed, actions)
    obs_b, rewards_b = _rollout(env, seed, actions)
    assert _equal(obs_a[0], obs_b[0]), "reset with the same seed gave another observation"
    assert len(obs_a) == len(obs_b) and all(_equal(x, y) for x, y in zip(obs_a, obs_b)), \
        "the same seed and actions gave another trajectory"
    assert rewards_a == rewards_b, "the same seed and actions gave other rewards"
    checked.append("determinism")

    _check_reset(env, seed + 1)
    done = False
    for a in actions:
        _, _, terminated, truncated = _check_step(env, a)
        if terminated or truncated:
            done = True
            break
    if done:
        _check_reset(env, None)
        checked.append("reset after the end of an episode")
    env.close()
    env.close()
    checked.append("close twice")
    return checked
