/// @file Module.cpp
/// @brief The extension module thyrix._thyrix; the package thyrix re-exports it.

#include "Bindings.h"

#include <ThyrixLite/ThyrixParameters.h>

#include <pybind11/numpy.h>

#include <type_traits>

PYBIND11_MODULE(_thyrix, m) {
  m.doc() = "Thyrix, a fast deterministic 2D quasistatic simulator (C++ core of the package).";
  m.attr("real_dtype") =
      pybind11::dtype::of<thyrix::real>();  // numpy's float64, or float32 with THYRIX_REAL=float
  thyrix::python::bindWorld(m);
  thyrix::python::bindSensors(m);
  thyrix::python::bindControllers(m);
  thyrix::python::bindAgents(m);
  thyrix::python::bindDrawing(m);
  thyrix::python::bindEnvironments(m);
  thyrix::python::bindEvaluation(m);
}
