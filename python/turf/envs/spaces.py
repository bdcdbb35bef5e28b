"""Box and Dict spaces: gymnasium.spaces when gymnasium is importable, else minimal ones of our own with the
same constructor, ``sample``, ``contains``, ``seed``, ``shape`` and ``dtype`` (what the environments and the
contract checker use)."""

import numpy as np

try:  # pragma: no cover - gymnasium is not in Debian
    import gymnasium as _gym
    from gymnasium.spaces import Box, Dict, Space
    HAVE_GYMNASIUM = True
    EnvBase = _gym.Env
except ImportError:
    HAVE_GYMNASIUM = False

    class Space:
        def __init__(self, shape=None, dtype=None, seed=None):
            self._shape = None if shape is None else tuple(shape)
            self.dtype = None if dtype is None else np.dtype(dtype)
            self._np_random = None
            if seed is not None:
                self.seed(seed)

        @property
        def shape(self):
            return self._shape

        @property
        def np_random(self):
            if self._np_random is None:
                self.seed()
            return self._np_random

        def seed(self, seed=None):
            self._np_random = np.random.default_rng(seed)
            return [seed]

        def __contains__(self, x):
            return self.contains(x)

    class Box(Space):
        """Every element in [low, high], of one shape and dtype."""

        def __init__(self, low, high, shape=None, dtype=np.float32, seed=None):
            dtype = np.dtype(dtype)
            if shape is None:
                shape = np.broadcast(np.asarray(low), np.asarray(high)).shape
            shape = tuple(int(d) for d in shape)
            self.low = np.broadcast_to(np.asarray(low, dtype=dtype), shape).copy()
            self.high = np.broadcast_to(np.asarray(high, dtype=dtype), shape).copy()
            super().__init__(shape, dtype, seed)

        def sample(self, mask=None):
            low = np.where(np.isfinite(self.low), self.low, -1e6).astype(np.float64)
            high = np.where(np.isfinite(self.high), self.high, 1e6).astype(np.float64)
            return self.np_random.uniform(low, high, self.shape).astype(self.dtype)

        def contains(self, x):
            if not isinstance(x, np.ndarray):
                try:
                    x = np.asarray(x, dtype=self.dtype)
                except (ValueError, TypeError):
                    return False
            return bool(np.can_cast(x.dtype, self.dtype) and x.shape == self.shape and np.all(x >= self.low)
                        and np.all(x <= self.high))

        def __repr__(self):
            return f"Box({self.low.min()}, {self.high.max()}, {self.shape}, {self.dtype})"

        def __eq__(self, other):
            return (isinstance(other, Box) and self.shape == other.shape and self.dtype == other.dtype
                    and np.array_equal(self.low, other.low) and np.array_equal(self.high, other.high))

    class Dict(Space):
        """A dict of named spaces."""

        def __init__(self, spaces=None, seed=None, **kwargs):
            spaces = dict(spaces or {}, **kwargs)
            self.spaces = dict(spaces)
            super().__init__(None, None, None)
            if seed is not None:
                self.seed(seed)

        def seed(self, seed=None):
            rng = np.random.default_rng(seed)
            self._np_random = rng
            seeds = [seed]
            for space in self.spaces.values():
                seeds += space.seed(int(rng.integers(2**31)))
            return seeds

        def sample(self, mask=None):
            return {k: s.sample() for k, s in self.spaces.items()}

        def contains(self, x):
            return (isinstance(x, dict) and set(x) == set(self.spaces)
                    and all(s.contains(x[k]) for k, s in self.spaces.items()))

        def __getitem__(self, key):
            return self.spaces[key]

        def keys(self):
            return self.spaces.keys()

        def items(self):
            return self.spaces.items()

        def __repr__(self):
            return "Dict(" + ", ".join(f"{k!r}: {s}" for k, s in self.spaces.items()) + ")"

    class EnvBase:
        """gymnasium.Env's shape: reset(seed, options) -> (obs, info); step(action) -> (obs, reward,
        terminated, truncated, info); np_random seeded by reset(seed=...)."""
        metadata = {"render_modes": []}
        render_mode = None
        spec = None
        _np_random = None

        @property
        def np_random(self):
            if self._np_random is None:
                self._np_random = np.random.default_rng()
            return self._np_random

        def reset(self, *, seed=None, options=None):
            if seed is not None:
                self._np_random = np.random.default_rng(seed)
            return None

        def render(self):
            return None

        def close(self):
            pass

        @property
        def unwrapped(self):
            return self
