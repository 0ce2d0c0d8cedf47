#pragma once
/// @file Bindings.h
/// @brief The parts of the Python module _thyrix, one function per concept, called in order by
/// Module.cpp (a class must be bound before a function that returns it).

#include <pybind11/pybind11.h>

#include <utility>

namespace thyrix::python {

/// Adds the method @p name to the already bound class @p cls (a later part of the module
/// extending a class bound by an earlier one).
template <class Function, class... Extra>
void addMethod(pybind11::handle cls, const char* name, Function&& function, const Extra&... extra) {
  pybind11::cpp_function method(
      std::forward<Function>(function), pybind11::name(name), pybind11::is_method(cls),
      pybind11::sibling(pybind11::getattr(cls, name, pybind11::none())), extra...);
  pybind11::setattr(cls, name, method);
}

/// Adds the read-only property @p name, computed by @p getter, to the bound class @p cls.
template <class Getter>
void addProperty(pybind11::handle cls, const char* name, Getter&& getter, const char* doc) {
  pybind11::cpp_function get(std::forward<Getter>(getter), pybind11::is_method(cls));
  pybind11::setattr(cls, name,
                    pybind11::module_::import("builtins")
                        .attr("property")(get, pybind11::none(), pybind11::none(), doc));
}

/// A Python view of @p object, a part of @p owner, that keeps @p owner alive.
template <class T>
pybind11::object viewOf(T& object, pybind11::handle owner) {
  pybind11::object view = pybind11::cast(&object, pybind11::return_value_policy::reference);
  pybind11::detail::keep_alive_impl(view, owner);
  return view;
}

/// World, Simulator, PhysicalObject, the shapes, registration, poses, contacts, solver settings.
void bindWorld(pybind11::module_& module);
/// Tactile activations of primitives and VisualSensor.
void bindSensors(pybind11::module_& module);
/// NetworkSpec, NeuralController, Genome and a Python callable as a controller.
void bindControllers(pybind11::module_& module);
/// Spherus, Pac and Iunctus with their simulators.
void bindAgents(pybind11::module_& module);
/// draw_svg(): a world as an SVG document.
void bindDrawing(pybind11::module_& module);
/// The C++ cores of SpherusEnv and SpherusVectorEnv.
void bindEnvironments(pybind11::module_& module);
/// evaluate() and derive_seed().
void bindEvaluation(pybind11::module_& module);

}  // namespace thyrix::python
