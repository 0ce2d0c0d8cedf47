// PeerBenchmarks: the scenes of issues 7 and 27 in Thyrix and, when they were found at
// configure time, in Box2D 2.4, Box2D v3 and Chipmunk 7, from identical layouts (PeerScenes.h).
// Each benchmark runs a whole scene once per repetition (->Iterations(1)) and reports, as counters:
//   us_per_step, steps_per_s    CPU time of the stepping thread over the timed steps only (the
//                               world is built untimed; this is also the benchmark's time);
//   wall_us_per_step            the same in wall-clock time (it grows with the machine's load);
//   contacts, ns_per_contact    contact points per step (sampled every 100 steps, 10 in piles),
//                               and the step time per contact point;
//   hash                        the final state's hash (32 bits; the label has all 64): equal
//                               across repetitions means a deterministic run;
//   penetration_r (piles)       the largest overlap in the final pile, over the radius;
//   max_penetration_r (piles)   the largest overlap seen in the samples of the timed steps;
//   max_gap, final_gap (chains) the largest joint gap over the run and at its end (m);
//   episodes_per_s (batch)      whole Spherus episodes (built and run) per second of wall time
//                               (the batch's time is wall time: it measures the threads' gain);
//   speedup_2_threads           batch/thyrix_paired: the batch on 1 thread, then on 2, back to
//                               back, wall time over wall time (machine/parallel_capacity: the
//                               same for fixed arithmetic).
// Names are "scene/engine"; thyrix_gs is Thyrix with its Gauss-Seidel solver instead of the
// default Baraff solver. Timing is manual (clocks read around stretches of steps only), so
// sampling the counters costs the engines nothing.
//
// Options: --quick shortens every scene (10 to 20 times) for a fast look; Google Benchmark's
// options apply (--benchmark_filter=arena, --benchmark_repetitions=3, ...).
// bench/run_comparison.sh runs the full comparison and prints the table.

#include "PeerScenes.h"
#include "ThyrixPeerScenes.h"

#ifdef THYRIX_HAVE_BOX2D
#include "Box2DScenes.h"
#endif
#ifdef THYRIX_HAVE_BOX2D_V3
#include "Box2DV3Scenes.h"
#endif
#ifdef THYRIX_HAVE_CHIPMUNK
#include "ChipmunkScenes.h"
#endif
#ifdef THYRIX_HAVE_SPHERUS
#include "SpherusPeerScene.h"
#endif

#include <benchmark/benchmark.h>

#include <time.h>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cinttypes>
#include <cstdio>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

namespace thyrix::peers {
namespace {

/// How long each scene runs (issue 7's numbers; --quick divides them).
struct Config {
  long arenaSteps = 100000;
  long crowdSteps = 20000;
  long pileWarmupSteps = 100;
  long pileSteps = 500;
  long chainSteps = 2000;
  // A population of an evolutionary run. Two threads finish a batch at most one episode apart,
  // so a small batch measures its own tail: with 32 episodes, up to 1/32 of the time is one
  // thread waiting for the other.
  int batchWorlds = 128;
  long batchSteps = 1000;
  // Steps between two samples of the contacts (and joint gaps), which are also the stretches
  // of steps timed at once: long enough that reading the clocks costs nothing measurable,
  // short enough to give the piles 50 samples.
  int arenaSampleEvery = 100;
  int pileSampleEvery = 10;
  int chainSampleEvery = 100;
  std::uint32_t seed = 1;
};

Config quickConfig() {
  Config config;
  config.arenaSteps = 5000;
  config.crowdSteps = 1000;
  config.pileWarmupSteps = 20;
  config.pileSteps = 50;
  config.chainSteps = 200;
  config.batchWorlds = 8;
  config.batchSteps = 250;
  return config;
}

/// CPU time of the calling thread (s). The machine may be shared with other work: the CPU
/// time of the stepping thread is what the steps cost, whatever else runs, where the wall
/// time grows with the load.
double threadSeconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + static_cast<double>(now.tv_nsec) * 1e-9;
}

/// CPU time of the whole process, all threads (s).
double processSeconds() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + static_cast<double>(now.tv_nsec) * 1e-9;
}

