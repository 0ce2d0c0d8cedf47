#!/usr/bin/python3
"""Speed of the Python package against C++ (a benchmark, not a test).

1. SpherusVectorEnv(64): steps per second (world-steps) with the actions passed from Python at
   each step, against the same worlds stepped by the same C++ loop with no Python in between.
2. thyrix.evaluate against the C++ thyrix::evaluate (the helper thyrix_evaluate_reference,
   timed inside the program), same genomes and options.
3. The cost of a Python callable as a controller: a Spherus world stepped with a callable
   against the same world with its effectors set once (no controller).

    PYTHONPATH=build/release/python /usr/bin/python3 bench/python_bench.py [--quick]
"""

import argparse
import os
import pathlib
import subprocess
import time

import numpy as np

import thyrix
from thyrix.envs import SpherusVectorEnv


def best_of(repeats, function):
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        function()
        times.append(time.perf_counter() - start)
    return min(times)


def vector_env(num_envs, threads, steps, repeats):
    env = SpherusVectorEnv(num_envs, threads=threads, seed=1, steps=1000)
    actions = np.random.default_rng(0).uniform(0, 1, size=(num_envs, 5))
    env.reset(seed=1)

    def from_python():
        for _ in range(steps):
            env.step(actions)

    python = best_of(repeats, from_python)
    env.reset(seed=1)
    cxx = best_of(repeats, lambda: env.step_in_cpp(actions, steps))
    rate_python = num_envs * steps / python
    rate_cxx = num_envs * steps / cxx
    print(f"SpherusVectorEnv({num_envs}, threads={threads}): Python {rate_python / 1e6:.3f} M "
          f"world-steps/s, C++ loop {rate_cxx / 1e6:.3f} M/s, ratio {rate_python / rate_cxx:.3f}")


def evaluate(reference, population, steps, threads, repeats):
    genomes = np.random.default_rng(3).normal(0, 1, size=(population, 333))
    python = best_of(repeats, lambda: thyrix.evaluate(genomes, steps=steps, threads=threads,
                                                      seed=1))
    text = "\n".join(" ".join(float(x).hex() for x in row) for row in genomes) + "\n"
    cxx = []
    for _ in range(repeats):
        run = subprocess.run([reference, "distance", str(steps), "ff:8", "1", str(threads), "1",
                              "0"], input=text, capture_output=True, text=True, check=True)
        cxx.append(float(run.stderr.split()[-1]))
    cxx = min(cxx)
    print(f"evaluate({population} genomes x {steps} steps, threads={threads}): Python "
          f"{python * 1e3:.1f} ms, C++ {cxx * 1e3:.1f} ms, ratio {cxx / python:.3f}")


def callable_controller(steps, repeats):
    action = np.array([1.0, 0.0, 1.0, 0.0, 0.5])

    def run(controller):
        world = thyrix.SpherusSimulator(seed=1, controller=controller)
        if controller is None:
            world.spherus.effectors = action
        return best_of(repeats, lambda: world.advance_time(steps)) / steps

    plain = run(None)
    network = run(thyrix.NeuralController(thyrix.spherus_network("ff:8")))
    python = run(lambda sensors: action)
    print(f"Spherus step: no controller {plain * 1e6:.2f} us, C++ NeuralController 35-8-5 "
          f"{network * 1e6:.2f} us, Python callable {python * 1e6:.2f} us "
          f"(the callable costs {(python - plain) * 1e6:.2f} us a step)")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--quick", action="store_true", help="fewer steps and repeats")
    parser.add_argument("--reference", default=None, help="thyrix_evaluate_reference's path")
    options = parser.parse_args()
    reference = options.reference or str(
        pathlib.Path(thyrix.__file__).resolve().parent.parent / "thyrix_evaluate_reference")
    steps, repeats = (200, 3) if options.quick else (1000, 10)
    print(f"{os.cpu_count()} hardware threads; real = {thyrix.real_dtype}")
    for threads in (1, 2):
        vector_env(64, threads, steps, repeats)
    for threads in (1, 2):
        evaluate(reference, 64, steps, threads, repeats)
    callable_controller(steps * 10, repeats)


if __name__ == "__main__":
    main()
