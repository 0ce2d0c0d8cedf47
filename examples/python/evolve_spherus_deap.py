#!/usr/bin/python3
"""Evolves a Spherus controller with DEAP, scoring each generation with thyrix.evaluate.

A plain generational genetic algorithm on real vectors (the network's parameters): tournament
selection, blend crossover, Gaussian mutation and one elite. Each generation's population is
scored at once, in C++ on every thread, by ``thyrix.evaluate``; each generation's episodes are
seeded by (seed, generation), so a run is reproduced from its seed. Writes one CSV line per
generation (``generation,best,mean``) to ``--out`` and the best genome to ``--genome`` (which
``SpherusText --genome FILE`` replays). Plot the CSV with ``plot_fitness.py``.

    PYTHONPATH=build/release/python /usr/bin/python3 examples/python/evolve_spherus_deap.py \\
        --generations 30 --out fitness.csv --genome best.genome
"""

import argparse
import random
import sys

import numpy as np
from deap import base, creator, tools

import thyrix


def parse_arguments(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--generations", type=int, default=30)
    parser.add_argument("--population", type=int, default=64)
    parser.add_argument("--steps", type=int, default=1000, help="steps of an episode")
    parser.add_argument("--trials", type=int, default=1, help="episodes per genome")
    parser.add_argument("--task", default="distance", choices=["distance", "clear"])
    parser.add_argument("--network", default="ff:8", help="ff[:H1,...] or ctrnn:N")
    parser.add_argument("--threads", type=int, default=None, help="default: all")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--out", default="fitness.csv", help="the fitness CSV")
    parser.add_argument("--genome", default=None, help="write the best genome here")
    return parser.parse_args(argv)


def main(argv=None):
    options = parse_arguments(argv)
    spec = thyrix.spherus_network(options.network)
    dimension = spec.parameter_count
    random.seed(options.seed)  # DEAP's operators draw from Python's random module

    if not hasattr(creator, "FitnessMax"):
        creator.create("FitnessMax", base.Fitness, weights=(1.0,))
        creator.create("Individual", list, fitness=creator.FitnessMax)
    toolbox = base.Toolbox()
    toolbox.register("gene", random.gauss, 0.0, 0.5)
    toolbox.register("individual", tools.initRepeat, creator.Individual, toolbox.gene, dimension)
    toolbox.register("population", tools.initRepeat, list, toolbox.individual)
    toolbox.register("mate", tools.cxBlend, alpha=0.3)
    toolbox.register("mutate", tools.mutGaussian, mu=0.0, sigma=0.2, indpb=0.1)
    toolbox.register("select", tools.selTournament, tournsize=3)

    def score(population, generation):
        fitness = thyrix.evaluate(np.array(population, dtype=float), task=options.task,
                                  steps=options.steps, trials=options.trials,
                                  threads=options.threads, seed=options.seed,
                                  generation=generation, network=spec)
        for individual, value in zip(population, fitness):
            individual.fitness.values = (float(value),)

    population = toolbox.population(n=options.population)
    best = None
    with open(options.out, "w") as out:
        out.write("generation,best,mean\n")
        for generation in range(options.generations):
            if generation > 0:
                elite = toolbox.clone(tools.selBest(population, 1)[0])
                chosen = toolbox.select(population, len(population) - 1)
                offspring = [toolbox.clone(individual) for individual in chosen]
                for a, b in zip(offspring[::2], offspring[1::2]):
                    if random.random() < 0.5:
                        toolbox.mate(a, b)
                for individual in offspring:
                    toolbox.mutate(individual)
                population = [elite] + offspring
            # Every genome is scored again each generation, on this generation's episodes.
            score(population, generation)
            values = [i.fitness.values[0] for i in population]
            best = tools.selBest(population, 1)[0]
            out.write(f"{generation},{max(values):.9g},{np.mean(values):.9g}\n")
            print(f"generation {generation}: best {max(values):.4f} mean {np.mean(values):.4f}",
                  flush=True)
    if options.genome:
        thyrix.Genome(spec, np.array(best, dtype=float)).save(options.genome)
    return 0


if __name__ == "__main__":
    sys.exit(main())