/// Wall-clock time (s).
double wallSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

/// The timed part of a run.
struct Measure {
  double seconds = 0;  ///< CPU time of the steps
  double wall = 0;     ///< wall-clock time of the steps
  long steps = 0;
  double contactSum = 0;
  long samples = 0;
};

/// Steps @p scene @p steps times, timing the steps alone; after every @p every steps, samples
/// the contacts and calls @p sample (untimed).
template <class Scene, class Sample>
Measure run(Scene& scene, long steps, int every, Sample&& sample) {
  Measure m;
  while (m.steps < steps) {
    const long chunk = std::min<long>(every, steps - m.steps);
    const double wall = wallSeconds();
    const double start = threadSeconds();
    for (long i = 0; i < chunk; ++i) scene.step();
    m.seconds += threadSeconds() - start;
    m.wall += wallSeconds() - wall;
    m.steps += chunk;
    m.contactSum += static_cast<double>(scene.contactCount());
    ++m.samples;
    sample(scene);
  }
  return m;
}

template <class Scene>
Measure run(Scene& scene, long steps, int every) {
  return run(scene, steps, every, [](const Scene&) {});
}

void setHash(benchmark::State& state, std::uint64_t hash) {
  state.counters["hash"] = hashCounter(hash);
  char label[32];
  std::snprintf(label, sizeof label, "hash=%016" PRIx64, hash);
  state.SetLabel(label);
}

/// The counters every scene reports.
void report(benchmark::State& state, const Measure& m, std::uint64_t hash) {
  const double perStep = m.seconds / static_cast<double>(m.steps);
  const double contacts = m.samples ? m.contactSum / static_cast<double>(m.samples) : 0;
  state.counters["us_per_step"] = perStep * 1e6;
  state.counters["steps_per_s"] = 1 / perStep;
  state.counters["wall_us_per_step"] = m.wall / static_cast<double>(m.steps) * 1e6;
  state.counters["contacts"] = contacts;
  state.counters["ns_per_contact"] = contacts > 0 ? perStep * 1e9 / contacts : 0;
  setHash(state, hash);
}

template <class Scene, class... Args>
void arena(benchmark::State& state, const ArenaLayout& layout, long steps, int every,
           Args... args) {
  for (auto _ : state) {
    Scene scene(layout, args...);
    const Measure m = run(scene, steps, every);
    state.SetIterationTime(m.seconds);
    report(state, m, scene.stateHash());
  }
  state.counters["agents"] = static_cast<double>(layout.agents.size());
}

template <class Scene, class... Args>
void arena(benchmark::State& state, const Config& config, int balls, Args... args) {
  arena<Scene>(state, arenaLayout(balls, config.seed), config.arenaSteps, config.arenaSampleEvery,
               args...);
}

/// crowd (issue 27): 10 agents of the arena and 1000 balls in a 40 x 40 m arena.
template <class Scene, class... Args>
void crowd(benchmark::State& state, const Config& config, Args... args) {
  arena<Scene>(state, crowdLayout(10, 1000, 40, config.seed), config.crowdSteps,
               config.arenaSampleEvery, args...);
}

template <class Scene, class... Args>
void pile(benchmark::State& state, const Config& config, int count, Args... args) {
  const PileLayout layout = pileLayout(count, config.seed);
  for (auto _ : state) {
    Scene scene(layout, args...);
    for (long i = 0; i < config.pileWarmupSteps; ++i) scene.step();
    double deepest = 0;  // over the samples of the timed run
    const Measure m = run(scene, config.pileSteps, config.pileSampleEvery, [&](const Scene& s) {
      deepest = std::max(deepest, largestPenetration(layout, s.centres()));
    });
    state.SetIterationTime(m.seconds);
    report(state, m, scene.stateHash());
    state.counters["penetration_r"] = largestPenetration(layout, scene.centres()) / layout.radius;
    state.counters["max_penetration_r"] = deepest / layout.radius;
  }
  state.counters["bodies"] = count;
}

