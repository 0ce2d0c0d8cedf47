#include "MpiEvaluation.h"

#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>

namespace thyrix {

namespace {

using Clock = std::chrono::steady_clock;

constexpr int requestTag = 1;  // rank -> leader: the last chunk's fitnesses, and maybe "more"
constexpr int chunkTag = 2;    // leader -> rank: the next chunk (first episode, count; 0: done)

// A batch's header, broadcast by the leader: command (0 stop, 1 evaluate), genomes, dimension,
// trials, seed, generation.
constexpr int headerSize = 6;
// A request: threads, more (1: send another chunk, 0: this rank is done with the generation),
// first episode, count, busy seconds this generation, then the fitnesses of that chunk.
constexpr std::size_t requestHead = 5;

using Micros = std::chrono::microseconds;

// Sleeps between two tests of a message: each wake-up from a sleep costs CPU time the episodes
// need, so a wait that may be long backs off from the shortest sleep to the longest.
constexpr Micros shortestPause(10);
constexpr Micros longestPause(400);

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Waits for @p request, sleeping between tests, at most @p longest (blocking MPI calls spin a
// core that this rank's or another rank's threads could use).
void waitFor(MPI_Request& request, Micros longest = longestPause) {
  Micros pause = shortestPause;
  for (;;) {
    int done = 0;
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (done) return;
    std::this_thread::sleep_for(pause);
    pause = std::min(pause * 2, longest);
  }
}

int toInt(std::size_t value, const char* what) {
  if (value > static_cast<std::size_t>(INT_MAX))
    throw std::runtime_error(std::string("MpiEvaluation: ") + what + " exceeds one MPI message");
  return static_cast<int>(value);
}

}  // namespace

struct MpiEvaluation::State {
  MPI_Comm comm = MPI_COMM_NULL;
  int rank = 0;
  int size = 1;
  bool startedMpi = false;
  bool stopped = false;                      // the stop was sent (leader) or received (other ranks)
  bool broken = false;                       // an exchange began and did not finish
  std::vector<double> flat;                  // the genomes, one after the other
  std::vector<std::vector<double>> genomes;  // other ranks: the genomes received
  std::vector<double> message;
  std::vector<std::size_t> threads;  // leader: every rank's threads, as last reported
  std::vector<double> speeds;  // leader: every rank's episodes a second in the last generation
  std::optional<Clock::time_point> lastEnd;  // leader: when the last evaluation ended

