"""Thyrix from Python: a very fast deterministic 2D quasistatic (F = m v) simulator.

The C++ core lives in the extension module ``thyrix._thyrix``; everything it offers is
re-exported here. ``thyrix.envs`` has the Gymnasium-style environments, ``thyrix.evaluate``
scores a population of neural-network genomes in parallel.
"""

import numpy as _np

from ._thyrix import *  # noqa: F401,F403  (the bindings are the package's API)
from ._thyrix import SpherusTask, evaluate_task, hardware_threads

__all__ = [name for name in dir() if not name.startswith("_")] + ["evaluate"]


def evaluate(genomes, task="distance", steps=1000, trials=1, threads=None, seed=1,
             generation=0, network="ff:8", objects=20, random_pose=True, comm=None):
    """Fitness of each genome of a population on a Spherus task, in parallel.

    Args:
        genomes: float array of shape ``(P, D)``, one genome (network parameters, in
            NetworkSpec's order) a row; ``D`` is the network's parameter count (333 for
            ``"ff:8"``).
        task: ``"distance"`` (straight distance covered, m) or ``"clear"`` (how far the balls
            were pushed toward the walls, m), or a ``SpherusTask`` (which then sets
            ``steps``, ``network``, ``objects`` and ``random_pose`` too).
        steps: steps of an episode.
        trials: episodes per genome; the fitness is their mean.
        threads: threads to use (default: every hardware thread).
        seed: the run's seed; episode ``t`` of genome ``i`` is seeded by
            ``derive_seed(seed, generation, i, t)``.
        generation: the generation, for the episodes' seeds.
        network: ``"ff"``, ``"ff:H1[,H2...]"``, ``"ctrnn:N"`` or a ``NetworkSpec``.
        objects: balls in the arena.
        random_pose: start the agent at a pose drawn from the episode's seed.
        comm: an mpi4py communicator, to spread the episodes over its ranks (``thyrix.mpi``):
            every rank calls ``evaluate`` with the same options, rank 0 with the genomes (the
            others may pass ``None``); rank 0 gets the fitnesses, the same numbers as without
            ``comm``, the other ranks ``None``. ``threads`` is then per rank.

    Returns:
        A float64 array of shape ``(P,)``: the same numbers as the C++ ``thyrix::evaluate``
        for the same genomes and options, whatever ``threads``.

    Raises:
        TypeError: ``genomes`` is not an array of real numbers.
        ValueError: a wrong shape, a non-finite value, or a bad option (named).
    """
    if not isinstance(task, SpherusTask):
        task = SpherusTask(task, steps, network, objects, random_pose)
    if threads is None:
        threads = hardware_threads()
    for name, value in (("trials", trials), ("threads", threads)):
        if isinstance(value, bool) or not isinstance(value, (int, _np.integer)) or value < 1:
            raise ValueError(f"{name} must be a positive integer (got {value!r})")
    if comm is not None:
        from . import mpi as _mpi  # imports mpi4py only when asked to

        return _mpi.evaluate(comm, genomes, task, int(trials), int(threads), int(seed),
                             int(generation))
    return evaluate_task(task, genomes, int(trials), int(threads), int(seed), int(generation))
