// The cost of a neural controller in the Spherus step: the same arena (20 circles, seed 1)
// driven by its RandomController; by the same random actions after a 35-8-5 network has run on
// the sensors (the same trajectory, so the difference is the network's cost); by the networks
// themselves (another trajectory); and the networks alone. Goal (issue 28): the 35-8-5 network
// adds at most 20% to the step.

#include <Agents/SpherusSimulator.h>
#include <Controller/NeuralController.h>
#include <Controller/RandomController.h>
#include <Tools/MTRandom.h>

#include <benchmark/benchmark.h>

#include <memory>
#include <span>
#include <vector>

namespace thyrix {
namespace {

const NetworkSpec feedForward{NetworkKind::FeedForward, {35, 8, 5}, Activation::Tanh};
const NetworkSpec ctrnn{NetworkKind::Ctrnn, {35, 8, 5}, Activation::Logistic};

/// A network with standard normal parameters (seed 1), as a first generation has.
std::unique_ptr<NeuralController> network(const NetworkSpec& spec) {
  auto controller = std::make_unique<NeuralController>(spec);
  MTRandom random(1);
  std::vector<real> parameters(controller->parameterCount());
  for (real& value : parameters) value = static_cast<real>(random.normal());
  controller->setParameters(parameters);
  return controller;
}

void spherusStep(benchmark::State& state, std::unique_ptr<Controller> controller) {
  SpherusSimulator::Options options;
  options.seed = 1;
  SpherusSimulator simulator(options, std::move(controller));
  for (int step = 0; step < 100; ++step) simulator.advanceTime();
  for (auto _ : state) simulator.advanceTime();
  benchmark::DoNotOptimize(simulator.spherus().centre());
}

/// The random controller's actions, after running a network on the same sensors: the world
/// moves exactly as with the random controller alone, so the difference is the network's cost.
class RandomAfterNetwork : public Controller {
 public:
  explicit RandomAfterNetwork(const NetworkSpec& spec) : network_(network(spec)), random_(1) {}
  void control(std::span<const real> sensors, std::span<real> effectors) override {
    network_->control(sensors, outputs_);
    benchmark::DoNotOptimize(outputs_.data());
    random_.control(sensors, effectors);
  }

 private:
  std::unique_ptr<NeuralController> network_;
  RandomController random_;
  std::vector<real> outputs_ = std::vector<real>(5);
};

void BM_SpherusStepRandom(benchmark::State& state) {
  spherusStep(state, std::make_unique<RandomController>(1));
}
void BM_SpherusStepFeedForward35_8_5(benchmark::State& state) {
  spherusStep(state, network(feedForward));
}
void BM_SpherusStepCtrnn35_8_5(benchmark::State& state) { spherusStep(state, network(ctrnn)); }
void BM_SpherusStepRandomAfterFeedForward35_8_5(benchmark::State& state) {
  spherusStep(state, std::make_unique<RandomAfterNetwork>(feedForward));
}
void BM_SpherusStepRandomAfterCtrnn35_8_5(benchmark::State& state) {
  spherusStep(state, std::make_unique<RandomAfterNetwork>(ctrnn));
}
BENCHMARK(BM_SpherusStepRandom);
BENCHMARK(BM_SpherusStepRandomAfterFeedForward35_8_5);
BENCHMARK(BM_SpherusStepRandomAfterCtrnn35_8_5);
BENCHMARK(BM_SpherusStepFeedForward35_8_5);
BENCHMARK(BM_SpherusStepCtrnn35_8_5);

/// The network alone, on sensors that change every call as an agent's do.
void networkControl(benchmark::State& state, const NetworkSpec& spec) {
  const std::unique_ptr<NeuralController> controller = network(spec);
  MTRandom random(2);
  std::vector<std::vector<real>> sensors(64, std::vector<real>(35));
  for (std::vector<real>& set : sensors)
    for (real& value : set) value = static_cast<real>(random.uniform());
  std::vector<real> effectors(5);
  std::size_t next = 0;
  for (auto _ : state) {
    controller->control(sensors[next], effectors);
    next = (next + 1) % sensors.size();
    benchmark::DoNotOptimize(effectors.data());
  }
}
void BM_FeedForward35_8_5(benchmark::State& state) { networkControl(state, feedForward); }
void BM_Ctrnn35_8_5(benchmark::State& state) { networkControl(state, ctrnn); }
BENCHMARK(BM_FeedForward35_8_5);
BENCHMARK(BM_Ctrnn35_8_5);

}  // namespace
}  // namespace thyrix
