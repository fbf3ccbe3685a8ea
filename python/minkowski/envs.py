"""Helpers for reinforcement-learning environments written on minkowski.

An environment subclasses ``WorldEnv``: it is a ``gymnasium.Env`` when Gymnasium is installed,
and otherwise a stand-in with the same interface (``reset(seed=None, options=None)`` returning
``(observation, info)``, ``step(action)`` returning ``(observation, reward, terminated,
truncated, info)``, ``render()`` returning an (H, W, 3) uint8 array for
``render_mode='rgb_array'``, ``close()``, ``np_random``, ``action_space`` and
``observation_space``). ``spaces.Box`` and ``spaces.Discrete`` are Gymnasium's when it is
installed, else stand-ins that sample, check membership and seed the same way.
"""

import types

import numpy

import minkowski

__all__ = ["HAVE_GYMNASIUM", "WorldEnv", "spaces"]

try:
    import gymnasium
    from gymnasium import spaces

    HAVE_GYMNASIUM = True
    _EnvBase = gymnasium.Env
except ImportError:
    HAVE_GYMNASIUM = False

    class _Space:
        def __init__(self, shape, dtype, seed=None):
            self.shape = shape
            self.dtype = numpy.dtype(dtype)
            self._np_random = numpy.random.default_rng(seed)

        @property
        def np_random(self):
            return self._np_random

        def seed(self, seed=None):
            self._np_random = numpy.random.default_rng(seed)
            return [seed]

        def __contains__(self, x):
            return self.contains(x)

    class Box(_Space):
        """Points of R^n between low and high (each bound a scalar or an array)."""

        def __init__(self, low, high, shape=None, dtype=numpy.float32, seed=None):
            if shape is None:
                shape = numpy.broadcast(numpy.asarray(low), numpy.asarray(high)).shape
            super().__init__(tuple(shape), dtype, seed)
            self.low = numpy.broadcast_to(numpy.asarray(low, dtype=self.dtype), self.shape).copy()
            self.high = numpy.broadcast_to(numpy.asarray(high, dtype=self.dtype), self.shape).copy()

        def sample(self):
            low = numpy.where(numpy.isfinite(self.low), self.low, -1.0)
            high = numpy.where(numpy.isfinite(self.high), self.high, 1.0)
            unbounded = ~numpy.isfinite(self.low) & ~numpy.isfinite(self.high)
            out = self._np_random.uniform(low, high, size=self.shape)
            out[unbounded] = self._np_random.normal(size=self.shape)[unbounded]
            return out.astype(self.dtype)

        def contains(self, x):
            x = numpy.asarray(x)
            return bool(x.shape == self.shape and numpy.all(x >= self.low)
                        and numpy.all(x <= self.high))

        def __repr__(self):
            return f"Box({self.low.min()}, {self.high.max()}, {self.shape}, {self.dtype})"

    class Discrete(_Space):
        """The integers start .. start + n - 1."""

        def __init__(self, n, seed=None, start=0):
            super().__init__((), numpy.int64, seed)
            self.n = int(n)
            self.start = int(start)

        def sample(self):
            return numpy.int64(self.start + self._np_random.integers(self.n))

        def contains(self, x):
            try:
                value = int(x)
            except (TypeError, ValueError):
                return False
            return value == x and self.start <= value < self.start + self.n

        def __repr__(self):
            return f"Discrete({self.n})"

    spaces = types.SimpleNamespace(Box=Box, Discrete=Discrete)

    class _EnvBase:
        """Gymnasium's Env interface, for machines without Gymnasium."""

        metadata = {"render_modes": []}
        render_mode = None
        spec = None
        _np_random = None

        @property
        def np_random(self):
            if self._np_random is None:
                self._np_random = numpy.random.default_rng()
            return self._np_random

        @property
        def unwrapped(self):
            return self

        def reset(self, *, seed=None, options=None):
            if seed is not None:
                self._np_random = numpy.random.default_rng(seed)
            return None

        def close(self):
            pass

        def __enter__(self):
            return self

        def __exit__(self, *exc):
            self.close()
            return False


class WorldEnv(_EnvBase):
    """An environment around a minkowski World: ``self.world`` holds it, ``view`` is the world
    box (lower, upper) that render() shows, drawn by a Renderer made on first use."""

    metadata = {"render_modes": ["rgb_array"], "render_fps": 50}
    frame_size = (600, 400)

    def __init__(self, render_mode=None):
        if render_mode is not None and render_mode not in self.metadata["render_modes"]:
            raise minkowski.InvalidArgumentError(
                f"render_mode {render_mode!r} is not one of {self.metadata['render_modes']}")
        self.render_mode = render_mode
        self.world = None
        self.view = ((-10.0, -10.0), (10.0, 10.0))
        self._renderer = None

    def render(self):
        """The world as an (H, W, 3) uint8 array (render_mode 'rgb_array'), else None."""
        if self.render_mode != "rgb_array" or self.world is None:
            return None
        if self._renderer is None:
            self._renderer = minkowski.Renderer(*self.frame_size)
        self._renderer.fit(self.view[0], self.view[1], 0)
        return self._renderer.render(self.world, layers=["shapes"])

    def close(self):
        self._renderer = None
        super().close()
