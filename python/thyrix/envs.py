"""Gymnasium-style environments of Spherus, with no dependency on gymnasium.

``SpherusEnv`` is one arena; ``SpherusVectorEnv`` steps many in C++, on several threads, with
the GIL released. When gymnasium is importable, the environments derive from ``gymnasium.Env``,
use its ``Box`` spaces and are registered as ``thyrix/Spherus-v0``.
"""

import collections
import secrets

import numpy as np

from . import _thyrix
from .spaces import Box

try:  # optional: Debian 12 does not package gymnasium
    import gymnasium as _gymnasium
except ImportError:  # pragma: no cover - depends on the machine
    _gymnasium = None

SENSORS = 35  #: Spherus's sensors: the observation's length
EFFECTORS = 5  #: Spherus's effectors: the action's length

#: A SpherusEnv's state (SpherusEnv.save_state()): the episode's ``world`` (a WorldState), the
#: stream's ``seed``, the ``episode``'s index, the ``step`` in it and the task's ``score`` so far.
#: Picklable and copyable.
SpherusEnvState = collections.namedtuple("SpherusEnvState", "world seed episode step score")


def _box(shape):
    """A [0, 1] box of ``shape`` in the simulation's real type (gymnasium's when present)."""
    if _gymnasium is not None:
        return _gymnasium.spaces.Box(0.0, 1.0, shape, dtype=_thyrix.real_dtype)
    return Box(0.0, 1.0, shape, dtype=_thyrix.real_dtype)


def _seed_value(seed, name="seed"):
    """A seed as a non-negative int below 2**64; a fresh random one for None."""
    if seed is None:
        return secrets.randbits(32)
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)):
        raise TypeError(f"{name} must be an int or None, not {type(seed).__name__}")
    if not 0 <= seed < 2 ** 64:
        raise ValueError(f"{name} must be in [0, 2**64) (got {seed})")
    return int(seed)


def _task(task, steps, objects, random_pose):
    if isinstance(steps, bool) or not isinstance(steps, (int, np.integer)) or steps < 1:
        raise ValueError(f"steps must be a positive integer (got {steps!r})")
    return _thyrix.SpherusTask(task, int(steps), "ff", objects, random_pose)


_Base = _gymnasium.Env if _gymnasium is not None else object


class SpherusEnv(_Base):
    """Spherus in its arena of balls; an episode lasts ``steps`` steps.

    Observation: the 35 sensors, each in [0, 1] (per circle: 8 contact, 7 visual, 2 velocity;
    then the link length). Action: the 5 effectors, each in [0, 1] (outside values are
    clamped): left forward and backward rockets, right forward and backward, link length.
    Reward: the step's increase of the task's fitness, so an episode's rewards sum to the
    fitness ``thyrix.evaluate`` would give it: with ``task="distance"`` the straight distance
    from the start (m), with ``"clear"`` how far the balls were pushed toward the walls (m).
    Episodes never terminate; they are truncated after ``steps`` steps.

    Seeding: ``reset(seed=s)`` starts episode 0 of the stream ``s``, laid out (and, with
    ``random_pose``, posed) from ``thyrix.derive_seed(s, 0, 0, 0)``; each ``reset()`` without
    a seed starts the stream's next episode k, from ``derive_seed(s, k, 0, 0)``. The same seed
    and actions give the same observations and rewards, bit for bit.
    """

    metadata = {"render_modes": ["svg"]}

    def __init__(self, seed=None, steps=1000, task="distance", objects=20, random_pose=True,
                 render_mode=None):
        """``seed``: the first reset's seed when reset() is given none (None: a random one).
        ``render_mode``: None or ``"svg"`` (render() works in both)."""
        if render_mode not in (None, "svg"):
            raise ValueError(f"render_mode must be None or 'svg' (got {render_mode!r})")
        self._core = _thyrix.SpherusEnvCore(_task(task, steps, objects, random_pose))
        self._first_seed = seed
        self._started = False
        self.render_mode = render_mode
        self.observation_space = _box((SENSORS,))
        self.action_space = _box((EFFECTORS,))

    def reset(self, seed=None, options=None):
        """Starts an episode; returns ``(observation, info)``.

        ``seed``: None continues the stream (its next episode), an int starts the stream of
        that seed. ``options`` is accepted for Gymnasium's API and ignored.
        """
        if _gymnasium is not None:
            super().reset(seed=seed)
        if seed is not None:
            observation = self._core.reset(_seed_value(seed))
        elif not self._started:
            observation = self._core.reset(_seed_value(self._first_seed))
        else:
            observation = self._core.reset_next()
        self._started = True
        return observation, {"episode": self._core.episode}

    def step(self, action):
        """Drives the agent with ``action`` (5 finite numbers) for one step; returns
        ``(observation, reward, terminated, truncated, info)``."""
        if not self._started:
            raise ValueError("reset() must be called before step()")
        observation, reward, terminated, truncated = self._core.step(action)
        return observation, reward, terminated, truncated, {}

    def save_state(self):
        """A snapshot of the environment (SpherusEnvState): restore_state() of it, in this or
        in another SpherusEnv made with the same arguments, goes on exactly as this one does
        from here, bit for bit (branching: try several actions from one point)."""
        if not self._started:
            raise ValueError("reset() must be called before save_state()")
        return SpherusEnvState(*self._core.save_state())

    def restore_state(self, state):
        """Puts the environment in ``state`` (from save_state()); returns the observation.
        Raises ValueError saying what differs if the state is of another task's world (the
        environment is then unchanged)."""
        observation = self._core.restore_state(*state)
        self._started = True
        return observation

    def render(self):
        """The arena as an SVG document (a string; no display server needed)."""
        if not self._started:
            raise ValueError("reset() must be called before render()")
        return self._core.render()

    def close(self):
        """Nothing to release."""

    @property
    def agent_centre(self):
        """The agent's centre (x, y), m."""
        return self._core.agent_centre


