// Benchmarks of ThyrixPro's quasistatic articulated-body algorithm: solve() on chains of 10,
// 100 and 1000 links, with and without recomputing the articulated inertias (a new
// configuration every step, or the same one), one Kokkevis test force (respond()), and a whole
// Simulator::advanceTime() of an articulated agent with such a chain. Every time should grow
// linearly with the link count: compare the per-link counters.

#include <ThyrixLite/Simulator.h>
#include <ThyrixPro/ArticulatedAgentQuasistatic.h>
#include <ThyrixPro/ArticulatedBody.h>
#include <ThyrixPro/ArticulatedLimb.h>
#include <ThyrixPro/ArticulatedLink.h>

#include <memory>

#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

namespace thyrix {
namespace {

/// A chain of @p count capsule links on a base, slightly curled, with torques and a push.
struct Chain {
  explicit Chain(int count) : body(2, 1, links(count)), out(body.makeOutput()) {
    for (int i = 0; i < count; ++i) {
      body.setJointAngle(i, real(0.3) * std::sin(real(i)));
      torques.push_back(real(0.1) * std::cos(real(i)));
    }
    wrenches.assign(static_cast<std::size_t>(count) + 1, Vector3{});
    wrenches.back() = {real(0.5), real(1), real(-2)};
  }
  static std::vector<ArticulatedLink> links(int count) {
    std::vector<ArticulatedLink> result;
    result.reserve(static_cast<std::size_t>(count));
    // Each link 0.5 long, jointed at its parent's tip (the first at the base's edge).
    for (int i = 0; i < count; ++i)
      result.push_back(
          ArticulatedLink::capsule(i - 1, Vector2{real(0.5), 0}, real(0.25), real(0.1), real(0.2)));
    return result;
  }
  ArticulatedBody body;
  ArticulatedBody::Output out;
  std::vector<real> torques;
  std::vector<Vector3> wrenches;
};

void perLink(benchmark::State& state) {
  state.counters["links"] = static_cast<double>(state.range(0));
  state.counters["ns_per_link"] = benchmark::Counter(
      static_cast<double>(state.iterations()) * static_cast<double>(state.range(0)),
      benchmark::Counter::kIsRate | benchmark::Counter::kInvert, benchmark::Counter::kIs1000);
}

/// A full step's solve: the configuration changed (one joint moved), so the kinematics and the
/// articulated inertias are recomputed before the bias and outward passes.
void BM_ArticulatedSolve(benchmark::State& state) {
  Chain chain(static_cast<int>(state.range(0)));
  real q = 0;
  for (auto _ : state) {
    q += real(1e-6);
    chain.body.setJointAngle(0, q);
    chain.body.solve(chain.torques, chain.wrenches, chain.out);
    benchmark::DoNotOptimize(chain.out.jointRates.data());
    benchmark::ClobberMemory();
  }
  perLink(state);
}
BENCHMARK(BM_ArticulatedSolve)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);

/// solve() in an unchanged configuration: the cached articulated inertias are reused.
void BM_ArticulatedSolveCached(benchmark::State& state) {
  Chain chain(static_cast<int>(state.range(0)));
  chain.body.computeArticulatedInertias();
  for (auto _ : state) {
    chain.body.solve(chain.torques, chain.wrenches, chain.out);
    benchmark::DoNotOptimize(chain.out.jointRates.data());
    benchmark::ClobberMemory();
  }
  perLink(state);
}
BENCHMARK(BM_ArticulatedSolveCached)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);

/// One column of the constraint matrix: a unit contact force at the last link's tip.
void BM_ArticulatedRespond(benchmark::State& state) {
  Chain chain(static_cast<int>(state.range(0)));
  const int last = chain.body.linkCount() - 1;
  chain.body.computeArticulatedInertias();
  const auto force = ArticulatedBody::TestForce::atPoint(last, chain.body.tip(last), Vector2{0, 1});
  for (auto _ : state) {
    chain.body.respond(force, chain.out);
    benchmark::DoNotOptimize(chain.body.velocityAlong(chain.out, force));
    benchmark::ClobberMemory();
  }
  perLink(state);
}
BENCHMARK(BM_ArticulatedRespond)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);

/// A whole simulator step (all eight phases: contact detection over the links' capsules, the
/// O(N) free motion, integration and placing the shapes) for an agent with a chain of N links
/// and torques on every joint. The agent's collision group keeps its links from touching each
/// other, so no contact is solved; the torques flip sign every step, so the chain wiggles about
/// its starting shape and the broad phase sees the same layout throughout.
void BM_ArticulatedAgentStep(benchmark::State& state) {
  const int count = static_cast<int>(state.range(0));
  Simulator simulator(real(0.01));
  auto& agent = simulator.registerObject(std::make_unique<ArticulatedAgentQuasistatic>(
      std::vector<ArticulatedBasePart>{ArticulatedBasePart::circle(real(0.5), 2)},
      std::vector<ArticulatedLimb>{
          ArticulatedLimb::chain({real(0.5), 0}, count, real(0.5), real(0.1), real(0.2))}));
  agent.collisionGroup = 1;
  for (int i = 0; i < count; ++i) agent.setJointAngle(i, real(0.3) * std::sin(real(i)));
  real sign = 1;
  for (auto _ : state) {
    sign = -sign;
    for (int i = 0; i < count; ++i) agent.setJointTorque(i, sign * real(0.01) * std::cos(real(i)));
    simulator.advanceTime();
    benchmark::DoNotOptimize(agent.jointAngles().data());
    benchmark::ClobberMemory();
  }
  perLink(state);
}
BENCHMARK(BM_ArticulatedAgentStep)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace thyrix
