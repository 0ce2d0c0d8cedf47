"""thyrix.evaluate against the C++ thyrix::evaluate, across thread counts, and bad input."""

import subprocess

import numpy as np
import pytest

import thyrix


def cxx_evaluate(reference, genomes, task, steps, network, trials, threads, seed, generation):
    """thyrix::evaluate run by the C++ helper program on the same genomes (exact hex floats)."""
    text = "\n".join(" ".join(float(x).hex() for x in row) for row in genomes) + "\n"
    result = subprocess.run(
        [reference, task, str(steps), network, str(trials), str(threads), str(seed),
         str(generation)],
        input=text, capture_output=True, text=True, check=True)
    return np.array([float.fromhex(line) for line in result.stdout.split()])


@pytest.mark.parametrize("task,network,trials,steps", [("distance", "ff:8", 2, 200),
                                                       ("distance", "ctrnn:3", 1, 200),
                                                       ("clear", "ff:8", 1, 3000)])
def test_the_same_numbers_as_the_cpp_evaluate(evaluate_reference, task, network, trials, steps):
    dimension = thyrix.spherus_network(network).parameter_count
    genomes = np.random.default_rng(9).normal(0, 1, size=(6, dimension))
    expected = cxx_evaluate(evaluate_reference, genomes, task, steps, network, trials, 2, 77, 3)
    got = thyrix.evaluate(genomes, task=task, steps=steps, network=network, trials=trials,
                          threads=1, seed=77, generation=3)
    assert got.shape == (6,) and got.dtype == np.float64
    assert np.array_equal(got, expected)
    assert len(set(got.tolist())) >= 3  # the genomes do differ


def test_the_same_numbers_whatever_the_threads():
    genomes = np.random.default_rng(1).normal(0, 1, size=(7, 333))
    results = [thyrix.evaluate(genomes, steps=150, trials=2, threads=t, seed=5) for t in (1, 2, 4)]
    assert np.array_equal(results[0], results[1]) and np.array_equal(results[0], results[2])


def test_an_episode_is_the_task_world_run_for_its_steps():
    """The evaluation's episode, rebuilt by hand from derive_seed and stepped from Python."""
    task = thyrix.SpherusTask("distance", 120, "ff:8")
    genomes = np.random.default_rng(2).normal(0, 1, size=(3, 333))
    got = thyrix.evaluate(genomes, task=task, trials=2, threads=2, seed=8, generation=1)
    for i, genome in enumerate(genomes):
        fitness = []
        for trial in range(2):
            world = task.make_world(genome, thyrix.derive_seed(8, 1, i, trial))
            world.advance_time(120)
            fitness.append(task.fitness(world))
        assert got[i] == (fitness[0] + fitness[1]) / 2


def test_bad_genomes_and_options():
    with pytest.raises(ValueError, match=r"genomes must have shape \(P, 333\)"):
        thyrix.evaluate(np.zeros((2, 10)))
    with pytest.raises(ValueError, match=r"genomes must have shape \(P, 333\)"):
        thyrix.evaluate(np.zeros(333))
    genomes = np.zeros((2, 333))
    genomes[1, 5] = np.inf
    with pytest.raises(ValueError, match="genomes must be finite"):
        thyrix.evaluate(genomes)
    with pytest.raises(TypeError, match="genomes must be an array of real numbers"):
        thyrix.evaluate(np.zeros((2, 333), dtype=complex))
    with pytest.raises(ValueError, match="trials"):
        thyrix.evaluate(np.zeros((2, 333)), trials=0)
    with pytest.raises(ValueError, match="threads"):
        thyrix.evaluate(np.zeros((2, 333)), threads=0)
    with pytest.raises(ValueError, match="--network"):
        thyrix.evaluate(np.zeros((2, 333)), network="big")
    assert thyrix.evaluate(np.zeros((0, 333)), steps=10).shape == (0,)
