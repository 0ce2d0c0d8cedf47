// SpherusEvolve: evolves a neural controller for Spherus with CMA-ES (or the self-adaptive ES),
// evaluating each generation in parallel, and writes the run's records to --out: fitness.csv,
// fitness.svg, best.genome and checkpoint, each replaced atomically. --resume continues a run
// bit for bit. Built with MPI, `mpirun -n K SpherusEvolve ...` spreads each generation over K
// ranks and writes the same files. Run with --help for the options.

#include "SpherusTask.h"

#include <CommandLine.h>
#include <Controller/Genome.h>
#include <Evolution/AtomicFile.h>
#include <Evolution/CmaEs.h>
#include <Evolution/Evaluate.h>
#include <Evolution/FitnessHistory.h>
#include <Evolution/FitnessPlot.h>
#include <Evolution/ProgressLine.h>
#include <Evolution/SeedDerivation.h>
#include <Evolution/SelfAdaptiveEs.h>
#include <Evolution/StateText.h>
#ifdef THYRIX_SPHERUS_EVOLVE_MPI
#include <Evolution/MpiEvaluation.h>
#endif

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <thread>
#include <utility>
#include <vector>

namespace {

using namespace thyrix;
namespace fs = std::filesystem;

const char* const usage =
    "Usage: SpherusEvolve --out DIR [options]\n"
    "Evolves a neural controller for Spherus and writes DIR/fitness.csv, DIR/fitness.svg,\n"
    "DIR/best.genome and DIR/checkpoint.\n"
    "  --task T            distance (ground covered) or clear (balls pushed to the walls);\n"
    "                      default distance\n"
    "  --generations G     generations to reach (default 100)\n"
    "  --population P      points a generation (default 0: CMA-ES's 4 + 3 ln n)\n"
    "  --steps S           steps of an episode (default 1000)\n"
    "  --trials K          episodes per controller; its fitness is their mean (default 1)\n"
    "  --threads T         threads evaluating (default 1; under mpirun, per rank); the files\n"
    "                      do not depend on it, nor on the number of ranks\n"
    "  --seed N            the run's seed (default 1)\n"
    "  --network N         ff:H1[,H2...], ff or ctrnn:N (default ff:8, a 35-8-5 network)\n"
    "  --strategy S        cma-es or sa-es (the self-adaptive ES); default cma-es\n"
    "  --sigma X           initial step size (default 0.5)\n"
    "  --objects N         balls in the arena (default 20)\n"
    "  --fixed-pose        start Spherus in the middle facing +y, not at a pose drawn from\n"
    "                      the episode's seed\n"
    "  --checkpoint-every K  write DIR/checkpoint every K generations and at the end\n"
    "                      (default 10)\n"
    "  --resume            continue the run in DIR up to --generations\n"
    "  --help              this text\n"
    "Under mpirun (when built with MPI), rank 0 runs the strategy and writes the files, every\n"
    "rank evaluates the chunks of episodes it is handed, and the idle time of each rank is\n"
    "printed at the end.\n";

struct Options {
  SpherusGoal goal = SpherusGoal::Distance;
  std::uint64_t generations = 100;
  std::size_t population = 0;
  long steps = 1000;
  std::size_t trials = 1;
  std::size_t threads = 1;
  std::uint64_t seed = 1;
  std::string network = "ff:8";
  std::string strategy = "cma-es";
  double sigma = 0.5;
  int objects = 20;
  bool fixedPose = false;
  std::uint64_t checkpointEvery = 10;
  std::string out;
  bool resume = false;
  bool help = false;
};

double parseSigma(std::string_view text) {
  double value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !(value > 0) ||
      !std::isfinite(value))
    throw std::invalid_argument("--sigma needs a positive number, not '" + std::string(text) + "'");
  return value;
}

