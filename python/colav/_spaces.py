"""The spaces of the environments: gymnasium.spaces.Box when Gymnasium is installed, otherwise a
small Box with the same attributes (shape, dtype, low, high, contains, sample, seed), so code
written for Gymnasium runs without it."""

import numpy as np

try:
    import gymnasium
except ImportError:
    gymnasium = None

NAVIGATION_SIZE = 6
NUM_RAYS = 180
# The paper's observation (scan_history=0); with a scan history each earlier scan adds NUM_RAYS.
OBSERVATION_SIZE = NAVIGATION_SIZE + NUM_RAYS
ACTION_SIZE = 2


class _FallbackBox:
    """A box [low, high] of float arrays, as gymnasium.spaces.Box."""

    def __init__(self, low, high, shape=None, dtype=np.float32, seed=None):
        self.dtype = np.dtype(dtype)
        self.shape = tuple(shape) if shape is not None else np.shape(low)
        self.low = np.broadcast_to(np.asarray(low, dtype=self.dtype), self.shape).copy()
        self.high = np.broadcast_to(np.asarray(high, dtype=self.dtype), self.shape).copy()
        self.np_random = np.random.default_rng(seed)

    def seed(self, seed=None):
        self.np_random = np.random.default_rng(seed)
        return [seed]

    def contains(self, x):
        if not isinstance(x, np.ndarray):
            x = np.asarray(x, dtype=self.dtype)
        return bool(
            x.shape == self.shape
            and np.can_cast(x.dtype, self.dtype)
            and np.all(x >= self.low)
            and np.all(x <= self.high)
        )

    def __contains__(self, x):
        return self.contains(x)

    def sample(self):
        """As Gymnasium samples a box: uniform where bounded, exponential from a single bound,
        standard normal where unbounded."""
        has_low, has_high = np.isfinite(self.low), np.isfinite(self.high)
        sample = self.np_random.normal(size=self.shape)
        bounded = has_low & has_high
        sample[bounded] = self.np_random.uniform(self.low[bounded], self.high[bounded])
        only_low, only_high = has_low & ~has_high, has_high & ~has_low
        sample[only_low] = self.low[only_low] + self.np_random.exponential(size=only_low.sum())
        sample[only_high] = self.high[only_high] - self.np_random.exponential(size=only_high.sum())
        return sample.astype(self.dtype)

    def __repr__(self):
        return f"Box({self.low.min()}, {self.high.max()}, {self.shape}, {self.dtype})"


Box = gymnasium.spaces.Box if gymnasium is not None else _FallbackBox


def _observation_bounds(observation_size):
    """u, v, r and cte/100 are unbounded; the two heading errors are angles in [-pi, pi]; the
    closeness values of every scan lie in [0, 1] (README, "Observation")."""
    low = np.full(observation_size, -np.inf, dtype=np.float32)
    high = np.full(observation_size, np.inf, dtype=np.float32)
    low[4:NAVIGATION_SIZE], high[4:NAVIGATION_SIZE] = -np.float32(np.pi), np.float32(np.pi)
    low[NAVIGATION_SIZE:], high[NAVIGATION_SIZE:] = 0.0, 1.0
    return low, high


def observation_space(observation_size, num_envs=None):
    """Box of one observation [observation_size] (6 + 180*(1+scan_history), the environment's
    observation_size), or of a batch [num_envs, observation_size]."""
    low, high = _observation_bounds(observation_size)
    if num_envs is not None:
        low, high = np.tile(low, (num_envs, 1)), np.tile(high, (num_envs, 1))
    return Box(low=low, high=high, dtype=np.float32)


def action_space(num_envs=None):
    """Box [-1, 1] of one action [2] (thrust, yaw moment), or of a batch [num_envs, 2]."""
    shape = (ACTION_SIZE,) if num_envs is None else (num_envs, ACTION_SIZE)
    return Box(low=-1.0, high=1.0, shape=shape, dtype=np.float32)
