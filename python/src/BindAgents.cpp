#include "ArrayChecks.h"
#include "Bindings.h"
#include "PythonController.h"

#include <Agents/IunctusSimulator.h>
#include <Agents/PacSimulator.h>
#include <Agents/SpherusSimulator.h>

#include <pybind11/stl.h>

#include <optional>

namespace py = pybind11;

namespace thyrix::python {

namespace {

/// The agent's sensors, effectors (settable: a controller-less agent is driven by hand) and
/// controller, common to the three agents.
template <class Agent, class Class>
void bindAgentSignals(Class& cls) {
  cls.def_property_readonly(
         "sensors", [](const Agent& a) { return copyOf(a.sensors()); },
         "A copy of the sensor activations of the last step, each in [0, 1].")
      .def_property(
          "effectors", [](const Agent& a) { return copyOf(a.effectors()); },
          [](Agent& a, py::handle values) {
            const std::span<real> effectors = a.effectors();
            const auto array =
                checkedArray(values, {static_cast<py::ssize_t>(effectors.size())}, "effectors");
            std::copy_n(array.data(), effectors.size(), effectors.begin());
          },
          "The effector activations (each used clamped to [0, 1]); set them to drive an agent "
          "that has no controller.")
      .def_property_readonly(
          "controller", [](const Agent& a) { return a.controller(); },
          py::return_value_policy::reference_internal, "The controller, or None.");
}

/// Views of @p circles, keeping @p owner alive.
py::list circleViews(const std::vector<Circle*>& circles, py::handle owner) {
  py::list list;
  for (Circle* circle : circles) list.append(viewOf(*circle, owner));
  return list;
}

}  // namespace

void bindAgents(py::module_& m) {
  py::class_<Spherus, PhysicalObject> spherus(
      m, "Spherus",
      "Two circles joined by a link whose length it commands, pushed by rockets. 35 sensors "
      "(per circle: 8 contact, 7 visual, 2 velocity; then the link length), 5 effectors (left "
      "forward and backward rockets, right forward and backward, link length).");
  bindAgentSignals<Spherus>(spherus);
  spherus
      .def_property_readonly(
          "centre", [](const Spherus& s) { return fromVector2(s.centre()); },
          "Midpoint of the two circles.")
      .def_property_readonly(
          "forward", [](const Spherus& s) { return fromVector2(s.forward()); },
          "Unit forward direction.")
      .def_property_readonly("left_circle", &Spherus::leftCircle,
                             py::return_value_policy::reference_internal, "The left circle.")
      .def_property_readonly("right_circle", &Spherus::rightCircle,
                             py::return_value_policy::reference_internal, "The right circle.");

  py::class_<SpherusSimulator, Simulator>(
      m, "SpherusSimulator",
      "A square walled arena with one Spherus and circles to push; the same options give the "
      "same world.")
      .def(py::init([](int objects, double objectRadius, double size, std::uint32_t seed,
                       double timestep, std::optional<std::uint32_t> poseSeed,
                       py::handle controller) {
             SpherusSimulator::Options options;
             options.objects = objects;
             options.objectRadius = static_cast<real>(objectRadius);
             options.size = static_cast<real>(size);
             options.seed = seed;
             options.timestep = static_cast<real>(timestep);
             options.poseSeed = poseSeed;
             return std::make_unique<SpherusSimulator>(
                 options, controllerFrom(controller, options.timestep));
           }),
           py::arg("objects") = 20, py::arg("object_radius") = 0.2, py::arg("size") = 10.0,
           py::arg("seed") = 1, py::arg("timestep") = 0.01, py::arg("pose_seed") = py::none(),
           py::arg("controller") = py::none(),
           "controller: None (set spherus.effectors yourself), a NeuralController (copied), a "
           "Genome, or a callable f(sensors) -> effectors. pose_seed: None starts the agent at "
           "the centre facing +y, a number at a pose drawn from it.")
      .def_property_readonly("spherus", &SpherusSimulator::spherus,
                             py::return_value_policy::reference_internal, "The agent.")
      .def_property_readonly(
          "obstacles",
          [](py::object self) {
            return circleViews(self.cast<const SpherusSimulator&>().obstacles(), self);
          },
          "The circles to push.");

  py::class_<Pac, PhysicalObject> pac(
      m, "Pac", "A ring of circles with a mouth that eats food (see docs/Agents.md).");
  bindAgentSignals<Pac>(pac);
  pac.def_property_readonly(
         "centre", [](const Pac& p) { return fromVector2(p.centre()); }, "The ring's centre.")
      .def_property_readonly(
          "heading", [](const Pac& p) { return static_cast<double>(p.heading()); },
          "Heading, rad.");

  py::class_<PacSimulator, Simulator>(m, "PacSimulator",
                                      "Two Pacs and food circles in a walled arena.")
      .def(py::init([](int food, double size, std::uint32_t seed, double timestep, py::handle first,
                       py::handle second) {
             PacSimulator::Options options;
             options.food = food;
             options.size = static_cast<real>(size);
             options.seed = seed;
             options.timestep = static_cast<real>(timestep);
             return std::make_unique<PacSimulator>(options, controllerFrom(first, options.timestep),
                                                   controllerFrom(second, options.timestep));
           }),
           py::arg("food") = 16, py::arg("size") = 8.0, py::arg("seed") = 1,
           py::arg("timestep") = 0.01, py::arg("first") = py::none(),
           py::arg("second") = py::none(),
           "first, second: the Pacs' controllers, as for "
           "SpherusSimulator.")
      .def(
          "pac",
          [](const PacSimulator& s, int i) -> Pac& {
            if (i != 0 && i != 1) throw py::index_error("pac index must be 0 or 1");
            return s.pac(i);
          },
          py::arg("index"), py::return_value_policy::reference_internal, "Pac 0 or 1.")
      .def_property_readonly(
          "food",
          [](py::object self) {
            return circleViews(self.cast<const PacSimulator&>().food(), self);
          },
          "The food circles.")
      .def("food_inside", &PacSimulator::foodInside, py::arg("pac"),
           "Food circles inside the ring of `pac`.");

  py::class_<Iunctus, PhysicalObject> iunctus(
      m, "Iunctus", "An articulated agent: a round base and a three-link limb.");
  bindAgentSignals<Iunctus>(iunctus);

  py::class_<IunctusSimulator, Simulator>(m, "IunctusSimulator",
                                          "An Iunctus and circles to catch in a walled arena.")
      .def(py::init([](int objects, double size, std::uint32_t seed, double timestep,
                       py::handle controller) {
             IunctusSimulator::Options options;
             options.objects = objects;
             options.size = static_cast<real>(size);
             options.seed = seed;
             options.timestep = static_cast<real>(timestep);
             return std::make_unique<IunctusSimulator>(
                 options, controllerFrom(controller, options.timestep));
           }),
           py::arg("objects") = 1, py::arg("size") = 8.0, py::arg("seed") = 1,
           py::arg("timestep") = 0.01, py::arg("controller") = py::none(),
           "controller: as for SpherusSimulator.")
      .def_property_readonly("iunctus", &IunctusSimulator::iunctus,
                             py::return_value_policy::reference_internal, "The agent.")
      .def_property_readonly(
          "objects_to_catch",
          [](py::object self) {
            return circleViews(self.cast<const IunctusSimulator&>().objectsToCatch(), self);
          },
          "The circles to catch.");
}

}  // namespace thyrix::python
