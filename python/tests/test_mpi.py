"""thyrix.evaluate over the ranks of an mpi4py job: the same numbers as one process, bad genomes
refused on every rank, and a rank whose evaluation raises ends the job."""

import os
import shutil
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import thyrix

MPI = pytest.importorskip("mpi4py.MPI")
MPIRUN = shutil.which("mpirun")
needs_mpirun = pytest.mark.skipif(MPIRUN is None, reason="mpirun (openmpi-bin) is not installed")


def mpirun(ranks, script):
    """Runs @p script as `python3 -m mpi4py` (an uncaught exception aborts the job) on ranks."""
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    return subprocess.run(
        [MPIRUN, "-n", str(ranks), "--oversubscribe", sys.executable, "-m", "mpi4py", "-c",
         textwrap.dedent(script)],
        capture_output=True, text=True, env=env, timeout=120)


def genomes():
    return np.random.default_rng(4).normal(0, 1, size=(9, 333))


def test_one_rank_gives_the_numbers_of_one_process():
    expected = thyrix.evaluate(genomes(), steps=100, trials=2, threads=1, seed=3, generation=2)
    got = thyrix.evaluate(genomes(), steps=100, trials=2, threads=2, seed=3, generation=2,
                          comm=MPI.COMM_SELF)
    assert np.array_equal(got, expected)


@needs_mpirun
def test_three_ranks_give_the_numbers_of_one_process():
    result = mpirun(3, """
        import numpy as np
        from mpi4py import MPI
        import thyrix
        comm = MPI.COMM_WORLD
        genomes = np.random.default_rng(4).normal(0, 1, size=(9, 333)) if comm.rank == 0 else None
        for generation, threads in ((1, 2), (2, 1)):  # rank 0: a thread of its own, or none
            fitness = thyrix.evaluate(genomes, steps=120, trials=3, threads=threads, seed=7,
                                      generation=generation, comm=comm)
            if comm.rank == 0:
                print(" ".join(float(f).hex() for f in fitness), flush=True)
            else:
                assert fitness is None
        """)
    assert result.returncode == 0, result.stderr
    lines = result.stdout.split("\n")
    for generation, line in zip((1, 2), lines):
        expected = thyrix.evaluate(genomes(), steps=120, trials=3, threads=1, seed=7,
                                   generation=generation)
        got = np.array([float.fromhex(x) for x in line.split()])
        assert np.array_equal(got, expected), f"generation {generation}"


@needs_mpirun
def test_bad_genomes_raise_on_every_rank():
    result = mpirun(2, """
        import numpy as np
        from mpi4py import MPI
        import thyrix
        comm = MPI.COMM_WORLD
        try:
            thyrix.evaluate(np.zeros((2, 10)) if comm.rank == 0 else None, comm=comm)
        except ValueError as error:
            print(f"rank {comm.rank}: {error}", flush=True)
        """)
    assert result.returncode == 0, result.stderr
    assert "rank 0: genomes must have shape (P, 333)" in result.stdout
    assert "rank 1: genomes must have shape (P, 333)" in result.stdout


@needs_mpirun
def test_a_rank_that_raises_ends_the_job():
    result = mpirun(2, """
        import numpy as np
        from mpi4py import MPI
        import thyrix
        import thyrix.mpi
        comm = MPI.COMM_WORLD
        if comm.rank == 1:
            class Failing(thyrix.mpi.EpisodeRunner):
                def run(self, first, count):
                    raise RuntimeError("this rank fails on purpose")
            thyrix.mpi.EpisodeRunner = Failing
        genomes = np.zeros((40, 333)) if comm.rank == 0 else None
        thyrix.evaluate(genomes, steps=100, comm=comm)
        """)
    assert result.returncode != 0
    assert "thyrix.evaluate (rank 1)" in result.stderr
    assert "this rank fails on purpose" in result.stderr
