#include <Controller/ActivationFunctions.h>
#include <Controller/NeuralController.h>
#include <ThyrixLite/InvalidArgument.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace thyrix {

namespace {

// sums[k] += sum_j weights[j * n + k] * inputs[j] for the W targets from sums, j in order, in
// a local array the compiler keeps in registers: accumulating in memory would chain every
// addition through a store and a load.
template <std::size_t W>
void accumulateBlock(const real* weights, std::span<const real> inputs, real* sums, std::size_t n) {
  real block[W];
  for (std::size_t k = 0; k < W; ++k) block[k] = sums[k];
  for (const real x : inputs) {
    for (std::size_t k = 0; k < W; ++k) block[k] += weights[k] * x;
    weights += n;
  }
  for (std::size_t k = 0; k < W; ++k) sums[k] = block[k];
}

// sums[i] += sum_j weights[j * n + i] * inputs[j] for every target i < n, j in order.
void accumulate(std::span<const real> weights, std::span<const real> inputs, real* sums,
                std::size_t n) {
  std::size_t i = 0;
  for (; i + 8 <= n; i += 8) accumulateBlock<8>(weights.data() + i, inputs, sums + i, n);
  for (; i + 4 <= n; i += 4) accumulateBlock<4>(weights.data() + i, inputs, sums + i, n);
  for (; i < n; ++i) accumulateBlock<1>(weights.data() + i, inputs, sums + i, n);
}

void requireCount(std::size_t count, std::size_t expected, const char* field) {
  if (count != expected)
    throw InvalidArgument(field, "must have " + std::to_string(expected) + " values (got " +
                                     std::to_string(count) + ")");
}

}  // namespace

NeuralController::NeuralController(NetworkSpec spec, real timestep)
    : spec_(std::move(spec)), timestep_(timestep) {
  requirePositive(timestep, "NeuralController.timestep");
  parameters_.assign(spec_.parameterCount(), 0);  // validates the spec
  const std::size_t widest = *std::max_element(spec_.layers.begin(), spec_.layers.end());
  if (spec_.kind == NetworkKind::Ctrnn) {
    const std::size_t neurons = spec_.layers[1];
    rate_.assign(neurons, 0);
    state_.assign(neurons, 0);
    firing_.assign(neurons, 0);
    scratch_.assign(neurons, 0);
  } else {
    scratch_.assign(2 * widest, 0);
  }
  useParameters();
}

void NeuralController::setParameters(std::span<const real> parameters) {
  requireCount(parameters.size(), parameters_.size(), "NeuralController.parameters");
  for (std::size_t p = 0; p < parameters.size(); ++p)
    if (!std::isfinite(parameters[p]))
      throw InvalidArgument("NeuralController.parameters", "value " + std::to_string(p) +
                                                               " must be finite (got " +
                                                               std::to_string(parameters[p]) + ")");
  if (parameters.data() != parameters_.data())  // parameters() passed back is already in place
    std::copy(parameters.begin(), parameters.end(), parameters_.begin());
  useParameters();
}

void NeuralController::useParameters() {
  // tau = dt + exp(p) > dt: the Euler factor dt / tau stays in (0, 1).
  for (std::size_t i = 0; i < rate_.size(); ++i)
    rate_[i] = static_cast<real>(
        timestep_ / (timestep_ + boundedExp(std::clamp<double>(parameters_[i], -60, 60))));
  reset();
}

void NeuralController::reset() {
  std::fill(state_.begin(), state_.end(), real(0));
  updateFiring();
}

void NeuralController::updateFiring() {
  const std::size_t neurons = state_.size();
  const real* biases = parameters_.data() + neurons;
  for (std::size_t i = 0; i < neurons; ++i) firing_[i] = state_[i] + biases[i];
  activateLayer(spec_.activation, firing_);
}

void NeuralController::control(std::span<const real> sensors, std::span<real> effectors) {
  requireCount(sensors.size(), spec_.layers.front(), "NeuralController.sensors");
  requireCount(effectors.size(), spec_.layers.back(), "NeuralController.effectors");
  if (spec_.kind == NetworkKind::Ctrnn)
    stepCtrnn(sensors, effectors);
  else
    feedForward(sensors, effectors);
}

void NeuralController::feedForward(std::span<const real> sensors, std::span<real> effectors) {
  const std::size_t half = scratch_.size() / 2;
  std::span<const real> in = sensors;
  real* out = scratch_.data();
  std::span<const real> parameters = parameters_;
  const std::size_t last = spec_.layers.size() - 1;
  for (std::size_t l = 1; l <= last; ++l) {
    const std::size_t n = spec_.layers[l];
    std::copy_n(parameters.begin(), n, out);  // the biases
    const std::size_t weightCount = in.size() * n;
    accumulate(parameters.subspan(n, weightCount), in, out, n);
    parameters = parameters.subspan(n + weightCount);
    if (l == last) {
      std::copy_n(out, n, effectors.begin());
      activateOutputs(spec_.activation, effectors);
    } else {
      activateLayer(spec_.activation, std::span<real>(out, n));
      in = std::span<const real>(out, n);
      out = out == scratch_.data() ? scratch_.data() + half : scratch_.data();
    }
  }
}

void NeuralController::stepCtrnn(std::span<const real> sensors, std::span<real> effectors) {
  const std::size_t inputs = sensors.size();
  const std::size_t neurons = state_.size();
  const std::size_t outputs = effectors.size();
  std::span<const real> gains =
      std::span<const real>(parameters_).subspan(2 * neurons, inputs * neurons);
  std::span<const real> weights =
      std::span<const real>(parameters_).subspan(2 * neurons + inputs * neurons, neurons * neurons);
  std::span<const real> outputBiases =
      std::span<const real>(parameters_)
          .subspan(2 * neurons + inputs * neurons + neurons * neurons, outputs);
  std::span<const real> outputWeights =
      std::span<const real>(parameters_)
          .subspan(2 * neurons + inputs * neurons + neurons * neurons + outputs, neurons * outputs);

  real* net = scratch_.data();
  std::fill_n(net, neurons, real(0));
  accumulate(gains, sensors, net, neurons);
  accumulate(weights, firing_, net, neurons);
  for (std::size_t i = 0; i < neurons; ++i) state_[i] += rate_[i] * (net[i] - state_[i]);
  updateFiring();

  std::copy(outputBiases.begin(), outputBiases.end(), effectors.begin());
  accumulate(outputWeights, firing_, effectors.data(), outputs);
  activateOutputs(spec_.activation, effectors);
}

void NeuralController::saveState(StateRecord& record) const {
  record.add(std::span<const real>(state_));
  record.add(std::span<const real>(firing_));
}

void NeuralController::restoreState(StateRecord::Reader& reader) {
  reader.reals(state_);
  reader.reals(firing_);
}

}  // namespace thyrix