Options parse(int argc, char** argv) {
  using examples::parseNumber;
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string_view option = argv[i];
    if (option == "--help") {
      o.help = true;
      return o;
    }
    if (option == "--resume") {
      o.resume = true;
      continue;
    }
    if (option == "--fixed-pose") {
      o.fixedPose = true;
      continue;
    }
    static constexpr std::string_view valued[] = {
        "--task", "--generations", "--population", "--steps",   "--trials",           "--threads",
        "--seed", "--network",     "--sigma",      "--objects", "--checkpoint-every", "--strategy",
        "--out"};
    if (std::find(std::begin(valued), std::end(valued), option) == std::end(valued))
      throw std::invalid_argument("unknown option: " + std::string(option));
    if (i + 1 >= argc) throw std::invalid_argument(std::string(option) + " needs a value");
    const std::string_view value = argv[++i];
    if (option == "--task")
      o.goal = parseSpherusGoal(value);
    else if (option == "--generations")
      o.generations = parseNumber<std::uint64_t>(option, value, 1);
    else if (option == "--population")
      o.population = parseNumber<std::size_t>(option, value, 0);
    else if (option == "--steps")
      o.steps = parseNumber<long>(option, value, 1);
    else if (option == "--trials")
      o.trials = parseNumber<std::size_t>(option, value, 1);
    else if (option == "--threads")
      o.threads = parseNumber<std::size_t>(option, value, 1);
    else if (option == "--seed")
      o.seed = parseNumber<std::uint64_t>(option, value, 0);
    else if (option == "--network") {
      (void)parseSpherusNetwork(value);  // refused here, with the usage, if malformed
      o.network = value;
    } else if (option == "--sigma")
      o.sigma = parseSigma(value);
    else if (option == "--objects")
      o.objects = parseNumber<int>(option, value, 0);
    else if (option == "--checkpoint-every")
      o.checkpointEvery = parseNumber<std::uint64_t>(option, value, 1);
    else if (option == "--strategy") {
      if (value != "cma-es" && value != "sa-es")
        throw std::invalid_argument("--strategy must be cma-es or sa-es, not '" +
                                    std::string(value) + "'");
      o.strategy = value;
    } else {  // --out
      if (value.empty()) throw std::invalid_argument("--out needs a directory");
      o.out = value;
    }
  }
  if (o.population == 1) throw std::invalid_argument("--population needs 2 or more (or 0)");
  // Bounds far above any real run, so that a typo cannot ask for all the memory.
  if (o.threads > 1024) throw std::invalid_argument("--threads needs at most 1024");
  if (o.population > 100000) throw std::invalid_argument("--population needs at most 100000");
  if (o.trials > 10000) throw std::invalid_argument("--trials needs at most 10000");
  if (o.out.empty()) throw std::invalid_argument("--out DIR is required");
  return o;
}

// SpherusTask, with a hook for the tests of a failing rank: THYRIX_TEST_FAIL_RANK=R makes rank R
// throw in its first episode, and THYRIX_TEST_FAIL_RANK=R:kill makes it die of SIGKILL there.
struct EvolveTask {
  SpherusTask spherus;
  bool fail = false;
  bool kill = false;

  [[nodiscard]] long steps() const { return spherus.steps(); }
  [[nodiscard]] std::unique_ptr<SpherusEpisode> makeWorld(const std::vector<double>& parameters,
                                                          std::uint64_t seed) const {
    if (kill) std::raise(SIGKILL);
    if (fail) throw std::runtime_error("THYRIX_TEST_FAIL_RANK: this rank fails on purpose");
    return spherus.makeWorld(parameters, seed);
  }
  [[nodiscard]] double fitness(const SpherusEpisode& episode) const {
    return spherus.fitness(episode);
  }
};

EvolveTask makeTask(const Options& o, int rank) {
  EvolveTask task;
  task.spherus.goal = o.goal;
  task.spherus.network = parseSpherusNetwork(o.network);
  task.spherus.stepCount = o.steps;
  task.spherus.arena.objects = o.objects;
  task.spherus.randomPose = !o.fixedPose;
  if (const char* fail = std::getenv("THYRIX_TEST_FAIL_RANK")) {
    const std::string text = fail;
    const std::string wanted = std::to_string(rank);
    task.fail = text == wanted;
    task.kill = text == wanted + ":kill";
  }
  return task;
}

// Evaluates a generation: on this process's threads, or over the ranks of an MPI job.
using GenerationEvaluator = std::function<std::vector<double>(
    std::span<const std::vector<double>> population, const EvaluationOptions& options)>;

