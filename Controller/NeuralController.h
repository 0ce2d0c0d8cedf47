#pragma once
/// @file NeuralController.h
/// @brief A controller that runs a feed-forward or continuous-time recurrent neural network
///        whose weights are one flat parameter vector.

#include <Controller/Controller.h>
#include <Controller/NeuralNetwork.h>

#include <cstddef>
#include <span>
#include <vector>

namespace thyrix {

/// Feeds the agent's sensors (in [0, 1]) to a network and writes its outputs, in [0, 1], to the
/// effectors. The network and the order of its parameters are described by NetworkSpec; an
/// optimiser sees only parameterCount() numbers and setParameters(). A new controller has every
/// parameter 0. Steps allocate nothing.
class NeuralController : public Controller {
 public:
  /// A network of shape @p spec with every parameter 0.
  /// @param spec the network's shape and the order of its parameters
  /// @param timestep the Euler step of a Ctrnn (s), normally the simulator's; unused by a
  ///        feed-forward network
  /// @throws InvalidArgument naming a "NetworkSpec." field (see NetworkSpec::validate()) or
  ///         "NeuralController.timestep" (not positive and finite)
  explicit NeuralController(NetworkSpec spec, real timestep = real(0.01));

  /// The network's shape.
  [[nodiscard]] const NetworkSpec& spec() const { return spec_; }
  /// The Euler step of a Ctrnn (s).
  [[nodiscard]] real timestep() const { return timestep_; }
  /// The length of the parameter vector (spec().parameterCount()).
  [[nodiscard]] std::size_t parameterCount() const { return parameters_.size(); }

  /// Replaces every parameter, in NetworkSpec's order, and resets the state (reset()).
  /// @throws InvalidArgument naming "NeuralController.parameters" (not parameterCount() values,
  ///         or one not finite); the controller is then unchanged
  void setParameters(std::span<const real> parameters);
  /// The parameters, in NetworkSpec's order.
  [[nodiscard]] std::span<const real> parameters() const { return parameters_; }

  /// The Ctrnn's neuron states `y_i` (empty for a feed-forward network).
  [[nodiscard]] std::span<const real> state() const { return state_; }

  /// Computes one step of the network from @p sensors and writes @p effectors, each in [0, 1].
  /// @throws InvalidArgument naming "NeuralController.sensors" or "NeuralController.effectors"
  ///         when their count differs from the spec's inputs or outputs
  void control(std::span<const real> sensors, std::span<real> effectors) override;

  /// Sets a Ctrnn's neuron states back to 0 (a feed-forward network has no state).
  void reset() override;
  /// Appends the CTRNN's neuron states and firing rates (nothing else carries over: a
  /// feed-forward network has no state).
  void saveState(StateRecord& record) const override;
  /// Reads back what saveState() appended.
  /// @throws std::runtime_error if the record's network has another number of neurons
  void restoreState(StateRecord::Reader& reader) override;

 private:
  void feedForward(std::span<const real> sensors, std::span<real> effectors);
  void stepCtrnn(std::span<const real> sensors, std::span<real> effectors);
  /// Derives the time constants' rates from the parameters and resets the state.
  void useParameters();
  /// act(y_i + theta_i) for every neuron, from the current states.
  void updateFiring();

  NetworkSpec spec_;
  real timestep_;
  std::vector<real> parameters_;
  std::vector<real> rate_;     ///< Ctrnn: dt / tau_i, computed once per setParameters()
  std::vector<real> state_;    ///< Ctrnn: y_i
  std::vector<real> firing_;   ///< Ctrnn: act(y_i + theta_i) of the current states
  std::vector<real> scratch_;  ///< two layers' activations (feed-forward) or net inputs (Ctrnn)
};

}  // namespace thyrix
