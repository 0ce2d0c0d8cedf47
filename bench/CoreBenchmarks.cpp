// Benchmarks of the ThyrixLite core: the step of a settled pile as the body count grows, the
// broad phase alone on the same layouts, and a crowd on one floor, to show they scale
// near-linearly.

#include <Scenes.h>
#include <ThyrixLite/Border.h>
#include <ThyrixLite/BroadPhase.h>
#include <ThyrixLite/Circle.h>
#include <ThyrixLite/Simulator.h>

#include <benchmark/benchmark.h>

#include <limits>
#include <memory>
#include <vector>

namespace thyrix {
namespace {

/// A pile 10 circles high and count / 10 wide, after 200 untimed steps at 1 m/s under their
/// weight: it has settled, and its contacts grow in proportion to the count.
struct SettledPile {
  explicit SettledPile(int count, ContactSolverKind solver) : simulator(real(1) / 60) {
    simulator.setContactSolver(solver);
    circles = scenes::addPile(simulator, count, 1, count / 10);
    for (int step = 0; step < 200; ++step) advance();
  }
  void advance() {
    scenes::push(circles, {0, -1});
    simulator.advanceTime();
  }
  Simulator simulator;
  std::vector<PhysicalObject*> circles;
};

void pileStep(benchmark::State& state, ContactSolverKind solver) {
  SettledPile pile(static_cast<int>(state.range(0)), solver);
  for (auto _ : state) pile.advance();
  state.counters["contacts"] = static_cast<double>(pile.simulator.contacts.size());
  state.counters["bodies"] = static_cast<double>(state.range(0));
  state.counters["us_per_body"] = benchmark::Counter(
      static_cast<double>(state.iterations()) * static_cast<double>(state.range(0)),
      benchmark::Counter::kIsRate | benchmark::Counter::kInvert, benchmark::Counter::kIs1000);
}

void BM_PileStepGaussSeidel(benchmark::State& state) {
  pileStep(state, ContactSolverKind::GaussSeidel);
}
void BM_PileStepBaraff(benchmark::State& state) { pileStep(state, ContactSolverKind::Baraff); }
BENCHMARK(BM_PileStepGaussSeidel)->Arg(1000)->Arg(4000)->Arg(16000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PileStepBaraff)->Arg(1000)->Arg(4000)->Arg(16000)->Unit(benchmark::kMillisecond);

/// A settled pile (settled as BM_PileStepBaraff's) then stepped with Baraff asked to solve
/// every island exactly (no size limit): what exact solves everywhere cost (docs/UsersGuide.md,
/// "Choosing a contact solver"). 100 bodies only: a pile of 1000 takes seconds a step.
void BM_PileStepBaraffExact(benchmark::State& state) {
  SettledPile pile(static_cast<int>(state.range(0)), ContactSolverKind::Baraff);
  pile.simulator.solverSettings().baraffMaxIslandContacts = std::numeric_limits<int>::max();
  std::size_t failed = 0;
  for (auto _ : state) {
    pile.advance();
    failed += pile.simulator.statistics().baraffFallbacks;
  }
  state.counters["contacts"] = static_cast<double>(pile.simulator.contacts.size());
  state.counters["baraff_failed"] =
      benchmark::Counter(static_cast<double>(failed), benchmark::Counter::kAvgIterations);
}
BENCHMARK(BM_PileStepBaraffExact)->Arg(100)->Unit(benchmark::kMillisecond);

/// Contact detection alone on a settled pile, run again and again on the same state. With
/// @p restSkipping off every shape is placed and every pair tested, as in a pile that moves;
/// with it on, nothing moved, so every contact is the last detection's (the best case).
void detectContacts(benchmark::State& state, bool restSkipping) {
  SettledPile pile(static_cast<int>(state.range(0)), ContactSolverKind::GaussSeidel);
  pile.simulator.restSkipping = restSkipping;
  for (auto _ : state) {
    pile.simulator.eraseContacts();
    pile.simulator.detectContacts();
  }
  state.counters["contacts"] = static_cast<double>(pile.simulator.contacts.size());
  state.counters["ns_per_body"] = benchmark::Counter(
      static_cast<double>(state.iterations()) * static_cast<double>(state.range(0)),
      benchmark::Counter::kIsRate | benchmark::Counter::kInvert, benchmark::Counter::kIs1000);
}
void BM_DetectContacts(benchmark::State& state) { detectContacts(state, false); }
void BM_DetectContactsAtRest(benchmark::State& state) { detectContacts(state, true); }
BENCHMARK(BM_DetectContacts)->Arg(1000)->Arg(4000)->Arg(16000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_DetectContactsAtRest)->Arg(1000)->Arg(4000)->Arg(16000)->Unit(benchmark::kMicrosecond);

/// A row of disks apart from each other on one floor, each pushed down: every contact is
/// with the floor, and every step's are the last step's. The floor is one side of all of them,
/// which cost a scan of its contacts per lookup before the last contacts were indexed by pair.
void BM_CrowdOnFloor(benchmark::State& state) {
  Simulator simulator(real(0.01));
  simulator.setContactSolver(ContactSolverKind::GaussSeidel);
  simulator.registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}));
  std::vector<PhysicalObject*> disks;
  for (std::int64_t i = 0; i < state.range(0); ++i) {
    auto& disk = simulator.registerObject(std::make_unique<Circle>(real(0.5), real(1)));
    disk.r = {real(1.5) * static_cast<real>(i), real(0.5)};
    disks.push_back(&disk);
  }
  for (auto _ : state) {
    scenes::push(disks, {0, -1});
    simulator.advanceTime();
  }
  state.counters["contacts"] = static_cast<double>(simulator.contacts.size());
  state.counters["ns_per_body"] = benchmark::Counter(
      static_cast<double>(state.iterations()) * static_cast<double>(state.range(0)),
      benchmark::Counter::kIsRate | benchmark::Counter::kInvert, benchmark::Counter::kIs1000);
}
BENCHMARK(BM_CrowdOnFloor)->Arg(1000)->Arg(4000)->Arg(16000)->Unit(benchmark::kMicrosecond);

void BM_Arena(benchmark::State& state) {
  Simulator simulator(real(0.01));
  scenes::addWalls(simulator, 10, 10);
  const auto circles = scenes::addRandomCircles(simulator, 22, real(0.2), 10, 1);
  const std::vector<PhysicalObject*> pushed(circles.begin(), circles.begin() + 2);
  for (auto _ : state) {
    scenes::push(pushed, {1, 0});
    simulator.advanceTime();
  }
}
BENCHMARK(BM_Arena);

}  // namespace
}  // namespace thyrix