// The run: the strategy, the history and the best controller so far.
struct Run {
  std::unique_ptr<Strategy> strategy;
  std::vector<GenerationRecord> history;
  double bestFitness = -INFINITY;
  std::vector<double> best;  // the best point evaluated so far
};

std::unique_ptr<Strategy> makeStrategy(const Options& o, std::size_t dimension) {
  const auto seed = static_cast<std::uint32_t>(splitMix64(o.seed ^ 0x5350484552555345ull));
  std::vector<double> start(dimension, 0.0);
  if (o.strategy == "sa-es")
    return std::make_unique<SelfAdaptiveEs>(std::move(start), o.sigma,
                                            o.population == 0 ? 20 : o.population, 0, seed);
  return std::make_unique<CmaEs>(std::move(start), o.sigma, o.population, seed);
}

// The options a checkpoint must share with the command line to be continued.
void writeSettings(StateWriter& w, const Options& o) {
  w.word("task", toString(o.goal));
  w.word("network", o.network);
  w.word("strategy", o.strategy);
  w.integer("population", o.population);
  w.integer("steps", static_cast<std::uint64_t>(o.steps));
  w.integer("trials", o.trials);
  w.integer("seed", o.seed);
  w.integer("objects", static_cast<std::uint64_t>(o.objects));
  w.word("fixed-pose", o.fixedPose ? "yes" : "no");
  w.doubles("sigma0", {&o.sigma, 1});
}

std::string checkpointText(const Options& o, const Run& run) {
  std::ostringstream text;
  StateWriter w(text);
  w.word("thyrix-spherus-evolve", "1");
  writeSettings(w, o);
  w.integer("generations-done", run.history.size());
  for (const GenerationRecord& r : run.history) {
    const double values[4] = {static_cast<double>(r.generation), r.best, r.mean, r.bestSoFar};
    w.doubles("record", values);
  }
  w.doubles("best-fitness", {&run.bestFitness, 1});
  w.doubles("best", run.best);
  run.strategy->save(text);
  w.word("end", "checkpoint");
  return text.str();
}

// Reads DIR/checkpoint into @p run, refusing one written with other settings.
void readCheckpoint(const fs::path& path, const Options& o, Run& run) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("--resume: cannot read " + path.string());
  StateReader r(in, "checkpoint " + path.string());
  if (r.word("thyrix-spherus-evolve") != "1")
    r.fail("is not a SpherusEvolve checkpoint of version 1");
  std::ostringstream expected;
  StateWriter w(expected);
  writeSettings(w, o);
  std::istringstream settings(expected.str());
  for (std::string line; std::getline(settings, line);) {
    const std::string key = line.substr(0, line.find(' '));
    std::string found;
    if (key == "sigma0") {
      const double sigma = r.doubles("sigma0", 1)[0];
      if (sigma != o.sigma)
        r.fail("was written with --sigma " + std::to_string(sigma) + ", not " +
               std::to_string(o.sigma));
      continue;
    }
    found = r.word(key);
    const std::string wanted = line.substr(key.size() + 1);
    if (found != wanted)
      r.fail("was written with --" + key + " " + found + ", not " + wanted +
             " (resume with the run's own options)");
  }
  const std::uint64_t done = r.integer("generations-done", 1u << 30);
  std::vector<GenerationRecord> history;
  for (std::uint64_t g = 0; g < done; ++g) {
    const std::vector<double> v = r.doubles("record", 4);
    if (v[0] != static_cast<double>(g + 1)) r.fail("has records out of order");
    history.push_back({g + 1, v[1], v[2], v[3]});
  }
  const double bestFitness = r.doubles("best-fitness", 1)[0];
  std::vector<double> best = r.doubles("best", run.strategy->dimension());
  try {
    run.strategy->restore(in);
  } catch (const std::runtime_error& error) {
    throw std::runtime_error("checkpoint " + path.string() + ": " + error.what());
  }
  if (run.strategy->generation() != done)
    r.fail("has a strategy at generation " + std::to_string(run.strategy->generation()) + ", not " +
           std::to_string(done));
  StateReader tail(in, "checkpoint " + path.string() + " (after the strategy)");
  if (tail.word("end") != "checkpoint") tail.fail("does not end with 'end checkpoint'");
  tail.end();
  run.history = std::move(history);
  run.bestFitness = bestFitness;
  run.best = std::move(best);
}

