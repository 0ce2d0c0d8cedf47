#pragma once
/// @file PythonController.h
/// @brief A Python callable as an agent's controller, and the conversion of a Python
/// `controller=` argument into the controller an agent owns.

#include <Controller/Controller.h>

#include <pybind11/pybind11.h>

#include <memory>

namespace thyrix::python {

/// Calls `function(sensors)` once per step, with a numpy copy of the sensors, and copies the
/// returned effectors (any array-like of the effectors' length, finite) into the agent. An
/// exception raised by the function, or a wrong result (TypeError, ValueError), propagates out
/// of the step. It runs with the GIL held: the world must be stepped from Python's thread (as
/// World.advance_time does).
class PythonController : public Controller {
 public:
  /// @throws pybind11::type_error unless @p function is callable
  explicit PythonController(pybind11::object function);
  ~PythonController() override;
  PythonController(const PythonController&) = delete;
  PythonController& operator=(const PythonController&) = delete;

  void control(std::span<const real> sensors, std::span<real> effectors) override;

  /// The callable.
  [[nodiscard]] const pybind11::object& function() const { return function_; }

 private:
  pybind11::object function_;
};

/// The controller an agent is to own, from a Python `controller=` argument: None (no
/// controller: the effectors are set by hand), a NeuralController (copied), a Genome (its
/// network) or a callable (PythonController).
/// @throws pybind11::type_error naming `controller` for anything else
std::unique_ptr<Controller> controllerFrom(pybind11::handle controller, real timestep);

}  // namespace thyrix::python