class SpherusVectorEnv:
    """``num_envs`` Spherus arenas stepped together in C++, on ``threads`` threads with the GIL
    released, with autoreset.

    Actions are ``(num_envs, 5)``, observations ``(num_envs, 35)``. As in Gymnasium's vector
    environments, ``reset(seed=s)`` seeds world i with ``s + i``: world i then follows exactly
    the trajectory of a ``SpherusEnv`` reset with that seed and given the same actions, whatever
    ``threads``. A world whose episode is truncated by a step is reset at once to its stream's
    next episode (as ``SpherusEnv.reset()`` without a seed): that step returns the new
    episode's first observation, and ``info["final_observation"]`` (rows where
    ``info["_final_observation"]`` is True) holds the last one.
    """

    metadata = {"render_modes": ["svg"], "autoreset_mode": "same-step"}

    def __init__(self, num_envs, threads=None, seed=None, steps=1000, task="distance",
                 objects=20, random_pose=True):
        """``threads``: threads stepping the worlds (default: every hardware thread, at most
        ``num_envs``). ``seed``: the first reset's seed when reset() is given none."""
        for name, value in (("num_envs", num_envs), ("threads", threads)):
            if value is None and name == "threads":
                continue
            if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < 1:
                raise ValueError(f"{name} must be a positive integer (got {value!r})")
        if threads is None:
            threads = min(int(num_envs), _thyrix.hardware_threads())
        self._core = _thyrix.SpherusVectorEnvCore(int(num_envs), int(threads),
                                                  _task(task, steps, objects, random_pose))
        self.num_envs = int(num_envs)
        self._first_seed = seed
        self._started = False
        self.single_observation_space = _box((SENSORS,))
        self.single_action_space = _box((EFFECTORS,))
        self.observation_space = _box((self.num_envs, SENSORS))
        self.action_space = _box((self.num_envs, EFFECTORS))

    @property
    def threads(self):
        """Threads stepping the worlds, the caller's included."""
        return self._core.threads

    def reset(self, seed=None, options=None):
        """Resets every world; returns ``(observations, info)``. ``seed=s`` seeds world i with
        ``s + i``; None starts each world's next episode (or, at the first reset, uses the
        constructor's seed, or a random one)."""
        if seed is not None:
            observations = self._core.reset(_seed_value(seed))
        elif not self._started:
            observations = self._core.reset(_seed_value(self._first_seed))
        else:
            observations = self._core.reset_next()
        self._started = True
        return observations, {}

    def step(self, actions):
        """One step of every world, row i of ``actions`` driving world i; returns
        ``(observations, rewards, terminated, truncated, info)``."""
        if not self._started:
            raise ValueError("reset() must be called before step()")
        observations, rewards, terminated, truncated, finals = self._core.step(actions)
        done = terminated | truncated
        info = {}
        if done.any():
            info = {"final_observation": finals, "_final_observation": done}
        return observations, rewards, terminated, truncated, info

    def render(self, index=0):
        """World ``index``'s arena as an SVG document."""
        if not self._started:
            raise ValueError("reset() must be called before render()")
        return self._core.render(index)

    def step_in_cpp(self, actions, steps):
        """Benchmark baseline: ``steps`` steps with the same actions, looping in C++."""
        self._core.step_in_cpp(actions, steps)

    def close(self):
        """Nothing to release."""


if _gymnasium is not None:  # pragma: no cover - depends on the machine
    if "thyrix/Spherus-v0" not in _gymnasium.registry:
        _gymnasium.register(id="thyrix/Spherus-v0", entry_point="thyrix.envs:SpherusEnv")
