#include <Controller/NeuralNetwork.h>
#include <ThyrixLite/InvalidArgument.h>

#include <string>

namespace thyrix {

namespace {

// The count of a spec whose sizes are already checked (each at most maxLayerSize, so no
// product overflows).
std::size_t countOf(const NetworkSpec& spec) {
  const std::vector<std::size_t>& layers = spec.layers;
  if (spec.kind == NetworkKind::Ctrnn) {
    const std::size_t inputs = layers[0];
    const std::size_t neurons = layers[1];
    const std::size_t outputs = layers[2];
    return 2 * neurons + inputs * neurons + neurons * neurons + outputs + neurons * outputs;
  }
  std::size_t count = 0;
  for (std::size_t l = 1; l < layers.size(); ++l) count += layers[l] + layers[l - 1] * layers[l];
  return count;
}

}  // namespace

void NetworkSpec::validate() const {
  if (kind != NetworkKind::FeedForward && kind != NetworkKind::Ctrnn)
    throw InvalidArgument("NetworkSpec.kind", "must be FeedForward or Ctrnn");
  if (activation != Activation::Tanh && activation != Activation::Logistic)
    throw InvalidArgument("NetworkSpec.activation", "must be Tanh or Logistic");
  if (kind == NetworkKind::Ctrnn && layers.size() != 3)
    throw InvalidArgument("NetworkSpec.layers",
                          "of a Ctrnn must be {inputs, neurons, outputs} (got " +
                              std::to_string(layers.size()) + " sizes)");
  if (layers.size() < 2 || layers.size() > maxLayers)
    throw InvalidArgument("NetworkSpec.layers", "must have 2 to " + std::to_string(maxLayers) +
                                                    " sizes (got " + std::to_string(layers.size()) +
                                                    ")");
  for (std::size_t l = 0; l < layers.size(); ++l)
    if (layers[l] == 0 || layers[l] > maxLayerSize)
      throw InvalidArgument("NetworkSpec.layers", "size " + std::to_string(l) + " must be 1 to " +
                                                      std::to_string(maxLayerSize) + " (got " +
                                                      std::to_string(layers[l]) + ")");
  if (countOf(*this) > maxParameterCount)
    throw InvalidArgument("NetworkSpec.layers", "need " + std::to_string(countOf(*this)) +
                                                    " parameters, more than " +
                                                    std::to_string(maxParameterCount));
}

std::size_t NetworkSpec::inputCount() const {
  validate();
  return layers.front();
}

std::size_t NetworkSpec::outputCount() const {
  validate();
  return layers.back();
}

std::size_t NetworkSpec::parameterCount() const {
  validate();
  return countOf(*this);
}

std::string_view toString(NetworkKind kind) {
  return kind == NetworkKind::Ctrnn ? "ctrnn" : "feed-forward";
}

std::string_view toString(Activation activation) {
  return activation == Activation::Logistic ? "logistic" : "tanh";
}

}  // namespace thyrix
