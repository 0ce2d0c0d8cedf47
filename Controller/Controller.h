#pragma once
/// @file Controller.h
/// @brief The interface between an agent's sensors and its effectors.

#include <ThyrixLite/StateRecord.h>
#include <ThyrixLite/ThyrixParameters.h>

#include <span>

namespace thyrix {

/// Maps sensor activations to effector activations, once per step. Every value is in [0, 1],
/// so a neural network, a hand-written rule or an evolved program can be plugged in alike.
/// A controller owns whatever state it needs (a network's activations, a random stream); it
/// shares nothing with other controllers, so agents in different threads stay independent.
class Controller {
 public:
  virtual ~Controller() = default;

  /// Reads @p sensors and writes every entry of @p effectors (each in [0, 1]).
  virtual void control(std::span<const real> sensors, std::span<real> effectors) = 0;

  /// Returns to the initial state (for the next episode). The default has no state.
  virtual void reset() {}

  /// Appends to @p record whatever of the controller's state the next control() reads (its
  /// random stream, a network's activations), for Simulator::saveState(). The default, for a
  /// controller without state, appends nothing.
  virtual void saveState(StateRecord& /*record*/) const {}
  /// Reads back, in the same order, what saveState() appended. The default reads nothing.
  virtual void restoreState(StateRecord::Reader& /*reader*/) {}
};

}  // namespace thyrix