// The run's files and their contents: the history, the best controller and, if @p checkpoint,
// the checkpoint.
std::vector<std::pair<fs::path, std::string>> records(const fs::path& dir, const Options& o,
                                                      const NetworkSpec& spec, const Run& run,
                                                      bool checkpoint) {
  std::vector<std::pair<fs::path, std::string>> files;
  files.emplace_back(dir / "fitness.csv", fitnessCsv(run.history));
  files.emplace_back(
      dir / "fitness.svg",
      fitnessPlotSvg(run.history, "SpherusEvolve --task " + std::string(toString(o.goal)) +
                                      " --network " + o.network));
  if (!run.best.empty()) {
    Genome genome;
    genome.spec = spec;
    genome.parameters.assign(run.best.begin(), run.best.end());
    std::ostringstream text;
    genome.write(text);
    files.emplace_back(dir / "best.genome", text.str());
  }
  if (checkpoint) files.emplace_back(dir / "checkpoint", checkpointText(o, run));
  return files;
}

void writeAll(const std::vector<std::pair<fs::path, std::string>>& files) {
  for (const auto& [path, content] : files) writeFileAtomically(path, content);
}

// Writes each generation's files on a thread of its own while the next generation is evaluated,
// so that the other ranks do not wait for the disk (a checkpoint holds megabytes); the contents
// are made before, since the strategy moves on. A failed write is reported at the next write or
// at finish().
class RecordWriter {
 public:
  ~RecordWriter() {
    if (thread_.joinable()) thread_.join();
  }
  void write(std::vector<std::pair<fs::path, std::string>> files) {
    finish();
    files_ = std::move(files);
    thread_ = std::thread([this] {
      try {
        writeAll(files_);
      } catch (...) {
        error_ = std::current_exception();
      }
    });
  }
  // Waits for the last write; rethrows its error.
  void finish() {
    if (thread_.joinable()) thread_.join();
    if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
  }

 private:
  std::vector<std::pair<fs::path, std::string>> files_;
  std::thread thread_;
  std::exception_ptr error_;
};

int evolve(const Options& o, const EvolveTask& task, const GenerationEvaluator& evaluateGeneration,
           ProgressLine& progress) {
  // One episode built before anything is created or written, so that options the arena refuses (too
  // many balls) are reported without leaving a run behind.
  (void)task.spherus.makeWorld(std::vector<double>(task.spherus.network.parameterCount(), 0.0),
                               o.seed);
  const fs::path dir = o.out;
  const fs::path checkpointPath = dir / "checkpoint";
  std::error_code error;
  fs::create_directories(dir, error);
  if (error || !fs::is_directory(dir))
    throw std::runtime_error("cannot create the directory --out " + o.out +
                             (error ? ": " + error.message() : ""));
  if (!o.resume && fs::exists(checkpointPath))
    throw std::runtime_error(o.out + " already holds a run (" + checkpointPath.string() +
                             "): continue it with --resume or choose another --out");
  if (o.resume && !fs::exists(checkpointPath))
    throw std::runtime_error("--resume: no checkpoint in " + o.out);

  Run run;
  run.strategy = makeStrategy(o, task.spherus.network.parameterCount());
  if (o.resume) readCheckpoint(checkpointPath, o, run);
  // Written before any work, so an unwritable directory is found at once.
  writeAll(records(dir, o, task.spherus.network, run, true));
  RecordWriter writer;

  EvaluationOptions evaluation;
  evaluation.trials = o.trials;
  evaluation.seed = o.seed;
  using Clock = std::chrono::steady_clock;
  const auto begin = Clock::now();
  const std::uint64_t first = run.history.size() + 1;
  for (std::uint64_t g = first; g <= o.generations; ++g) {
    const auto population = run.strategy->ask();
    evaluation.generation = g;
    const auto start = Clock::now();
    const std::vector<double> fitness = evaluateGeneration(population, evaluation);
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    const auto bestIndex = static_cast<std::size_t>(
        std::max_element(fitness.begin(), fitness.end()) - fitness.begin());
    if (fitness[bestIndex] > run.bestFitness) {
      run.bestFitness = fitness[bestIndex];
      run.best = population[bestIndex];
    }
    run.strategy->tell(fitness);
    double sum = 0;
    for (double f : fitness) sum += f;
    run.history.push_back(
        {g, fitness[bestIndex], sum / static_cast<double>(fitness.size()), run.bestFitness});
    writer.write(records(dir, o, task.spherus.network, run,
                         g % o.checkpointEvery == 0 || g == o.generations));

    const double elapsed = std::chrono::duration<double>(Clock::now() - begin).count();
    Progress p;
    p.generation = g;
    p.generations = o.generations;
    p.best = run.history.back().best;
    p.mean = run.history.back().mean;
    p.bestSoFar = run.bestFitness;
    p.evaluationsPerSecond =
        seconds > 0 ? static_cast<double>(fitness.size() * o.trials) / seconds : 0;
    p.secondsLeft =
        elapsed / static_cast<double>(g - first + 1) * static_cast<double>(o.generations - g);
    progress.update(p);
  }
  writer.finish();
  return 0;
}

