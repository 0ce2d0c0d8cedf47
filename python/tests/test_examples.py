"""The examples under examples/python run: a couple of DEAP generations, then the plot."""

import os
import subprocess
import sys

import numpy as np

import thyrix
from conftest import ROOT

EXAMPLES = ROOT / "examples" / "python"


def test_deap_evolution_for_two_generations_then_the_plot(tmp_path):
    csv = tmp_path / "fitness.csv"
    genome = tmp_path / "best.genome"
    env = dict(os.environ)
    result = subprocess.run(
        [sys.executable, str(EXAMPLES / "evolve_spherus_deap.py"), "--generations", "2",
         "--population", "8", "--steps", "100", "--threads", "2", "--seed", "3",
         "--out", str(csv), "--genome", str(genome)],
        capture_output=True, text=True, env=env, check=True)
    assert result.stdout.count("generation ") == 2
    rows = np.genfromtxt(csv, delimiter=",", names=True)
    assert rows["generation"].tolist() == [0, 1]
    assert (rows["best"] >= rows["mean"]).all()
    best = thyrix.Genome.load(str(genome))
    assert best.spec == thyrix.spherus_network("ff:8")
    assert np.isfinite(best.parameters).all()
    png = tmp_path / "fitness.png"
    subprocess.run([sys.executable, str(EXAMPLES / "plot_fitness.py"), str(csv), str(png)],
                   check=True, env=env)
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
