#pragma once
/// @file MpiEvaluation.h
/// @brief evaluate() over the ranks of an MPI job: rank 0 hands out chunks of episodes on demand.

#include <Evolution/Evaluate.h>
#include <Evolution/ThreadPool.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

namespace thyrix {

/// The time one rank spent on the evaluations so far (MpiEvaluation::rankTimes()).
struct RankTime {
  double busySeconds = 0;  ///< running episodes
  double idleSeconds = 0;  ///< waiting for work while the generation was not yet done
};

/// An MPI job's ranks, evaluating together: rank 0 (the leader) runs the strategy and calls
/// evaluate(task, genomes, options, pool, ranks); every other rank calls
/// serveEvaluations(task, pool, ranks), which evaluates what the leader hands out until the
/// leader's MpiEvaluation is destroyed. The leader broadcasts the genomes and then hands out
/// chunks of episodes on demand (guided: large first, smaller towards the end, so that no rank
/// idles long; a rank asks for its next chunk as it starts one, so that it never waits for the
/// answer); each rank runs its chunks on its own threads and the results are stored by
/// episode index, so the fitnesses equal those of evaluate() on one process, bit for bit, for
/// any number of ranks and threads. Only the thread that made this object may call MPI
/// (MPI_THREAD_FUNNELED). A rank whose task throws, or that dies, must end the whole job: if an
/// exception leaves serveEvaluations() (or the leader's exchange) half done, the destructor
/// calls MPI_Abort, and Open MPI ends a job whose rank dies.
class MpiEvaluation {
 public:
  /// Starts MPI (MPI_Init_thread) unless it was started already, on a private duplicate of
  /// MPI_COMM_WORLD. Run by every rank of the job.
  /// @throws std::runtime_error if MPI cannot give threads the funneled level
  MpiEvaluation(int& argc, char**& argv);
  /// The leader tells the other ranks to stop (and each of them waits for that); then MPI is
  /// finalized if this object started it. After an interrupted exchange: MPI_Abort (exit 1).
  ~MpiEvaluation();
  MpiEvaluation(const MpiEvaluation&) = delete;
  MpiEvaluation& operator=(const MpiEvaluation&) = delete;

  /// This process's rank in the job (0 is the leader).
  [[nodiscard]] int rank() const;
  /// The number of ranks in the job.
  [[nodiscard]] int size() const;
  /// The leader's record of every rank's busy and idle time (index = rank) over the
  /// evaluations so far; empty on the other ranks.
  [[nodiscard]] const std::vector<RankTime>& rankTimes() const { return times_; }
  /// Leader: the seconds from the end of each evaluation to the start of the next (the
  /// strategy's work and the files, while the other ranks wait), summed; 0 on the other ranks.
  [[nodiscard]] double betweenSeconds() const { return betweenSeconds_; }
  /// Ends the whole job at once with exit status @p status (MPI_Abort).
  [[noreturn]] void abort(int status) const;

  /// One batch of episodes as the ranks see it.
  struct Batch {
    std::span<const std::vector<double>> genomes;  ///< the points to evaluate
    EvaluationOptions options;                     ///< trials, seed and generation
  };
  /// Runs the episodes `first` to `first + fitness.size() - 1` of @p batch on this rank's
  /// threads (see evaluateEpisodes()).
  using ChunkJob =
      std::function<void(const Batch& batch, std::size_t first, std::span<double> fitness)>;

  /// Leader only: spreads all `genomes.size() * options.trials` episodes of @p batch over the
  /// ranks (this one included, with @p threads threads) and writes their fitnesses to
  /// @p episodes by episode index. The task's exception on this rank is rethrown once the
  /// other ranks are idle.
  void distribute(const Batch& batch, std::size_t threads, std::span<double> episodes,
                  const ChunkJob& job);
  /// Other ranks: runs the chunks the leader hands out, on @p threads threads, until the leader
  /// stops. An exception thrown by @p job leaves here with the exchange half done (so the
  /// destructor aborts the job).
  void serve(std::size_t threads, const ChunkJob& job);

 private:
  struct State;
  std::unique_ptr<State> state_;
  std::vector<RankTime> times_;
  double betweenSeconds_ = 0;
};

/// evaluate() over the ranks of @p ranks: called by the leader (rank 0) while the other ranks run
/// serveEvaluations() with the same task. The result equals, bit for bit, that of
/// evaluate(task, genomes, options, pool) in one process.
/// @throws InvalidArgument naming "EvaluationOptions.trials" if it is 0, or if a genome's size
///         differs from the first's ("genomes"); the task's exception on the leader
template <class T>
requires Task<T, std::vector<double>> std::vector<double> evaluate(
    const T& task, std::span<const std::vector<double>> genomes, const EvaluationOptions& options,
    ThreadPool& pool, MpiEvaluation& ranks) {
  if (options.trials == 0)
    throw InvalidArgument("EvaluationOptions.trials", "must be at least 1 (got 0)");
  for (const std::vector<double>& genome : genomes)
    if (genome.size() != genomes[0].size())
      throw InvalidArgument("genomes", "must all have the same number of parameters");
  std::vector<double> episodes(genomes.size() * options.trials);
  ranks.distribute(
      {genomes, options}, pool.threadCount(), episodes,
      [&](const MpiEvaluation::Batch& batch, std::size_t first, std::span<double> fitness) {
        evaluateEpisodes(task, batch.genomes, batch.options, first, fitness, pool);
      });
  return meanOverTrials(episodes, options.trials);
}

/// The other ranks' side of evaluate() over MPI ranks: evaluates the chunks rank 0 hands out
/// with @p task on @p pool, until rank 0's MpiEvaluation is destroyed.
template <class T>
requires Task<T, std::vector<double>>
void serveEvaluations(const T& task, ThreadPool& pool, MpiEvaluation& ranks) {
  ranks.serve(pool.threadCount(),
              [&](const MpiEvaluation::Batch& batch, std::size_t first, std::span<double> fitness) {
                evaluateEpisodes(task, batch.genomes, batch.options, first, fitness, pool);
              });
}

}  // namespace thyrix
