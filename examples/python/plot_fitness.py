#!/usr/bin/python3
"""Plots a fitness CSV (generation,best,mean, as evolve_spherus_deap.py writes) with
matplotlib, without a display: ``plot_fitness.py fitness.csv fitness.png`` (any format
matplotlib saves: .png, .svg, .pdf)."""

import sys

import matplotlib

matplotlib.use("Agg")  # no display server needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if len(argv) != 2:
        print("usage: plot_fitness.py FITNESS.csv OUTPUT.(png|svg|pdf)", file=sys.stderr)
        return 2
    data = np.genfromtxt(argv[0], delimiter=",", names=True)
    data = np.atleast_1d(data)
    figure, axes = plt.subplots(figsize=(6, 4))
    axes.plot(data["generation"], data["best"], label="best")
    axes.plot(data["generation"], data["mean"], label="mean")
    axes.set_xlabel("generation")
    axes.set_ylabel("fitness")
    axes.legend()
    figure.tight_layout()
    figure.savefig(argv[1])
    return 0


if __name__ == "__main__":
    sys.exit(main())