template <class Scene, class... Args>
void chain(benchmark::State& state, const Config& config, int links, Args... args) {
  const ChainLayout layout = chainLayout(links);
  for (auto _ : state) {
    Scene scene(layout, args...);
    double largest = 0;
    const Measure m = run(scene, config.chainSteps, config.chainSampleEvery, [&](const Scene& s) {
      largest = std::max(largest, s.largestJointGap());
    });
    state.SetIterationTime(m.seconds);
    report(state, m, scene.stateHash());
    state.counters["max_gap"] = largest;
    state.counters["final_gap"] = scene.largestJointGap();
  }
  state.counters["links"] = links;
}

#ifdef THYRIX_HAVE_SPHERUS
void spherus(benchmark::State& state, const Config& config) {
  if (!sameArena(arenaLayout(20, config.seed), config.seed)) {
    state.SkipWithError("the arena layout differs from SpherusSimulator's");
    return;
  }
  for (auto _ : state) {
    ThyrixSpherus scene(config.seed, 20);
    const Measure m = run(scene, config.arenaSteps, config.arenaSampleEvery);
    state.SetIterationTime(m.seconds);
    report(state, m, scene.stateHash());
  }
}

/// One evaluation as an evolutionary run does it: build the world, run an episode, return
/// the final state's hash.
std::uint64_t episode(std::uint32_t seed, long steps) {
  ThyrixSpherus scene(seed, 20);
  for (long i = 0; i < steps; ++i) scene.step();
  return scene.stateHash();
}

/// Runs @p worlds episodes (seeds 1, 2, ...) on @p threads threads, each taking the next
/// episode not yet taken; returns the hashes in seed order, whoever computed them.
std::vector<std::uint64_t> batchRun(int worlds, long steps, int threads) {
  std::vector<std::uint64_t> hashes(static_cast<std::size_t>(worlds));
  std::atomic<int> next{0};
  const auto work = [&] {
    for (int i = next++; i < worlds; i = next++)
      hashes[static_cast<std::size_t>(i)] = episode(static_cast<std::uint32_t>(i + 1), steps);
  };
  std::vector<std::thread> helpers;
  for (int t = 1; t < threads; ++t) helpers.emplace_back(work);
  work();
  for (std::thread& helper : helpers) helper.join();
  return hashes;
}

void batch(benchmark::State& state, const Config& config, int threads) {
  // The reference: the same episodes on one thread, untimed.
  const std::vector<std::uint64_t> reference =
      threads > 1 ? batchRun(config.batchWorlds, config.batchSteps, 1)
                  : std::vector<std::uint64_t>{};
  std::vector<std::uint64_t> hashes;
  double seconds = 0;
  double cpu = 0;
  for (auto _ : state) {
    const double wall = wallSeconds();
    const double start = processSeconds();
    hashes = batchRun(config.batchWorlds, config.batchSteps, threads);
    cpu = processSeconds() - start;
    seconds = wallSeconds() - wall;
    state.SetIterationTime(seconds);
  }
  const bool identical = reference.empty() || reference == hashes;
  if (!identical) state.SkipWithError("the episodes differ from the 1-thread run");
  StateHash all;
  for (const std::uint64_t hash : hashes) all.mix(hash);
  const double steps =
      static_cast<double>(config.batchWorlds) * static_cast<double>(config.batchSteps);
  state.counters["threads"] = threads;
  state.counters["episodes_per_s"] = config.batchWorlds / seconds;
  state.counters["us_per_step"] = seconds / steps * 1e6;
  state.counters["steps_per_s"] = steps / seconds;
  // CPU time of all the threads: close to threads x wall time when the cores were free.
  state.counters["cpu_us_per_step"] = cpu / steps * 1e6;
  state.counters["identical"] = identical ? 1 : 0;
  setHash(state, all.value());
}