#ifdef THYRIX_SPHERUS_EVOLVE_MPI
// Rank 0 evolves and the other ranks evaluate what it hands out; then rank 0 prints each rank's
// idle time, and the time between generations, when only rank 0 works.
int run(const Options& o, MpiEvaluation& ranks) {
  const EvolveTask task = makeTask(o, ranks.rank());
  ThreadPool pool(o.threads);
  if (ranks.rank() != 0) {
    serveEvaluations(task, pool, ranks);
    return 0;
  }
  // Under mpirun the output reaches the terminal or the job's log through Open MPI, which makes
  // stdout look like a terminal either way: plain lines, readable in a log.
  ProgressLine progress = ranks.size() == 1 ? ProgressLine(stdout) : ProgressLine(stdout, false);
  const int status = evolve(
      o, task,
      [&](std::span<const std::vector<double>> population, const EvaluationOptions& options) {
        return evaluate(task, population, options, pool, ranks);
      },
      progress);
  if (ranks.size() > 1) {
    std::printf("idle time of the %d ranks, while a generation was being evaluated:\n",
                ranks.size());
    const std::vector<RankTime>& times = ranks.rankTimes();
    for (std::size_t r = 0; r < times.size(); ++r) {
      const double all = times[r].busySeconds + times[r].idleSeconds;
      std::printf("  rank %zu: idle %.3f s of %.3f s (%.1f%%)\n", r, times[r].idleSeconds, all,
                  all > 0 ? 100 * times[r].idleSeconds / all : 0.0);
    }
    std::printf("between generations (rank 0 runs the strategy, the other ranks wait): %.3f s\n",
                ranks.betweenSeconds());
  }
  return status;
}
#else
int run(const Options& o) {
  const EvolveTask task = makeTask(o, 0);
  ThreadPool pool(o.threads);
  ProgressLine progress(stdout);
  return evolve(
      o, task,
      [&](std::span<const std::vector<double>> population, const EvaluationOptions& options) {
        return evaluate(task, population, options, pool);
      },
      progress);
}
#endif

}  // namespace

int main(int argc, char** argv) {
#ifdef THYRIX_SPHERUS_EVOLVE_MPI
  std::optional<MpiEvaluation> ranks;
  try {
    ranks.emplace(argc, argv);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "SpherusEvolve: %s\n", error.what());
    return 1;
  }
  const int rank = ranks->rank();
  // Every rank parses the same options; rank 0 alone speaks for them.
  const std::string who =
      ranks->size() > 1 ? "SpherusEvolve (rank " + std::to_string(rank) + ")" : "SpherusEvolve";
#else
  const int rank = 0;
  const std::string who = "SpherusEvolve";
#endif
  Options options;
  try {
    options = parse(argc, argv);
  } catch (const std::invalid_argument& error) {
    if (rank == 0) std::fprintf(stderr, "SpherusEvolve: %s\n%s", error.what(), usage);
    return 2;
  }
  if (options.help) {
    if (rank == 0) std::fputs(usage, stdout);
    return 0;
  }
  try {
#ifdef THYRIX_SPHERUS_EVOLVE_MPI
    return run(options, *ranks);
#else
    return run(options);
#endif
  } catch (const std::exception& error) {
    std::fprintf(stderr, "%s: %s\n", who.c_str(), error.what());
    return 1;
  }
}
