#include "PythonController.h"

#include "ArrayChecks.h"

#include <Controller/Genome.h>
#include <Controller/NeuralController.h>

#include <algorithm>

namespace py = pybind11;

namespace thyrix::python {

PythonController::PythonController(py::object function) : function_(std::move(function)) {
  if (!PyCallable_Check(function_.ptr()))
    throw py::type_error("controller must be callable, a NeuralController, a Genome or None");
}

PythonController::~PythonController() {
  // An agent may be destroyed when Python has released the GIL (a world freed by C++).
  py::gil_scoped_acquire gil;
  function_ = py::object();
}

void PythonController::control(std::span<const real> sensors, std::span<real> effectors) {
  const py::object result = function_(copyOf(sensors));
  const auto values =
      checkedArray(result, {static_cast<py::ssize_t>(effectors.size())}, "controller's result");
  std::copy_n(values.data(), effectors.size(), effectors.begin());
}

std::unique_ptr<Controller> controllerFrom(py::handle controller, real timestep) {
  if (controller.is_none()) return nullptr;
  if (py::isinstance<NeuralController>(controller))
    return std::make_unique<NeuralController>(controller.cast<const NeuralController&>());
  if (py::isinstance<Genome>(controller))
    return controller.cast<const Genome&>().makeController(timestep);
  return std::make_unique<PythonController>(py::reinterpret_borrow<py::object>(controller));
}

}  // namespace thyrix::python