/// The batch's speed-up measured in pairs: each iteration runs the batch on one thread, then
/// at once on two. A slow spell of a shared host (sessions 5 and 6 saw spells of minutes, in
/// which both threads' CPU time per step rose by a fifth) then falls on both halves of a pair
/// rather than on one of the separate batch benchmarks, whose ratio it would skew; the
/// repetitions' median ratio is the speed-up.
void batchPaired(benchmark::State& state, const Config& config) {
  double one = 0;
  double two = 0;
  bool identical = true;
  std::vector<std::uint64_t> hashes;
  for (auto _ : state) {
    double start = wallSeconds();
    const std::vector<std::uint64_t> reference = batchRun(config.batchWorlds, config.batchSteps, 1);
    one = wallSeconds() - start;
    start = wallSeconds();
    hashes = batchRun(config.batchWorlds, config.batchSteps, 2);
    two = wallSeconds() - start;
    identical = identical && hashes == reference;
    state.SetIterationTime(one + two);
  }
  if (!identical) state.SkipWithError("the episodes differ from the 1-thread run");
  StateHash all;
  for (const std::uint64_t hash : hashes) all.mix(hash);
  state.counters["speedup_2_threads"] = one / two;
  state.counters["identical"] = identical ? 1 : 0;
  setHash(state, all.value());
}
#endif

/// Fixed arithmetic that needs no memory: what one thread does in a given time.
double spin(long count) {
  double sum = 0;
  for (long i = 1; i <= count; ++i) sum += 1 / static_cast<double>(i);
  return sum;
}

/// The machine's own parallel capacity at the moment of the run: the same arithmetic on 1
/// thread, then on each of 2 threads. On a shared machine other work may take a core, and
/// then no program gains from a second thread: read the batch's speed-up against this one.
void parallelCapacity(benchmark::State& state) {
  const long count = 100'000'000;
  double one = 0;
  double two = 0;
  for (auto _ : state) {
    double start = wallSeconds();
    benchmark::DoNotOptimize(spin(count));
    one = wallSeconds() - start;
    start = wallSeconds();
    std::thread helper([count] { benchmark::DoNotOptimize(spin(count)); });
    benchmark::DoNotOptimize(spin(count));
    helper.join();
    two = wallSeconds() - start;
    state.SetIterationTime(one + two);
  }
  state.counters["speedup_2_threads"] = 2 * one / two;
}