  // Leader: broadcasts @p header (and waits for it to leave); other ranks: receives it. These
  // wait here, their cores idle, while the leader runs the strategy, so they test often: a late
  // wake-up delays their whole generation.
  void broadcast(std::uint64_t (&header)[headerSize]) {
    MPI_Request request;
    MPI_Ibcast(header, headerSize, MPI_UINT64_T, 0, comm, &request);
    waitFor(request, 5 * shortestPause);
  }
};

MpiEvaluation::MpiEvaluation(int& argc, char**& argv) : state_(std::make_unique<State>()) {
  int initialized = 0;
  MPI_Initialized(&initialized);
  int provided = MPI_THREAD_SINGLE;
  if (initialized) {
    MPI_Query_thread(&provided);
  } else {
    MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
    state_->startedMpi = true;
  }
  if (provided < MPI_THREAD_FUNNELED) {
    if (state_->startedMpi) MPI_Finalize();
    throw std::runtime_error("MpiEvaluation: MPI does not support threads (MPI_THREAD_FUNNELED)");
  }
  MPI_Comm_dup(MPI_COMM_WORLD, &state_->comm);
  MPI_Comm_rank(state_->comm, &state_->rank);
  MPI_Comm_size(state_->comm, &state_->size);
  if (state_->rank == 0) times_.resize(static_cast<std::size_t>(state_->size));
}

MpiEvaluation::~MpiEvaluation() {
  State& s = *state_;
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (finalized) return;  // whoever started MPI ended it first
  if (s.broken) abort(1);
  if (s.size > 1 && !s.stopped) {
    std::uint64_t header[headerSize] = {};
    s.broadcast(header);
    // Another rank that never served learns here that the leader went on without it.
    if (s.rank != 0 && header[0] != 0) abort(1);
  }
  MPI_Comm_free(&s.comm);
  if (s.startedMpi) MPI_Finalize();
}

int MpiEvaluation::rank() const { return state_->rank; }

int MpiEvaluation::size() const { return state_->size; }

void MpiEvaluation::abort(int status) const {
  MPI_Abort(MPI_COMM_WORLD, status);
  std::_Exit(status);
}

void MpiEvaluation::distribute(const Batch& batch, std::size_t threads, std::span<double> episodes,
                               const ChunkJob& job) {
  State& s = *state_;
  if (s.rank != 0) throw std::logic_error("MpiEvaluation::distribute: only rank 0 distributes");
  const auto start = Clock::now();
  if (s.lastEnd) betweenSeconds_ += std::chrono::duration<double>(start - *s.lastEnd).count();
  const std::size_t total = episodes.size();
  if (s.size == 1) {
    job(batch, 0, episodes);
    times_[0].busySeconds += secondsSince(start);
    s.lastEnd = Clock::now();
    return;
  }
  const std::size_t dimension = batch.genomes.empty() ? 0 : batch.genomes[0].size();
  s.flat.clear();
  for (const std::vector<double>& genome : batch.genomes)
    s.flat.insert(s.flat.end(), genome.begin(), genome.end());
  const int flatCount = toInt(s.flat.size(), "the population");
  (void)toInt(total + requestHead, "the episodes");
  s.broken = true;
  std::uint64_t header[headerSize] = {1,
                                      batch.genomes.size(),
                                      dimension,
                                      batch.options.trials,
                                      batch.options.seed,
                                      batch.options.generation};
  s.broadcast(header);
  MPI_Request request;
  MPI_Ibcast(s.flat.data(), flatCount, MPI_DOUBLE, 0, s.comm, &request);
  waitFor(request);

  const auto ranks = static_cast<std::size_t>(s.size);
  s.threads.assign(ranks, threads);
  s.speeds.resize(ranks, 0.0);
  std::vector<std::size_t> handed(ranks, 0);  // episodes handed to each rank
  std::mutex mutex;
  std::size_t next = 0;  // the first episode not yet handed out
  bool stop = false;     // the leader's task threw: hand out nothing more
  // Guided self-scheduling: a rank with the share w of the ranks' speed gets w/4 of what is left,
  // in multiples of its threads, so chunks shrink as the generation ends and the ranks finish
  // about together. The speeds are those of the last generation (a slow or busy node gets less);
  // until every rank has one, the shares are those of the threads.
  auto take = [&](std::size_t rank, std::size_t most) {
    std::lock_guard lock(mutex);
    const bool measured =
        std::all_of(s.speeds.begin(), s.speeds.end(), [](double v) { return v > 0; });
    double all = 0;
    for (std::size_t r = 0; r < ranks; ++r)
      all += measured ? s.speeds[r] : static_cast<double>(s.threads[r]);
    const double share = (measured ? s.speeds[rank] : static_cast<double>(s.threads[rank])) / all;
    const std::size_t left = stop ? 0 : total - next;
    const std::size_t rankThreads = s.threads[rank];
    auto count = static_cast<std::size_t>(std::ceil(static_cast<double>(left) * share / 4));
    count = std::min(
        {left, most, (std::max(count, rankThreads) + rankThreads - 1) / rankThreads * rankThreads});
    const std::pair<std::size_t, std::size_t> chunk{next, count};
    next += count;
    handed[rank] += count;
    return chunk;
  };
  std::exception_ptr localError;
  double localBusy = 0;
  // Runs the leader's next chunk, of at most @p most episodes; false when none is left.
  auto runLocal = [&](std::size_t most) {
    try {
      const auto [first, count] = take(0, most);
      if (count == 0) return false;
      const auto begin = Clock::now();
      job(batch, first, episodes.subspan(first, count));
      localBusy += secondsSince(begin);
      return true;
    } catch (...) {
      localError = std::current_exception();
      std::lock_guard lock(mutex);
      stop = true;
      return false;
    }
  };
  {
    // With one thread the leader runs its episodes on this thread, one at a time, and answers
    // the other ranks between them: no thread of its own and no sleeps, whose wake-ups would take
    // CPU time from the episodes. With more, a thread of its own runs its chunks on the pool.
    bool localLeft = threads == 1;
    std::jthread local;
    if (!localLeft)
      local = std::jthread([&] {
        while (runLocal(total)) {
        }
      });
    std::vector<double> busy(ranks, 0.0);
    // The seconds of work each rank holds beyond the chunk it runs, at its last speed (0: not
    // known; infinite: it is done). Its next request comes when it starts that work, so the
    // leader sleeps at most a quarter of the least of them between tests, and never more than
    // longestPause (on a loaded machine a long sleep ends late).
    std::vector<double> held(ranks, 0.0);
    held[0] = INFINITY;
    auto longest = [&] {
      {
        std::lock_guard lock(mutex);
        // The generation ends when the leader hears from the last rank: listen closely.
        if (stop || next == total) return 10 * shortestPause;
      }
      const double shortest = *std::min_element(held.begin(), held.end());
      if (!(shortest > 0)) return longestPause;
      return std::clamp(Micros(static_cast<long>(std::min(shortest, 1.0) * 1e6 / 4)),
                        5 * shortestPause, longestPause);
    };
    int finished = 0;  // ranks that sent their last fitnesses
    Micros pause = shortestPause;
    while (finished < s.size - 1 || localLeft) {
      int arrived = 0;
      MPI_Status status;
      MPI_Iprobe(MPI_ANY_SOURCE, requestTag, s.comm, &arrived, &status);
      if (!arrived) {
        if (localLeft) {
          localLeft = runLocal(1);
          continue;
        }
        std::this_thread::sleep_for(pause);
        pause = std::min(pause * 2, longest());
        continue;
      }
      int length = 0;
      MPI_Get_count(&status, MPI_DOUBLE, &length);
      s.message.resize(static_cast<std::size_t>(length));
      MPI_Recv(s.message.data(), length, MPI_DOUBLE, status.MPI_SOURCE, requestTag, s.comm,
               MPI_STATUS_IGNORE);
      const auto source = static_cast<std::size_t>(status.MPI_SOURCE);
      const auto first = static_cast<std::size_t>(s.message[2]);
      const auto count = static_cast<std::size_t>(s.message[3]);
      busy[source] = s.message[4];
      std::copy_n(s.message.begin() + requestHead, count,
                  episodes.begin() + static_cast<std::ptrdiff_t>(first));
      if (s.message[1] == 0) {
        ++finished;
        held[source] = INFINITY;
        pause = std::min(pause, longest());
        continue;
      }
      // A rank's first request of the generation: it waits with nothing to run, and asks for
      // its next chunk as soon as this one arrives.
      const bool firstRequest = handed[source] == 0 && count == 0;
      {
        std::lock_guard lock(mutex);
        s.threads[source] = std::max<std::size_t>(1, static_cast<std::size_t>(s.message[0]));
      }
      const auto [nextFirst, nextCount] = take(source, total);
      std::uint64_t reply[2] = {nextFirst, nextCount};
      MPI_Send(reply, 2, MPI_UINT64_T, status.MPI_SOURCE, chunkTag, s.comm);
      held[source] = s.speeds[source] > 0 ? static_cast<double>(nextCount) / s.speeds[source] : 0;
      pause = firstRequest ? shortestPause : longest();
    }
    if (local.joinable()) local.join();
    busy[0] = localBusy;
    const double wall = secondsSince(start);
    for (std::size_t r = 0; r < ranks; ++r) {
      times_[r].busySeconds += busy[r];
      times_[r].idleSeconds += std::max(0.0, wall - busy[r]);
      if (handed[r] > 0 && busy[r] > 0) s.speeds[r] = static_cast<double>(handed[r]) / busy[r];
    }
  }
  s.lastEnd = Clock::now();
  s.broken = false;
  if (localError) std::rethrow_exception(localError);
}

void MpiEvaluation::serve(std::size_t threads, const ChunkJob& job) {
  State& s = *state_;
  if (s.rank == 0) throw std::logic_error("MpiEvaluation::serve: rank 0 distributes");
  while (!s.stopped) {
    std::uint64_t header[headerSize] = {};
    s.broadcast(header);
    if (header[0] == 0) {
      s.stopped = true;
      break;
    }
    s.broken = true;
    const std::size_t count = header[1];
    const std::size_t dimension = header[2];
    s.flat.resize(count * dimension);
    MPI_Request request;
    MPI_Ibcast(s.flat.data(), static_cast<int>(s.flat.size()), MPI_DOUBLE, 0, s.comm, &request);
    waitFor(request);
    s.genomes.resize(count);
    for (std::size_t i = 0; i < count; ++i)
      s.genomes[i].assign(s.flat.begin() + static_cast<std::ptrdiff_t>(i * dimension),
                          s.flat.begin() + static_cast<std::ptrdiff_t>((i + 1) * dimension));
    Batch batch;
    batch.genomes = s.genomes;
    batch.options.threads = threads;
    batch.options.trials = header[3];
    batch.options.seed = header[4];
    batch.options.generation = header[5];
    // The fitnesses of the chunk last run (none yet), sent with the request for the next chunk.
    s.message.assign(requestHead, 0.0);
    s.message[0] = static_cast<double>(threads);
    std::uint64_t reply[2] = {};
    auto send = [&](bool more) {
      s.message[1] = more ? 1 : 0;
      MPI_Send(s.message.data(), static_cast<int>(s.message.size()), MPI_DOUBLE, 0, requestTag,
               s.comm);
      if (more) MPI_Irecv(reply, 2, MPI_UINT64_T, 0, chunkTag, s.comm, &request);
    };
    send(true);
    double busy = 0;
    for (;;) {
      waitFor(request);
      const std::uint64_t chunkFirst = reply[0];
      const std::uint64_t chunkCount = reply[1];
      if (chunkCount == 0) break;
      // Asks for the next chunk before running this one, so that the leader's answer travels
      // while this rank works.
      send(true);
      s.message.resize(requestHead + chunkCount);
      s.message[2] = static_cast<double>(chunkFirst);
      s.message[3] = static_cast<double>(chunkCount);
      const auto begin = Clock::now();
      job(batch, chunkFirst, std::span<double>(s.message).subspan(requestHead));
      busy += secondsSince(begin);
      s.message[4] = busy;
    }
    send(false);
    s.broken = false;
  }
}

}  // namespace thyrix
