#pragma once
/// @file NeuralNetwork.h
/// @brief What a neural network is: its kind, its units, its layer sizes and the order of its
///        parameters in one flat vector.

#include <cstddef>
#include <string_view>
#include <vector>

namespace thyrix {

/// The two networks a NeuralController runs.
enum class NetworkKind {
  FeedForward,  ///< layers of units, each fed by the layer before it; no state
  Ctrnn         ///< a continuous-time recurrent network (Beer 1995), integrated by forward Euler
};

/// The squashing function of the units, computed with basic arithmetic only
/// (ActivationFunctions.h), so a network gives the same bits on every platform.
enum class Activation {
  Tanh,     ///< tanh(x) in (-1, 1); an output is mapped to (0, 1) as (1 + tanh(x)) / 2
  Logistic  ///< 1 / (1 + exp(-x)) in (0, 1)
};

/// The shape of a network, which is what a genome is for: with it, a flat parameter vector
/// defines the network completely.
///
/// **FeedForward**, `layers = {inputs, hidden..., outputs}` (at least two entries). Each layer
/// `l >= 1` of `n` units fed by `m` units of layer `l - 1` takes `n + m * n` parameters, layer
/// after layer: first the `n` biases `b_i`, then the `m * n` weights source by source
/// (`w_ji` for j = 0..m-1, and for each j, i = 0..n-1). A unit computes
/// `a_i = act(b_i + sum_j w_ji x_j)`, the sum taken in the order of j; the last layer's
/// activations, mapped to [0, 1] (see Activation), are the outputs.
///
/// **Ctrnn**, `layers = {inputs, neurons, outputs}`. With `N` neurons of state `y_i`, `I` inputs
/// `s_k` and `O` outputs, Beer's equation
/// `tau_i dy_i/dt = -y_i + sum_j w_ji act(y_j + theta_j) + sum_k g_ki s_k`
/// is stepped by forward Euler with the controller's timestep `dt`, from `y = 0`. Output `o` is
/// `act01(c_o + sum_j v_jo act(y_j + theta_j))` after the step, with `act01` the activation
/// mapped to [0, 1]. The parameters, in this order:
/// - `N` time-constant parameters `p_i`, with `tau_i = dt + exp(p_i)` (s): always above `dt`, so
///   the Euler step is stable whatever the parameter (`p_i` is limited to [-60, 60], where
///   `exp(p_i)` is already negligible beside `dt` or the neuron frozen);
/// - `N` biases `theta_i`;
/// - `I * N` input gains `g_ki`, source by source (k = 0..I-1, then i = 0..N-1);
/// - `N * N` recurrent weights `w_ji`, source by source (j, then i);
/// - `O` output biases `c_o`;
/// - `N * O` output weights `v_jo`, source by source (j, then o).
struct NetworkSpec {
  /// Largest layer a spec may have (units), so that a corrupt genome cannot ask for a huge one.
  static constexpr std::size_t maxLayerSize = std::size_t{1} << 16;
  /// Most layers a feed-forward spec may have (inputs and outputs included).
  static constexpr std::size_t maxLayers = 64;
  /// Most parameters a spec may have, for the same reason as maxLayerSize.
  static constexpr std::size_t maxParameterCount = std::size_t{1} << 28;

  NetworkKind kind = NetworkKind::FeedForward;  ///< feed-forward or recurrent
  /// FeedForward: inputs, hidden layers..., outputs. Ctrnn: inputs, neurons, outputs.
  std::vector<std::size_t> layers;
  Activation activation = Activation::Tanh;  ///< the units' function

  /// The inputs the network reads (sensors): `layers.front()`.
  /// @throws InvalidArgument naming "NetworkSpec.layers" unless the spec is valid (validate())
  [[nodiscard]] std::size_t inputCount() const;
  /// The outputs the network writes (effectors): `layers.back()`.
  /// @throws InvalidArgument naming "NetworkSpec.layers" unless the spec is valid (validate())
  [[nodiscard]] std::size_t outputCount() const;
  /// The length of the flat parameter vector, in the order documented above.
  /// @throws InvalidArgument naming "NetworkSpec.layers" unless the spec is valid (validate())
  [[nodiscard]] std::size_t parameterCount() const;

  /// @throws InvalidArgument naming "NetworkSpec.layers" (fewer than two sizes or more than
  ///         maxLayers, a Ctrnn without exactly three, a size of 0 or above maxLayerSize, more
  ///         than maxParameterCount parameters) or "NetworkSpec.kind" /
  ///         "NetworkSpec.activation" (a value outside its enumeration)
  void validate() const;

  /// Equal kind, activation and layer sizes.
  friend bool operator==(const NetworkSpec&, const NetworkSpec&) = default;
};

/// "feed-forward" or "ctrnn", the names a genome file uses.
[[nodiscard]] std::string_view toString(NetworkKind kind);
/// "tanh" or "logistic", the names a genome file uses.
[[nodiscard]] std::string_view toString(Activation activation);

}  // namespace thyrix