void registerAll(const Config& config) {
  const auto add = [](const std::string& name, auto function) {
    benchmark::RegisterBenchmark(name.c_str(), function)
        ->Iterations(1)
        ->UseManualTime()
        ->Unit(benchmark::kMillisecond);
  };
  const auto baraff = ContactSolverKind::Baraff;
  const auto gaussSeidel = ContactSolverKind::GaussSeidel;

  // The arena (20 balls), then more crowded ones: how the lead holds as a world grows,
  // most of it at rest.
  for (const int balls : {20, 80, 160}) {
    const std::string scene = balls == 20 ? "arena" : "arena" + std::to_string(balls);
    add(scene + "/thyrix",
        [=](benchmark::State& s) { arena<ThyrixArena>(s, config, balls, baraff); });
    add(scene + "/thyrix_gs",
        [=](benchmark::State& s) { arena<ThyrixArena>(s, config, balls, gaussSeidel); });
#ifdef THYRIX_HAVE_BOX2D
    add(scene + "/box2d", [=](benchmark::State& s) { arena<Box2DArena>(s, config, balls); });
#endif
#ifdef THYRIX_HAVE_BOX2D_V3
    add(scene + "/box2d_v3", [=](benchmark::State& s) { arena<Box2DV3Arena>(s, config, balls); });
#endif
#ifdef THYRIX_HAVE_CHIPMUNK
    add(scene + "/chipmunk", [=](benchmark::State& s) { arena<ChipmunkArena>(s, config, balls); });
#endif
  }
  add("crowd/thyrix", [=](benchmark::State& s) { crowd<ThyrixArena>(s, config, baraff); });
  add("crowd/thyrix_gs", [=](benchmark::State& s) { crowd<ThyrixArena>(s, config, gaussSeidel); });
#ifdef THYRIX_HAVE_BOX2D
  add("crowd/box2d", [=](benchmark::State& s) { crowd<Box2DArena>(s, config); });
#endif
#ifdef THYRIX_HAVE_BOX2D_V3
  add("crowd/box2d_v3", [=](benchmark::State& s) { crowd<Box2DV3Arena>(s, config); });
#endif
#ifdef THYRIX_HAVE_CHIPMUNK
  add("crowd/chipmunk", [=](benchmark::State& s) { crowd<ChipmunkArena>(s, config); });
#endif
#ifdef THYRIX_HAVE_SPHERUS
  add("spherus/thyrix", [=](benchmark::State& s) { spherus(s, config); });
#endif

  for (const int count : {1000, 10000}) {
    const std::string scene = "pile" + std::to_string(count);
    add(scene + "/thyrix",
        [=](benchmark::State& s) { pile<ThyrixPile>(s, config, count, baraff); });
    add(scene + "/thyrix_gs",
        [=](benchmark::State& s) { pile<ThyrixPile>(s, config, count, gaussSeidel); });
#ifdef THYRIX_HAVE_BOX2D
    add(scene + "/box2d", [=](benchmark::State& s) { pile<Box2DPile>(s, config, count); });
#endif
#ifdef THYRIX_HAVE_BOX2D_V3
    add(scene + "/box2d_v3", [=](benchmark::State& s) { pile<Box2DV3Pile>(s, config, count); });
#endif
#ifdef THYRIX_HAVE_CHIPMUNK
    add(scene + "/chipmunk", [=](benchmark::State& s) { pile<ChipmunkPile>(s, config, count); });
#endif
  }

  for (const int links : {10, 100, 1000}) {
    const std::string scene = "chain" + std::to_string(links);
    add(scene + "/thyrix",
        [=](benchmark::State& s) { chain<ThyrixChain>(s, config, links, baraff); });
    add(scene + "/thyrix_gs",
        [=](benchmark::State& s) { chain<ThyrixChain>(s, config, links, gaussSeidel); });
#ifdef THYRIX_HAVE_BOX2D
    add(scene + "/box2d", [=](benchmark::State& s) { chain<Box2DChain>(s, config, links); });
#endif
#ifdef THYRIX_HAVE_BOX2D_V3
    add(scene + "/box2d_v3", [=](benchmark::State& s) { chain<Box2DV3Chain>(s, config, links); });
#endif
#ifdef THYRIX_HAVE_CHIPMUNK
    add(scene + "/chipmunk", [=](benchmark::State& s) { chain<ChipmunkChain>(s, config, links); });
#endif
  }

#ifdef THYRIX_HAVE_SPHERUS
  for (const int threads : {1, 2})
    add("batch/thyrix_" + std::to_string(threads) + "thread",
        [=](benchmark::State& s) { batch(s, config, threads); });
  add("batch/thyrix_paired", [=](benchmark::State& s) { batchPaired(s, config); });
#endif
  add("machine/parallel_capacity", parallelCapacity);
}

}  // namespace
}  // namespace thyrix::peers

int main(int argc, char** argv) {
  // Our own option first, removed before Google Benchmark reads the rest.
  thyrix::peers::Config config;
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--quick") == 0)
      config = thyrix::peers::quickConfig();
    else
      argv[kept++] = argv[i];
  }
  argc = kept;
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  thyrix::peers::registerAll(config);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
