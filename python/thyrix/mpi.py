"""``thyrix.evaluate`` over the ranks of an mpi4py job.

Every rank of the communicator calls :func:`evaluate` with the same options; rank 0 passes the
genomes (the other ranks pass ``None``). Rank 0 broadcasts them and hands out chunks of episodes
on demand, large first and smaller towards the end, so that no rank idles long; a rank asks for
its next chunk as it starts one, so that the answer travels while it works. Every rank runs its
chunks on its own threads, rank 0 included. The fitnesses, returned on rank 0 (``None``
elsewhere), are the same numbers, bit for bit, as ``thyrix.evaluate`` in one process, for any
number of ranks and threads. A rank whose evaluation raises prints the error and ends the whole
job (``MPI_Abort``), so that no rank waits for it forever.
"""

import sys
import threading
import time
import traceback

import numpy as _np
from mpi4py import MPI

from ._thyrix import EpisodeRunner

_REQUEST = 3071  # rank -> rank 0: the last chunk's fitnesses, and whether it wants another
_CHUNK = 3072  # rank 0 -> rank: the next chunk (first episode, count; count 0: done)
_SHORTEST_PAUSE = 1e-5  # seconds between two tests of a message, backing off to the longest
_LONGEST_PAUSE = 4e-4  # a rank holds its next chunk, so an answer this late leaves it no time idle


def _wait(request):
    """Waits for a nonblocking request, sleeping between tests (a blocking call spins a core)."""
    pause = _SHORTEST_PAUSE
    while not request.Test():
        time.sleep(pause)
        pause = min(pause * 2, _LONGEST_PAUSE)


def _abort(comm, rank):
    sys.stderr.write(f"thyrix.evaluate (rank {rank}): {traceback.format_exc()}")
    sys.stderr.flush()
    comm.Abort(1)


def _serve(comm, rank, runner, threads):
    """Another rank's side: runs the chunks rank 0 hands out, one asked for ahead."""
    reply = _np.empty(2, dtype=_np.int64)
    result = (threads, True, 0, None)  # (threads, wants another chunk, first, fitnesses)
    comm.send(result, dest=0, tag=_REQUEST)
    request = comm.Irecv(reply, source=0, tag=_CHUNK)
    while True:
        _wait(request)
        first, count = int(reply[0]), int(reply[1])
        if count == 0:
            break
        comm.send(result, dest=0, tag=_REQUEST)  # asks for the next chunk, before running this one
        request = comm.Irecv(reply, source=0, tag=_CHUNK)
        try:
            result = (threads, True, first, runner.run(first, count))
        except BaseException:  # noqa: B902  (any failure ends the job)
            _abort(comm, rank)
    comm.send((threads, False) + result[2:], dest=0, tag=_REQUEST)


def evaluate(comm, genomes, task, trials, threads, seed, generation):
    """The episodes' work of ``thyrix.evaluate(..., comm=comm)``; see the module's text."""
    rank, size = comm.Get_rank(), comm.Get_size()
    header = None
    if rank == 0:
        try:  # checks the genomes (shape, finite values) and runs no episode
            genomes = _np.ascontiguousarray(genomes, dtype=_np.float64)
            runner = EpisodeRunner(task, genomes, trials, threads, seed, generation)
            header = genomes.shape
        except (TypeError, ValueError) as error:
            header = f"{type(error).__name__}: {error}"
    header = comm.bcast(header, root=0)
    if isinstance(header, str):  # every rank raises the same error
        kind, message = header.split(": ", 1)
        raise (TypeError if kind == "TypeError" else ValueError)(message)
    shape = header
    if rank != 0:
        genomes = _np.empty(shape, dtype=_np.float64)
    comm.Bcast(genomes, root=0)
    total = shape[0] * trials

    if rank != 0:
        try:
            runner = EpisodeRunner(task, genomes, trials, threads, seed, generation)
        except BaseException:  # noqa: B902  (any failure ends the job)
            _abort(comm, rank)
        _serve(comm, rank, runner, threads)
        return None

    episodes = _np.empty(total, dtype=_np.float64)
    lock = threading.Lock()
    state = {"next": 0, "stop": False, "error": None}
    rank_threads = [threads] * size
    handed = [0] * size

    def take(to, most):
        # Guided self-scheduling: t of the T threads get t/(4T) of what is left, in multiples of t.
        with lock:
            left = 0 if state["stop"] else total - state["next"]
            all_threads = sum(rank_threads)
            t = rank_threads[to]
            count = -(-left * t // (4 * all_threads))
            count = min(left, most, -(-max(count, t) // t) * t)
            first = state["next"]
            state["next"] += count
            handed[to] += count
            return first, count

    def run_local(most):
        """Runs rank 0's next chunk of at most ``most`` episodes; False when none is left."""
        try:
            first, count = take(0, most)
            if count == 0:
                return False
            episodes[first:first + count] = runner.run(first, count)
            return True
        except BaseException as error:  # noqa: B902  (raised again once the ranks are done)
            with lock:
                state["stop"] = True
                state["error"] = error
            return False

    # With one thread, rank 0 runs its episodes one at a time between the answers to the other
    # ranks (no thread of its own, no sleeps); with more, a thread of its own runs its chunks.
    local_left = threads == 1
    worker = None
    if not local_left:
        def run_all():
            while run_local(total):
                pass

        worker = threading.Thread(target=run_all, daemon=True)
        worker.start()
    finished = 0
    status = MPI.Status()
    pause = _SHORTEST_PAUSE
    while finished < size - 1 or local_left:
        if not comm.Iprobe(source=MPI.ANY_SOURCE, tag=_REQUEST, status=status):
            if local_left:
                local_left = run_local(1)
                continue
            time.sleep(pause)
            pause = min(pause * 2, _LONGEST_PAUSE)
            continue
        source = status.Get_source()
        source_threads, more, first, result = comm.recv(source=source, tag=_REQUEST)
        if result is not None:
            episodes[first:first + len(result)] = result
        if not more:
            finished += 1
            continue
        # A rank's first request: it waits with nothing to run and asks again at once.
        pause = _SHORTEST_PAUSE if handed[source] == 0 else _LONGEST_PAUSE
        with lock:
            rank_threads[source] = max(1, int(source_threads))
        comm.Send(_np.array(take(source, total), dtype=_np.int64), dest=source, tag=_CHUNK)
    if worker is not None:
        worker.join()
    if state["error"] is not None:
        raise state["error"]
    # Summed in trial order from 0, as thyrix::evaluate does, for the same bits.
    fitness = _np.zeros(shape[0], dtype=_np.float64)
    for t in range(trials):
        fitness += episodes[t::trials]
    return fitness / trials
