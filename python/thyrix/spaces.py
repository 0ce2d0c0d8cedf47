"""Box: the observation and action spaces of the environments, without gymnasium."""

import numpy as np


class Box:
    """A box of real vectors, like ``gymnasium.spaces.Box``: ``shape``, ``low``, ``high``,
    ``dtype``, ``sample()`` and ``contains()``."""

    def __init__(self, low, high, shape, dtype=np.float64, seed=None):
        self.shape = tuple(shape)
        self.dtype = np.dtype(dtype)
        self.low = np.full(self.shape, low, dtype=self.dtype)
        self.high = np.full(self.shape, high, dtype=self.dtype)
        self._rng = np.random.default_rng(seed)

    def seed(self, seed=None):
        """Reseeds sample()."""
        self._rng = np.random.default_rng(seed)

    def sample(self):
        """A uniform random point of the box."""
        return self._rng.uniform(self.low, self.high).astype(self.dtype)

    def contains(self, x):
        """True when ``x`` has the box's shape and lies inside it."""
        x = np.asarray(x)
        return (x.shape == self.shape and np.can_cast(x.dtype, self.dtype)
                and bool(np.all(x >= self.low)) and bool(np.all(x <= self.high)))

    def __contains__(self, x):
        return self.contains(x)

    def __repr__(self):
        return f"Box({self.low.flat[0]}, {self.high.flat[0]}, {self.shape}, {self.dtype})"
